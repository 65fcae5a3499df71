#include "tessella/tissue/builders.hpp"

#include <string>

#include "tessella/tissue/errors.hpp"

namespace tessella {

namespace {

void addVertices(Tissue& t, std::span<const Vec3> positions) {
  for (std::size_t i = 0; i < positions.size(); ++i) {
    if (!positions[i].allFinite())
      throw InputError("vertex " + std::to_string(i) + " has a non-finite coordinate");
    t.addVertex(positions[i]);
  }
}

std::vector<VertexId> loopOf(const std::vector<Index>& loop, std::size_t nverts, const char* what,
                             std::size_t which) {
  if (loop.size() < 3)
    throw InputError(std::string(what) + " " + std::to_string(which) + " has " + std::to_string(loop.size()) +
                     " vertices (at least 3 needed)");
  std::vector<VertexId> out;
  out.reserve(loop.size());
  for (Index v : loop) {
    if (v >= nverts)
      throw InputError(std::string(what) + " " + std::to_string(which) + " uses vertex " + std::to_string(v) +
                       " but there are only " + std::to_string(nverts) + " vertices");
    out.emplace_back(v);
  }
  return out;
}

}  // namespace

Tissue buildPolygonTissue(std::span<const Vec3> positions, const std::vector<std::vector<Index>>& polygons,
                          Embedding embedding) {
  Tissue t(2, embedding);
  addVertices(t, positions);
  for (std::size_t p = 0; p < polygons.size(); ++p) {
    const auto loop = loopOf(polygons[p], positions.size(), "polygon", p);
    try {
      t.addPolygon(loop);
    } catch (const TopologyError& e) {
      throw InputError("polygon " + std::to_string(p) + ": " + e.what());
    }
  }
  return t;
}

Tissue buildPolyhedralTissue(std::span<const Vec3> positions, const std::vector<std::vector<Index>>& faces,
                             const std::vector<std::vector<CellFace>>& cells) {
  Tissue t(3, Embedding::Volume);
  addVertices(t, positions);
  std::vector<FaceId> face_ids(faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const auto loop = loopOf(faces[f], positions.size(), "face", f);
    try {
      face_ids[f] = t.addPolygon(loop);
    } catch (const TopologyError& e) {
      throw InputError("face " + std::to_string(f) + ": " + e.what());
    }
  }
  std::vector<OrientedFace> oriented;
  for (std::size_t c = 0; c < cells.size(); ++c) {
    oriented.clear();
    for (const CellFace& cf : cells[c]) {
      if (cf.face >= faces.size())
        throw InputError("cell " + std::to_string(c) + " uses face " + std::to_string(cf.face) + " but there are only " +
                         std::to_string(faces.size()) + " faces");
      oriented.emplace_back(face_ids[cf.face], cf.reversed);
    }
    try {
      t.addVolume(oriented);
    } catch (const TopologyError& e) {
      throw InputError("cell " + std::to_string(c) + ": " + e.what());
    }
  }
  return t;
}

}  // namespace tessella
