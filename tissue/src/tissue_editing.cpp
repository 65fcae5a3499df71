// Editing primitives of Tissue: split an edge, a face, a cell by a plane.
// Every primitive checks its input (geometry included) before it changes
// anything, applies the property division policies itself, and leaves a
// valid complex.

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <stdexcept>

#include "polygon_kernels.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/tissue/tissue.hpp"

namespace tessella {

namespace {

std::string fmt(const Vec3& p) {
  std::ostringstream s;
  s.precision(12);
  s << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return s.str();
}

// SplitOptions out of range would snap whole cells onto the plane or let
// slivers (or nothing) through: refused before anything changes.
void checkSplitOptions(const SplitOptions& o) {
  const auto text = [](double v) {
    std::ostringstream s;
    s.precision(12);
    s << v;
    return s.str();
  };
  if (!(o.snap_tolerance >= 0.0 && o.snap_tolerance <= kMaxSnapTolerance))
    throw InputError("splitCell: option snap_tolerance = " + text(o.snap_tolerance) + " is out of range; expected [0, " +
                     text(kMaxSnapTolerance) + "] (a fraction of the cell size)");
  if (!(o.min_fraction >= 0.0 && o.min_fraction < 0.5))
    throw InputError("splitCell: option min_fraction = " + text(o.min_fraction) +
                     " is out of range; expected [0, 0.5) (a fraction of the cell's measure)");
}

// Area and normal of a loop of points, with the tissue's kernel.
struct LoopArea {
  double area;
  Vec3 normal;
};
LoopArea loopArea(const std::vector<Vec3>& pts, bool planar) {
  double a;
  Vec3 c, nrm;
  detail::polygonKernel(
      pts.size(), [&](std::size_t i) -> const Vec3& { return pts[i]; }, planar, false, a, c, nrm,
      nullptr);
  return {a, nrm};
}

// Edge parameter of `point` on a -> b, required strictly inside.
double edgeParameter(const Vec3& a, const Vec3& b, const Vec3& point, EdgeId e) {
  const Vec3 ab = b - a;
  const double l2 = ab.squaredNorm();
  if (!(l2 > 0)) throw GeometryError("edge " + std::to_string(e.index()) + " has zero length", {1, e.index()});
  if (!point.allFinite())
    throw GeometryError("split point of edge " + std::to_string(e.index()) + " is not finite", {1, e.index()});
  const double t = (point - a).dot(ab) / l2;
  constexpr double kEps = 1e-12;
  if (!(t > kEps && t < 1 - kEps))
    throw GeometryError("split point " + fmt(point) + " of edge " + std::to_string(e.index()) +
                            " is not strictly between its vertices (parameter " + std::to_string(t) + ")",
                        {1, e.index()});
  return t;
}

// A tiny map over a handful of keys (a cell's vertices, the nodes of one
// cut): linear search in a vector beats hashing at these sizes and does not
// allocate per entry.
template <typename K, typename V>
class SmallMap {
 public:
  V& operator[](const K& k) {
    for (auto& [key, value] : items_)
      if (key == k) return value;
    items_.emplace_back(k, V{});
    return items_.back().second;
  }
  void set(const K& k, const V& v) {
    for (auto& [key, value] : items_)
      if (key == k) {
        value = v;
        return;
      }
    items_.emplace_back(k, v);
  }
  const V& at(const K& k) const {
    for (const auto& [key, value] : items_)
      if (key == k) return value;
    throw std::out_of_range("SmallMap::at");
  }
  const V* find(const K& k) const {
    for (const auto& [key, value] : items_)
      if (key == k) return &value;
    return nullptr;
  }
  auto begin() const { return items_.begin(); }
  auto end() const { return items_.end(); }
  std::size_t size() const { return items_.size(); }

 private:
  std::vector<std::pair<K, V>> items_;
};

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
  const auto [e, f2] = complex_.splitFace(f, a, b);  // checks the topology
  grew(1);
  grew(2);
  if (dim() == 2)
    dividedCell(f.index(), f2.index(), fraction);
  else
    properties_[2].divide(f.index(), f2.index(), fraction);
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
      throw GeometryError("segment " + fmt(pa) + " - " + fmt(pb) + " does not split face " +
                              std::to_string(f.index()) + " into two positive parts",
                          {2, f.index()});
  }
  const VertexId va = splitEdge(ea, pa).vertex;
  const VertexId vb = splitEdge(eb, pb).vertex;
  return splitFace(f, va, vb);
}

CellSplit Tissue::splitCell(CellId c, const Plane& plane, const SplitOptions& options) {
  checkSplitOptions(options);
  if (!alive(c)) throw TopologyError("cannot divide dead cell " + std::to_string(c.index()), {dim(), c.index()});
  if (!plane.point.allFinite() || !plane.normal.allFinite() || !(plane.normal.norm() > 0))
    throw GeometryError("division plane of cell " + std::to_string(c.index()) + " is invalid: point " +
                            fmt(plane.point) + ", normal " + fmt(plane.normal),
                        {dim(), c.index()});
  return dim() == 2 ? splitCell2D(c, plane, options) : splitCell3D(c, plane, options);
}

CellSplit Tissue::splitCell2D(CellId c, const Plane& plane, const SplitOptions& options) {
  const FaceId f(c.index());
  const std::string who = "cell " + std::to_string(c.index()) + " (lineage " + std::to_string(lineageId(c)) + ")";
  const std::vector<VertexId> verts(complex_.faceVertices(f).begin(), complex_.faceVertices(f).end());
  std::vector<EdgeId> edges;
  for (OrientedEdge oe : complex_.faceEdges(f)) edges.push_back(oe.handle());
  const int n = static_cast<int>(verts.size());
  const PolygonMeasures m = polygonMeasures(*this, f);
  if (!(m.area > 0)) throw GeometryError(who + " has non-positive area " + formatNumber(m.area), {2, f.index()});
  const Vec3 normal = plane.normal.normalized();
  const Vec3 u = normal.cross(m.normal);
  if (u.norm() < 1e-9) throw GeometryError("division plane is parallel to " + who, {2, f.index()});
  const double tol = options.snap_tolerance * std::sqrt(m.area);

  std::vector<double> d(n);
  for (int i = 0; i < n; ++i) {
    d[i] = normal.dot(position(verts[i]) - plane.point);
    if (std::abs(d[i]) <= tol) d[i] = 0;
  }
  for (int i = 0; i < n; ++i)
    if (d[i] == 0 && d[(i + 1) % n] == 0)
      throw GeometryError("division plane runs along wall " + std::to_string(edges[i].index()) + " of " + who,
                          {1, edges[i].index()});

  struct Crossing {
    int pos;  // vertex index, or edge index (between pos and pos+1)
    bool at_vertex;
    Vec3 point;
    double u;
  };
  std::vector<Crossing> crossings;
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    if (d[i] == 0) {
      // A vertex on the plane counts only where the boundary crosses, not touches.
      const double before = d[(i + n - 1) % n], after = d[j];
      if (before * after < 0) crossings.push_back({i, true, position(verts[i]), 0});
    } else if (d[i] * d[j] < 0) {
      const double t = d[i] / (d[i] - d[j]);
      crossings.push_back({i, false, position(verts[i]) + t * (position(verts[j]) - position(verts[i])), 0});
    }
  }
  if (crossings.size() < 2)
    throw GeometryError("division plane through " + fmt(plane.point) + " misses " + who, {2, f.index()});
  for (Crossing& x : crossings) x.u = u.dot(x.point - plane.point);
  // A non-convex cell can be crossed 4, 6, ... times: the chords alternate
  // inside/outside along the line; keep the chord through the plane's point
  // (or the nearest one if the point lies outside the cell).
  std::size_t first = 0, second = 1;
  if (crossings.size() > 2) {
    if (crossings.size() % 2)
      throw GeometryError("division plane crosses the boundary of " + who + " an odd number of times",
                          {2, f.index()});
    std::vector<std::size_t> order(crossings.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](auto a, auto b) { return crossings[a].u < crossings[b].u; });
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
  }
  const Crossing A = crossings[first], B = crossings[second];

  // The two parts, walking the loop from A to B and from B to A.
  auto part = [&](const Crossing& from, const Crossing& to, int& side) {
    std::vector<Vec3> pts{from.point};
    side = 0;
    const int stop = to.at_vertex ? to.pos : (to.pos + 1) % n;
    for (int i = (from.pos + 1) % n; i != stop; i = (i + 1) % n) {
      pts.push_back(position(verts[i]));
      if (side == 0 && d[i] != 0) side = d[i] > 0 ? 1 : -1;
    }
    pts.push_back(to.point);
    return pts;
  };
  int side_ab = 0, side_ba = 0;
  const std::vector<Vec3> pab = part(A, B, side_ab), pba = part(B, A, side_ba);
  const bool flat = embedding_ == Embedding::Planar;
  const LoopArea lab = loopArea(pab, flat), lba = loopArea(pba, flat);
  if (!(lab.area > 0 && lba.area > 0 && lab.normal.dot(m.normal) > 0 && lba.normal.dot(m.normal) > 0))
    throw GeometryError("division plane does not cut " + who + " into two positive parts", {2, f.index()});
  const double total = lab.area + lba.area;
  if (std::min(lab.area, lba.area) < options.min_fraction * total)
    throw GeometryError("division of " + who + " would leave a sliver of " +
                            formatNumber(std::min(lab.area, lba.area) / total, 6) + " of its area (minimum " +
                            formatNumber(options.min_fraction) + ")",
                        {2, f.index()});

  CellSplit result;
  auto vertexAt = [&](const Crossing& x) {
    if (x.at_vertex) return verts[x.pos];
    const EdgeSplit s = splitEdge(edges[x.pos], x.point);
    result.new_vertices.push_back(s.vertex);
    return s.vertex;
  };
  const VertexId va = vertexAt(A), vb = vertexAt(B);
  // The mother keeps the negative side: the face keeps the loop part it is split from.
  const bool ab_positive = side_ab > 0 || (side_ab == 0 && side_ba < 0);
  const VertexId from = ab_positive ? vb : va, to = ab_positive ? va : vb;
  const double kept_area = ab_positive ? lba.area : lab.area;
  const auto [e, f2] = complex_.splitFace(f, from, to);
  grew(1);
  grew(2);
  dividedCell(f.index(), f2.index(), kept_area / total);
  ++geometry_version_;
  paranoidCheck("splitCell");
  result.daughter = CellId(f2.index());
  result.wall = WallId(e.index());
  return result;
}

CellSplit Tissue::splitCell3D(CellId c, const Plane& plane, const SplitOptions& options) {
  const VolumeId vol(c.index());
  const std::string who = "cell " + std::to_string(c.index()) + " (lineage " + std::to_string(lineageId(c)) + ")";
  const double volume = cellMeasure(*this, c);
  if (!(volume > 0)) throw GeometryError(who + " has non-positive volume " + formatNumber(volume), {3, c.index()});
  const Vec3 normal = plane.normal.normalized();
  const double tol = options.snap_tolerance * std::cbrt(volume);

  // Signed distances of the cell's vertices, snapped to the plane.
  SmallMap<Index, double> dist;
  bool any_pos = false, any_neg = false;
  for (VertexId v : cellVertices(c)) {
    double dv = normal.dot(position(v) - plane.point);
    if (std::abs(dv) <= tol) dv = 0;
    dist[v.index()] = dv;
    any_pos |= dv > 0;
    any_neg |= dv < 0;
  }
  if (!any_pos || !any_neg) {
    // A wall in the plane (the plane of a face of the cell): said as in 2D.
    for (OrientedFace of : complex_.volumeFaces(vol)) {
      const auto loop = complex_.faceVertices(of.handle());
      if (std::all_of(loop.begin(), loop.end(), [&](VertexId v) { return dist.at(v.index()) == 0; }))
        throw GeometryError("division plane runs along wall " + std::to_string(of.handle().index()) + " of " + who,
                            {2, of.handle().index()});
    }
    throw GeometryError("division plane through " + fmt(plane.point) + " misses " + who, {3, c.index()});
  }
  auto D = [&](VertexId v) { return dist.at(v.index()); };

  // Nodes of the cut polygon: vertices on the plane (key v) and crossed edges (key -(e+1)).
  using Key = std::int64_t;
  auto vkey = [](VertexId v) { return static_cast<Key>(v.index()); };
  auto ekey = [](EdgeId e) { return -static_cast<Key>(e.index()) - 1; };
  SmallMap<Key, Vec3> node_point;
  std::vector<std::pair<Key, Key>> segments;
  std::vector<std::tuple<FaceId, Key, Key>> face_cuts;
  SmallMap<Index, int> face_side;
  const std::vector<OrientedFace> faces(complex_.volumeFaces(vol).begin(), complex_.volumeFaces(vol).end());
  for (OrientedFace of : faces) {
    const FaceId f = of.handle();
    bool pos = false, neg = false;
    std::vector<Key> nodes;
    for (OrientedEdge oe : complex_.faceEdges(f)) {
      const VertexId a = complex_.tail(oe), b = complex_.head(oe);
      const double da = D(a), db = D(b);
      pos |= da > 0;
      neg |= da < 0;
      if (da == 0) {
        nodes.push_back(vkey(a));
        node_point.set(vkey(a), position(a));
      } else if (da * db < 0) {
        nodes.push_back(ekey(oe.handle()));
        const double t = da / (da - db);
        node_point.set(ekey(oe.handle()), position(a) + t * (position(b) - position(a)));
      }
    }
    if (pos && neg) {
      if (nodes.size() != 2)
        throw GeometryError("division plane crosses wall " + std::to_string(f.index()) + " of " + who + " " +
                                std::to_string(nodes.size()) + " times (a non-convex wall)",
                            {2, f.index()});
      segments.emplace_back(nodes[0], nodes[1]);
      face_cuts.emplace_back(f, nodes[0], nodes[1]);
    } else if (!pos && !neg) {
      throw GeometryError("division plane runs along wall " + std::to_string(f.index()) + " of " + who,
                          {2, f.index()});
    } else {
      face_side[f.index()] = pos ? 1 : -1;
    }
  }
  // Existing edges on the plane between a positive and a negative face.
  SmallMap<Index, int> edge_sides;
  for (OrientedFace of : faces) {
    const int* side = face_side.find(of.handle().index());
    if (!side) continue;
    for (OrientedEdge oe : complex_.faceEdges(of.handle())) {
      const VertexId a = complex_.tail(oe), b = complex_.head(oe);
      if (D(a) != 0 || D(b) != 0) continue;
      edge_sides[oe.handle().index()] += *side > 0 ? 1 : 2;
      if (edge_sides[oe.handle().index()] == 3) segments.emplace_back(vkey(a), vkey(b));
    }
  }
  // The segments must form exactly one closed loop.
  SmallMap<Key, std::vector<Key>> adj;
  for (auto [a, b] : segments) {
    adj[a].push_back(b);
    adj[b].push_back(a);
  }
  for (const auto& [k, nb] : adj)
    if (nb.size() != 2)
      throw GeometryError("division plane does not cut " + who + " along a single closed polygon", {3, c.index()});
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
    throw GeometryError("division plane cuts " + who + " into more than two pieces", {3, c.index()});
  if (ring.size() < 3) throw GeometryError("division plane only grazes " + who, {3, c.index()});
  {
    Vec3 area = Vec3::Zero();
    for (std::size_t i = 0; i < ring.size(); ++i)
      area += node_point.at(ring[i]).cross(node_point.at(ring[(i + 1) % ring.size()]));
    if (area.dot(normal) < 0) std::reverse(ring.begin(), ring.end());
  }
  // Predicted volume on the positive side: the positive part of every wall fan,
  // coned to a point on the plane (the cut face adds nothing).
  {
    double v6 = 0;
    const Vec3& q = plane.point;
    for (OrientedFace of : faces) {
      const auto loop = complex_.faceVertices(of.handle());
      Vec3 cf = Vec3::Zero();
      for (VertexId v : loop) cf += position(v);
      cf /= static_cast<double>(loop.size());
      for (std::size_t i = 0; i < loop.size(); ++i) {
        Vec3 tri[3] = {cf, position(loop[i]), position(loop[(i + 1) % loop.size()])};
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
    const double positive = v6 / 6.0, smaller = std::min(positive, volume - positive);
    if (smaller < options.min_fraction * volume)
      throw GeometryError("division of " + who + " would leave a sliver of " + formatNumber(smaller / volume, 6) +
                              " of its volume (minimum " + formatNumber(options.min_fraction) + ")",
                          {3, c.index()});
  }

  // --- edit: split crossed edges, then crossed walls, then the volume --------
  CellSplit result;
  SmallMap<Key, VertexId> node_vertex;
  for (Key k : ring) {
    if (k >= 0) {
      node_vertex[k] = VertexId(static_cast<Index>(k));
    } else {
      const EdgeSplit s = splitEdge(EdgeId(static_cast<Index>(-k - 1)), node_point.at(k));
      node_vertex[k] = s.vertex;
      dist[s.vertex.index()] = 0;
      result.new_vertices.push_back(s.vertex);
    }
  }
  for (auto [f, a, b] : face_cuts) splitFace(f, node_vertex.at(a), node_vertex.at(b));
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
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const VertexId a = node_vertex.at(ring[i]), b = node_vertex.at(ring[(i + 1) % ring.size()]);
    const EdgeId e = complex_.findEdge(a, b);
    if (!e) throw TopologyError("internal: missing cut edge while dividing " + who, {3, c.index()});
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
