// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// 3D tissues -> TetGen tetrahedra: measures, region tags, conformity, quality,
// non-planar walls, non-convex cells, bad geometry.

#include <catch2/catch.hpp>
#include <omp.h>

#include <cmath>

#include "mesh_test_support.hpp"
#include "tessella/mesh/geometry_check.hpp"
#include "tessella/mesh/mesh_tissue.hpp"
#include "tessella/tissue/builders.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/generators/grids.hpp"
#include "tessella/generators/voronoi.hpp"

using namespace tessella;
using namespace tessella::mesh;
using namespace tessella::test;

namespace {

/// The 6 outward faces of the box [lo, hi] with corner vertices base..base+7.
void addBox(std::vector<Vec3>& p, std::vector<std::vector<Index>>& faces, std::vector<std::vector<CellFace>>& cells,
            const Vec3& lo, const Vec3& hi, bool inside_out = false) {
  const Index b = static_cast<Index>(p.size());
  for (int z = 0; z < 2; ++z)
    for (const auto& [x, y] : {std::pair{0, 0}, {1, 0}, {1, 1}, {0, 1}})
      p.emplace_back(x ? hi.x() : lo.x(), y ? hi.y() : lo.y(), z ? hi.z() : lo.z());
  const Index f = static_cast<Index>(faces.size());
  faces.push_back({b + 0, b + 3, b + 2, b + 1});
  faces.push_back({b + 4, b + 5, b + 6, b + 7});
  faces.push_back({b + 0, b + 1, b + 5, b + 4});
  faces.push_back({b + 1, b + 2, b + 6, b + 5});
  faces.push_back({b + 2, b + 3, b + 7, b + 6});
  faces.push_back({b + 3, b + 0, b + 4, b + 7});
  std::vector<CellFace> cell;
  for (Index k = 0; k < 6; ++k) cell.push_back({f + k, inside_out});
  cells.push_back(cell);
}

void requireRadiusEdge(const FeMesh& mesh, double bound) {
  double worst = 0;
  for (int e = 0; e < mesh.numElements(); ++e) worst = std::max(worst, tetRadiusEdgeRatio(mesh, e));
  INFO("worst radius-edge ratio " << worst);
  CHECK(worst <= bound * (1 + 1e-6));
}

const char* methodName(VolumeMethod m) { return m == VolumeMethod::CellByCell ? "cell_by_cell" : "whole_tissue"; }

/// Smallest angle (degrees) of wall facet f and its longest edge.
std::pair<double, double> facetShape(const FeMesh& mesh, int f) {
  double smallest = 180, longest = 0;
  for (int k = 0; k < 3; ++k) {
    const Vec3 a = mesh.nodes.row(mesh.wall_facets(f, k)).transpose();
    const Vec3 b = mesh.nodes.row(mesh.wall_facets(f, (k + 1) % 3)).transpose();
    const Vec3 c = mesh.nodes.row(mesh.wall_facets(f, (k + 2) % 3)).transpose();
    smallest = std::min(smallest, std::atan2((b - a).cross(c - a).norm(), (b - a).dot(c - a)) * 180.0 / M_PI);
    longest = std::max(longest, (b - a).norm());
  }
  return {smallest, longest};
}

}  // namespace

TEST_CASE("box grid: every tetrahedron in its cell, exact volumes, quality", "[mesh][volume]") {
  const VolumeMethod method = GENERATE(VolumeMethod::CellByCell, VolumeMethod::WholeTissue);
  INFO(methodName(method));
  const Tissue t = boxGrid(3, 2, 2, 1.0, 1.5, 0.8);
  MeshOptions o;
  o.volume_method = method;
  o.max_volume = 0.02;
  o.radius_edge_ratio = 1.5;
  const FeMesh mesh = meshTissue(t, o);
  CHECK(mesh.dim == 3);
  requireMeasuresMatch(t, mesh);
  for (CellId c : t.cells()) CHECK(relativelyClose(cellMeasuresOfMesh(mesh, t.cellSlots())[c.index()], 1.2));
  requireConforming(mesh);
  requireWallsMatch(t, mesh);
  requireRadiusEdge(mesh, o.radius_edge_ratio);
  for (int e = 0; e < mesh.numElements(); ++e) CHECK(elementMeasure(mesh, e) <= o.max_volume * (1 + 1e-9));
}

TEST_CASE("non-planar walls are meshed as their fan surfaces", "[mesh][volume]") {
  // Two stacked cubes whose shared wall has one raised, displaced corner:
  // four walls become non-planar.
  std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1},
                         {1.1, 1.05, 1.3}, {0, 1, 1}, {0, 0, 2}, {1, 0, 2}, {1, 1, 2}, {0, 1, 2}};
  const std::vector<std::vector<Index>> faces = {
      {0, 3, 2, 1}, {4, 5, 6, 7}, {8, 9, 10, 11},                      // bottom, middle, top
      {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7},           // lower sides
      {4, 5, 9, 8}, {5, 6, 10, 9}, {6, 7, 11, 10}, {7, 4, 8, 11}};      // upper sides
  const std::vector<std::vector<CellFace>> cells = {
      {{0, false}, {1, false}, {3, false}, {4, false}, {5, false}, {6, false}},
      {{1, true}, {2, false}, {7, false}, {8, false}, {9, false}, {10, false}}};
  const Tissue t = buildPolyhedralTissue(p, faces, cells);
  const VolumeMethod method = GENERATE(VolumeMethod::CellByCell, VolumeMethod::WholeTissue);
  INFO(methodName(method));
  const FeMesh mesh = meshTissue(t, MeshOptions{.max_volume = 0.01, .volume_method = method});
  requireGoodMesh(t, mesh);
  // The fan centres of the non-planar walls are mesher nodes, not tissue vertices.
  CHECK((mesh.node_vertex.array() < 0).count() >= 4);
}

TEST_CASE("a non-convex cell whose centroid lies outside it", "[mesh][volume]") {
  // A U-shaped prism: the centroid (1.5, 1.40, 0.5) is in the notch.
  std::vector<Vec3> p;
  const std::vector<std::pair<double, double>> u = {{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 0.5}, {1, 0.5}, {1, 3}, {0, 3}};
  for (double z : {0.0, 1.0})
    for (const auto& [x, y] : u) p.emplace_back(x, y, z);
  std::vector<std::vector<Index>> faces;
  faces.push_back({7, 6, 5, 4, 3, 2, 1, 0});        // bottom, outward -z
  faces.push_back({8, 9, 10, 11, 12, 13, 14, 15});  // top
  for (Index i = 0; i < 8; ++i) faces.push_back({i, (i + 1) % 8, (i + 1) % 8 + 8, i + 8});
  std::vector<CellFace> cell;
  for (Index f = 0; f < 10; ++f) cell.push_back({f, false});
  const Tissue t = buildPolyhedralTissue(p, faces, {cell});
  REQUIRE(relativelyClose(cellMeasure(t, CellId(0)), 6.5));
  const VolumeMethod method = GENERATE(VolumeMethod::CellByCell, VolumeMethod::WholeTissue);
  INFO(methodName(method));
  const FeMesh mesh = meshTissue(t, MeshOptions{.max_volume = 0.05, .volume_method = method});
  requireGoodMesh(t, mesh);
  CHECK(relativelyClose(totalMeasureOfMesh(mesh), 6.5));
}

TEST_CASE("a cell enclosing another: the inner cell is a cavity of the outer one", "[mesh][volume]") {
  std::vector<Vec3> p;
  std::vector<std::vector<Index>> faces;
  std::vector<std::vector<CellFace>> cells;
  addBox(p, faces, cells, Vec3(0, 0, 0), Vec3(3, 3, 3));
  addBox(p, faces, cells, Vec3(1, 1.2, 0.9), Vec3(2, 2, 2));
  for (Index f = 6; f < 12; ++f) cells[0].push_back({f, true});  // the inner box's walls, seen from outside
  const Tissue t = buildPolyhedralTissue(p, faces, cells);
  REQUIRE(relativelyClose(cellMeasure(t, CellId(0)), 27.0 - 0.88));
  const VolumeMethod method = GENERATE(VolumeMethod::CellByCell, VolumeMethod::WholeTissue);
  INFO(methodName(method));
  const FeMesh mesh = meshTissue(t, MeshOptions{.max_volume = 0.1, .volume_method = method});
  requireGoodMesh(t, mesh);
  CHECK(relativelyClose(totalMeasureOfMesh(mesh), 27.0));
}

TEST_CASE("cell by cell: wall triangles honour the size and angle bounds, the walls conform", "[mesh][volume]") {
  const Tissue t = boxGrid(2, 2, 1, 1.0, 0.7, 1.3);
  MeshOptions o;
  o.max_edge_length = 0.25;
  o.min_angle_degrees = 28;
  o.max_volume = 0.01;
  const FeMesh mesh = meshTissue(t, o);
  requireGoodMesh(t, mesh);
  double smallest = 180, longest = 0;
  for (int f = 0; f < mesh.numWallFacets(); ++f) {
    const auto [angle, edge] = facetShape(mesh, f);
    smallest = std::min(smallest, angle);
    longest = std::max(longest, edge);
  }
  CHECK(smallest >= 28.0 - 1e-9);  // a box has no input angle below 90 degrees
  CHECK(longest <= 0.25 * (1 + 1e-9));
  for (int e = 0; e < mesh.numElements(); ++e) CHECK(elementMeasure(mesh, e) <= o.max_volume * (1 + 1e-9));
}

TEST_CASE("cell by cell: the mesh does not depend on the thread count", "[mesh][volume][voronoi]") {
  const Box box{Vec3(0, 0, 0), Vec3(2, 2, 1)};
  const Tissue t = voronoiTissue(randomSeeds(box, 30, 5), box);
  REQUIRE(findGeometryDefects(t).ok);
  const MeshOptions o{.max_volume = 0.01};
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const FeMesh one = meshTissue(t, o);
  omp_set_num_threads(2);
  const FeMesh two = meshTissue(t, o);
  omp_set_num_threads(threads);
  requireGoodMesh(t, two);
  CHECK(one.nodes == two.nodes);
  CHECK(one.elements == two.elements);
  CHECK(one.element_cell == two.element_cell);
  CHECK(one.wall_facets == two.wall_facets);
  CHECK(one.facet_wall == two.facet_wall);
}

TEST_CASE("bad 3D geometry is reported before TetGen runs", "[mesh][volume][errors]") {
  std::vector<Vec3> p;
  std::vector<std::vector<Index>> faces;
  std::vector<std::vector<CellFace>> cells;
  SECTION("an inverted cell") {
    addBox(p, faces, cells, Vec3(0, 0, 0), Vec3(1, 1, 1));
    addBox(p, faces, cells, Vec3(2, 0, 0), Vec3(3, 1, 1), true);
    const Tissue t = buildPolyhedralTissue(p, faces, cells);
    try {
      meshTissue(t);
      FAIL("no error");
    } catch (const GeometryError& e) {
      CHECK_THAT(e.what(), Catch::Contains("cell 1") && Catch::Contains("inverted"));
      CHECK(e.element().index == 1);
    }
  }
  SECTION("overlapping cells") {
    addBox(p, faces, cells, Vec3(0, 0, 0), Vec3(1, 1, 1));
    addBox(p, faces, cells, Vec3(0.5, 0.5, 0.5), Vec3(1.5, 1.5, 1.5));
    const Tissue t = buildPolyhedralTissue(p, faces, cells);
    try {
      meshTissue(t);
      FAIL("no error");
    } catch (const GeometryError& e) {
      CHECK_THAT(e.what(), Catch::Contains("walls") && Catch::Contains("intersect"));
    }
  }
  SECTION("a flat (zero-volume) cell") {
    addBox(p, faces, cells, Vec3(0, 0, 0), Vec3(1, 1, 1e-14));
    const Tissue t = buildPolyhedralTissue(p, faces, cells);
    const MeshabilityReport r = findGeometryDefects(t);
    CHECK_FALSE(r.ok);
    CHECK_THAT(r.message, Catch::Contains("zero"));
    CHECK_THROWS_AS(meshTissue(t), GeometryError);
  }
  SECTION("a wall folded through its neighbour") {
    // Two stacked cubes whose shared wall's corner dips through the bottom.
    addBox(p, faces, cells, Vec3(0, 0, 0), Vec3(1, 1, 1));
    p[4] = Vec3(0.3, 0.3, -0.5);  // the top corner of the lower cube pokes through its bottom wall
    const Tissue t = buildPolyhedralTissue(p, faces, cells);
    const MeshabilityReport r = findGeometryDefects(t);
    CHECK_FALSE(r.ok);
    INFO(r.message);
    CHECK_THROWS_AS(meshTissue(t), GeometryError);
  }
}

TEST_CASE("cell by cell: a cell that cannot be meshed in time fails at the time limits, naming it and every try",
          "[mesh][volume][errors]") {
  // Two unit cubes with a volume bound of 2e-7: millions of tetrahedra each, far more than TetGen makes in the
  // limits below, so every try of every cell is stopped (docs/meshing.md, "Time limits").
  const Tissue t = boxGrid(2, 1, 1, 1.0, 1.0, 1.0);
  MeshOptions o;
  o.max_volume = 2e-7;
  o.max_edge_length = 0.25;  // coarse walls: the time goes to TetGen
  SECTION("the cell's limit: try k may run for 1/2^(k+1) of it, the last as long as the one before") {
    o.cell_time_limit = 0.2;
    try {
      meshTissue(t, o);
      FAIL("no error");
    } catch (const GeometryError& e) {
      INFO(e.what());
      CHECK(e.element().index == 0);
      CHECK_THAT(e.what(), Catch::Contains("could not mesh cell 0 (2 cells failed)"));
      CHECK_THAT(e.what(), Catch::Contains("0.2 s per cell, mesh.cell_time_limit"));
      // The seven tries, in turn: 0.1, 0.05, 0.025, 0.0125, 0.00625, 0.003125 and 0.003125 s (adding up to 0.2).
      CHECK_THAT(e.what(), Catch::Contains("T1e-7q1.5a2e-07 in a cube: did not finish within 0.1 s; "
                                           "switches pYzAQT1e-7q1.5a2e-07: did not finish within 0.05 s"));
      CHECK_THAT(e.what(), Catch::Contains("pYzAQq1.5a2e-07: did not finish within 0.025 s"));
      CHECK_THAT(e.what(), Catch::Contains("pYzAQT1e-9q1.5a2e-07: did not finish within 0.0125 s"));
      CHECK_THAT(e.what(), Catch::Contains("pYzAQT1e-6q1.5a2e-07: did not finish within 0.00625 s"));
      CHECK_THAT(e.what(), Catch::Contains("pYzAQT1e-7q1.5a2e-07 in a cube turned: did not finish within 0.00313 s; "
                                           "switches pYzAQT1e-7q1.5a2e-07 turned: did not finish within 0.00313 s"));
    }
  }
  SECTION("the mesh's limit: the runs going are stopped, no other try starts") {
    o.cell_time_limit = 0;  // none
    o.time_limit = 0.3;
    try {
      meshTissue(t, o);
      FAIL("no error");
    } catch (const GeometryError& e) {
      INFO(e.what());
      CHECK_THAT(e.what(), Catch::Contains("could not mesh cell 0 (2 cells failed)"));
      CHECK_THAT(e.what(), Catch::Contains("none per cell, mesh.cell_time_limit; 0.3 s per mesh, mesh.time_limit"));
      CHECK_THAT(e.what(), Catch::Contains("at the time limit of the run (0.3 s)"));
      CHECK_THAT(e.what(), Catch::Contains("not tried: switches pYzAQT1e-6q1.5a2e-07 (the time limit of the mesh "
                                           "was spent)"));
    }
  }
}
