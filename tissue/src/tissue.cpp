// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/tissue/tissue.hpp"

#include <algorithm>
#include <string_view>

#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"
#include "tessella/tissue/validate.hpp"

namespace tessella {

const char* embeddingName(Embedding e) {
  switch (e) {
    case Embedding::Planar: return "planar";
    case Embedding::Surface: return "surface";
    case Embedding::Volume: return "volume";
  }
  return "?";
}

Tissue::Tissue(int dim, Embedding embedding) : complex_(dim), embedding_(embedding) {
  if ((dim == 3) != (embedding == Embedding::Volume))
    throw InputError(std::string("a ") + std::to_string(dim) + "D tissue cannot have the " +
                     embeddingName(embedding) + " embedding");
  PropertyStore& cells = properties_[dim];
  // Division sets these itself (see dividedCell); Reset keeps policies out of it.
  lineage_ = &cells.add<std::int64_t>(kLineageName, -1, DivisionPolicy::Reset);
  parent_ = &cells.add<std::int64_t>(kParentName, -1, DivisionPolicy::Reset);
  birth_ = &cells.add<double>(kBirthTimeName, 0.0, DivisionPolicy::Reset);
  for (const char* n : {kLineageName, kParentName, kBirthTimeName}) cells.lock(n);
}

Tissue::Tissue(CellComplex complex, std::vector<Vec3> positions, Embedding embedding)
    : Tissue(complex.dim(), embedding) {
  if (positions.size() != complex.slots(0))
    throw InputError(std::to_string(positions.size()) + " positions given for " +
                     std::to_string(complex.slots(0)) + " vertices");
  for (std::size_t i = 0; i < positions.size(); ++i)
    if (!positions[i].allFinite())
      throw InputError("vertex " + std::to_string(i) + " has a non-finite coordinate");
  complex_ = std::move(complex);
  positions_ = std::move(positions);
  for (int d = 0; d <= dim(); ++d) grew(d);
  for (Index c = 0; c < complex_.slots(dim()); ++c)
    if (complex_.alive(dim(), c)) newCell(c);
  ++geometry_version_;
}

Tissue::Tissue(const Tissue& other)
    : complex_(other.complex_),
      embedding_(other.embedding_),
      positions_(other.positions_),
      properties_(other.properties_),
      next_lineage_(other.next_lineage_),
      time_(other.time_),
      geometry_version_(other.geometry_version_) {
  PropertyStore& cells = properties_[dim()];
  lineage_ = &cells.get<std::int64_t>(kLineageName);
  parent_ = &cells.get<std::int64_t>(kParentName);
  birth_ = &cells.get<double>(kBirthTimeName);
}

Tissue& Tissue::operator=(const Tissue& other) {
  if (this != &other) {
    Tissue copy(other);
    *this = std::move(copy);
  }
  return *this;
}

// Columns live on the heap, so the lineage pointers survive a move.
Tissue::Tissue(Tissue&& other) noexcept = default;
Tissue& Tissue::operator=(Tissue&& other) noexcept = default;
Tissue::~Tissue() = default;

const std::vector<std::uint8_t>& Tissue::aliveFlags(int degree) const {
  if (degree > dim()) return no_elements_;
  return complex_.aliveFlags(degree);
}

void Tissue::grew(int degree) { properties_[degree].resize(complex_.slots(degree)); }

void Tissue::newCell(Index cell) {
  (*lineage_)[cell] = next_lineage_++;
  (*parent_)[cell] = -1;
  (*birth_)[cell] = time_;
}

void Tissue::dividedCell(Index mother, Index daughter, double fraction) {
  const std::int64_t mother_lineage = (*lineage_)[mother];
  properties_[dim()].divide(mother, daughter, fraction);
  for (Index c : {mother, daughter}) {
    (*lineage_)[c] = next_lineage_++;
    (*parent_)[c] = mother_lineage;
    (*birth_)[c] = time_;
  }
}

void Tissue::restoreLineage(CellId c, std::int64_t lineage, std::int64_t parent, double birth_time) {
  if (!alive(c)) throw InputError("restoreLineage: cell " + std::to_string(c.index()) + " is not alive");
  if (lineage < 0) throw InputError("restoreLineage: negative lineage id " + std::to_string(lineage));
  (*lineage_)[c] = lineage;
  (*parent_)[c] = parent;
  (*birth_)[c] = birth_time;
  next_lineage_ = std::max(next_lineage_, lineage + 1);
}

void Tissue::reserveLineageIds(std::int64_t next) { next_lineage_ = std::max(next_lineage_, next); }

void Tissue::paranoidCheck([[maybe_unused]] const char* where) const {
#ifdef TESSELLA_PARANOID
  // Removing cells may legitimately open holes or tunnels; splits never
  // change the Euler characteristic, so they are checked in full.
  ValidateOptions options;
  options.check_euler = std::string_view(where) != "removeCell";
  const ValidationReport report = validate(*this, options);
  if (!report) throw TopologyError(std::string("after ") + where + ": " + report.message, report.element);
#endif
}

// --- cells and walls ----------------------------------------------------------

std::vector<WallId> Tissue::cellWalls(CellId c) const {
  std::vector<WallId> out;
  if (dim() == 2) {
    for (OrientedEdge oe : complex_.faceEdges(FaceId(c.index()))) out.emplace_back(oe.handle().index());
  } else {
    for (OrientedFace of : complex_.volumeFaces(VolumeId(c.index()))) out.emplace_back(of.handle().index());
  }
  return out;
}

std::vector<CellId> Tissue::wallCells(WallId w) const {
  std::vector<CellId> out;
  if (dim() == 2) {
    for (FaceId f : complex_.edgeFaces(EdgeId(w.index()))) out.emplace_back(f.index());
  } else {
    for (VolumeId c : complex_.faceVolumes(FaceId(w.index()))) out.emplace_back(c.index());
  }
  return out;
}

std::vector<CellId> Tissue::cellNeighbors(CellId c) const {
  std::vector<CellId> out;
  for (WallId w : cellWalls(c))
    for (CellId n : wallCells(w))
      if (n != c && std::find(out.begin(), out.end(), n) == out.end()) out.push_back(n);
  return out;
}

std::vector<VertexId> Tissue::cellVertices(CellId c) const {
  if (dim() == 2) {
    const auto loop = complex_.faceVertices(FaceId(c.index()));
    return {loop.begin(), loop.end()};
  }
  std::vector<VertexId> out;
  for (OrientedFace of : complex_.volumeFaces(VolumeId(c.index())))
    for (VertexId v : complex_.faceVertices(of.handle())) out.push_back(v);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

bool Tissue::isBoundaryWall(WallId w) const {
  return dim() == 2 ? complex_.edgeFaces(EdgeId(w.index())).size() == 1
                    : complex_.faceVolumes(FaceId(w.index())).size() == 1;
}

FaceId Tissue::cellFace(CellId c) const {
  if (dim() != 2) throw TopologyError("cellFace() is for 2D tissues; cells of a 3D tissue are volumes");
  return FaceId(c.index());
}

VolumeId Tissue::cellVolume(CellId c) const {
  if (dim() != 3) throw TopologyError("cellVolume() is for 3D tissues; cells of a 2D tissue are faces");
  return VolumeId(c.index());
}

// --- positions ----------------------------------------------------------------

void Tissue::setPosition(VertexId v, const Vec3& p) {
  positions_[v.index()] = p;
  ++geometry_version_;
}

std::span<Vec3> Tissue::mutablePositions() {
  ++geometry_version_;
  return positions_;
}

// --- building -------------------------------------------------------------------

VertexId Tissue::addVertex(const Vec3& p) {
  if (!p.allFinite())
    throw InputError("vertex position is not finite: " + formatPoint(p));
  const VertexId v = complex_.addVertex();
  positions_.push_back(p);
  grew(0);
  ++geometry_version_;
  return v;
}

EdgeId Tissue::addEdge(VertexId from, VertexId to) {
  const EdgeId e = complex_.addEdge(from, to);
  grew(1);
  ++geometry_version_;
  return e;
}

FaceId Tissue::addFace(std::span<const OrientedEdge> loop) {
  const FaceId f = complex_.addFace(loop);
  grew(2);
  if (dim() == 2) newCell(f.index());
  ++geometry_version_;
  return f;
}

FaceId Tissue::addPolygon(std::span<const VertexId> loop) {
  const std::size_t n = loop.size();
  if (n < 3) throw TopologyError("a polygon needs at least 3 vertices, got " + std::to_string(n));
  for (VertexId v : loop)
    if (!complex_.alive(v))
      throw TopologyError("polygon uses dead or invalid vertex", {0, v.index()});
  std::vector<OrientedEdge> edges(n);
  std::vector<EdgeId> created;
  try {
    for (std::size_t i = 0; i < n; ++i) {
      const VertexId a = loop[i], b = loop[(i + 1) % n];
      EdgeId e = complex_.findEdge(a, b);
      if (!e) {
        e = addEdge(a, b);
        created.push_back(e);
      }
      edges[i] = OrientedEdge(e, complex_.edgeFrom(e) != a);
    }
    return addFace(edges);
  } catch (...) {
    // Leave the complex as it was: drop the edges made for this polygon.
    for (auto it = created.rbegin(); it != created.rend(); ++it) complex_.remove(1, it->index());
    throw;
  }
}

VolumeId Tissue::addVolume(std::span<const OrientedFace> faces) {
  const VolumeId c = complex_.addVolume(faces);
  grew(3);
  newCell(c.index());
  ++geometry_version_;
  return c;
}

// --- removal and compaction -------------------------------------------------------

void Tissue::removeCell(CellId c) {
  if (!alive(c)) throw TopologyError("cannot remove dead cell " + std::to_string(c.index()), {dim(), c.index()});
  std::vector<FaceId> faces;
  if (dim() == 3) {
    for (OrientedFace of : complex_.volumeFaces(VolumeId(c.index()))) faces.push_back(of.handle());
    complex_.remove(3, c.index());
  } else {
    faces.push_back(FaceId(c.index()));
  }
  std::vector<EdgeId> edges;
  for (FaceId f : faces) {
    if (!complex_.faceVolumes(f).empty()) continue;
    for (OrientedEdge oe : complex_.faceEdges(f)) edges.push_back(oe.handle());
    complex_.remove(2, f.index());
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  std::vector<VertexId> verts;
  for (EdgeId e : edges) {
    if (!complex_.alive(e) || !complex_.edgeFaces(e).empty()) continue;
    for (VertexId v : complex_.edgeVertices(e)) verts.push_back(v);
    complex_.remove(1, e.index());
  }
  std::sort(verts.begin(), verts.end());
  verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
  for (VertexId v : verts)
    if (complex_.alive(v) && complex_.vertexEdges(v).empty()) complex_.remove(0, v.index());
  ++geometry_version_;
  paranoidCheck("removeCell");
}

Renumbering Tissue::compact() {
  Renumbering r = complex_.compact();
  for (int d = 0; d <= 3; ++d)
    properties_[d].compact(r.old_to_new[d], complex_.slots(d));
  std::vector<Vec3> pos(complex_.slots(0));
  for (std::size_t i = 0; i < positions_.size(); ++i)
    if (r.old_to_new[0][i] != kInvalidIndex) pos[r.old_to_new[0][i]] = positions_[i];
  positions_ = std::move(pos);
  ++geometry_version_;
  return r;
}

std::size_t Tissue::bytes() const {
  std::size_t b = complex_.bytes() + positions_.capacity() * sizeof(Vec3);
  for (const auto& p : properties_) b += p.bytes();
  return b;
}

}  // namespace tessella
