// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/tissue/builders.hpp"

#include <string>

#include "tessella/tissue/errors.hpp"

namespace tessella {

namespace {

// Nested lists -> CSR offsets and items.
template <typename T>
void flatten(const std::vector<std::vector<T>>& lists, std::vector<Index>& offsets, std::vector<T>& items) {
  offsets.assign(1, 0);
  offsets.reserve(lists.size() + 1);
  std::size_t total = 0;
  for (const auto& l : lists) total += l.size();
  items.reserve(total);
  for (const auto& l : lists) {
    items.insert(items.end(), l.begin(), l.end());
    offsets.push_back(static_cast<Index>(items.size()));
  }
}

// Loops as a complex; a bad loop becomes an InputError naming it as `what`.
CellComplex loopsComplex(int dim, std::size_t num_vertices, std::span<const Index> offsets,
                         std::span<const Index> loop_vertices, const char* what,
                         std::span<const Index> face_ids = {}) {
  try {
    return CellComplex::fromLoops(dim, num_vertices, offsets, loop_vertices, face_ids);
  } catch (const TopologyError& e) {
    throw InputError(std::string(what) + " " + std::to_string(e.element().index) + ": " + e.what());
  }
}

}  // namespace

Tissue buildPolygonTissue(std::span<const Vec3> positions, const std::vector<std::vector<Index>>& polygons,
                          Embedding embedding) {
  std::vector<Index> offsets, items;
  flatten(polygons, offsets, items);
  return buildPolygonTissue(std::vector<Vec3>(positions.begin(), positions.end()), offsets, items, embedding);
}

Tissue buildPolygonTissue(std::vector<Vec3> positions, std::span<const Index> offsets,
                          std::span<const Index> loop_vertices, Embedding embedding,
                          std::span<const Index> face_ids) {
  CellComplex c = loopsComplex(2, positions.size(), offsets, loop_vertices, "polygon", face_ids);
  return Tissue(std::move(c), std::move(positions), embedding);
}

Tissue buildPolyhedralTissue(std::span<const Vec3> positions, const std::vector<std::vector<Index>>& faces,
                             const std::vector<std::vector<CellFace>>& cells) {
  std::vector<Index> face_offsets, face_items, cell_offsets;
  std::vector<CellFace> cell_items;
  flatten(faces, face_offsets, face_items);
  flatten(cells, cell_offsets, cell_items);
  return buildPolyhedralTissue(std::vector<Vec3>(positions.begin(), positions.end()), face_offsets, face_items,
                               cell_offsets, cell_items);
}

Tissue buildPolyhedralTissue(std::vector<Vec3> positions, std::span<const Index> face_offsets,
                             std::span<const Index> face_vertices, std::span<const Index> cell_offsets,
                             std::span<const CellFace> cell_faces,
                             std::span<const std::uint8_t> closed_by_construction) {
  const std::size_t ncells = cell_offsets.empty() ? 0 : cell_offsets.size() - 1;
  if (!closed_by_construction.empty() && closed_by_construction.size() != ncells)
    throw InputError("buildPolyhedralTissue: " + std::to_string(closed_by_construction.size()) +
                     " closed-by-construction flags for " + std::to_string(ncells) + " cells");
  CellComplex c = loopsComplex(3, positions.size(), face_offsets, face_vertices, "face");
  const std::size_t nf = c.slots(2);
  std::vector<OrientedFace> oriented;
  oriented.reserve(cell_faces.size());
  for (std::size_t k = 0; k < ncells; ++k)
    for (Index i = cell_offsets[k]; i < cell_offsets[k + 1]; ++i) {
      const CellFace& cf = cell_faces[i];
      if (cf.face >= nf)
        throw InputError("cell " + std::to_string(k) + " uses face " + std::to_string(cf.face) +
                         " but there are only " + std::to_string(nf) + " faces");
      oriented.emplace_back(FaceId(cf.face), cf.reversed);
    }
  try {
    c.addVolumes(cell_offsets, oriented, closed_by_construction);
  } catch (const TopologyError& e) {
    throw InputError("cell " + std::to_string(e.element().index) + ": " + e.what());
  }
  return Tissue(std::move(c), std::move(positions), Embedding::Volume);
}

}  // namespace tessella
