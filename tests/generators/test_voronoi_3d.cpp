// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// 3D Voronoi tissues: validity, exact filling of the box (and of an
// icosahedron, whose volume is known in closed form), the Voronoi property of
// cells and walls, Delaunay adjacency by brute force, cospherical seeds,
// errors and Lloyd relaxation.

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/tissue/validate.hpp"
#include "tessella/generators/voronoi.hpp"

using namespace tessella;

namespace {

// p is inside the convex cell c iff it is behind every wall's outward plane.
bool cellContains(const Tissue& t, CellId c, const Vec3& p, double tol) {
  const VolumeId vol = t.cellVolume(c);
  for (const OrientedFace& of : t.topology().volumeFaces(vol)) {
    const PolygonMeasures m = polygonMeasures(t, of.handle());
    const Vec3 outward = m.normal * of.sign();
    if ((p - m.centroid).dot(outward) > tol) return false;
  }
  return true;
}

// Brute-force Delaunay adjacency: the part of the bisector plane of i and j
// closer to them than to every other seed has positive area. Clips a large
// square of that plane by the half-planes of all other seeds.
bool delaunayNeighbours(const std::vector<Vec3>& seeds, std::size_t i, std::size_t j) {
  const Vec3 m = (seeds[i] + seeds[j]) / 2;
  const Vec3 n = (seeds[j] - seeds[i]).normalized();
  const Vec3 u = n.unitOrthogonal(), v = n.cross(u);
  using P = Eigen::Vector2d;
  std::vector<P> poly = {{-100, -100}, {100, -100}, {100, 100}, {-100, 100}};
  for (std::size_t k = 0; k < seeds.size() && poly.size() >= 3; ++k) {
    if (k == i || k == j) continue;
    // keep x with (x - (si+sk)/2) . (sk - si) <= 0, x = m + a u + b v
    const Vec3 d = seeds[k] - seeds[i];
    const P g(d.dot(u), d.dot(v));
    const double h = ((seeds[i] + seeds[k]) / 2 - m).dot(d);
    std::vector<P> next;
    for (std::size_t q = 0; q < poly.size(); ++q) {
      const P& a = poly[q];
      const P& b = poly[(q + 1) % poly.size()];
      const double sa = g.dot(a) - h, sb = g.dot(b) - h;
      if (sa <= 0) next.push_back(a);
      if ((sa < 0 && sb > 0) || (sa > 0 && sb < 0)) next.push_back(a + (b - a) * (sa / (sa - sb)));
    }
    poly = next;
  }
  double area = 0;
  for (std::size_t q = 0; q < poly.size(); ++q) {
    const P& a = poly[q];
    const P& b = poly[(q + 1) % poly.size()];
    area += a.x() * b.y() - a.y() * b.x();
  }
  return area / 2 > 1e-12;
}

double coefficientOfVariation(const std::vector<double>& v) {
  double mean = 0, var = 0;
  for (double x : v) mean += x;
  mean /= v.size();
  for (double x : v) var += (x - mean) * (x - mean);
  return std::sqrt(var / v.size()) / mean;
}

template <typename F>
std::string errorOf(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "<no InputError>";
}

}  // namespace

TEST_CASE("random 3D Voronoi tissue fills the box and has the Voronoi property",
          "[voronoi][voronoi3d]") {
  const Box box{Vec3(-1, 0, 2), Vec3(1, 1.5, 3)};
  const auto seeds = randomSeeds(box, 150, 11);
  const Tissue t = voronoiTissue(seeds, box);
  const auto report = validate(t);
  INFO(report.message);
  REQUIRE(report.ok);
  REQUIRE(t.numCells() == seeds.size());
  CHECK(totalMeasure(t) == Approx(2 * 1.5 * 1).epsilon(1e-12));
  for (CellId c : t.cells()) {
    INFO("cell " << c.index());
    CHECK(cellContains(t, c, seeds[c.index()], 1e-12));
  }
  for (VertexId v : t.vertices()) {
    const Vec3& p = t.position(v);
    CHECK(((p - box.min).array() >= 0).all());
    CHECK(((box.max - p).array() >= 0).all());
  }
  for (WallId w : t.walls()) {
    const auto cells = t.wallCells(w);
    if (cells.size() != 2) continue;
    const Vec3& si = seeds[cells[0].index()];
    const Vec3& sj = seeds[cells[1].index()];
    for (VertexId v : t.topology().faceVertices(handle_cast<FaceId>(w))) {
      const Vec3& p = t.position(v);
      const double di = (p - si).norm();
      CHECK(di == Approx((p - sj).norm()).margin(1e-10));
      for (const Vec3& s : seeds) CHECK((p - s).norm() >= di - 1e-10);
    }
  }
}

TEST_CASE("3D Voronoi neighbours are the Delaunay neighbours for interior cells",
          "[voronoi][voronoi3d]") {
  const Box box;
  const auto seeds = randomSeeds(box, 120, 21);
  const Tissue t = voronoiTissue(seeds, box);
  REQUIRE(validate(t).ok);
  int interior = 0;
  for (CellId c : t.cells()) {
    const auto walls = t.cellWalls(c);
    if (std::any_of(walls.begin(), walls.end(), [&](WallId w) { return t.isBoundaryWall(w); }))
      continue;
    ++interior;
    std::set<std::size_t> tissue_neighbours, delaunay;
    for (CellId d : t.cellNeighbors(c)) tissue_neighbours.insert(d.index());
    for (std::size_t j = 0; j < seeds.size(); ++j)
      if (j != c.index() && delaunayNeighbours(seeds, c.index(), j)) delaunay.insert(j);
    INFO("cell " << c.index());
    CHECK(tissue_neighbours == delaunay);
  }
  CHECK(interior >= 5);
}

// Cell c's vertex positions, sorted.
std::vector<std::array<double, 3>> cellPoints(const Tissue& t, CellId c) {
  std::vector<std::array<double, 3>> points;
  for (VertexId v : t.cellVertices(c)) points.push_back({t.position(v).x(), t.position(v).y(), t.position(v).z()});
  std::sort(points.begin(), points.end());
  return points;
}

TEST_CASE("3D Voronoi cells of a few hundred seeds: volumes, Delaunay neighbours, any seed order",
          "[voronoi][voronoi3d]") {
  // The generator works along CGAL's spatial order of the seeds and maps back
  // to cell k = seed k: listing the same seeds in another order must give the
  // same cells (volumes, vertices, neighbours), renumbered.
  const Box box{Vec3(0, 0, 0), Vec3(2, 1, 1.5)};
  const std::size_t n = 400;
  const auto seeds = randomSeeds(box, n, 31);
  const Tissue t = voronoiTissue(seeds, box);
  const auto report = validate(t);
  INFO(report.message);
  REQUIRE(report.ok);
  REQUIRE(t.numCells() == n);
  double total = 0;
  for (CellId c : t.cells()) total += cellMeasure(t, c);
  CHECK(total == Approx(2 * 1 * 1.5).epsilon(1e-12));

  int interior = 0;
  for (CellId c : t.cells()) {
    const auto walls = t.cellWalls(c);
    if (std::any_of(walls.begin(), walls.end(), [&](WallId w) { return t.isBoundaryWall(w); })) continue;
    ++interior;
    std::set<std::size_t> tissue_neighbours, delaunay;
    for (CellId d : t.cellNeighbors(c)) tissue_neighbours.insert(d.index());
    for (std::size_t j = 0; j < n; ++j)
      if (j != c.index() && delaunayNeighbours(seeds, c.index(), j)) delaunay.insert(j);
    INFO("cell " << c.index());
    CHECK(tissue_neighbours == delaunay);
  }
  CHECK(interior >= 50);

  // Seed m of the permuted list is seed perm[m] (137 is prime to 400).
  std::vector<std::size_t> perm(n);
  std::vector<Vec3> permuted(n);
  for (std::size_t m = 0; m < n; ++m) {
    perm[m] = (m * 137 + 11) % n;
    permuted[m] = seeds[perm[m]];
  }
  const Tissue u = voronoiTissue(permuted, box);
  REQUIRE(validate(u).ok);
  REQUIRE(u.numVertices() == t.numVertices());
  REQUIRE(u.numWalls() == t.numWalls());
  for (std::size_t m = 0; m < n; ++m) {
    const CellId cu(static_cast<Index>(m)), ct(static_cast<Index>(perm[m]));
    INFO("permuted cell " << m << " = cell " << perm[m]);
    CHECK(cellMeasure(u, cu) == Approx(cellMeasure(t, ct)).epsilon(1e-12));
    std::set<std::size_t> nu, nt;
    for (CellId d : u.cellNeighbors(cu)) nu.insert(perm[d.index()]);
    for (CellId d : t.cellNeighbors(ct)) nt.insert(d.index());
    CHECK(nu == nt);
    const auto pu = cellPoints(u, cu), pt = cellPoints(t, ct);
    REQUIRE(pu.size() == pt.size());
    double worst = 0;
    for (std::size_t k = 0; k < pu.size(); ++k)
      for (int a = 0; a < 3; ++a) worst = std::max(worst, std::abs(pu[k][a] - pt[k][a]));
    CHECK(worst <= 1e-12);
  }
}

TEST_CASE("3D Voronoi tissue in a ball fills its icosahedron", "[voronoi][voronoi3d]") {
  Ball ball;
  ball.center = Vec3(1, 2, 3);
  ball.radius = 2;
  ball.subdivisions = 0;  // a regular icosahedron inscribed in the sphere
  const auto seeds = randomSeeds(ball, 100, 8);
  const Tissue t = voronoiTissue(seeds, ball);
  const auto report = validate(t);
  INFO(report.message);
  REQUIRE(report.ok);
  // Circumradius R = a sin(2 pi / 5) for edge a; volume 5/12 (3 + sqrt 5) a^3.
  const double a = ball.radius / std::sin(2 * std::numbers::pi / 5);
  const double volume = 5.0 / 12 * (3 + std::sqrt(5.0)) * a * a * a;
  CHECK(totalMeasure(t) == Approx(volume).epsilon(1e-12));
  for (CellId c : t.cells()) CHECK(cellContains(t, c, seeds[c.index()], 1e-12));
  for (VertexId v : t.vertices())
    CHECK((t.position(v) - ball.center).norm() <= ball.radius * (1 + 1e-12));

  ball.subdivisions = 2;
  const Tissue fine = voronoiTissue(randomSeeds(ball, 100, 8), ball);
  REQUIRE(validate(fine).ok);
  const double sphere = 4.0 / 3 * std::numbers::pi * 8;
  // Inscribed polyhedra: finer ones enclose more, all less than the sphere.
  CHECK(totalMeasure(fine) < sphere);
  CHECK(totalMeasure(fine) > volume);
  CHECK(totalMeasure(fine) > 0.95 * sphere);
}

// Cospherical seeds (cubic lattices): test_voronoi_bulk.cpp.

TEST_CASE("3D Voronoi tissues are reproducible from the rng seed", "[voronoi][voronoi3d]") {
  const Box box;
  const Tissue a = voronoiTissue(randomSeeds(box, 60, 5), box);
  const Tissue b = voronoiTissue(randomSeeds(box, 60, 5), box);
  REQUIRE(a.numVertices() == b.numVertices());
  REQUIRE(a.numFaces() == b.numFaces());
  bool same = true;
  for (VertexId v : a.vertices()) same &= a.position(v) == b.position(v);
  for (FaceId f : a.faces()) {
    const auto la = a.topology().faceVertices(f), lb = b.topology().faceVertices(f);
    same &= std::equal(la.begin(), la.end(), lb.begin(), lb.end());
  }
  CHECK(same);
}

TEST_CASE("bad 3D seeds raise InputError naming the seed", "[voronoi][voronoi3d][errors]") {
  const Box box;
  const std::vector<Vec3> seeds = {{0.1, 0.1, 0.1}, {0.9, 0.2, 0.3}, {0.5, 0.8, 0.2},
                                   {0.3, 0.4, 0.9}, {0.6, 0.6, 0.6}};
  auto dup = seeds;
  dup.push_back(seeds[2]);
  CHECK_THAT(errorOf([&] { voronoiTissue(dup, box); }),
             Catch::Contains("seed 2 ") && Catch::Contains("seed 5 "));

  const std::vector<Vec3> flat = {{0.1, 0.1, 0.5}, {0.9, 0.2, 0.5}, {0.5, 0.8, 0.5}, {0.3, 0.4, 0.5}};
  CHECK_THAT(errorOf([&] { voronoiTissue(flat, box); }), Catch::Contains("coplanar"));

  CHECK_THAT(errorOf([&] { voronoiTissue(std::vector<Vec3>(seeds.begin(), seeds.begin() + 3), box); }),
             Catch::Contains("at least 4 seeds"));

  auto outside = seeds;
  outside[4] = Vec3(0.5, 0.5, -0.25);
  CHECK_THAT(errorOf([&] { voronoiTissue(outside, box); }),
             Catch::Contains("seed 4 at (0.5, 0.5, -0.25)") && Catch::Contains("outside"));

  auto inf = seeds;
  inf[0].x() = INFINITY;
  CHECK_THAT(errorOf([&] { voronoiTissue(inf, box); }), Catch::Contains("seed 0 "));

  Ball ball;
  ball.subdivisions = 0;
  auto in_sphere_not_polyhedron = seeds;
  in_sphere_not_polyhedron[1] = Vec3(0, 0, 0.99);  // beyond the icosahedron's face
  for (Vec3& s : in_sphere_not_polyhedron) s.head<2>() *= 0.1;
  CHECK_THAT(errorOf([&] { voronoiTissue(in_sphere_not_polyhedron, ball); }),
             Catch::Contains("seed 1 ") && Catch::Contains("20 faces"));
}

TEST_CASE("Lloyd relaxation evens out 3D cell volumes", "[voronoi][voronoi3d][lloyd]") {
  const Box box;
  const auto seeds = randomSeeds(box, 100, 2);
  VoronoiOptions relaxed;
  relaxed.lloyd_iterations = 8;
  const Tissue raw = voronoiTissue(seeds, box);
  const Tissue smooth = voronoiTissue(seeds, box, relaxed);
  REQUIRE(validate(smooth).ok);
  CHECK(totalMeasure(smooth) == Approx(1.0).epsilon(1e-12));
  std::vector<double> before, after;
  for (CellId c : raw.cells()) before.push_back(cellMeasure(raw, c));
  for (CellId c : smooth.cells()) after.push_back(cellMeasure(smooth, c));
  INFO("CV before " << coefficientOfVariation(before) << " after " << coefficientOfVariation(after));
  CHECK(coefficientOfVariation(after) < 0.6 * coefficientOfVariation(before));
}

TEST_CASE("nearly cospherical seeds (a jittered grid) give a valid tissue or a GeometryError",
          "[voronoi][voronoi3d][degenerate]") {
  // Exact grids and clearly perturbed ones must work. Between (jitter near
  // the weld tolerance, 1e-10 of the domain size) the two cells of a wall
  // can see different slivers; the generator must then refuse with a
  // GeometryError naming the seeds, never return a broken tissue.
  int refused = 0;
  for (double jitter : {0.0, 1e-13, 1e-11, 1e-10, 1e-9, 1e-7, 1e-5}) {
    for (std::uint64_t rng = 0; rng < 3; ++rng) {
      const int n = 4;
      const auto noise = randomSeeds(Box{Vec3::Constant(-1), Vec3::Constant(1)}, n * n * n, rng);
      std::vector<Vec3> seeds;
      for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
          for (int i = 0; i < n; ++i)
            seeds.push_back(Vec3((i + 0.5) / n, (j + 0.5) / n, (k + 0.5) / n) +
                            jitter * noise[seeds.size()]);
      INFO("jitter " << jitter << " rng " << rng);
      try {
        const Tissue t = voronoiTissue(seeds, Box{});
        const auto report = validate(t);
        INFO(report.message);
        REQUIRE(report.ok);
        CHECK(totalMeasure(t) == Approx(1.0).epsilon(1e-12));
      } catch (const GeometryError& e) {
        if (jitter == 0.0 || jitter >= 1e-7) FAIL(e.what());
        ++refused;
      }
    }
  }
  WARN("jittered 3D grids refused with GeometryError: " << refused << " of 15 near-degenerate runs");
}
