// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include <catch2/catch.hpp>

#include <omp.h>

#include <cstring>

#include "fixtures.hpp"
#include "tessella/tissue/geometry.hpp"

using namespace tessella;
using namespace tessella::fixtures;

namespace {

// J/2 for a regular n-gon of circumradius r: the in-plane second moment
// about any centroidal axis (J = A r^2 (1 + 2 cos^2(pi/n)) / 6).
double regularPolygonAxisMoment(int n, double r) {
  const double area = 0.5 * n * r * r * std::sin(2 * M_PI / n);
  return 0.5 * area * r * r * (1 + 2 * std::pow(std::cos(M_PI / n), 2)) / 6;
}

bool matClose(const Mat3& a, const Mat3& b, double tol) { return (a - b).cwiseAbs().maxCoeff() <= tol; }

}  // namespace

TEST_CASE("regular polygons: area, centroid, normal, second moments", "[tissue][geometry]") {
  for (int n : {3, 4, 5, 6, 7, 12, 40}) {
    const double r = 1.7;
    Tissue t = singlePolygon(regularPolygon(n, r));
    const PolygonMeasures m = polygonMeasures(t, FaceId(0));
    const double area = 0.5 * n * r * r * std::sin(2 * M_PI / n);
    CHECK(m.area == Approx(area).epsilon(1e-13));
    CHECK(m.centroid.norm() < 1e-13);
    CHECK((m.normal - Vec3::UnitZ()).norm() < 1e-15);
    const double I = regularPolygonAxisMoment(n, r);
    CHECK(matClose(m.second_moment, Vec3(I, I, 0).asDiagonal().toDenseMatrix(), 1e-12));
  }
}

TEST_CASE("rectangle second moments and main axis", "[tissue][geometry]") {
  Tissue t = rectangularGrid(1, 1, 3.0, 1.0, Vec3(2, 5, 0));
  const PolygonMeasures m = polygonMeasures(t, FaceId(0));
  CHECK(m.area == Approx(3.0));
  CHECK((m.centroid - Vec3(3.5, 5.5, 0)).norm() < 1e-14);
  CHECK(m.second_moment(0, 0) == Approx(1.0 * 27 / 12));
  CHECK(m.second_moment(1, 1) == Approx(3.0 * 1 / 12));
  CHECK(std::abs(m.second_moment(0, 1)) < 1e-14);
  const PrincipalAxes ax = cellPrincipalAxes(t, CellId(0));
  CHECK(std::abs(ax.axes.col(0).dot(Vec3::UnitX())) == Approx(1.0));
}

TEST_CASE("polygon measures are invariant under rigid motion, start vertex and (up to sign) orientation",
          "[tissue][geometry]") {
  const std::vector<Vec3> base{{0, 0, 0}, {4, 0, 0}, {4, 1, 0}, {1, 1, 0}, {1, 3, 0}, {0, 3, 0}};  // an L
  const PolygonMeasures ref = polygonMeasures(base);
  CHECK(ref.area == Approx(6.0));  // non-convex: 4x1 + 1x2
  CHECK((ref.centroid - Vec3((4 * 2.0 + 2 * 0.5) / 6, (4 * 0.5 + 2 * 2.0) / 6, 0)).norm() < 1e-14);
  const Mat3 R = rotation(0.7, Vec3(1, 2, 3));
  const Vec3 shift(10, -4, 2);
  for (int start = 0; start < 6; ++start) {
    for (bool reverse : {false, true}) {
      std::vector<Vec3> pts;
      for (int i = 0; i < 6; ++i) {
        const int k = reverse ? (start - i + 12) % 6 : (start + i) % 6;
        pts.push_back(R * base[k] + shift);
      }
      Tissue t = singlePolygon(pts, Embedding::Surface);
      const PolygonMeasures m = polygonMeasures(t, FaceId(0));
      CHECK(m.area == Approx(ref.area).epsilon(1e-13));
      CHECK((m.centroid - (R * ref.centroid + shift)).norm() < 1e-12);
      CHECK((m.normal - (reverse ? -1.0 : 1.0) * (R * Vec3::UnitZ())).norm() < 1e-13);
      CHECK(matClose(m.second_moment, R * ref.second_moment * R.transpose(), 1e-12));
    }
  }
}

TEST_CASE("non-planar loops: fan surface, well defined and robust", "[tissue][geometry]") {
  // A saddle quad: its fan area exceeds the projected area and tends to it when flattened.
  auto saddle = [](double h) {
    return std::vector<Vec3>{{0, 0, 0}, {1, 0, h}, {1, 1, 0}, {0, 1, h}};
  };
  const double flat = polygonMeasures(saddle(0)).area;
  CHECK(flat == Approx(1.0));
  double previous = flat;
  for (double h : {0.01, 0.1, 0.5}) {
    const PolygonMeasures m = polygonMeasures(saddle(h));
    CHECK(m.area > previous);
    previous = m.area;
    CHECK(std::abs(m.normal.z()) == Approx(1.0));
    CHECK((m.centroid - Vec3(0.5, 0.5, h / 2)).norm() < 1e-14);  // symmetric
    // Analytic fan area: 4 triangles from (0.5, 0.5, h/2), each with area
    // 0.5 * |(p - c) x (q - c)| = 0.5 * sqrt(0.25 + h^2/4) ... computed exactly below.
    const Vec3 c(0.5, 0.5, h / 2);
    const Vec3 a = Vec3(0, 0, 0) - c, b = Vec3(1, 0, h) - c;
    CHECK(m.area == Approx(4 * 0.5 * a.cross(b).norm()).epsilon(1e-14));
  }
  // A cylinder strip of planar quads: total area is the polygonal cross-section times the length.
  const double R = 2.0, angle = 1.2;
  const std::size_t ny = 8;
  Tissue sheet = curvedSheet(5, ny, R, angle);
  const double chord = 2 * R * std::sin(angle / ny / 2);
  CHECK(totalMeasure(sheet) == Approx(ny * chord).epsilon(1e-13));
}

TEST_CASE("boxes: volume, surface, centroid, inertia", "[tissue][geometry]") {
  const double a = 1.0, b = 2.0, c = 3.0;
  const Mat3 R = rotation(0.3, Vec3(0.2, -1, 0.5));
  const Vec3 shift(-3, 1, 7);
  for (bool moved : {false, true}) {
    Tissue t = moved ? box(a, b, c, R, shift) : box(a, b, c);
    const PolyhedronMeasures m = polyhedronMeasures(t, VolumeId(0));
    const Mat3 Q = moved ? R : Mat3::Identity();
    const Vec3 centre = Q * Vec3(a / 2, b / 2, c / 2) + (moved ? shift : Vec3::Zero());
    CHECK(m.volume == Approx(a * b * c).epsilon(1e-13));
    CHECK(m.surface_area == Approx(2 * (a * b + b * c + c * a)).epsilon(1e-13));
    CHECK((m.centroid - centre).norm() < 1e-12);
    const double V = a * b * c;
    const Mat3 S = Vec3(a * a, b * b, c * c).asDiagonal().toDenseMatrix() * (V / 12);
    CHECK(matClose(m.second_moment, Q * S * Q.transpose(), 1e-12));
    const Mat3 I = inertiaTensor(m.second_moment);
    const Mat3 Iref = Vec3(b * b + c * c, a * a + c * c, a * a + b * b).asDiagonal().toDenseMatrix() * (V / 12);
    CHECK(matClose(I, Q * Iref * Q.transpose(), 1e-12));
    const PrincipalAxes ax = principalAxes(m.second_moment);
    CHECK(std::abs(ax.axes.col(0).dot(Q * Vec3::UnitZ())) == Approx(1.0));  // longest side c
  }
}

TEST_CASE("tetrahedra: volume, centroid and second moment against the unit simplex integrals",
          "[tissue][geometry]") {
  // Unit right tetrahedron: V = 1/6, integral x^2 = 1/60, integral xy = 1/120.
  const Mat3 S0 = (Mat3() << 2, 1, 1, 1, 2, 1, 1, 1, 2).finished() / 120.0;
  const Vec3 g(0.25, 0.25, 0.25);
  const Mat3 S = S0 - (1.0 / 6) * g * g.transpose();
  for (bool flip : {false, true}) {
    Tissue t = flip ? tetrahedron(Vec3::Zero(), Vec3::UnitY(), Vec3::UnitX(), Vec3::UnitZ())
                    : tetrahedron(Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ());
    const PolyhedronMeasures m = polyhedronMeasures(t, VolumeId(0));
    CHECK(m.volume == Approx(1.0 / 6).epsilon(1e-14));
    CHECK((m.centroid - g).norm() < 1e-15);
    CHECK(matClose(m.second_moment, S, 1e-15));
    CHECK(m.surface_area == Approx(1.5 + std::sqrt(3.0) / 2).epsilon(1e-14));
  }
  // An affine image: volume scales by det(A), second moment by A S A^T.
  Mat3 A;
  A << 2, 0.3, 0, 0.1, 1.5, 0.2, 0, 0.4, 0.8;
  const Vec3 shift(1, 2, 3);
  Tissue t = tetrahedron(shift, A.col(0) + shift, A.col(1) + shift, A.col(2) + shift);
  const PolyhedronMeasures m = polyhedronMeasures(t, VolumeId(0));
  CHECK(m.volume == Approx(A.determinant() / 6).epsilon(1e-13));
  CHECK((m.centroid - (A * g + shift)).norm() < 1e-13);
  CHECK(matClose(m.second_moment, A.determinant() * A * S * A.transpose(), 1e-13));
}

TEST_CASE("prisms over regular polygons", "[tissue][geometry]") {
  for (int n : {3, 5, 8}) {
    const double r = 1.3, h = 2.2;
    Tissue t = prism(n, r, h);
    const PolyhedronMeasures m = polyhedronMeasures(t, VolumeId(0));
    const double A = 0.5 * n * r * r * std::sin(2 * M_PI / n);
    CHECK(m.volume == Approx(A * h).epsilon(1e-13));
    CHECK((m.centroid - Vec3(0, 0, h / 2)).norm() < 1e-13);
    const double I = regularPolygonAxisMoment(n, r) * h;
    CHECK(matClose(m.second_moment, Vec3(I, I, A * h * h * h / 12).asDiagonal().toDenseMatrix(), 1e-12));
  }
}

TEST_CASE("batched recompute equals per-element queries and is bit-identical across thread counts",
          "[tissue][geometry]") {
  for (int which = 0; which < 3; ++which) {
    Tissue t = which == 0 ? hexagonalGrid(30, 20, 0.5) : which == 1 ? curvedSheet(20, 20, 1.5, 2.0)
                                                                    : boxGrid(6, 5, 4, 1.0, 0.5, 2.0);
    // Perturb positions so nothing is symmetric.
    std::uint64_t s = 12345;
    for (Vec3& p : t.mutablePositions()) {
      s = s * 6364136223846793005ull + 1442695040888963407ull;
      p += 1e-3 * Vec3(double(s >> 40) / (1 << 24), double((s >> 16) & 0xffffff) / (1 << 24), 0.0);
    }
    GeometryCache one, two;
    omp_set_num_threads(1);
    recomputeGeometry(t, one);
    omp_set_num_threads(2);
    recomputeGeometry(t, two);
    CHECK(one.fresh(t));
    CHECK(std::memcmp(one.face_area.data(), two.face_area.data(), one.face_area.size() * sizeof(double)) == 0);
    CHECK(std::memcmp(one.face_centroid.data(), two.face_centroid.data(), one.face_centroid.size() * sizeof(Vec3)) == 0);
    CHECK(std::memcmp(one.face_second_moment.data(), two.face_second_moment.data(),
                      one.face_second_moment.size() * sizeof(Sym3)) == 0);
    CHECK(std::memcmp(one.volume.data(), two.volume.data(), one.volume.size() * sizeof(double)) == 0);
    CHECK(std::memcmp(one.volume_second_moment.data(), two.volume_second_moment.data(),
                      one.volume_second_moment.size() * sizeof(Sym3)) == 0);
    for (CellId c : t.cells()) {
      CHECK(one.cellMeasure(t, c) == cellMeasure(t, c));
      CHECK(one.cellCentroid(t, c) == cellCentroid(t, c));
    }
    for (EdgeId e : t.edges()) CHECK(one.edge_length[e.index()] == edgeLength(t, e));
    t.setPosition(VertexId(0), t.position(VertexId(0)) + Vec3(0.01, 0, 0));
    CHECK_FALSE(one.fresh(t));
  }
}

TEST_CASE("tissue totals: grids tile their rectangle and box exactly", "[tissue][geometry]") {
  CHECK(totalMeasure(rectangularGrid(7, 3, 0.5, 2.0)) == Approx(7 * 0.5 * 3 * 2.0).epsilon(1e-14));
  CHECK(totalMeasure(boxGrid(3, 4, 5, 0.5, 1.0, 2.0)) == Approx(1.5 * 4 * 10).epsilon(1e-14));
  const double r = 0.8;
  CHECK(totalMeasure(hexagonalGrid(5, 4, r)) == Approx(20 * 1.5 * std::sqrt(3.0) * r * r).epsilon(1e-13));
}
