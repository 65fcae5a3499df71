// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Geometry that holds on real cells: non-convex polygons that are not
// star-shaped from their vertex mean (planar, tilted and curved), their
// invariance to the loop's start and direction, 3D walls of that kind, the
// validate() checks for pinched, self-intersecting and overlapping cells, and
// the Euler characteristic of pieces touching at a vertex or along an edge.

#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <omp.h>
#include <vector>

#include "fixtures.hpp"
#include "l_prisms.hpp"
#include "tessella/tissue/builders.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/generators/grids.hpp"
#include "tessella/tissue/validate.hpp"

using namespace tessella;
using namespace tessella::fixtures;

namespace {

// A closed-form region made of axis-aligned rectangles (in the z = 0 plane):
// area, centroid and second moment about the centroid.
struct Rect {
  double x0, y0, x1, y1;
};
PolygonMeasures rectangles(const std::vector<Rect>& rs, const std::vector<Rect>& holes = {}) {
  PolygonMeasures m;
  Vec3 first = Vec3::Zero();
  Mat3 second = Mat3::Zero();  // about the origin
  const auto add = [&](const Rect& r, double s) {
    const double w = r.x1 - r.x0, h = r.y1 - r.y0, a = s * w * h;
    const double cx = 0.5 * (r.x0 + r.x1), cy = 0.5 * (r.y0 + r.y1);
    m.area += a;
    first += a * Vec3(cx, cy, 0);
    second(0, 0) += a * (w * w / 12 + cx * cx);
    second(1, 1) += a * (h * h / 12 + cy * cy);
    second(0, 1) += a * cx * cy;
  };
  for (const Rect& r : rs) add(r, 1);
  for (const Rect& r : holes) add(r, -1);
  second(1, 0) = second(0, 1);
  m.centroid = first / m.area;
  m.second_moment = second - m.area * m.centroid * m.centroid.transpose();
  m.normal = Vec3::UnitZ();
  return m;
}

// An L (vertex mean on the reflex corner), a C (vertex mean in the notch) and
// a dart (star-shaped from its tip, not from its vertex mean).
const std::vector<Vec3>& kL = fixtures::kLShape;
const std::vector<Vec3> kC{{0, 0, 0}, {3, 0, 0}, {3, 1, 0}, {1, 1, 0}, {1, 2, 0}, {3, 2, 0}, {3, 3, 0}, {0, 3, 0}};
const std::vector<Vec3> kDart{{0, 0, 0}, {4, 0, 0}, {0.2, 0.2, 0}, {0, 4, 0}};

std::vector<Vec3> rotated(const std::vector<Vec3>& loop, int start, bool reverse) {
  std::vector<Vec3> out;
  const int n = static_cast<int>(loop.size());
  for (int i = 0; i < n; ++i) out.push_back(loop[reverse ? (start - i + 2 * n) % n : (start + i) % n]);
  return out;
}

bool matClose(const Mat3& a, const Mat3& b, double tol) { return (a - b).norm() <= tol * std::max(1.0, b.norm()); }

// The fan from the vertex mean folds for these shapes (the old measure was wrong on curved ones).
bool fanFolds(const std::vector<Vec3>& loop) { return polygonTriangulation(loop).folded; }

}  // namespace

TEST_CASE("non-convex polygons not star-shaped from their vertex mean: closed forms, tilted in 3D",
          "[tissue][geometry][real]") {
  const PolygonMeasures L = rectangles({{0, 0, 2, 1}, {0, 1, 1, 2}});
  const PolygonMeasures C = rectangles({{0, 0, 3, 3}}, {{1, 1, 3, 2}});
  REQUIRE(L.area == 3.0);
  REQUIRE(C.area == 7.0);
  const Mat3 R = rotation(0.9, Vec3(1, -2, 0.5));
  const Vec3 shift(3, 1, -2);
  for (const auto& [loop, ref] : {std::pair{kL, L}, std::pair{kC, C}}) {
    REQUIRE(fanFolds(loop));
    for (int start = 0; start < static_cast<int>(loop.size()); ++start)
      for (bool reverse : {false, true}) {
        std::vector<Vec3> pts = rotated(loop, start, reverse);
        for (Vec3& p : pts) p = R * p + shift;
        const Tissue t = singlePolygon(pts, Embedding::Surface);
        const PolygonMeasures m = polygonMeasures(t, FaceId(0));
        CHECK(m.area == Approx(ref.area).epsilon(1e-13));
        CHECK((m.centroid - (R * ref.centroid + shift)).norm() < 1e-12);
        CHECK((m.normal - (reverse ? -1.0 : 1.0) * (R * Vec3::UnitZ())).norm() < 1e-13);
        CHECK(matClose(m.second_moment, R * ref.second_moment * R.transpose(), 1e-12));
        CHECK(validate(t).ok);
      }
  }
}

TEST_CASE("a dart lifted onto a paraboloid and a sphere is measured on the fan from its kernel",
          "[tissue][geometry][real]") {
  // The dart is star-shaped from its tip region, not from its vertex mean:
  // the surface is the fan from the centroid of its projection's kernel,
  // placed in its best-fit plane; area and centroid of that fan exactly.
  const auto lifts = {std::function<double(double, double)>([](double x, double y) { return 0.1 * (x * x + y * y); }),
                      std::function<double(double, double)>(
                          [](double x, double y) { return std::sqrt(25.0 - x * x - y * y) - 5.0; })};
  for (const auto& lift : lifts) {
    std::vector<Vec3> pts = kDart;
    for (Vec3& p : pts) p.z() = lift(p.x(), p.y());
    const PolygonTriangulation s = polygonTriangulation(pts);
    REQUIRE(s.folded);
    REQUIRE(s.fan());
    double area = 0;
    Vec3 first = Vec3::Zero();
    for (int i = 0; i < 4; ++i) {
      const Vec3 &p = pts[i], &q = pts[(i + 1) % 4];
      const Vec3 cr = (p - s.center).cross(q - s.center);
      CHECK(cr.dot(s.normal) > 0);  // the apex sees every edge
      area += 0.5 * cr.norm();
      first += 0.5 * cr.norm() * (s.center + p + q) / 3.0;
    }
    // The apex lies in the kernel of the projected dart (near the tip, x, y < 0.22).
    Vec3 mean = Vec3::Zero();
    for (const Vec3& p : pts) mean += p / 4.0;
    CHECK(std::abs((s.center - mean).dot(s.normal)) < 1e-12);
    for (int start = 0; start < 4; ++start)
      for (bool reverse : {false, true}) {
        const Tissue t = singlePolygon(rotated(pts, start, reverse), Embedding::Surface);
        const PolygonMeasures m = polygonMeasures(t, FaceId(0));
        CHECK(m.area == Approx(area).epsilon(1e-13));
        CHECK((m.centroid - first / area).norm() < 1e-12);
        CHECK(cellMeasure(t, CellId(0)) == m.area);
        CHECK(validate(t).ok);
      }
    // Flattened, the lift disappears: the exact planar dart (0.8, centroid (11/15, 11/15)).
    std::vector<Vec3> flat = pts;
    for (Vec3& p : flat) p.z() = 0;
    const PolygonMeasures f = polygonMeasures(flat);
    CHECK(f.area == Approx(0.8).epsilon(1e-13));
    CHECK((f.centroid - Vec3(11.0 / 15, 11.0 / 15, 0)).norm() < 1e-13);
  }
}

TEST_CASE("a curved non-convex cell: same measures from any start vertex and either direction",
          "[tissue][geometry][real]") {
  std::vector<Vec3> c = kC;
  for (Vec3& p : c) p.z() = 0.15 * (p.x() * p.x() + 0.5 * p.y() * p.y());  // a paraboloid patch
  REQUIRE(fanFolds(c));
  const PolygonMeasures ref = polygonMeasures(c);
  // Between the projected area and the area of the lifted bounding rectangle's surface.
  CHECK(ref.area > 7.0);
  CHECK(ref.area < 7.0 * 2.0);
  for (int start = 0; start < 8; ++start)
    for (bool reverse : {false, true}) {
      const PolygonMeasures m = polygonMeasures(rotated(c, start, reverse));
      CHECK(m.area == Approx(ref.area).epsilon(1e-13));
      CHECK((m.centroid - ref.centroid).norm() < 1e-12);
      CHECK((m.normal - (reverse ? -1.0 : 1.0) * ref.normal).norm() < 1e-13);
      CHECK(matClose(m.second_moment, ref.second_moment, 1e-12));
    }
  // The triangles cover the outline's projection once: n - 2 of them, all positively oriented.
  const PolygonTriangulation tri = polygonTriangulation(c);
  REQUIRE(tri.triangles.size() == c.size() - 2);
  double projected = 0;
  for (const auto& k : tri.triangles) {
    const double s = (c[k[1]] - c[k[0]]).cross(c[k[2]] - c[k[0]]).dot(tri.normal);
    CHECK(s > 0);
    projected += 0.5 * s;
  }
  double shoelace = 0;
  for (std::size_t i = 0; i < c.size(); ++i) shoelace += 0.5 * c[i].cross(c[(i + 1) % c.size()]).dot(tri.normal);
  CHECK(projected == Approx(shoelace).epsilon(1e-13));
}

TEST_CASE("folded cells: the cache equals the per-element queries bit for bit, for any thread count",
          "[tissue][geometry][real]") {
  // A curved sheet with a C-shaped and an L-shaped cell, and a 3D prism over an L with a non-planar L on top.
  std::vector<Vec3> p = kC;
  for (const Vec3& q : {Vec3(4, 0, 0), Vec3(4, 3, 0)}) p.push_back(q);
  for (Vec3& q : p) q.z() = 0.1 * q.x() * q.x() - 0.05 * q.y() * q.y();
  const Tissue sheet = buildPolygonTissue(p, {{0, 1, 2, 3, 4, 5, 6, 7}, {1, 8, 9, 6, 5, 4, 3, 2}}, Embedding::Surface);
  REQUIRE(validate(sheet).ok);
  REQUIRE(fanFolds({p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7]}));

  std::vector<Vec3> q;
  for (double z : {0.0, 1.0})
    for (const Vec3& v : kL) q.push_back(v + Vec3(0, 0, z + (z > 0 ? 0.2 * v.x() * v.y() : 0.0)));
  std::vector<std::vector<Index>> faces{{5, 4, 3, 2, 1, 0}, {6, 7, 8, 9, 10, 11}};
  for (Index i = 0; i < 6; ++i) faces.push_back({i, (i + 1) % 6, (i + 1) % 6 + 6, i + 6});
  std::vector<std::vector<CellFace>> cells(1);
  for (Index f = 0; f < faces.size(); ++f) cells[0].push_back({f, false});
  const Tissue prism = buildPolyhedralTissue(q, faces, cells);
  REQUIRE(validate(prism).ok);

  for (const Tissue* t : {&sheet, &prism}) {
    GeometryCache one, two;
    const int threads = omp_get_max_threads();
    omp_set_num_threads(1);
    recomputeGeometry(*t, one);
    omp_set_num_threads(std::max(2, threads));
    recomputeGeometry(*t, two);
    omp_set_num_threads(threads);
    for (FaceId f : t->faces()) {
      const PolygonMeasures m = polygonMeasures(*t, f);
      CHECK(one.face_area[f.index()] == m.area);
      CHECK(two.face_area[f.index()] == m.area);
      CHECK(one.face_centroid[f.index()] == m.centroid);
      CHECK(two.face_centroid[f.index()] == m.centroid);
      CHECK(Sym3::fromMatrix(m.second_moment).v == two.face_second_moment[f.index()].v);
    }
    if (t->dim() == 3)
      for (CellId c : t->cells()) {
        const PolyhedronMeasures m = polyhedronMeasures(*t, VolumeId(c.index()));
        CHECK(one.volume[c.index()] == m.volume);
        CHECK(two.volume[c.index()] == m.volume);
        CHECK(two.volume_centroid[c.index()] == m.centroid);
        CHECK(cellMeasure(*t, c) == m.volume);
      }
  }
}

TEST_CASE("3D: a prism over an L (folded planar walls) has the exact volume, and a non-planar folded wall adds up",
          "[tissue][geometry][real]") {
  const double h = 1.5;
  // The middle L is made non-planar: it is the wall between the two prisms.
  const fixtures::StackedPrisms prisms = fixtures::stackedLPrisms(h, 0.3);
  const std::vector<Vec3>& q = prisms.positions;
  const Tissue t = prisms.build();
  REQUIRE(validate(t).ok);
  std::vector<Vec3> middle(q.begin() + 6, q.begin() + 12);
  REQUIRE(fanFolds(middle));
  const double v0 = cellMeasure(t, CellId(0)), v1 = cellMeasure(t, CellId(1));
  CHECK(v0 > 0);
  CHECK(v1 > 0);
  CHECK(v0 + v1 == Approx(3.0 * 2 * h).epsilon(1e-13));
  // The same prisms with a flat middle wall: exact volumes and centroids.
  const Tissue flat = fixtures::stackedLPrisms(h, 0.0).build();
  const PolyhedronMeasures m = polyhedronMeasures(flat, VolumeId(0));
  CHECK(m.volume == Approx(3.0 * h).epsilon(1e-13));
  CHECK((m.centroid - Vec3(2.5 / 3, 2.5 / 3, h / 2)).norm() < 1e-12);
  CHECK(m.surface_area == Approx(2 * 3.0 + 8 * h).epsilon(1e-13));
}

TEST_CASE("validate reports a pinched cell with its vertices", "[tissue][validate][real]") {
  // Issue 18: vertices 109 and 130 are opposite corners of cell 50.
  for (double offset : {0.0, 1e-16, 1e-15, 1e-13}) {
    Tissue t = hexagonalGrid(10, 10);
    t.setPosition(VertexId(130), t.position(VertexId(109)) + Vec3(offset, 0, 0));
    const ValidationReport r = validate(t);
    INFO("offset " << offset << ": " << r.message);
    CHECK_FALSE(r.ok);
    CHECK(r.message.find("face 50") != std::string::npos);
    CHECK(r.message.find("pinched") != std::string::npos);
    CHECK(r.message.find("109") != std::string::npos);
    CHECK(r.message.find("130") != std::string::npos);
    CHECK(r.element == ElementId{2, 50});
  }
  Tissue fine = hexagonalGrid(10, 10);
  fine.setPosition(VertexId(130), fine.position(VertexId(109)) + Vec3(1e-6, 0, 0));
  CHECK(validate(fine).ok);
}

TEST_CASE("validate reports a self-intersecting outline", "[tissue][validate][real]") {
  ValidateOptions crossings;
  crossings.check_self_intersection = true;
  // A bow tie with unequal lobes (positive net area), planar and curved.
  for (Embedding e : {Embedding::Planar, Embedding::Surface}) {
    std::vector<Vec3> p{{0, 0, 0}, {3, 3, 0}, {3, 0, 0}, {0, 1, 0}};
    if (e == Embedding::Surface)
      for (Vec3& v : p) v.z() = 0.05 * v.x() * v.y();
    const Tissue t = singlePolygon(p, e);
    const ValidationReport r = validate(t, crossings);
    INFO(r.message);
    CHECK_FALSE(r.ok);
    CHECK(r.message.find("self-intersecting") != std::string::npos);
  }
  // A spike: an edge running back along the previous one.
  const Tissue spike = singlePolygon({{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {1, 1, 0}, {1.5, 1.5, 0}, {0, 2, 0}},
                                     Embedding::Surface);
  CHECK(validate(spike, crossings).message.find("self-intersecting") != std::string::npos);
}

TEST_CASE("validate reports a curved-sheet cell folded over onto its neighbour", "[tissue][validate][real]") {
  // Two cells sharing the wall 1-2; the second is folded back over the first.
  const std::vector<Vec3> p{{0, 0, 0}, {1, 0, 0.1}, {1, 1, 0.1}, {0, 1, 0}, {0.5, 0, 0.2}, {0.5, 1, 0.2}};
  const Tissue t = buildPolygonTissue(p, {{0, 1, 2, 3}, {1, 4, 5, 2}}, Embedding::Surface);
  const ValidationReport r = validate(t);
  INFO(r.message);
  CHECK_FALSE(r.ok);
  CHECK(r.message.find("overlaps its neighbour cell 0") != std::string::npos);
  // Unfolded, it is fine.
  std::vector<Vec3> q = p;
  q[4].x() = q[5].x() = 2;
  CHECK(validate(buildPolygonTissue(q, {{0, 1, 2, 3}, {1, 4, 5, 2}}, Embedding::Surface)).ok);
}

TEST_CASE("Euler characteristic of pieces touching at a vertex or along an edge", "[tissue][validate][real]") {
  // Issue 14: each piece and the union have characteristic 1.
  Tissue squares = rectangularGrid(2, 2);
  squares.removeCell(CellId(0));
  squares.removeCell(CellId(3));
  const ValidationReport r2 = validate(squares);
  INFO(r2.message);
  CHECK(r2.ok);
  Tissue boxes = boxGrid(2, 2, 1);
  boxes.removeCell(CellId(0));
  boxes.removeCell(CellId(3));
  const ValidationReport r3 = validate(boxes);
  INFO(r3.message);
  CHECK(r3.ok);
  // Boxes touching at a vertex only.
  Tissue corner = boxGrid(2, 2, 2);
  for (Index c = 1; c < 7; ++c) corner.removeCell(CellId(c));
  CHECK(validate(corner).ok);
  // One piece touching itself at a vertex: a 3 x 3 grid without its centre
  // and a corner is a C whose ends (cells 1 and 3) meet at a point.
  Tissue c_shape = rectangularGrid(3, 3);
  for (Index c : {0, 4}) c_shape.removeCell(CellId(c));
  const ValidationReport rc = validate(c_shape);
  INFO(rc.message);
  CHECK(rc.ok);
  // A ring whose pieces touch at points only.
  Tissue ring = rectangularGrid(3, 3);
  for (Index c : {0, 4, 6}) ring.removeCell(CellId(c));
  CHECK(validate(ring).ok);
  // Still caught: a tunnel through boxes, a handle-free but holed 3D piece.
  Tissue tunnel = boxGrid(3, 3, 1);
  tunnel.removeCell(CellId(4));
  CHECK(validate(tunnel).message.find("Euler characteristic") != std::string::npos);
}
