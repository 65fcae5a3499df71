// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// 2D Voronoi tissues: validity, exact tiling of the domain, the Voronoi
// property of cells and walls, Delaunay adjacency (checked by brute force,
// independently of CGAL), degenerate seeds, errors and Lloyd relaxation.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/tissue/validate.hpp"
#include "tessella/generators/voronoi.hpp"

using namespace tessella;

namespace {

// Is p inside the (convex, counter-clockwise) loop of cell c, up to tol?
bool cellContains(const Tissue& t, CellId c, const Vec3& p, double tol) {
  const auto loop = t.topology().faceVertices(t.cellFace(c));
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const Vec3& a = t.position(loop[k]);
    const Vec3& b = t.position(loop[(k + 1) % loop.size()]);
    const double cross = (b.x() - a.x()) * (p.y() - a.y()) - (b.y() - a.y()) * (p.x() - a.x());
    if (cross < -tol * (b - a).norm()) return false;
  }
  return true;
}

// Brute-force Delaunay adjacency: seeds i and j are Delaunay neighbours iff
// part of their bisector (of positive length) is closer to them than to any
// other seed. The bisector is m + u d; every other seed k bounds u.
bool delaunayNeighbours(const std::vector<Vec3>& seeds, std::size_t i, std::size_t j) {
  const Vec3 m = (seeds[i] + seeds[j]) / 2;
  const Vec3 d(-(seeds[j] - seeds[i]).y(), (seeds[j] - seeds[i]).x(), 0);
  double lo = -1e300, hi = 1e300;
  for (std::size_t k = 0; k < seeds.size(); ++k) {
    if (k == i || k == j) continue;
    // closer to i than to k:  (x - (si+sk)/2) . (sk - si) <= 0
    const Vec3 n = seeds[k] - seeds[i];
    const double a = d.dot(n), b = ((seeds[i] + seeds[k]) / 2 - m).dot(n);
    if (std::abs(a) < 1e-300) {
      if (b < 0) return false;
      continue;
    }
    if (a > 0) hi = std::min(hi, b / a);
    else lo = std::max(lo, b / a);
  }
  return hi - lo > 1e-9;
}

double coefficientOfVariation(const std::vector<double>& v) {
  double mean = 0, var = 0;
  for (double x : v) mean += x;
  mean /= v.size();
  for (double x : v) var += (x - mean) * (x - mean);
  return std::sqrt(var / v.size()) / mean;
}

std::vector<double> cellAreas(const Tissue& t) {
  std::vector<double> a;
  for (CellId c : t.cells()) a.push_back(cellMeasure(t, c));
  return a;
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

TEST_CASE("random 2D Voronoi tissue in a rectangle tiles it and has the Voronoi property",
          "[voronoi][voronoi2d]") {
  const Rectangle rect{Vec3(-1, 2, 0), Vec3(3, 4.5, 0)};
  const auto seeds = randomSeeds(rect, 300, 42);
  const Tissue t = voronoiTissue(seeds, rect);

  const auto report = validate(t);
  INFO(report.message);
  REQUIRE(report.ok);
  REQUIRE(t.numCells() == seeds.size());
  REQUIRE(t.embedding() == Embedding::Planar);
  CHECK(totalMeasure(t) == Approx(4.0 * 2.5).epsilon(1e-12));

  for (CellId c : t.cells()) {
    INFO("cell " << c.index());
    CHECK(cellContains(t, c, seeds[c.index()], 1e-12));
    for (VertexId v : t.cellVertices(c)) {
      const Vec3& p = t.position(v);
      CHECK(p.z() == 0);
      CHECK(p.x() >= rect.min.x());
      CHECK(p.x() <= rect.max.x());
      CHECK(p.y() >= rect.min.y());
      CHECK(p.y() <= rect.max.y());
    }
  }
  // Every vertex of a wall between cells i and j is equidistant from seeds i
  // and j, and no seed is closer.
  for (WallId w : t.walls()) {
    const auto cells = t.wallCells(w);
    if (cells.size() != 2) continue;
    const Vec3& si = seeds[cells[0].index()];
    const Vec3& sj = seeds[cells[1].index()];
    const EdgeId e = handle_cast<EdgeId>(w);
    for (VertexId v : t.topology().edgeVertices(e)) {
      const Vec3& p = t.position(v);
      const double di = (p - si).norm(), dj = (p - sj).norm();
      CHECK(di == Approx(dj).margin(1e-10));
      for (const Vec3& s : seeds) CHECK((p - s).norm() >= di - 1e-10);
    }
  }
}

TEST_CASE("2D Voronoi neighbours are the Delaunay neighbours for interior cells",
          "[voronoi][voronoi2d]") {
  const Rectangle rect;
  const auto seeds = randomSeeds(rect, 80, 7);
  const Tissue t = voronoiTissue(seeds, rect);
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
  CHECK(interior > 20);
}

TEST_CASE("2D Voronoi tissue in a disk tiles the documented boundary polygon",
          "[voronoi][voronoi2d]") {
  Disk disk;
  disk.center = Vec3(0.5, -2, 0);
  disk.radius = 3;
  disk.boundary_segments = 64;
  const auto seeds = randomSeeds(disk, 400, 3);
  const Tissue t = voronoiTissue(seeds, disk);
  const auto report = validate(t);
  INFO(report.message);
  REQUIRE(report.ok);
  const double polygon_area = 64 / 2.0 * 9 * std::sin(2 * std::numbers::pi / 64);
  CHECK(totalMeasure(t) == Approx(polygon_area).epsilon(1e-12));
  for (CellId c : t.cells()) CHECK(cellContains(t, c, seeds[c.index()], 1e-12));
  for (VertexId v : t.vertices())
    CHECK((t.position(v) - disk.center).norm() <= disk.radius * (1 + 1e-12));
}

TEST_CASE("cocircular seeds of a regular grid give square cells without zero-length edges",
          "[voronoi][voronoi2d]") {
  const int n = 6;
  std::vector<Vec3> seeds;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) seeds.emplace_back((i + 0.5) / n, (j + 0.5) / n, 0);
  const Tissue t = voronoiTissue(seeds, Rectangle{});
  const auto report = validate(t);
  INFO(report.message);
  REQUIRE(report.ok);
  CHECK(t.numVertices() == static_cast<std::size_t>((n + 1) * (n + 1)));
  CHECK(t.numEdges() == static_cast<std::size_t>(2 * n * (n + 1)));
  for (CellId c : t.cells()) {
    CHECK(t.cellVertices(c).size() == 4);
    CHECK(cellMeasure(t, c) == Approx(1.0 / (n * n)).epsilon(1e-12));
  }
  for (EdgeId e : t.edges()) CHECK(edgeLength(t, e) == Approx(1.0 / n).epsilon(1e-9));
}

TEST_CASE("a Voronoi vertex on the domain boundary and a wall through a corner are snapped",
          "[voronoi][voronoi2d]") {
  // Seeds 0, 1, 2 have their circumcentre at (0.5, 0) up to rounding; seeds
  // 3 and 4 are mirror images across the diagonal through corner (1, 1).
  const std::vector<Vec3> seeds = {{0.25, 0.25, 0}, {0.75, 0.25, 0}, {0.5, std::sqrt(0.125), 0},
                                   {0.6, 0.9, 0},   {0.9, 0.6, 0},   {0.2, 0.8, 0}};
  const Tissue t = voronoiTissue(seeds, Rectangle{});
  const auto report = validate(t);
  INFO(report.message);
  REQUIRE(report.ok);
  CHECK(totalMeasure(t) == Approx(1.0).epsilon(1e-12));
  for (EdgeId e : t.edges()) CHECK(edgeLength(t, e) > 1e-6);
  // The corner (1, 1) is one vertex shared by the cells of seeds 3 and 4.
  int corner_vertices = 0;
  for (VertexId v : t.vertices())
    if ((t.position(v) - Vec3(1, 1, 0)).norm() < 1e-9) ++corner_vertices;
  CHECK(corner_vertices == 1);
}

TEST_CASE("2D Voronoi tissues are reproducible from the rng seed", "[voronoi][voronoi2d]") {
  Disk disk;
  const Tissue a = voronoiTissue(randomSeeds(disk, 120, 99), disk);
  const Tissue b = voronoiTissue(randomSeeds(disk, 120, 99), disk);
  const Tissue c = voronoiTissue(randomSeeds(disk, 120, 100), disk);
  REQUIRE(a.numVertices() == b.numVertices());
  REQUIRE(a.numCells() == b.numCells());
  bool same = true;
  for (VertexId v : a.vertices()) same &= a.position(v) == b.position(v);
  for (CellId cell : a.cells()) {
    const auto la = a.topology().faceVertices(a.cellFace(cell));
    const auto lb = b.topology().faceVertices(b.cellFace(cell));
    same &= std::equal(la.begin(), la.end(), lb.begin(), lb.end());
  }
  CHECK(same);
  CHECK(a.position(VertexId(0)) != c.position(VertexId(0)));
}

TEST_CASE("bad 2D seeds raise InputError naming the seed", "[voronoi][voronoi2d][errors]") {
  const Rectangle rect;
  std::vector<Vec3> seeds = {{0.1, 0.1, 0}, {0.9, 0.2, 0}, {0.5, 0.8, 0}, {0.3, 0.4, 0}};

  auto dup = seeds;
  dup.push_back({0.9, 0.2, 0});
  const std::string exact = errorOf([&] { voronoiTissue(dup, rect); });
  CHECK_THAT(exact, Catch::Contains("seed 1 ") && Catch::Contains("seed 4 ") &&
                        Catch::Contains("duplicate"));

  auto near = seeds;
  near.push_back({0.3 + 1e-13, 0.4, 0});
  CHECK_THAT(errorOf([&] { voronoiTissue(near, rect); }),
             Catch::Contains("seed 3 ") && Catch::Contains("seed 4 "));

  const std::vector<Vec3> line = {{0.1, 0.1, 0}, {0.2, 0.2, 0}, {0.3, 0.3, 0}, {0.7, 0.7, 0}};
  CHECK_THAT(errorOf([&] { voronoiTissue(line, rect); }),
             Catch::Contains("collinear") && Catch::Contains("seed 0 ") && Catch::Contains("seed 3 "));

  CHECK_THAT(errorOf([&] { voronoiTissue(std::vector<Vec3>(seeds.begin(), seeds.begin() + 2), rect); }),
             Catch::Contains("at least 3 seeds"));

  auto outside = seeds;
  outside[2] = Vec3(0.5, 1.25, 0);
  CHECK_THAT(errorOf([&] { voronoiTissue(outside, rect); }),
             Catch::Contains("seed 2 at (0.5, 1.25, 0)") && Catch::Contains("outside"));

  auto nan = seeds;
  nan[3].y() = std::nan("");
  CHECK_THAT(errorOf([&] { voronoiTissue(nan, rect); }),
             Catch::Contains("seed 3 ") && Catch::Contains("non-finite"));

  auto lifted = seeds;
  lifted[1].z() = 0.5;
  CHECK_THAT(errorOf([&] { voronoiTissue(lifted, rect); }), Catch::Contains("seed 1 "));

  // A seed inside the circle but outside its 8-gon boundary polygon.
  Disk coarse;
  coarse.boundary_segments = 8;
  const std::vector<Vec3> in_circle = {{0, 0, 0}, {0.5, 0, 0}, {0, 0.5, 0},
                                       {0.99 * std::cos(0.39), 0.99 * std::sin(0.39), 0}};
  CHECK_THAT(errorOf([&] { voronoiTissue(in_circle, coarse); }),
             Catch::Contains("seed 3 ") && Catch::Contains("8 segments"));

  CHECK_THAT(errorOf([&] { voronoiTissue(seeds, Rectangle{Vec3(1, 0, 0), Vec3(0, 1, 0)}); }),
             Catch::Contains("rectangle"));
  VoronoiOptions bad;
  bad.lloyd_iterations = -1;
  CHECK_THAT(errorOf([&] { voronoiTissue(seeds, rect, bad); }), Catch::Contains("lloyd_iterations"));
}

TEST_CASE("seeds on the domain boundary and corners are valid", "[voronoi][voronoi2d]") {
  const std::vector<Vec3> seeds = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0, 0},
                                   {0.3, 0.6, 0}};
  const Tissue t = voronoiTissue(seeds, Rectangle{});
  const auto report = validate(t);
  INFO(report.message);
  REQUIRE(report.ok);
  CHECK(totalMeasure(t) == Approx(1.0).epsilon(1e-12));
  for (CellId c : t.cells()) CHECK(cellContains(t, c, seeds[c.index()], 1e-12));
}

TEST_CASE("Lloyd relaxation evens out 2D cell areas", "[voronoi][voronoi2d][lloyd]") {
  const Rectangle rect;
  const auto seeds = randomSeeds(rect, 200, 5);
  VoronoiOptions relaxed;
  relaxed.lloyd_iterations = 10;
  const Tissue raw = voronoiTissue(seeds, rect);
  const Tissue smooth = voronoiTissue(seeds, rect, relaxed);
  REQUIRE(validate(smooth).ok);
  CHECK(totalMeasure(smooth) == Approx(1.0).epsilon(1e-12));
  const double before = coefficientOfVariation(cellAreas(raw));
  const double after = coefficientOfVariation(cellAreas(smooth));
  INFO("CV before " << before << " after " << after);
  CHECK(after < 0.5 * before);
}

TEST_CASE("nearly cocircular seeds (a jittered grid) still give a valid tiling",
          "[voronoi][voronoi2d][degenerate]") {
  // Jitter below, at and above the weld tolerance (1e-10 of the domain size):
  // the tiny Voronoi edges are either merged or kept, never left half-merged.
  for (double jitter : {1e-13, 1e-11, 1e-10, 1e-9, 1e-7}) {
    for (std::uint64_t rng = 0; rng < 5; ++rng) {
      const int n = 8;
      const auto noise = randomSeeds(Rectangle{Vec3(-1, -1, 0), Vec3(1, 1, 0)}, n * n, rng);
      std::vector<Vec3> seeds;
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
          seeds.push_back(Vec3((i + 0.5) / n, (j + 0.5) / n, 0) + jitter * noise[j * n + i]);
      const Tissue t = voronoiTissue(seeds, Rectangle{});
      const auto report = validate(t);
      INFO("jitter " << jitter << " rng " << rng << ": " << report.message);
      REQUIRE(report.ok);
      CHECK(totalMeasure(t) == Approx(1.0).epsilon(1e-12));
      for (CellId c : t.cells()) CHECK(cellContains(t, c, seeds[c.index()], 1e-12));
    }
  }
}

namespace {

// Every vertex of every cell is at least as close to the cell's seed as to
// any other seed (searched in a grid of buckets). With the areas adding up to
// the domain's, this makes each cell exactly its seed's Voronoi cell: a
// polygon whose vertices all lie in the (convex) Voronoi cell lies inside it.
std::size_t verticesCloserToAnotherSeed(const Tissue& t, const std::vector<Vec3>& seeds, const Rectangle& r) {
  const int m = static_cast<int>(std::sqrt(static_cast<double>(seeds.size())));
  const double wx = (r.max.x() - r.min.x()) / m, wy = (r.max.y() - r.min.y()) / m;
  std::vector<std::vector<std::size_t>> bucket(static_cast<std::size_t>(m) * m);
  auto cellOf = [&](double v, double lo, double w) { return std::clamp(static_cast<int>((v - lo) / w), 0, m - 1); };
  for (std::size_t k = 0; k < seeds.size(); ++k)
    bucket[cellOf(seeds[k].y(), r.min.y(), wy) * m + cellOf(seeds[k].x(), r.min.x(), wx)].push_back(k);
  std::size_t bad = 0;
  for (CellId c : t.cells())
    for (VertexId v : t.cellVertices(c)) {
      const Vec3& p = t.position(v);
      const double own = (p - seeds[c.index()]).norm();
      const int x0 = cellOf(p.x() - own, r.min.x(), wx), x1 = cellOf(p.x() + own, r.min.x(), wx);
      const int y0 = cellOf(p.y() - own, r.min.y(), wy), y1 = cellOf(p.y() + own, r.min.y(), wy);
      bool closer = false;
      for (int y = y0; y <= y1 && !closer; ++y)
        for (int x = x0; x <= x1 && !closer; ++x)
          for (std::size_t k : bucket[y * m + x]) closer |= (p - seeds[k]).norm() < own - 1e-9;
      bad += closer;
    }
  return bad;
}

}  // namespace

TEST_CASE("large 2D Voronoi tissues (two half triangulations) are exact Voronoi tilings",
          "[voronoi][voronoi2d][split]") {
  // 10^5 seeds and more are triangulated as two halves side by side; cells
  // that cannot be certified from their half send the job to one
  // triangulation. Both must give the exact tiling.
  const Rectangle rect{Vec3(0, 0, 0), Vec3(2, 1, 0)};
  std::vector<Vec3> seeds = randomSeeds(rect, 120000, 77);
  SECTION("uniform seeds") {}
  SECTION("a big cell on the split line (not certifiable from a half)") {
    // Empty a disk around the domain's centre, where the median x falls, and
    // put one seed in its middle: its cell reaches far past the halves' margin.
    std::erase_if(seeds, [](const Vec3& s) { return (s - Vec3(1, 0.5, 0)).norm() < 0.08; });
    seeds.emplace_back(1.0, 0.5, 0);
  }
  SECTION("a lattice (cocircular seeds everywhere, also on the split line)") {
    seeds.clear();
    for (int j = 0; j < 250; ++j)
      for (int i = 0; i < 500; ++i) seeds.emplace_back((i + 0.5) / 250, (j + 0.5) / 250, 0);
  }
  const Tissue t = voronoiTissue(seeds, rect);
  const auto report = validate(t);
  INFO(report.message);
  REQUIRE(report.ok);
  REQUIRE(t.numCells() == seeds.size());
  CHECK(totalMeasure(t) == Approx(2.0).epsilon(1e-11));
  CHECK(verticesCloserToAnotherSeed(t, seeds, rect) == 0);
  std::size_t outside = 0;
  for (CellId c : t.cells()) outside += !cellContains(t, c, seeds[c.index()], 1e-12);
  CHECK(outside == 0);
}
