// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Names of the field-data arrays that make a .vtu a Tessella snapshot. The
// writer and the reader share them, and docs/output.md documents them.

#include <optional>
#include <string>

#include "tessella/tissue/tissue.hpp"

namespace tessella::io::detail {

/// Bumped when a change would make older readers misread a snapshot.
inline constexpr int kSnapshotFormatVersion = 1;

inline constexpr const char* kFormatVersionArray = "tessella_format_version";
/// ParaView's own name for a dataset's time.
inline constexpr const char* kTimeArray = "TimeValue";
inline constexpr const char* kDimArray = "tessella_dim";
/// "planar" | "surface" | "volume"
inline constexpr const char* kEmbeddingArray = "tessella_embedding";
/// Lineage ids below this value were used in the run, perhaps by cells that
/// no longer exist; recorded for analyses of the lineage.
inline constexpr const char* kNextLineageArray = "tessella_next_lineage_id";
/// Which cell-data / point-data arrays are properties (the rest are derived).
inline constexpr const char* kCellPropertiesArray = "tessella_cell_properties";
inline constexpr const char* kVertexPropertiesArray = "tessella_vertex_properties";
/// Division policy of each listed property, in the same order ("copy",
/// "split_by_measure", "reset", "custom"); absent in files before it existed.
inline constexpr const char* kCellPoliciesArray = "tessella_cell_property_policies";
inline constexpr const char* kVertexPoliciesArray = "tessella_vertex_property_policies";

/// Prefixes of the one-tuple field arrays holding each listed property's
/// default value (what a new element gets; a Reset column's value after a
/// division), as "<prefix><property name>"; absent in files before they
/// existed, when the type's zero is the default.
inline constexpr const char* kCellDefaultPrefix = "tessella_cell_default:";
inline constexpr const char* kVertexDefaultPrefix = "tessella_vertex_default:";
/// The run's state beside the tissue (RunState), as "key=value" strings.
inline constexpr const char* kRunStateArray = "tessella_run_state";

/// The tissue's CellComplex as a ComplexLayout (wall and edge numbering,
/// orientations, list orders), so that a restart rebuilds the very complex
/// the run had: one UInt32 field array per layout list, named
/// "<prefix><list>" (no volume lists in 2D). Absent in older
/// files (and in 2D files before 2D layouts were stored), which read back
/// with walls matched by vertex set and edges numbered by first use.
inline constexpr const char* kTopologyPrefix = "tessella_topology:";

/// The layout's lists by name, in one place for the writer and the reader;
/// the volume lists only in 3D (a 2D layout has them empty, and they are not
/// stored).
template <typename Layout, typename Visit>
void forEachLayoutList(Layout& layout, Visit visit) {
  visit("edge_vertices", layout.edge_vertices);
  visit("face_edge_offsets", layout.face_edge_offsets);
  visit("face_edges", layout.face_edges);
  if (layout.dim == 3) {
    visit("volume_face_offsets", layout.volume_face_offsets);
    visit("volume_faces", layout.volume_faces);
  }
  visit("vertex_edge_offsets", layout.vertex_edge_offsets);
  visit("vertex_edges", layout.vertex_edges);
  visit("edge_face_offsets", layout.edge_face_offsets);
  visit("edge_faces", layout.edge_faces);
  if (layout.dim == 3) {
    visit("face_volume_offsets", layout.face_volume_offsets);
    visit("face_volumes", layout.face_volumes);
  }
}

/// Derived cell measures, written for ParaView and never read back.
inline constexpr const char* kAreaArray = "area";
inline constexpr const char* kVolumeArray = "volume";

inline const char* embeddingTag(Embedding e) {
  switch (e) {
    case Embedding::Planar: return "planar";
    case Embedding::Surface: return "surface";
    case Embedding::Volume: return "volume";
  }
  return "unknown";
}

inline std::optional<Embedding> embeddingFromTag(const std::string& tag) {
  if (tag == "planar") return Embedding::Planar;
  if (tag == "surface") return Embedding::Surface;
  if (tag == "volume") return Embedding::Volume;
  return std::nullopt;
}

}  // namespace tessella::io::detail
