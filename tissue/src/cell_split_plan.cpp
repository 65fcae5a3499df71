// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Planning a division (cell_split_plan.hpp): which edges and walls the plane
// crosses, where the new vertices go, which side each part goes to. Reads the
// tissue only; Tissue::splitCell applies the plan (tissue_editing.cpp).

#include "tessella/tissue/cell_split_plan.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <tuple>

#include "editing_helpers.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"
#include "tessella/tissue/geometry.hpp"

namespace tessella {

namespace {

using detail::LoopArea;
using detail::loopArea;
using detail::pointText;
using detail::SmallMap;

// SplitOptions out of range would snap whole cells onto the plane or let
// slivers (or nothing) through: refused before anything changes.
void checkSplitOptions(const SplitOptions& o) {
  if (!(o.snap_tolerance >= 0.0 && o.snap_tolerance <= kMaxSnapTolerance))
    throw InputError("splitCell: option snap_tolerance = " + formatNumber(o.snap_tolerance) +
                     " is out of range; expected [0, " + formatNumber(kMaxSnapTolerance) +
                     "] (a fraction of the cell size)");
  if (!(o.min_fraction >= 0.0 && o.min_fraction < 0.5))
    throw InputError("splitCell: option min_fraction = " + formatNumber(o.min_fraction) +
                     " is out of range; expected [0, 0.5) (a fraction of the cell's measure)");
}

// The checks common to both dimensions, in splitCell's order.
void checkSplitInput(const Tissue& t, CellId c, const Plane& plane, const SplitOptions& options, int dim) {
  checkSplitOptions(options);
  if (t.dim() != dim)
    throw InputError("planCellSplit" + std::to_string(dim) + "D: the tissue is " + std::to_string(t.dim()) + "D");
  if (!t.alive(c)) throw TopologyError("cannot divide dead cell " + std::to_string(c.index()), {t.dim(), c.index()});
  if (!plane.point.allFinite() || !plane.normal.allFinite() || !(plane.normal.norm() > 0))
    throw GeometryError("division plane of cell " + std::to_string(c.index()) + " is invalid: point " +
                            pointText(plane.point) + ", normal " + pointText(plane.normal),
                        {t.dim(), c.index()});
}

// A cell as error messages name it, spelled out only when one is thrown
// (planning succeeds far more often than not).
struct CellName {
  const Tissue& t;
  CellId c;
  std::string str() const {
    return "cell " + std::to_string(c.index()) + " (lineage " + std::to_string(t.lineageId(c)) + ")";
  }
};

// --- 2D ------------------------------------------------------------------------

// Where the plane's trace crosses a cell's boundary loop.
struct Crossing {
  int pos;  // vertex index, or edge index (between pos and pos+1)
  bool at_vertex;
  Vec3 point;
  double u;  // coordinate along the trace
};

// A 2D cell's loop with the snapped signed distance of each vertex.
struct Loop2 {
  std::vector<VertexId> verts;
  std::vector<EdgeId> edges;
  std::vector<double> d;
  int size() const { return static_cast<int>(verts.size()); }
};

Loop2 signedLoop(const Tissue& t, FaceId f, const Vec3& normal, const Plane& plane, double tol,
                 const CellName& who) {
  const CellComplex& cx = t.topology();
  Loop2 loop;
  loop.verts.assign(cx.faceVertices(f).begin(), cx.faceVertices(f).end());
  for (OrientedEdge oe : cx.faceEdges(f)) loop.edges.push_back(oe.handle());
  const int n = loop.size();
  loop.d.resize(n);
  for (int i = 0; i < n; ++i) {
    loop.d[i] = normal.dot(t.position(loop.verts[i]) - plane.point);
    if (std::abs(loop.d[i]) <= tol) loop.d[i] = 0;
  }
  for (int i = 0; i < n; ++i)
    if (loop.d[i] == 0 && loop.d[(i + 1) % n] == 0)
      throw GeometryError("division plane runs along wall " +
                              std::to_string(loop.edges[i].index()) + " of " + who.str(),
                          {1, loop.edges[i].index()});
  return loop;
}

std::vector<Crossing> crossings(const Tissue& t, const Loop2& loop) {
  const int n = loop.size();
  const auto& d = loop.d;
  std::vector<Crossing> out;
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    if (d[i] == 0) {
      // A vertex on the plane counts only where the boundary crosses, not touches.
      const double before = d[(i + n - 1) % n], after = d[j];
      if (before * after < 0) out.push_back({i, true, t.position(loop.verts[i]), 0});
    } else if (d[i] * d[j] < 0) {
      const double s = d[i] / (d[i] - d[j]);
      const Vec3& a = t.position(loop.verts[i]);
      out.push_back({i, false, a + s * (t.position(loop.verts[j]) - a), 0});
    }
  }
  return out;
}

// A non-convex cell can be crossed 4, 6, ... times: the chords alternate
// inside/outside along the line; the chord through the plane's point (or the
// nearest one if the point lies outside the cell) is kept. Its two crossings,
// in loop order.
std::pair<std::size_t, std::size_t> chosenChord(const std::vector<Crossing>& crossings, const CellName& who,
                                                FaceId f) {
  if (crossings.size() == 2) return {0, 1};
  if (crossings.size() % 2)
    throw GeometryError(
        "division plane crosses the boundary of " + who.str() + " an odd number of times",
        {2, f.index()});
  std::vector<std::size_t> order(crossings.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return crossings[a].u < crossings[b].u; });
  std::size_t first = 0, second = 1;
  double best = INFINITY;
  for (std::size_t k = 0; k + 1 < order.size(); k += 2) {
    const double lo = crossings[order[k]].u, hi = crossings[order[k + 1]].u;
    const double dist = lo <= 0 && 0 <= hi ? 0 : std::min(std::abs(lo), std::abs(hi));
    if (dist < best) {
      best = dist;
      first = std::min(order[k], order[k + 1]);
      second = std::max(order[k], order[k + 1]);
    }
  }
  return {first, second};
}

// The points of the loop part from one crossing to the other, and its side
// (the sign of its first vertex off the plane; 0 if none).
std::vector<Vec3> loopPart(const Tissue& t, const Loop2& loop, const Crossing& from, const Crossing& to, int& side) {
  const int n = loop.size();
  std::vector<Vec3> pts{from.point};
  side = 0;
  const int stop = to.at_vertex ? to.pos : (to.pos + 1) % n;
  for (int i = (from.pos + 1) % n; i != stop; i = (i + 1) % n) {
    pts.push_back(t.position(loop.verts[i]));
    if (side == 0 && loop.d[i] != 0) side = loop.d[i] > 0 ? 1 : -1;
  }
  pts.push_back(to.point);
  return pts;
}

CutNode cutNode(const Loop2& loop, const Crossing& x) {
  if (x.at_vertex) return {loop.verts[x.pos], {}, x.point};
  return {{}, loop.edges[x.pos], x.point};
}

}  // namespace

CellSplitPlan2D planCellSplit2D(const Tissue& t, CellId c, const Plane& plane, const SplitOptions& options) {
  checkSplitInput(t, c, plane, options, 2);
  const FaceId f(c.index());
  const CellName who{t, c};
  const PolygonMeasures m = polygonMeasures(t, f);
  if (!(m.area > 0))
    throw GeometryError(who.str() + " has non-positive area " + formatNumber(m.area, 6),
                        {2, f.index()});
  const Vec3 normal = plane.normal.normalized();
  const Vec3 u = normal.cross(m.normal);
  if (u.norm() < 1e-9) throw GeometryError("division plane is parallel to " + who.str(), {2, f.index()});
  const Loop2 loop = signedLoop(t, f, normal, plane, options.snap_tolerance * std::sqrt(m.area), who);

  std::vector<Crossing> found = crossings(t, loop);
  if (found.size() < 2)
    throw GeometryError("division plane through " + pointText(plane.point) + " misses " + who.str(), {2, f.index()});
  for (Crossing& x : found) x.u = u.dot(x.point - plane.point);
  const auto [first, second] = chosenChord(found, who, f);
  const Crossing A = found[first], B = found[second];

  // Both parts must have a positive area on the cell's side, and neither be a sliver.
  int side_ab = 0, side_ba = 0;
  const std::vector<Vec3> pab = loopPart(t, loop, A, B, side_ab), pba = loopPart(t, loop, B, A, side_ba);
  const bool flat = t.embedding() == Embedding::Planar;
  const LoopArea lab = loopArea(pab, flat), lba = loopArea(pba, flat);
  if (!(lab.area > 0 && lba.area > 0 && lab.normal.dot(m.normal) > 0 && lba.normal.dot(m.normal) > 0))
    throw GeometryError("division plane does not cut " + who.str() + " into two positive parts", {2, f.index()});
  const double total = lab.area + lba.area;
  if (std::min(lab.area, lba.area) < options.min_fraction * total)
    throw GeometryError("division of " + who.str() + " would leave a sliver of " +
                            formatNumber(std::min(lab.area, lba.area) / total, 6) + " of its area (minimum " +
                            formatNumber(options.min_fraction) + ")",
                        {2, f.index()});

  CellSplitPlan2D plan;
  plan.cell = c;
  plan.topology_version = t.topologyVersion();
  plan.geometry_version = t.geometryVersion();
  plan.plane = Plane{plane.point, normal};
  plan.snap_distance = options.snap_tolerance * std::sqrt(m.area);
  plan.a = cutNode(loop, A);
  plan.b = cutNode(loop, B);
  // The mother keeps the negative side.
  plan.daughter_from_a_to_b = side_ab > 0 || (side_ab == 0 && side_ba < 0);
  plan.mother_fraction = (plan.daughter_from_a_to_b ? lba.area : lab.area) / total;
  return plan;
}

// --- 3D ------------------------------------------------------------------------

namespace {

// Nodes of the cut polygon: vertices on the plane (key v) and crossed edges (key -(e+1)).
using Key = std::int64_t;
Key vertexKey(VertexId v) { return static_cast<Key>(v.index()); }
Key edgeKey(EdgeId e) { return -static_cast<Key>(e.index()) - 1; }

// What the plane does to a 3D cell's walls: the segments it draws on them
// (between nodes), the walls it cuts, and the side of every wall it does not.
struct WallTraces {
  SmallMap<Index, double> dist;  // snapped signed distance of every vertex of the cell
  SmallMap<Key, Vec3> node_point;
  std::vector<std::pair<Key, Key>> segments;
  std::vector<std::tuple<FaceId, Key, Key>> face_cuts;
  SmallMap<Index, int> face_side;
};

SmallMap<Index, double> signedDistances(const Tissue& t, CellId c, const Vec3& normal, const Plane& plane,
                                        double tol, const CellName& who) {
  SmallMap<Index, double> dist;
  bool any_pos = false, any_neg = false;
  for (VertexId v : t.cellVertices(c)) {
    double dv = normal.dot(t.position(v) - plane.point);
    if (std::abs(dv) <= tol) dv = 0;
    dist[v.index()] = dv;
    any_pos |= dv > 0;
    any_neg |= dv < 0;
  }
  if (!any_pos || !any_neg) {
    // A wall in the plane (the plane of a face of the cell): said as in 2D.
    for (OrientedFace of : t.topology().volumeFaces(VolumeId(c.index()))) {
      const auto loop = t.topology().faceVertices(of.handle());
      if (std::all_of(loop.begin(), loop.end(), [&](VertexId v) { return dist.at(v.index()) == 0; }))
        throw GeometryError("division plane runs along wall " +
                                std::to_string(of.handle().index()) + " of " + who.str(),
                            {2, of.handle().index()});
    }
    throw GeometryError("division plane through " + pointText(plane.point) + " misses " + who.str(), {3, c.index()});
  }
  return dist;
}

void traceWalls(const Tissue& t, const std::vector<OrientedFace>& faces, WallTraces& w, const CellName& who) {
  const CellComplex& cx = t.topology();
  for (OrientedFace of : faces) {
    const FaceId f = of.handle();
    bool pos = false, neg = false;
    std::vector<Key> nodes;
    for (OrientedEdge oe : cx.faceEdges(f)) {
      const VertexId a = cx.tail(oe), b = cx.head(oe);
      const double da = w.dist.at(a.index()), db = w.dist.at(b.index());
      pos |= da > 0;
      neg |= da < 0;
      if (da == 0) {
        nodes.push_back(vertexKey(a));
        w.node_point.set(vertexKey(a), t.position(a));
      } else if (da * db < 0) {
        nodes.push_back(edgeKey(oe.handle()));
        const double s = da / (da - db);
        w.node_point.set(edgeKey(oe.handle()), t.position(a) + s * (t.position(b) - t.position(a)));
      }
    }
    if (pos && neg) {
      if (nodes.size() != 2)
        throw GeometryError("division plane crosses wall " + std::to_string(f.index()) + " of " + who.str() + " " +
                                std::to_string(nodes.size()) + " times (a non-convex wall)",
                            {2, f.index()});
      w.segments.emplace_back(nodes[0], nodes[1]);
      w.face_cuts.emplace_back(f, nodes[0], nodes[1]);
    } else if (!pos && !neg) {
      throw GeometryError(
          "division plane runs along wall " + std::to_string(f.index()) + " of " + who.str(),
          {2, f.index()});
    } else {
      w.face_side[f.index()] = pos ? 1 : -1;
    }
  }
  // Existing edges on the plane between a positive and a negative wall.
  SmallMap<Index, int> edge_sides;
  for (OrientedFace of : faces) {
    const int* side = w.face_side.find(of.handle().index());
    if (!side) continue;
    for (OrientedEdge oe : cx.faceEdges(of.handle())) {
      const VertexId a = cx.tail(oe), b = cx.head(oe);
      if (w.dist.at(a.index()) != 0 || w.dist.at(b.index()) != 0) continue;
      edge_sides[oe.handle().index()] += *side > 0 ? 1 : 2;
      if (edge_sides[oe.handle().index()] == 3) w.segments.emplace_back(vertexKey(a), vertexKey(b));
    }
  }
}

// The segments as one closed loop of nodes, counter-clockwise seen from the
// positive side; refused when they make none or several.
std::vector<Key> cutRing(const WallTraces& w, const Vec3& normal, const CellName& who, CellId c) {
  SmallMap<Key, std::vector<Key>> adj;
  for (auto [a, b] : w.segments) {
    adj[a].push_back(b);
    adj[b].push_back(a);
  }
  for (const auto& [k, nb] : adj)
    if (nb.size() != 2)
      throw GeometryError(
          "division plane does not cut " + who.str() + " along a single closed polygon",
          {3, c.index()});
  std::vector<Key> ring{adj.begin()->first};
  Key prev = ring[0], cur = adj.begin()->second[0];
  while (cur != ring[0]) {
    ring.push_back(cur);
    const auto& nb = adj.at(cur);
    const Key next = nb[0] == prev ? nb[1] : nb[0];
    prev = cur;
    cur = next;
    if (ring.size() > adj.size()) break;
  }
  if (ring.size() != adj.size())
    throw GeometryError("division plane cuts " + who.str() + " into more than two pieces", {3, c.index()});
  if (ring.size() < 3) throw GeometryError("division plane only grazes " + who.str(), {3, c.index()});
  Vec3 area = Vec3::Zero();
  for (std::size_t i = 0; i < ring.size(); ++i)
    area += w.node_point.at(ring[i]).cross(w.node_point.at(ring[(i + 1) % ring.size()]));
  if (area.dot(normal) < 0) std::reverse(ring.begin(), ring.end());
  return ring;
}

// Volume on the positive side: the positive part of every wall fan, coned to
// a point on the plane (the cut face adds nothing).
double positiveVolume(const Tissue& t, const std::vector<OrientedFace>& faces, const Vec3& normal,
                      const Plane& plane) {
  const CellComplex& cx = t.topology();
  double v6 = 0;
  const Vec3& q = plane.point;
  for (OrientedFace of : faces) {
    const auto loop = cx.faceVertices(of.handle());
    Vec3 cf = Vec3::Zero();
    for (VertexId v : loop) cf += t.position(v);
    cf /= static_cast<double>(loop.size());
    for (std::size_t i = 0; i < loop.size(); ++i) {
      Vec3 tri[3] = {cf, t.position(loop[i]), t.position(loop[(i + 1) % loop.size()])};
      if (of.reversed()) std::swap(tri[1], tri[2]);
      std::vector<Vec3> clipped;  // Sutherland-Hodgman against d > 0
      for (int k = 0; k < 3; ++k) {
        const Vec3 &p = tri[k], &r = tri[(k + 1) % 3];
        const double dp = normal.dot(p - q), dr = normal.dot(r - q);
        if (dp > 0) clipped.push_back(p);
        if ((dp > 0) != (dr > 0) && dp != dr) clipped.push_back(p + dp / (dp - dr) * (r - p));
      }
      for (std::size_t k = 1; k + 1 < clipped.size(); ++k)
        v6 += (clipped[0] - q).dot((clipped[k] - q).cross(clipped[k + 1] - q));
    }
  }
  return v6 / 6.0;
}

// The checks of the edits that apply a plan (Tissue::applyCellSplit: splitEdge
// for every new corner, in ring order, then splitFace for every crossed wall),
// made on the same numbers in the same order, so that applying the plan cannot
// throw after its first edit. Each crossed wall's loop is the one splitFace
// would see: its vertices with the new corners inserted on their edges. The
// share of its area each crossed wall keeps, in the order of w.face_cuts (the
// fraction splitFace computes; the plan carries it, so the edit need not
// measure the wall again).
std::vector<double> checkEdits(const Tissue& t, const WallTraces& w, const std::vector<Key>& ring,
                               const CellName& who) {
  const CellComplex& cx = t.topology();
  for (Key k : ring) {
    if (k >= 0) continue;
    const EdgeId e(static_cast<Index>(-k - 1));
    try {
      detail::edgeParameter(t.position(cx.edgeFrom(e)), t.position(cx.edgeTo(e)), w.node_point.at(k), e);
    } catch (const GeometryError& error) {
      throw GeometryError("division plane of " + who.str() + ": " + error.what(), error.element());
    }
  }
  const bool flat = t.embedding() == Embedding::Planar;
  std::vector<double> kept;
  kept.reserve(w.face_cuts.size());
  std::vector<Vec3> whole, keep, move;
  for (const auto& [f, a, b] : w.face_cuts) {
    whole.clear();
    int ia = -1, ib = -1;
    const auto vertices = cx.faceVertices(f);
    const auto edges = cx.faceEdges(f);
    for (std::size_t i = 0; i < vertices.size(); ++i) {
      const Key kv = vertexKey(vertices[i]), ke = edgeKey(edges[i].handle());
      if (kv == a) ia = static_cast<int>(whole.size());
      if (kv == b) ib = static_cast<int>(whole.size());
      whole.push_back(t.position(vertices[i]));
      if (const Vec3* p = w.node_point.find(ke)) {
        if (ke == a) ia = static_cast<int>(whole.size());
        if (ke == b) ib = static_cast<int>(whole.size());
        whole.push_back(*p);
      }
    }
    const int n = static_cast<int>(whole.size());
    const auto refuse = [&](const std::string& why) {
      throw GeometryError("division plane of " + who.str() + " cannot split wall " + std::to_string(f.index()) +
                              ": " + why,
                          {2, f.index()});
    };
    if (ia < 0 || ib < 0 || ia == ib || (ia + 1) % n == ib || (ib + 1) % n == ia)
      refuse("its two corners are equal or adjacent on its loop");
    if (a >= 0 && b >= 0) {
      if (const EdgeId e = cx.findEdge(VertexId(static_cast<Index>(a)), VertexId(static_cast<Index>(b))))
        refuse("its corners, vertices " + std::to_string(a) + " and " + std::to_string(b) +
               ", are already joined by edge " + std::to_string(e.index()));
    }
    // Tissue::splitFace's test, on the same points in the same order.
    keep.clear();
    move.clear();
    for (int i = ia;; i = (i + 1) % n) {
      keep.push_back(whole[i]);
      if (i == ib) break;
    }
    for (int i = ib;; i = (i + 1) % n) {
      move.push_back(whole[i]);
      if (i == ia) break;
    }
    const LoopArea lw = loopArea(whole, flat), lk = loopArea(keep, flat), lm = loopArea(move, flat);
    if (!(lk.area > 0 && lm.area > 0 && lk.normal.dot(lw.normal) > 0 && lm.normal.dot(lw.normal) > 0))
      refuse("a part would have non-positive area on the wall's side (the cut leaves the warped wall)");
    kept.push_back(lk.area / (lk.area + lm.area));
  }
  return kept;
}

}  // namespace

CellSplitPlan3D planCellSplit3D(const Tissue& t, CellId c, const Plane& plane, const SplitOptions& options) {
  checkSplitInput(t, c, plane, options, 3);
  const VolumeId vol(c.index());
  const CellName who{t, c};
  const double volume = cellMeasure(t, c);
  if (!(volume > 0))
    throw GeometryError(who.str() + " has non-positive volume " + formatNumber(volume, 6),
                        {3, c.index()});
  const Vec3 normal = plane.normal.normalized();
  const double tol = options.snap_tolerance * std::cbrt(volume);

  WallTraces w;
  w.dist = signedDistances(t, c, normal, plane, tol, who);
  const std::vector<OrientedFace> faces(t.topology().volumeFaces(vol).begin(), t.topology().volumeFaces(vol).end());
  traceWalls(t, faces, w, who);
  const std::vector<Key> ring = cutRing(w, normal, who, c);
  const double positive = positiveVolume(t, faces, normal, plane), smaller = std::min(positive, volume - positive);
  if (smaller < options.min_fraction * volume)
    throw GeometryError("division of " + who.str() + " would leave a sliver of " + formatNumber(smaller / volume, 6) +
                            " of its volume (minimum " + formatNumber(options.min_fraction) + ")",
                        {3, c.index()});
  const std::vector<double> kept = checkEdits(t, w, ring, who);

  CellSplitPlan3D plan;
  plan.cell = c;
  plan.topology_version = t.topologyVersion();
  plan.geometry_version = t.geometryVersion();
  for (Key k : ring) {
    if (k >= 0)
      plan.ring.push_back({VertexId(static_cast<Index>(k)), {}, w.node_point.at(k)});
    else
      plan.ring.push_back({{}, EdgeId(static_cast<Index>(-k - 1)), w.node_point.at(k)});
  }
  const auto corner = [&](Key k) {
    return static_cast<std::size_t>(std::find(ring.begin(), ring.end(), k) - ring.begin());
  };
  for (std::size_t i = 0; i < w.face_cuts.size(); ++i) {
    const auto& [f, a, b] = w.face_cuts[i];
    plan.wall_cuts.push_back({f, corner(a), corner(b), kept[i]});
  }
  for (const auto& [v, d] : w.dist) plan.distances.emplace_back(VertexId(v), d);
  return plan;
}

}  // namespace tessella
