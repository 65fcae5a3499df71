// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Building tissues from plain arrays (generators, file readers, tests).

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "tessella/tissue/tissue.hpp"

namespace tessella {

/// A 2D tissue from vertex positions and polygons (vertex index loops).
/// Shared edges are created once. Loops must all run the same way round
/// (counter-clockwise seen from +z for a planar tissue); throws InputError
/// naming the polygon for a loop with fewer than 3 vertices or a bad index.
Tissue buildPolygonTissue(std::span<const Vec3> positions,
                          const std::vector<std::vector<Index>>& polygons,
                          Embedding embedding = Embedding::Planar);

/// The same from flat (CSR) arrays: polygon k is
/// loop_vertices[offsets[k] .. offsets[k+1]). Built in bulk (no search per
/// edge); the result is identical to the nested-vector form. With `face_ids`
/// (optional), the loops are listed in build order instead: loop q is
/// polygon face_ids[q], see CellComplex::fromLoops.
Tissue buildPolygonTissue(std::vector<Vec3> positions, std::span<const Index> offsets,
                          std::span<const Index> loop_vertices, Embedding embedding = Embedding::Planar,
                          std::span<const Index> face_ids = {});

/// One face of a polyhedral cell as used by buildPolyhedralTissue: an index
/// into the face list and whether its loop normal points into the cell.
struct CellFace {
  Index face = 0;
  bool reversed = false;
};

/// A 3D tissue from vertex positions, wall polygons (vertex index loops, each
/// shared by its one or two cells) and cells (faces with orientation).
Tissue buildPolyhedralTissue(std::span<const Vec3> positions,
                             const std::vector<std::vector<Index>>& faces,
                             const std::vector<std::vector<CellFace>>& cells);

/// The same from flat (CSR) arrays: face k is face_vertices[face_offsets[k] ..
/// face_offsets[k+1]), cell k is cell_faces[cell_offsets[k] .. cell_offsets[k+1]).
/// `closed_by_construction` (optional, one flag per cell): cells whose
/// surface the caller guarantees closed and consistently oriented, see
/// CellComplex::addVolumes.
Tissue buildPolyhedralTissue(std::vector<Vec3> positions, std::span<const Index> face_offsets,
                             std::span<const Index> face_vertices, std::span<const Index> cell_offsets,
                             std::span<const CellFace> cell_faces,
                             std::span<const std::uint8_t> closed_by_construction = {});

/// How checkPolyhedra treats the `reversed` flags of the cells' faces.
enum class FaceOrientation {
  Given,    ///< as the caller set them: checked, never changed
  Outward,  ///< set here: each cell's faces consistently oriented, normals pointing out of it
};

/// Checks the arrays of buildPolyhedralTissue before building, with messages in the caller's numbering (cell k,
/// face f, edge u-v by its vertex indices), and with FaceOrientation::Outward first sets every `reversed` flag.
/// InputError for: a face with fewer than 3 vertices, a vertex index out of range or repeated in a face, two faces
/// with the same vertices (a wall shared by two cells is one face listed by both), a face listed by more than two
/// cells; a cell with fewer than 4 faces, a face index out of range or listed twice, an open cell (an edge in only
/// one of its faces), an edge in more than two of its faces, faces in several separate pieces, a surface that
/// cannot be oriented consistently (Given: that is not), and (Given) faces pointing into the cell or (either) a
/// cell that encloses no volume.
void checkPolyhedra(std::span<const Vec3> positions, const std::vector<std::vector<Index>>& faces,
                    std::vector<std::vector<CellFace>>& cells, FaceOrientation orientation);

}  // namespace tessella
