// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Internal to io/: the importing shared by the formats whose cells are
// labelled patches of one polygon surface (MorphoGraphX cell meshes,
// cell-complex PLY files of an L1 layer). Each label's faces must form a
// disk; its outline becomes a cell of a curved-sheet tissue.

#include <cstdint>
#include <numeric>
#include <span>
#include <string>
#include <vector>

#include "tessella/io/import.hpp"
#include "tessella/tissue/tissue.hpp"

namespace tessella::io::detail {

using Label = std::int64_t;

inline std::uint64_t edgeKey(Index u, Index v) { return (std::uint64_t(u) << 32) | v; }

struct UnionFind {
  std::vector<Index> parent;
  explicit UnionFind(std::size_t n) { reset(n); }
  /// n singletons again (keeps the storage).
  void reset(std::size_t n) {
    parent.resize(n);
    std::iota(parent.begin(), parent.end(), Index{0});
  }
  Index find(Index x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(Index a, Index b) { parent[find(a)] = find(b); }
};

/// A vertex of the file, nine digits: enough to find it in the file and tell it from its neighbours.
std::string fmtPoint(const Vec3& p);

/// InputError for scale <= 0, simplify < 0, or either not finite.
void checkImportOptions(const ImportOptions& options);

/// A polygon surface whose faces carry the label of the cell they lie in,
/// indices checked against the vertex count.
struct LabelledSurface {
  std::string path;
  std::vector<Vec3> positions;
  /// MorphoGraphX: a cell's label on its centre vertex (-1 on walls); empty
  /// when the format has none. Only used to tell two cells with one label
  /// from one cell in two pieces.
  std::vector<Label> vertex_label;
  std::vector<std::size_t> face_offsets;  ///< size faces + 1
  std::vector<Index> face_vertices;
  std::vector<Label> face_label;
  /// The index in the file of each face, for messages; empty when face f is
  /// the file's face f.
  std::vector<Index> file_face;
  std::size_t numFaces() const { return face_label.size(); }
  std::string faceId(std::size_t f) const { return std::to_string(file_face.empty() ? f : file_face[f]); }
  std::span<const Index> face(std::size_t f) const {
    return {face_vertices.data() + face_offsets[f], face_offsets[f + 1] - face_offsets[f]};
  }
};

/// InputError when two vertices used by faces are at the same position (the
/// mesh is not welded), naming both and a face of each.
void checkDuplicateVertices(const LabelledSurface& m);

/// The cells found on a surface, sorted by label.
struct SheetCells {
  std::vector<Label> labels;
  std::vector<std::vector<Index>> faces;     ///< per cell, its faces in the file
  std::vector<std::vector<Index>> outlines;  ///< per cell, file vertex indices
};

struct LabelledSheet {
  Tissue tissue;  ///< cell c is cells.labels[c]; cell property `label` (int64)
  SheetCells cells;
};

/// Checks the surface (welded, every label a disk), repairs one-triangle
/// slivers when options.repair (each in report.repairs), simplifies walls
/// when options.simplify > 0 (report.simplified_vertices), scales, and builds
/// the curved-sheet tissue of the outlines. InputError naming the file, the
/// face and the cell label for every defect.
LabelledSheet buildLabelledSheet(LabelledSurface& m, const ImportOptions& options, ImportReport& report);

/// Vertices of the surface used by no face.
std::size_t unusedVertices(const LabelledSurface& m);

}  // namespace tessella::io::detail
