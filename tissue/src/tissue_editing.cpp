// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Editing primitives of Tissue: split an edge, a face, a cell by a plane.
// Every primitive checks its input (geometry included) before it changes
// anything, applies the property division policies itself, and leaves a
// valid complex.

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "editing_helpers.hpp"
#include "tessella/tissue/cell_split_plan.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/tissue/tissue.hpp"

namespace tessella {

namespace {

using detail::edgeParameter;
using detail::LoopArea;
using detail::loopArea;
using detail::pointText;
using detail::SmallMap;

// The checks of the edits that apply a 2D plan (Tissue::applyCellSplit:
// splitEdge for a new end a, then for b, then the complex's splitFace), made
// before the first edit on the numbers those edits see, so that a refused
// plan leaves the tissue as it was. The second splitEdge sees b's edge as it
// is now: splitting a's edge moves no vertex and keeps every other edge's ends.
// A plan planCellSplit2D made on this tissue passes every topology check below
// (its ends are distinct crossings of the cell's loop: a vertex on the plane is
// no end of a crossed edge, two vertices on it are not adjacent); its new
// vertices may still lie within 1e-12 of their edge's ends (snap tolerance 0),
// where splitEdge refuses them. That check is not planning's own, as
// Tissue::splitCells takes such plans (it places the vertex as planned).
void checkChordEdits(const Tissue& t, const CellSplitPlan2D& plan) {
  const CellComplex& cx = t.topology();
  const CellId c = plan.cell;
  if (!t.alive(c))
    throw TopologyError("cannot divide dead cell " + std::to_string(c.index()), {2, c.index()});
  const FaceId f(c.index());
  const auto who = [&] {
    return "cell " + std::to_string(c.index()) + " (lineage " + std::to_string(t.lineageId(c)) + ")";
  };
  const auto refuse = [&](const std::string& why) {
    throw TopologyError("the division plan of " + who() + " " + why, {2, c.index()});
  };
  // Each end on the cell's loop: a new vertex's edge bounds the cell (one of
  // at most two faces), an existing vertex is found on the loop (rare: a
  // vertex on the plane).
  for (const CutNode* x : {&plan.a, &plan.b}) {
    if (!x->isNew()) {
      if (cx.loopPosition(f, x->vertex) < 0)
        refuse("ends at vertex " + std::to_string(x->vertex.index()) + ", not on its loop");
      continue;
    }
    if (!cx.alive(x->edge) || std::ranges::find(cx.edgeFaces(x->edge), f) == cx.edgeFaces(x->edge).end())
      refuse("cuts edge " + std::to_string(x->edge.index()) + ", not on its loop");
    try {
      edgeParameter(t.position(cx.edgeFrom(x->edge)), t.position(cx.edgeTo(x->edge)), x->point, x->edge);
    } catch (const GeometryError& error) {
      throw GeometryError("division plane of " + who() + ": " + error.what(), error.element());
    }
  }
  const CutNode &a = plan.a, &b = plan.b;
  if (!a.isNew() && !b.isNew()) {
    // The complex's splitFace refuses these.
    const int n = static_cast<int>(cx.faceVertices(f).size());
    const int ia = cx.loopPosition(f, a.vertex), ib = cx.loopPosition(f, b.vertex);
    if (ia == ib || (ia + 1) % n == ib || (ib + 1) % n == ia)
      refuse("joins vertices " + std::to_string(a.vertex.index()) + " and " + std::to_string(b.vertex.index()) +
             ", equal or adjacent on its loop");
    if (const EdgeId e = cx.findEdge(a.vertex, b.vertex))
      refuse("joins vertices " + std::to_string(a.vertex.index()) + " and " + std::to_string(b.vertex.index()) +
             ", already joined by edge " + std::to_string(e.index()));
  } else if (a.isNew() && b.isNew()) {
    if (a.edge == b.edge) refuse("cuts edge " + std::to_string(a.edge.index()) + " twice");
  } else {
    // A new vertex is adjacent to, and joined to, its edge's ends only.
    const VertexId v = a.isNew() ? b.vertex : a.vertex;
    const EdgeId e = a.isNew() ? a.edge : b.edge;
    if (cx.edgeFrom(e) == v || cx.edgeTo(e) == v)
      refuse("joins vertex " + std::to_string(v.index()) + " to a new vertex on its own edge " +
             std::to_string(e.index()));
  }
}

}  // namespace

double Tissue::measureFraction(int degree, Index kept, Index part) const {
  double a = 0, b = 0;
  switch (degree) {
    case 1: a = edgeLength(*this, EdgeId(kept)); b = edgeLength(*this, EdgeId(part)); break;
    case 2: a = polygonMeasures(*this, FaceId(kept)).area; b = polygonMeasures(*this, FaceId(part)).area; break;
    case 3: a = cellMeasure(*this, CellId(kept)); b = cellMeasure(*this, CellId(part)); break;
  }
  return a + b > 0 ? a / (a + b) : 0.5;
}

EdgeSplit Tissue::splitEdge(EdgeId e, const Vec3& point) {
  if (!complex_.alive(e)) throw TopologyError("cannot split dead edge " + std::to_string(e.index()), {1, e.index()});
  edgeParameter(position(complex_.edgeFrom(e)), position(complex_.edgeTo(e)), point, e);
  const auto [v, e2] = complex_.splitEdge(e);
  positions_.push_back(point);
  grew(0);
  grew(1);
  properties_[1].divide(e.index(), e2.index(), measureFraction(1, e.index(), e2.index()));
  ++geometry_version_;
  paranoidCheck("splitEdge");
  return {v, e2};
}

FaceSplit Tissue::splitFace(FaceId f, VertexId a, VertexId b) {
  if (!complex_.alive(f)) throw TopologyError("cannot split dead face " + std::to_string(f.index()), {2, f.index()});
  const auto loop = complex_.faceVertices(f);
  const int n = static_cast<int>(loop.size());
  const int ia = complex_.loopPosition(f, a), ib = complex_.loopPosition(f, b);
  const bool flat = embedding_ == Embedding::Planar;
  double fraction = 0.5;
  if (ia >= 0 && ib >= 0 && ia != ib) {
    // Both parts must keep a positive area on the face's side: a chord
    // leaving a non-convex face would make one part inverted.
    std::vector<Vec3> keep, move, whole;
    for (int i = ia;; i = (i + 1) % n) {
      keep.push_back(position(loop[i]));
      if (i == ib) break;
    }
    for (int i = ib;; i = (i + 1) % n) {
      move.push_back(position(loop[i]));
      if (i == ia) break;
    }
    for (VertexId v : loop) whole.push_back(position(v));
    if (keep.size() >= 3 && move.size() >= 3) {
      const LoopArea w = loopArea(whole, flat), k = loopArea(keep, flat), m = loopArea(move, flat);
      if (!(k.area > 0 && m.area > 0 && k.normal.dot(w.normal) > 0 && m.normal.dot(w.normal) > 0))
        throw GeometryError("splitting face " + std::to_string(f.index()) + " between vertices " +
                                std::to_string(a.index()) + " and " + std::to_string(b.index()) +
                                " leaves a part with non-positive area (the chord leaves the face)",
                            {2, f.index()});
      fraction = k.area / (k.area + m.area);
    }
  }
  return commitFaceSplit(f, a, b, fraction);
}

FaceSplit Tissue::commitFaceSplit(FaceId f, VertexId a, VertexId b, double kept) {
  const auto [e, f2] = complex_.splitFace(f, a, b);  // checks the topology
  grew(1);
  grew(2);
  if (dim() == 2)
    dividedCell(f.index(), f2.index(), kept);
  else
    properties_[2].divide(f.index(), f2.index(), kept);
  ++geometry_version_;
  paranoidCheck("splitFace");
  return {e, f2};
}

FaceSplit Tissue::splitFace(FaceId f, EdgeId ea, const Vec3& pa, EdgeId eb, const Vec3& pb) {
  if (!complex_.alive(f)) throw TopologyError("cannot split dead face " + std::to_string(f.index()), {2, f.index()});
  const int ia = complex_.loopPosition(f, ea), ib = complex_.loopPosition(f, eb);
  if (ia < 0 || ib < 0)
    throw TopologyError("edge " + std::to_string((ia < 0 ? ea : eb).index()) + " is not on face " +
                            std::to_string(f.index()) + "'s loop",
                        {2, f.index()});
  if (ia == ib) throw TopologyError("a segment splitting face " + std::to_string(f.index()) + " needs two different edges", {2, f.index()});
  edgeParameter(position(complex_.edgeFrom(ea)), position(complex_.edgeTo(ea)), pa, ea);
  edgeParameter(position(complex_.edgeFrom(eb)), position(complex_.edgeTo(eb)), pb, eb);
  // Predict both parts before editing, so a bad segment changes nothing.
  {
    const auto loop = complex_.faceVertices(f);
    const int n = static_cast<int>(loop.size());
    std::vector<Vec3> keep{pa}, move{pb}, whole;
    for (int i = (ia + 1) % n;; i = (i + 1) % n) {
      keep.push_back(position(loop[i]));
      if (i == ib) break;
    }
    keep.push_back(pb);
    for (int i = (ib + 1) % n;; i = (i + 1) % n) {
      move.push_back(position(loop[i]));
      if (i == ia) break;
    }
    move.push_back(pa);
    for (VertexId v : loop) whole.push_back(position(v));
    const bool flat = embedding_ == Embedding::Planar;
    const LoopArea w = loopArea(whole, flat), k = loopArea(keep, flat), m = loopArea(move, flat);
    if (!(k.area > 0 && m.area > 0 && k.normal.dot(w.normal) > 0 && m.normal.dot(w.normal) > 0))
      throw GeometryError("segment " + pointText(pa) + " - " + pointText(pb) + " does not split face " +
                              std::to_string(f.index()) + " into two positive parts",
                          {2, f.index()});
  }
  const VertexId va = splitEdge(ea, pa).vertex;
  const VertexId vb = splitEdge(eb, pb).vertex;
  return splitFace(f, va, vb);
}

CellSplit Tissue::splitCell(CellId c, const Plane& plane, const SplitOptions& options) {
  // Planning checks everything and throws before the tissue changes.
  if (dim() == 2) return applyCellSplit(planCellSplit2D(*this, c, plane, options));
  return applyCellSplit(planCellSplit3D(*this, c, plane, options));
}

void Tissue::checkPlanVersions(CellId c, std::uint64_t topology_version, std::uint64_t geometry_version) const {
  if (topology_version != topologyVersion() || geometry_version != geometryVersion())
    throw std::logic_error("splitCell: the plan of cell " + std::to_string(c.index()) +
                           " was made on another state of the tissue (topology version " +
                           std::to_string(topology_version) + ", geometry version " +
                           std::to_string(geometry_version) + "; the tissue's are " +
                           std::to_string(topologyVersion()) + " and " + std::to_string(geometryVersion()) +
                           "): plan it again");
}

CellSplit Tissue::splitCell(const CellSplitPlan2D& plan) {
  if (dim() != 2) throw std::logic_error("splitCell: a 2D plan given to a 3D tissue");
  checkPlanVersions(plan.cell, plan.topology_version, plan.geometry_version);
  return applyCellSplit(plan);
}

CellSplit Tissue::splitCell(const CellSplitPlan3D& plan) {
  if (dim() != 3) throw std::logic_error("splitCell: a 3D plan given to a 2D tissue");
  checkPlanVersions(plan.cell, plan.topology_version, plan.geometry_version);
  return applyCellSplit(plan);
}

CellSplit Tissue::applyCellSplit(const CellSplitPlan2D& plan) {
  // Everything below that could refuse the plan is checked here first. What
  // follows then cannot throw but for lack of memory, a user's Custom
  // division function (run after its element is split) or a paranoid build's
  // validate(): splitEdge's checks and the complex's splitFace checks are those
  // of checkChordEdits, and the built-in property policies and the lineage
  // only assign values to slots grew() made.
  checkChordEdits(*this, plan);
  const FaceId f(plan.cell.index());
  CellSplit result;
  auto vertexAt = [&](const CutNode& x) {
    if (!x.isNew()) return x.vertex;
    const EdgeSplit s = splitEdge(x.edge, x.point);
    result.new_vertices.push_back(s.vertex);
    return s.vertex;
  };
  const VertexId va = vertexAt(plan.a), vb = vertexAt(plan.b);
  // The face keeps the loop part it is split from (the mother's); the new face is the daughter.
  const VertexId from = plan.daughter_from_a_to_b ? vb : va, to = plan.daughter_from_a_to_b ? va : vb;
  const auto [e, f2] = complex_.splitFace(f, from, to);
  grew(1);
  grew(2);
  dividedCell(f.index(), f2.index(), plan.mother_fraction);
  ++geometry_version_;
  paranoidCheck("splitCell");
  result.daughter = CellId(f2.index());
  result.wall = WallId(e.index());
  return result;
}

CellSplit Tissue::applyCellSplit(const CellSplitPlan3D& plan) {
  const CellId c = plan.cell;
  const VolumeId vol(c.index());
  SmallMap<Index, double> dist;
  for (const auto& [v, d] : plan.distances) dist.set(v.index(), d);
  // Split crossed edges, then crossed walls, then the volume.
  CellSplit result;
  std::vector<VertexId> corner(plan.ring.size());
  for (std::size_t i = 0; i < plan.ring.size(); ++i) {
    const CutNode& node = plan.ring[i];
    if (!node.isNew()) {
      corner[i] = node.vertex;
      continue;
    }
    const EdgeSplit s = splitEdge(node.edge, node.point);
    corner[i] = s.vertex;
    dist[s.vertex.index()] = 0;
    result.new_vertices.push_back(s.vertex);
  }
  // The walls as splitFace would split them (its checks were made by the plan,
  // which also measured the share each keeps).
  for (const auto& cut : plan.wall_cuts) commitFaceSplit(cut.wall, corner[cut.from], corner[cut.to], cut.kept_fraction);
  // A wall goes to the daughter when its first vertex off the plane is on the positive side.
  std::vector<FaceId> moving;
  for (OrientedFace of : complex_.volumeFaces(vol)) {
    for (VertexId v : complex_.faceVertices(of.handle())) {
      const double dv = dist.at(v.index());
      if (dv != 0) {
        if (dv > 0) moving.push_back(of.handle());
        break;
      }
    }
  }
  std::vector<OrientedEdge> loop;
  for (std::size_t i = 0; i < corner.size(); ++i) {
    const VertexId a = corner[i], b = corner[(i + 1) % corner.size()];
    const EdgeId e = complex_.findEdge(a, b);
    if (!e)
      throw TopologyError("internal: missing cut edge while dividing cell " + std::to_string(c.index()) +
                              " (lineage " + std::to_string(lineageId(c)) + ")",
                          {3, c.index()});
    loop.emplace_back(e, complex_.edgeFrom(e) != a);
  }
  const auto [cut, c2] = complex_.splitVolume(vol, moving, loop, +1);
  grew(2);
  grew(3);
  dividedCell(vol.index(), c2.index(), measureFraction(3, vol.index(), c2.index()));
  ++geometry_version_;
  paranoidCheck("splitCell");
  result.daughter = CellId(c2.index());
  result.wall = WallId(cut.index());
  return result;
}

}  // namespace tessella
