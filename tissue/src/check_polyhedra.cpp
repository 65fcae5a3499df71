// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// checkPolyhedra: the arrays of a 3D tissue checked (and oriented) before
// buildPolyhedralTissue, so a mistake is reported in the caller's numbering:
// the builder only knows its own edge ids.

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <unordered_map>

#include "tessella/tissue/builders.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"

namespace tessella {

namespace {

std::uint64_t undirected(Index u, Index v) {
  return (std::uint64_t(std::min(u, v)) << 32) | std::max(u, v);
}

std::string edgeName(Index u, Index v) { return "edge " + std::to_string(u) + "-" + std::to_string(v); }

// One use of an edge by a face of the cell: the face's position in the cell's
// list and whether the face's loop runs u -> v (u < v) there.
struct EdgeUse {
  std::size_t local = 0;
  bool forward = false;
};

void checkFaces(std::span<const Vec3> positions, const std::vector<std::vector<Index>>& faces) {
  const std::size_t nv = positions.size();
  for (std::size_t v = 0; v < nv; ++v)
    if (!positions[v].allFinite())
      throw InputError("vertex " + std::to_string(v) + ": position " + formatPoint(positions[v]) + " is not finite");
  std::unordered_map<std::string, std::size_t> by_vertex_set;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const auto& loop = faces[f];
    const std::string face = "face " + std::to_string(f);
    if (loop.size() < 3)
      throw InputError(face + " has " + std::to_string(loop.size()) + " vertices (at least 3 needed)");
    for (Index v : loop)
      if (v >= nv)
        throw InputError(face + ": vertex index " + std::to_string(v) + " is out of range (there are " +
                         std::to_string(nv) + " vertices)");
    std::vector<Index> sorted = loop;
    std::sort(sorted.begin(), sorted.end());
    if (auto it = std::adjacent_find(sorted.begin(), sorted.end()); it != sorted.end())
      throw InputError(face + " passes twice through vertex " + std::to_string(*it));
    std::string key(reinterpret_cast<const char*>(sorted.data()), sorted.size() * sizeof(Index));
    const auto [it, fresh] = by_vertex_set.emplace(std::move(key), f);
    if (!fresh)
      throw InputError("faces " + std::to_string(it->second) + " and " + std::to_string(f) +
                       " have the same vertices: a wall shared by two cells is one face listed by both cells");
  }
}

// Signed volume of the cell's surface (fans from each face's vertex mean),
// relative to its first vertex for precision.
double signedVolume(std::span<const Vec3> positions, const std::vector<std::vector<Index>>& faces,
                    const std::vector<CellFace>& cell) {
  const Vec3 origin = positions[faces[cell.front().face].front()];
  double six_v = 0;
  for (const CellFace& cf : cell) {
    const auto& loop = faces[cf.face];
    Vec3 mean = Vec3::Zero();
    for (Index v : loop) mean += positions[v] - origin;
    mean /= double(loop.size());
    double face_sum = 0;
    for (std::size_t i = 0; i < loop.size(); ++i)
      face_sum += mean.dot((positions[loop[i]] - origin).cross(positions[loop[(i + 1) % loop.size()]] - origin));
    six_v += cf.reversed ? -face_sum : face_sum;
  }
  return six_v / 6.0;
}

}  // namespace

void checkPolyhedra(std::span<const Vec3> positions, const std::vector<std::vector<Index>>& faces,
                    std::vector<std::vector<CellFace>>& cells, FaceOrientation orientation) {
  checkFaces(positions, faces);
  std::vector<std::vector<std::size_t>> face_cells(faces.size());
  for (std::size_t k = 0; k < cells.size(); ++k) {
    auto& cell = cells[k];
    const std::string name = "cell " + std::to_string(k);
    if (cell.size() < 4)
      throw InputError(name + " has " + std::to_string(cell.size()) + " faces, a closed cell needs at least 4");
    for (const CellFace& cf : cell)
      if (cf.face >= faces.size())
        throw InputError(name + ": face index " + std::to_string(cf.face) + " is out of range (there are " +
                         std::to_string(faces.size()) + " faces)");
    for (std::size_t i = 0; i < cell.size(); ++i)
      for (std::size_t j = i + 1; j < cell.size(); ++j)
        if (cell[i].face == cell[j].face)
          throw InputError(name + " lists face " + std::to_string(cell[i].face) + " twice");
    for (const CellFace& cf : cell) {
      auto& users = face_cells[cf.face];
      users.push_back(k);
      if (users.size() > 2)
        throw InputError("face " + std::to_string(cf.face) + " is listed by cells " + std::to_string(users[0]) +
                         ", " + std::to_string(users[1]) + " and " + std::to_string(users[2]) +
                         ": a wall bounds at most two cells");
    }

    // Every edge of the cell in exactly two of its faces.
    std::unordered_map<std::uint64_t, std::vector<EdgeUse>> uses;
    for (std::size_t i = 0; i < cell.size(); ++i) {
      const auto& loop = faces[cell[i].face];
      for (std::size_t p = 0; p < loop.size(); ++p) {
        const Index u = loop[p], v = loop[(p + 1) % loop.size()];
        uses[undirected(u, v)].push_back({i, u < v});
      }
    }
    auto faceOf = [&](const EdgeUse& use) { return "face " + std::to_string(cell[use.local].face); };
    std::vector<std::uint64_t> keys;
    keys.reserve(uses.size());
    for (const auto& [key, list] : uses) keys.push_back(key);
    std::sort(keys.begin(), keys.end());  // the first bad edge by vertex numbers, whatever the hashing
    for (std::uint64_t key : keys) {
      const auto& list = uses.at(key);
      const Index u = static_cast<Index>(key >> 32), v = static_cast<Index>(key & 0xffffffffu);
      if (list.size() == 1)
        throw InputError(name + " is open: " + edgeName(u, v) + " of its " + faceOf(list[0]) +
                         " is in no other face of the cell");
      if (list.size() > 2)
        throw InputError(name + ": " + edgeName(u, v) + " is in " + std::to_string(list.size()) + " of its faces (" +
                         faceOf(list[0]) + ", " + faceOf(list[1]) + ", " + faceOf(list[2]) +
                         "): the cell's surface is not a closed manifold");
    }

    // Walk the faces across shared edges: one piece, consistently oriented.
    std::vector<int> flip(cell.size(), -1);
    std::vector<std::vector<std::uint64_t>> edges_of(cell.size());
    for (std::uint64_t key : keys)
      for (const EdgeUse& use : uses.at(key)) edges_of[use.local].push_back(key);
    const bool given = orientation == FaceOrientation::Given;
    flip[0] = given ? cell[0].reversed : 0;
    std::vector<std::size_t> stack{0};
    while (!stack.empty()) {
      const std::size_t i = stack.back();
      stack.pop_back();
      for (std::uint64_t key : edges_of[i]) {
        const auto& list = uses.at(key);
        const EdgeUse& here = list[0].local == i ? list[0] : list[1];
        const EdgeUse& there = list[0].local == i ? list[1] : list[0];
        // Consistent: the two faces run along the edge in opposite directions.
        const int wanted = (here.forward != bool(flip[i])) == there.forward ? 1 : 0;
        const int has = given ? int(cell[there.local].reversed) : flip[there.local];
        if (has >= 0 && has != wanted) {
          const Index u = static_cast<Index>(key >> 32), v = static_cast<Index>(key & 0xffffffffu);
          if (given)
            throw InputError(name + ": its " + faceOf(here) + " and " + faceOf(there) + " run the same way along " +
                             edgeName(u, v) + " with the orientations given: the surface is not consistently "
                             "oriented (flip one of them, or let the faces be oriented automatically)");
          throw InputError(name + ": its faces cannot be oriented consistently (at " + edgeName(u, v) + ", between " +
                           faceOf(here) + " and " + faceOf(there) + "): the surface is not orientable");
        }
        if (flip[there.local] < 0) {
          flip[there.local] = wanted;
          stack.push_back(there.local);
        }
      }
    }
    for (std::size_t i = 0; i < cell.size(); ++i)
      if (flip[i] < 0)
        throw InputError(name + " is made of separate closed surfaces: its face " + std::to_string(cell[i].face) +
                         " is not connected to its face " + std::to_string(cell[0].face) + " through shared edges");
    if (!given)
      for (std::size_t i = 0; i < cell.size(); ++i) cell[i].reversed = flip[i] != 0;

    // Outward: positive enclosed volume.
    double extent = 0;
    for (const CellFace& cf : cell)
      for (Index v : faces[cf.face]) extent = std::max(extent, (positions[v] - positions[faces[cell[0].face][0]]).norm());
    const double volume = signedVolume(positions, faces, cell);
    if (!(std::abs(volume) > 1e-12 * extent * extent * extent))
      throw InputError(name + " encloses no volume (" + formatNumber(volume) + ")");
    if (volume < 0) {
      if (given)
        throw InputError(name + ": with the orientations given its faces point into it (enclosed volume " +
                         formatNumber(volume) + "): reverse every face of the cell");
      for (CellFace& cf : cell) cf.reversed = !cf.reversed;
    }
  }
}

}  // namespace tessella
