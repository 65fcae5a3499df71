// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/tissue/geometry.hpp"

#include <array>
#include <string>
#include <vector>

#include <Eigen/Eigenvalues>

#include "polygon_kernels.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"
#include "tessella/tissue/resize_discarding.hpp"

namespace tessella {

namespace {

bool planar(const Tissue& t) { return t.embedding() == Embedding::Planar; }

// The sweeps over every edge and face deal chunks of this many to the threads
// in turn rather than one contiguous share each: on a growing tissue the last
// faces (daughters, whose loops gather positions from two places, in array
// pages first touched by the sweep) cost more, and with contiguous shares they
// all fell to the last thread while the others waited.
constexpr int kInterleavedChunk = 4096;

// The surface a face is measured on: its vertex mean and, when the fan from
// that mean folds, the loop's own triangles (polygon_kernels.hpp).
struct FaceSurface {
  Vec3 center = Vec3::Zero();              // the fan apex
  std::vector<std::array<int, 3>> folded;  // empty: the fan from `center`
};

FaceSurface faceSurface(const Tissue& t, FaceId f) {
  const auto loop = t.topology().faceVertices(f);
  detail::FoldedSurface fs =
      detail::foldedSurface(loop.size(), [&](std::size_t i) -> const Vec3& { return t.position(loop[i]); });
  return {fs.apex, std::move(fs.triangles)};
}

// Volume integrals of a polyhedron by the divergence theorem over the
// surfaces its faces are measured on (signed fans from the face centres, or a
// folded face's own triangles), about a reference point r (the mean of face
// centres). surface(i) is the surface of the cell's i-th face.
template <typename Surface>
void polyhedronKernel(const Tissue& t, VolumeId c, Surface surface, bool moments, double& volume, Vec3& centroid,
                      Mat3* second_moment) {
  const CellComplex& k = t.topology();
  const auto faces = k.volumeFaces(c);
  Vec3 r = Vec3::Zero();
  for (std::size_t i = 0; i < faces.size(); ++i) r += surface(i).center;
  r /= static_cast<double>(faces.size());
  double v6 = 0;
  Vec3 first = Vec3::Zero();
  Mat3 second = Mat3::Zero();
  // Inlined by force: left to itself GCC sometimes calls this once per
  // triangle (it did when the 2D loop's kernel was inlined: 3D 3.3 -> 5.8 ms).
  const auto add = [&](const Vec3& a, const Vec3& b, const Vec3& d) __attribute__((always_inline)) {
    const double w = a.dot(b.cross(d));  // 6 x signed tetrahedron volume
    v6 += w;
    const Vec3 s = a + b + d;
    first += w * s;
    if (moments) second += w * (a * a.transpose() + b * b.transpose() + d * d.transpose() + s * s.transpose());
  };
  for (std::size_t fi = 0; fi < faces.size(); ++fi) {
    const OrientedFace of = faces[fi];
    const FaceSurface& fs = surface(fi);
    const auto loop = k.faceVertices(of.handle());
    if (!fs.folded.empty()) {
      for (const auto& tri : fs.folded) {
        const Vec3 a = t.position(loop[tri[0]]) - r;
        const Vec3 b = t.position(loop[tri[1]]) - r, d = t.position(loop[tri[2]]) - r;
        of.reversed() ? add(a, d, b) : add(a, b, d);
      }
      continue;
    }
    const Vec3 a = fs.center - r;
    const std::size_t n = loop.size();
    Vec3 p = t.position(loop[n - 1]) - r;
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3 q = t.position(loop[i]) - r;
      of.reversed() ? add(a, q, p) : add(a, p, q);
      p = q;
    }
  }
  volume = v6 / 6.0;
  const Vec3 g = v6 != 0 ? Vec3(first / (4.0 * v6)) : Vec3::Zero();
  centroid = r + g;
  if (moments && second_moment) *second_moment = second / 120.0 - volume * g * g.transpose();
}

/// The per-element form: the surfaces of the cell's faces, computed once.
void polyhedronKernel(const Tissue& t, VolumeId c, bool moments, double& volume, Vec3& centroid,
                      Mat3* second_moment) {
  std::vector<FaceSurface> surfaces;
  for (OrientedFace of : t.topology().volumeFaces(c)) surfaces.push_back(faceSurface(t, of.handle()));
  polyhedronKernel(
      t, c, [&](std::size_t i) -> const FaceSurface& { return surfaces[i]; }, moments, volume, centroid,
      second_moment);
}

// Face measures and/or second moments of every face into the cache (its
// arrays sized by the caller). Without Measures the kernel's area, centroid
// and normal go to locals: the second moments come out of the same
// arithmetic either way, so they are bit-identical to a pass computing both.
// With `surfaces` (non-planar faces only), each live face's surface too, as
// faceSurface would find it: the volume pass then need not look again.
template <bool Planar, bool Measures, bool Moments, bool Surfaces>
void facesLoop(const Tissue& t, GeometryCache& cache, FaceSurface* surfaces) {
  const CellComplex& k = t.topology();
  const auto& face_alive = k.aliveFlags(2);
  const std::int64_t nf = static_cast<std::int64_t>(k.slots(2));
  const Vec3* x = t.positions().data();
  double* area = Measures ? cache.face_area.data() : nullptr;
  Vec3* centroid = Measures ? cache.face_centroid.data() : nullptr;
  Vec3* normal = Measures ? cache.face_normal.data() : nullptr;
  Sym3* second = Moments ? cache.face_second_moment.data() : nullptr;
#pragma omp parallel for schedule(static, kInterleavedChunk)
  for (std::int64_t f = 0; f < nf; ++f) {
    if (!face_alive[f]) {
      if constexpr (Measures) {
        area[f] = 0;
        centroid[f].setZero();
        normal[f].setZero();
      }
      if constexpr (Moments) second[f] = Sym3{};
      continue;
    }
    const auto loop = k.faceVertices(FaceId(static_cast<Index>(f)));
    double a;
    Vec3 g, n;
    Mat3 m;
    const auto at = [&](std::size_t i) -> const Vec3& { return x[loop[i].index()]; };
    if constexpr (Planar) {
      detail::planarPolygonKernel<Moments>(loop.size(), at, Measures ? area[f] : a, Measures ? centroid[f] : g,
                                           Measures ? normal[f] : n, Moments ? &m : nullptr);
    } else if constexpr (Surfaces) {
      detail::FoldedSurface surface;
      detail::polygonKernel(loop.size(), at, Planar, Moments, Measures ? area[f] : a, Measures ? centroid[f] : g,
                            Measures ? normal[f] : n, Moments ? &m : nullptr, &surface);
      surfaces[f] = FaceSurface{surface.apex, std::move(surface.triangles)};
    } else {
      detail::polygonKernel(loop.size(), at, Planar, Moments, Measures ? area[f] : a, Measures ? centroid[f] : g,
                            Measures ? normal[f] : n, Moments ? &m : nullptr);
    }
    if constexpr (Moments) second[f] = Sym3::fromMatrix(m);
  }
}

template <bool Planar, bool Surfaces>
void facesLoop(const Tissue& t, GeometryCache& cache, bool measures, bool moments, FaceSurface* surfaces) {
  if (measures)
    moments ? facesLoop<Planar, true, true, Surfaces>(t, cache, surfaces)
            : facesLoop<Planar, true, false, Surfaces>(t, cache, surfaces);
  else if (moments)
    facesLoop<Planar, false, true, Surfaces>(t, cache, surfaces);
}

// Volume measures and/or second moments of every volume (3D); measures read
// the face areas, which the caller has made fresh. `surfaces`: every face's
// surface (vertex mean, folded triangles), shared by the two volumes of each
// face; empty when the face pass did not find them, and then found here.
void volumesLoop(const Tissue& t, GeometryCache& cache, bool measures, bool moments,
                 std::vector<FaceSurface>& surfaces) {
  const CellComplex& k = t.topology();
  const auto& face_alive = k.aliveFlags(2);
  const auto& vol_alive = k.aliveFlags(3);
  const std::int64_t nf = static_cast<std::int64_t>(k.slots(2));
  const std::int64_t nc = static_cast<std::int64_t>(k.slots(3));
  if (surfaces.empty()) {
    surfaces.resize(nf);
#pragma omp parallel for schedule(static)
    for (std::int64_t f = 0; f < nf; ++f)
      if (face_alive[f]) surfaces[f] = faceSurface(t, FaceId(static_cast<Index>(f)));
  }
  if (measures) {
    resizeDiscarding(cache.volume, nc);
    resizeDiscarding(cache.volume_surface, nc);
    resizeDiscarding(cache.volume_centroid, nc);
  }
  if (moments) resizeDiscarding(cache.volume_second_moment, nc);
#pragma omp parallel for schedule(static)
  for (std::int64_t c = 0; c < nc; ++c) {
    if (!vol_alive[c]) {
      if (measures) {
        cache.volume[c] = cache.volume_surface[c] = 0;
        cache.volume_centroid[c].setZero();
      }
      if (moments) cache.volume_second_moment[c] = Sym3{};
      continue;
    }
    const VolumeId vc(static_cast<Index>(c));
    const auto faces_of = k.volumeFaces(vc);
    double v;
    Vec3 g;
    Mat3 m;
    polyhedronKernel(
        t, vc, [&](std::size_t i) -> const FaceSurface& { return surfaces[faces_of[i].handle().index()]; }, moments,
        measures ? cache.volume[c] : v, measures ? cache.volume_centroid[c] : g, moments ? &m : nullptr);
    if (moments) cache.volume_second_moment[c] = Sym3::fromMatrix(m);
    if (measures) {
      double s = 0;
      for (OrientedFace of : faces_of) s += cache.face_area[of.handle().index()];
      cache.volume_surface[c] = s;
    }
  }
}

}  // namespace

PrincipalAxes principalAxes(const Mat3& second_moment) {
  Eigen::SelfAdjointEigenSolver<Mat3> solver(second_moment);
  PrincipalAxes out;
  // Eigen sorts increasingly; we want the longest axis first.
  for (int i = 0; i < 3; ++i) {
    out.values(i) = solver.eigenvalues()(2 - i);
    out.axes.col(i) = solver.eigenvectors().col(2 - i);
  }
  return out;
}

Mat3 inertiaTensor(const Mat3& second_moment) {
  return second_moment.trace() * Mat3::Identity() - second_moment;
}

double edgeLength(const Tissue& t, EdgeId e) {
  const auto ev = t.topology().edgeVertices(e);
  return (t.position(ev[1]) - t.position(ev[0])).norm();
}

Vec3 edgeMidpoint(const Tissue& t, EdgeId e) {
  const auto ev = t.topology().edgeVertices(e);
  return 0.5 * (t.position(ev[0]) + t.position(ev[1]));
}

PolygonTriangulation polygonTriangulation(std::span<const Vec3> loop) {
  if (loop.size() < 3) throw GeometryError("a polygon needs at least 3 points");
  PolygonTriangulation out;
  const auto at = [&](std::size_t i) -> const Vec3& { return loop[i]; };
  for (const Vec3& p : loop) out.center += p;
  out.center /= static_cast<double>(loop.size());
  Vec3 vec_area = Vec3::Zero();
  for (std::size_t i = 0; i < loop.size(); ++i)
    vec_area += (loop[(i + loop.size() - 1) % loop.size()] - out.center).cross(loop[i] - out.center);
  if (vec_area.norm() > 0) out.normal = vec_area / vec_area.norm();
  detail::FoldedSurface fs = detail::foldedSurface(loop.size(), at);
  out.center = fs.apex;
  out.folded = fs.folded;
  out.triangles = std::move(fs.triangles);
  return out;
}

PolygonDefect polygonDefect(std::span<const Vec3> loop) {
  const std::size_t n = loop.size();
  PolygonDefect d;
  if (n < 3) return d;
  Vec3 lo = loop[0], hi = loop[0], mean = Vec3::Zero();
  for (const Vec3& p : loop) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p), mean += p;
  mean /= static_cast<double>(n);
  const double tiny = 1e-12 * (hi - lo).norm();
  const auto adjacent = [n](std::size_t i, std::size_t j) { return j == i + 1 || (i == 0 && j == n - 1); };
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      if (!adjacent(i, j) && (loop[i] - loop[j]).norm() <= tiny)
        return {PolygonDefect::Pinched, static_cast<int>(i), static_cast<int>(j)};
  Vec3 vec_area = Vec3::Zero();
  for (std::size_t i = 0; i < n; ++i) vec_area += (loop[(i + n - 1) % n] - mean).cross(loop[i] - mean);
  if (!(vec_area.norm() > 0)) return {PolygonDefect::NoArea, 0, 0};
  const Vec3 normal = vec_area.normalized();
  const Vec3 e1 = normal.unitOrthogonal(), e2 = normal.cross(e1);
  std::vector<std::array<double, 2>> q(n);
  for (std::size_t i = 0; i < n; ++i) q[i] = {(loop[i] - mean).dot(e1), (loop[i] - mean).dot(e2)};
  // Closed segments [a, b] and [c, e] meet (orientations within rounding count as collinear).
  const auto meet = [&](const auto& a, const auto& b, const auto& c, const auto& e) {
    const int d1 = detail::orient2Sign(c, e, a), d2 = detail::orient2Sign(c, e, b);
    const int d3 = detail::orient2Sign(a, b, c), d4 = detail::orient2Sign(a, b, e);
    const auto on = [](const auto& p, const auto& r, const auto& x) {
      return std::min(p[0], r[0]) <= x[0] && x[0] <= std::max(p[0], r[0]) && std::min(p[1], r[1]) <= x[1] &&
             x[1] <= std::max(p[1], r[1]);
    };
    if (d1 * d2 < 0 && d3 * d4 < 0) return true;
    // Collinear within rounding: an overlap along the line. A vertex merely
    // touching another edge within rounding is left to the pinch test.
    if (d1 == 0 && d2 == 0 && d3 == 0 && d4 == 0)
      return on(c, e, a) || on(c, e, b) || on(a, b, c) || on(a, b, e);
    return false;
  };
  for (std::size_t i = 0; i < n; ++i) {
    // An edge folding back along the previous one (a spike of zero width).
    const auto &a = q[(i + n - 1) % n], &b = q[i], &c = q[(i + 1) % n];
    if (detail::orient2Sign(a, b, c) == 0 && (a[0] - b[0]) * (c[0] - b[0]) + (a[1] - b[1]) * (c[1] - b[1]) > 0)
      return {PolygonDefect::SelfIntersecting, static_cast<int>((i + n - 1) % n), static_cast<int>(i)};
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;
      if (meet(q[i], q[(i + 1) % n], q[j], q[(j + 1) % n]))
        return {PolygonDefect::SelfIntersecting, static_cast<int>(i), static_cast<int>(j)};
    }
  }
  return d;
}

std::string polygonDefectText(const PolygonDefect& d, std::span<const VertexId> vertices,
                              std::span<const Vec3> loop) {
  const std::size_t n = loop.size();
  const auto vid = [&](int i) {
    const auto k = static_cast<std::size_t>(i) % n;
    return std::to_string(vertices.empty() ? static_cast<Index>(k) : vertices[k].index());
  };
  switch (d.kind) {
    case PolygonDefect::None:
      return {};
    case PolygonDefect::Pinched: {
      const double gap = (loop[static_cast<std::size_t>(d.first)] - loop[static_cast<std::size_t>(d.second)]).norm();
      return "is pinched: its non-adjacent vertices " + vid(d.first) + " and " + vid(d.second) + " are " +
             formatNumber(gap, 3) + " apart (at most 1e-12 of the cell's size)";
    }
    case PolygonDefect::SelfIntersecting:
      return "has a self-intersecting outline (in its best-fit plane): its edges " + vid(d.first) + "-" +
             vid(d.first + 1) + " and " + vid(d.second) + "-" + vid(d.second + 1) + " (vertex ids) cross or touch";
    case PolygonDefect::NoArea:
      return "has no vector area (a degenerate outline)";
  }
  return {};
}

PolygonMeasures polygonMeasures(std::span<const Vec3> loop) {
  if (loop.size() < 3) throw GeometryError("a polygon needs at least 3 points");
  PolygonMeasures m;
  detail::polygonKernel(
      loop.size(), [&](std::size_t i) -> const Vec3& { return loop[i]; }, false, true, m.area,
      m.centroid, m.normal, &m.second_moment);
  return m;
}

PolygonMeasures polygonMeasures(const Tissue& t, FaceId f) {
  const auto loop = t.topology().faceVertices(f);
  PolygonMeasures m;
  detail::polygonKernel(
      loop.size(), [&](std::size_t i) -> const Vec3& { return t.position(loop[i]); }, planar(t),
      true, m.area, m.centroid, m.normal, &m.second_moment);
  return m;
}

PolyhedronMeasures polyhedronMeasures(const Tissue& t, VolumeId c) {
  PolyhedronMeasures m;
  polyhedronKernel(t, c, true, m.volume, m.centroid, &m.second_moment);
  for (OrientedFace of : t.topology().volumeFaces(c)) m.surface_area += polygonMeasures(t, of.handle()).area;
  return m;
}

double wallMeasure(const Tissue& t, WallId w) {
  return t.dim() == 2 ? edgeLength(t, EdgeId(w.index())) : polygonMeasures(t, FaceId(w.index())).area;
}

double cellMeasure(const Tissue& t, CellId c) {
  if (t.dim() == 2) {
    const auto loop = t.topology().faceVertices(FaceId(c.index()));
    PolygonMeasures m;
    detail::polygonKernel(
        loop.size(), [&](std::size_t i) -> const Vec3& { return t.position(loop[i]); }, planar(t),
        false, m.area, m.centroid, m.normal, nullptr);
    return m.area;
  }
  double v = 0;
  Vec3 g;
  polyhedronKernel(t, VolumeId(c.index()), false, v, g, nullptr);
  return v;
}

Vec3 cellCentroid(const Tissue& t, CellId c) {
  return t.dim() == 2 ? polygonMeasures(t, FaceId(c.index())).centroid
                      : polyhedronMeasures(t, VolumeId(c.index())).centroid;
}

Mat3 cellSecondMoment(const Tissue& t, CellId c) {
  return t.dim() == 2 ? polygonMeasures(t, FaceId(c.index())).second_moment
                      : polyhedronMeasures(t, VolumeId(c.index())).second_moment;
}

PrincipalAxes cellPrincipalAxes(const Tissue& t, CellId c) {
  return principalAxes(cellSecondMoment(t, c));
}

double totalMeasure(const Tissue& t) {
  double total = 0;
  for (CellId c : t.cells()) total += cellMeasure(t, c);
  return total;
}

const char* geometryQuantityName(GeometryQuantity q) {
  switch (q) {
    case GeometryQuantity::EdgeLengths: return "edge_lengths";
    case GeometryQuantity::FaceMeasures: return "face_measures";
    case GeometryQuantity::FaceSecondMoments: return "face_second_moments";
    case GeometryQuantity::VolumeMeasures: return "volume_measures";
    case GeometryQuantity::VolumeSecondMoments: return "volume_second_moments";
  }
  return "?";
}

namespace {
constexpr std::array<GeometryQuantity, kGeometryQuantityCount> kEveryQuantity{
    GeometryQuantity::EdgeLengths, GeometryQuantity::FaceMeasures, GeometryQuantity::FaceSecondMoments,
    GeometryQuantity::VolumeMeasures, GeometryQuantity::VolumeSecondMoments};

// The quantities a tissue has: no volumes in 2D.
GeometryQuantities applicable(const Tissue& t, GeometryQuantities quantities) {
  return t.dim() == 3 ? quantities
                      : quantities.without(GeometryQuantity::VolumeMeasures | GeometryQuantity::VolumeSecondMoments);
}
}  // namespace

bool GeometryCache::fresh(const Tissue& t, GeometryQuantities quantities) const {
  quantities = applicable(t, quantities);
  for (GeometryQuantity q : kEveryQuantity) {
    const Versions& v = versions_[static_cast<std::size_t>(q)];
    if (quantities.contains(q) && (v.topology != t.topologyVersion() || v.geometry != t.geometryVersion()))
      return false;
  }
  return true;
}

const GeometryCache& GeometryCache::require(const Tissue& t, GeometryQuantities quantities) {
  GeometryQuantities stale;
  for (GeometryQuantity q : kEveryQuantity)
    if (quantities.contains(q) && !fresh(t, q)) stale = stale | q;
  if (!stale.empty()) compute(t, stale);
  return *this;
}

void GeometryCache::recompute(const Tissue& t, GeometryQuantities quantities) { compute(t, quantities); }

void GeometryCache::forget() { versions_.fill(Versions{}); }

void GeometryCache::compute(const Tissue& t, GeometryQuantities quantities) {
  using Q = GeometryQuantity;
  quantities = applicable(t, quantities);
  // Volume measures sum the face areas into each volume's surface.
  if (quantities.contains(Q::VolumeMeasures) && !fresh(t, Q::FaceMeasures)) quantities = quantities | Q::FaceMeasures;
  const CellComplex& k = t.topology();

  if (quantities.contains(Q::EdgeLengths)) {
    const auto& edge_alive = k.aliveFlags(1);
    const std::int64_t ne = static_cast<std::int64_t>(k.slots(1));
    resizeDiscarding(edge_length, ne);
#pragma omp parallel for schedule(static, kInterleavedChunk)
    for (std::int64_t e = 0; e < ne; ++e)
      edge_length[e] = edge_alive[e] ? edgeLength(t, EdgeId(static_cast<Index>(e))) : 0.0;
  }

  const bool face_measures = quantities.contains(Q::FaceMeasures);
  const bool face_moments = quantities.contains(Q::FaceSecondMoments);
  const std::size_t nf = k.slots(2);
  // Each pass below writes every slot (dead ones get zeros): a growing
  // tissue's arrays are not copied when they move.
  if (face_measures) {
    resizeDiscarding(face_area, nf);
    resizeDiscarding(face_centroid, nf);
    resizeDiscarding(face_normal, nf);
  }
  if (face_moments) resizeDiscarding(face_second_moment, nf);
  const bool volume_measures = quantities.contains(Q::VolumeMeasures);
  const bool volume_moments = quantities.contains(Q::VolumeSecondMoments);
  // A face pass before a volume pass keeps the faces' surfaces for it.
  std::vector<FaceSurface> surfaces;
  if ((face_measures || face_moments) && (volume_measures || volume_moments)) surfaces.resize(nf);
  // The embedding and what to compute as template arguments: each loop is
  // compiled with its own straight kernel (same arithmetic).
  if (planar(t))
    facesLoop<true, false>(t, *this, face_measures, face_moments, nullptr);
  else if (surfaces.empty())
    facesLoop<false, false>(t, *this, face_measures, face_moments, nullptr);
  else
    facesLoop<false, true>(t, *this, face_measures, face_moments, surfaces.data());

  if (volume_measures || volume_moments) volumesLoop(t, *this, volume_measures, volume_moments, surfaces);

  for (GeometryQuantity q : kEveryQuantity)
    if (quantities.contains(q)) {
      versions_[static_cast<std::size_t>(q)] = Versions{t.topologyVersion(), t.geometryVersion()};
      ++computations_[static_cast<std::size_t>(q)];
    }
}

GeometryQuantities geometryQuantities(const GeometryOptions& options) {
  GeometryQuantities quantities = kCellMeasures;
  if (options.edges) quantities = quantities | GeometryQuantity::EdgeLengths;
  if (options.second_moments)
    quantities = quantities | GeometryQuantity::FaceSecondMoments | GeometryQuantity::VolumeSecondMoments;
  return quantities;
}

void recomputeGeometry(const Tissue& t, GeometryCache& cache, const GeometryOptions& options) {
  cache.recompute(t, geometryQuantities(options));
}

}  // namespace tessella
