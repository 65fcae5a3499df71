// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Internal to io/: the cell complex that the cell-complex PLY importer reads
// and the labelled-tetrahedra importer derives, and the closed-volume core
// both use (import_cell_complex.cpp): classifying a volume's faces, and
// building a 3D tissue whose walls are the faces, oriented outwards per cell.

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "labelled_surface.hpp"

namespace tessella::io::detail {

/// A cell complex read into plain arrays, every index checked: faces as
/// vertex loops, volumes as face lists, one label per volume.
struct ComplexFile {
  std::string path;
  std::vector<Vec3> positions;
  std::vector<std::size_t> face_offsets;  // vertex loops
  std::vector<Index> face_vertices;
  std::vector<std::size_t> volume_offsets;
  std::vector<Index> volume_faces;
  std::vector<Label> volume_label;
  bool signed_one_based = false;  // volume face_index written as +-(face + 1)
  bool faces_from_edges = false;  // faces listed edges (edge_index)

  std::size_t numFaces() const { return face_offsets.size() - 1; }
  std::size_t numVolumes() const { return volume_label.size(); }
  std::span<const Index> face(std::size_t f) const {
    return {face_vertices.data() + face_offsets[f], face_offsets[f + 1] - face_offsets[f]};
  }
  std::span<const Index> volume(std::size_t v) const {
    return {volume_faces.data() + volume_offsets[v], volume_offsets[v + 1] - volume_offsets[v]};
  }
  /// What the format calls a cell and, per face, the file element it comes
  /// from (empty: face f is the file's face f), for messages.
  std::string volume_noun = "volume";
  std::string face_noun = "face";
  std::vector<Index> face_element;  ///< when set, face f is a side of element face_element[f]
  /// What each face is in the file, for the layout note (without face_element).
  std::string face_origin = "a face of the file";
  std::string volumeRef(std::size_t v) const {
    return volume_noun + " " + std::to_string(v) + " (label " + std::to_string(volume_label[v]) + ")";
  }
  std::string faceName(std::size_t f) const {
    if (face_element.empty()) return face_noun + " " + std::to_string(f);
    std::string vertices;
    for (Index u : face(f)) vertices += (vertices.empty() ? "" : " ") + std::to_string(u);
    return "the side (vertices " + vertices + ") of element " + std::to_string(face_element[f]);
  }
  std::string volumeName(std::size_t v) const { return "'" + path + "' " + volumeRef(v); }
};

/// InputError when two faces have the same vertices (a wall listed twice instead of shared).
void checkDuplicateFaces(const ComplexFile& m);

enum class Shape { Closed, Patch };

/// A volume's faces as one surface: its shape, and for a closed surface the
/// orientation of each face (+1: the loop as written points out of the cell).
struct VolumeSurface {
  Shape shape = Shape::Closed;
  std::vector<int> orientation;  ///< per face of the volume, in its listing order (closed only)
};

/// Classifies volume v (closed sphere or disk patch) and orients a closed
/// one outwards; InputError naming the volume and its label otherwise.
VolumeSurface analyseVolume(const ComplexFile& m, std::size_t v);

/// The 3D tissue of closed volumes (surfaces[v].shape == Closed for all):
/// checks the vertices are welded and each face bounds at most two cells,
/// one on each side; cells ordered by label with the int64 property `label`.
/// Adds the layout note (and notes on dropped faces and vertices) to `report`.
ImportResult importClosedVolumes(const ComplexFile& m, const std::vector<VolumeSurface>& surfaces,
                                 const ImportOptions& options, ImportReport& report);

/// Everything after reading: the closed cells of a 3D tissue or the patches
/// of a sheet (detected, then the matching note first in the report), or an
/// InputError for a mix. `report` comes with path, format and file counts.
ImportResult importComplex(const ComplexFile& m, const ImportOptions& options, ImportReport report);

}  // namespace tessella::io::detail
