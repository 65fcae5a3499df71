#include "tessella/tissue/geometry.hpp"

#include <Eigen/Eigenvalues>

#include "polygon_kernels.hpp"
#include "tessella/tissue/errors.hpp"

namespace tessella {

namespace {

bool planar(const Tissue& t) { return t.embedding() == Embedding::Planar; }

// Volume integrals of a polyhedron by the divergence theorem over the signed
// fans of its faces, about a reference point r (the mean of face centres).
template <typename FaceCenter>
void polyhedronKernel(const Tissue& t, VolumeId c, FaceCenter faceCenter, bool moments,
                      double& volume, Vec3& centroid, Mat3* second_moment) {
  const CellComplex& k = t.topology();
  const auto faces = k.volumeFaces(c);
  Vec3 r = Vec3::Zero();
  for (OrientedFace of : faces) r += faceCenter(of.handle());
  r /= static_cast<double>(faces.size());
  double v6 = 0;
  Vec3 first = Vec3::Zero();
  Mat3 second = Mat3::Zero();
  for (OrientedFace of : faces) {
    const FaceId f = of.handle();
    const Vec3 a = faceCenter(f) - r;
    const auto loop = k.faceVertices(f);
    const std::size_t n = loop.size();
    Vec3 p = t.position(loop[n - 1]) - r;
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3 q = t.position(loop[i]) - r;
      const Vec3& b = of.reversed() ? q : p;
      const Vec3& d = of.reversed() ? p : q;
      const double w = a.dot(b.cross(d));  // 6 x signed tetrahedron volume
      v6 += w;
      const Vec3 s = a + b + d;
      first += w * s;
      if (moments)
        second += w * (a * a.transpose() + b * b.transpose() + d * d.transpose() + s * s.transpose());
      p = q;
    }
  }
  volume = v6 / 6.0;
  const Vec3 g = v6 != 0 ? Vec3(first / (4.0 * v6)) : Vec3::Zero();
  centroid = r + g;
  if (moments && second_moment) *second_moment = second / 120.0 - volume * g * g.transpose();
}

Vec3 vertexMean(const Tissue& t, FaceId f) {
  const auto loop = t.topology().faceVertices(f);
  Vec3 c = Vec3::Zero();
  for (VertexId v : loop) c += t.position(v);
  return c / static_cast<double>(loop.size());
}

// Measures of every face into the cache (sized by the caller).
template <bool Planar, bool Moments>
void facesLoop(const Tissue& t, GeometryCache& cache) {
  const CellComplex& k = t.topology();
  const auto& face_alive = k.aliveFlags(2);
  const std::int64_t nf = static_cast<std::int64_t>(k.slots(2));
  const Vec3* x = t.positions().data();
  double* area = cache.face_area.data();
  Vec3* centroid = cache.face_centroid.data();
  Vec3* normal = cache.face_normal.data();
  Sym3* second = Moments ? cache.face_second_moment.data() : nullptr;
#pragma omp parallel for schedule(static)
  for (std::int64_t f = 0; f < nf; ++f) {
    if (!face_alive[f]) {
      area[f] = 0;
      centroid[f].setZero();
      normal[f].setZero();
      if constexpr (Moments) second[f] = Sym3{};
      continue;
    }
    const auto loop = k.faceVertices(FaceId(static_cast<Index>(f)));
    Mat3 m;
    detail::polygonKernel(
        loop.size(), [&](std::size_t i) -> const Vec3& { return x[loop[i].index()]; }, Planar, Moments,
        area[f], centroid[f], normal[f], Moments ? &m : nullptr);
    if constexpr (Moments) second[f] = Sym3::fromMatrix(m);
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
  polyhedronKernel(
      t, c, [&](FaceId f) { return vertexMean(t, f); }, true, m.volume, m.centroid,
      &m.second_moment);
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
  polyhedronKernel(
      t, VolumeId(c.index()), [&](FaceId f) { return vertexMean(t, f); }, false, v, g, nullptr);
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

void recomputeGeometry(const Tissue& t, GeometryCache& cache, const GeometryOptions& options) {
  const CellComplex& k = t.topology();
  const bool flat = planar(t);
  const bool moments = options.second_moments;
  const auto& edge_alive = k.aliveFlags(1);
  const auto& face_alive = k.aliveFlags(2);
  const std::int64_t ne = static_cast<std::int64_t>(k.slots(1));
  const std::int64_t nf = static_cast<std::int64_t>(k.slots(2));

  if (options.edges) {
    cache.edge_length.resize(ne);
#pragma omp parallel for schedule(static)
    for (std::int64_t e = 0; e < ne; ++e)
      cache.edge_length[e] = edge_alive[e] ? edgeLength(t, EdgeId(static_cast<Index>(e))) : 0.0;
  }

  cache.face_area.resize(nf);
  cache.face_centroid.resize(nf);
  cache.face_normal.resize(nf);
  if (moments) cache.face_second_moment.resize(nf);
  // The embedding and the moments flag as template arguments: each of the
  // four loops is compiled with its own straight kernel (same arithmetic).
  if (flat)
    moments ? facesLoop<true, true>(t, cache) : facesLoop<true, false>(t, cache);
  else
    moments ? facesLoop<false, true>(t, cache) : facesLoop<false, false>(t, cache);

  if (t.dim() == 3) {
    const auto& vol_alive = k.aliveFlags(3);
    const std::int64_t nc = static_cast<std::int64_t>(k.slots(3));
    // Face vertex means, shared by the two volumes of each face.
    std::vector<Vec3> centers(nf);
#pragma omp parallel for schedule(static)
    for (std::int64_t f = 0; f < nf; ++f)
      centers[f] = face_alive[f] ? vertexMean(t, FaceId(static_cast<Index>(f))) : Vec3::Zero();
    cache.volume.resize(nc);
    cache.volume_surface.resize(nc);
    cache.volume_centroid.resize(nc);
    if (moments) cache.volume_second_moment.resize(nc);
#pragma omp parallel for schedule(static)
    for (std::int64_t c = 0; c < nc; ++c) {
      if (!vol_alive[c]) {
        cache.volume[c] = cache.volume_surface[c] = 0;
        cache.volume_centroid[c].setZero();
        if (moments) cache.volume_second_moment[c] = Sym3{};
        continue;
      }
      const VolumeId vc(static_cast<Index>(c));
      Mat3 m;
      polyhedronKernel(
          t, vc, [&](FaceId f) -> const Vec3& { return centers[f.index()]; }, moments,
          cache.volume[c], cache.volume_centroid[c], moments ? &m : nullptr);
      if (moments) cache.volume_second_moment[c] = Sym3::fromMatrix(m);
      double s = 0;
      for (OrientedFace of : k.volumeFaces(vc)) s += cache.face_area[of.handle().index()];
      cache.volume_surface[c] = s;
    }
  }
  cache.topology_version = t.topologyVersion();
  cache.geometry_version = t.geometryVersion();
}

}  // namespace tessella
