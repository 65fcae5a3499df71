// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Planar tissues -> CGAL triangle meshes: measures, tags, conformity, quality.

#include <catch2/catch.hpp>

#include "mesh_test_support.hpp"
#include "tessella/mesh/geometry_check.hpp"
#include "tessella/mesh/mesh_tissue.hpp"
#include "tessella/tissue/builders.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/generators/grids.hpp"
#include "tessella/generators/voronoi.hpp"
#include "tessella/tissue/geometry.hpp"

using namespace tessella;
using namespace tessella::mesh;
using namespace tessella::test;

namespace {

void requireQuality(const FeMesh& mesh, const MeshOptions& o) {
  for (int e = 0; e < mesh.numElements(); ++e) {
    INFO("triangle " << e);
    CHECK(triangleMinAngleDegrees(mesh, e) >= o.min_angle_degrees - 1e-9);
    if (o.max_edge_length > 0)
      for (int k = 0; k < 3; ++k) {
        const Eigen::Vector3d a = mesh.nodes.row(mesh.elements(e, k));
        const Eigen::Vector3d b = mesh.nodes.row(mesh.elements(e, (k + 1) % 3));
        CHECK((b - a).norm() <= o.max_edge_length * (1 + 1e-12));
      }
  }
}

void requireCounterClockwise(const FeMesh& mesh) {
  for (int e = 0; e < mesh.numElements(); ++e) {
    const Eigen::Vector3d a = mesh.nodes.row(mesh.elements(e, 0));
    const Eigen::Vector3d b = mesh.nodes.row(mesh.elements(e, 1));
    const Eigen::Vector3d c = mesh.nodes.row(mesh.elements(e, 2));
    CHECK((b - a).cross(c - a).z() > 0);
  }
}

}  // namespace

TEST_CASE("rectangular grid: conforming quality mesh with exact cell areas", "[mesh][planar]") {
  const Tissue t = rectangularGrid(4, 3, 1.0, 2.0);
  MeshOptions o;
  o.min_angle_degrees = 25.0;
  o.max_edge_length = 0.3;
  const FeMesh mesh = meshTissue(t, o);
  CHECK(mesh.dim == 2);
  requireMeasuresMatch(t, mesh);
  requireConforming(mesh);
  requireWallsMatch(t, mesh);
  requireQuality(mesh, o);
  requireCounterClockwise(mesh);
  // Size bound: no triangle can be larger than the equilateral one of side 0.3.
  CHECK(mesh.numElements() >= static_cast<int>(24.0 / (std::sqrt(3.0) / 4 * 0.09)));
}

TEST_CASE("hexagonal grid meshes cell by cell", "[mesh][planar]") {
  const Tissue t = hexagonalGrid(5, 4, 1.0);
  MeshOptions o;
  o.min_angle_degrees = 28.0;
  o.max_edge_length = 0.4;
  const FeMesh mesh = meshTissue(t, o);
  requireMeasuresMatch(t, mesh);
  requireConforming(mesh);
  requireWallsMatch(t, mesh);
  requireQuality(mesh, o);
}

TEST_CASE("each wall's facets run in order from its first vertex to its second", "[mesh][planar]") {
  // Refinement splits walls; the facets of a wall must be its pieces in
  // order: contiguous in wall_facets, the first starting at the node of the
  // wall's first vertex, each starting where the one before ended, the last
  // ending at the node of its second vertex, the points between added by the
  // mesher (node_vertex -1) and on the wall's segment.
  const Rectangle rect{Vec3::Zero(), Vec3(6, 5, 0)};
  const Tissue t = voronoiTissue(randomSeeds(rect, 30, 7), rect);
  MeshOptions o;
  o.max_edge_length = 0.2;
  const FeMesh mesh = meshTissue(t, o);
  std::vector<int> node_of(t.slots(0), -1);
  for (int n = 0; n < mesh.numNodes(); ++n)
    if (mesh.node_vertex(n) >= 0) node_of[static_cast<std::size_t>(mesh.node_vertex(n))] = n;
  std::vector<bool> done(t.slots(1), false);
  int split_walls = 0;
  for (int f = 0; f < mesh.numWallFacets();) {
    const EdgeId e(static_cast<Index>(mesh.facet_wall(f)));
    INFO("wall " << e.index() << ", facet " << f);
    REQUIRE_FALSE(done[e.index()]);  // its facets are contiguous
    done[e.index()] = true;
    const Vec3 a = t.position(t.topology().edgeFrom(e)), b = t.position(t.topology().edgeTo(e));
    CHECK(mesh.wall_facets(f, 0) == node_of[t.topology().edgeFrom(e).index()]);
    const int first = f;
    for (; f + 1 < mesh.numWallFacets() && mesh.facet_wall(f + 1) == mesh.facet_wall(f); ++f) {
      const int n = mesh.wall_facets(f, 1);
      CHECK(mesh.wall_facets(f + 1, 0) == n);
      CHECK(mesh.node_vertex(n) == -1);
      const Vec3 p = mesh.nodes.row(n).transpose();
      CHECK((p - a).cross(b - a).norm() <= 1e-12 * (b - a).squaredNorm());
      CHECK((p - a).dot(b - a) > 0);
      CHECK((p - b).dot(a - b) > 0);
    }
    CHECK(mesh.wall_facets(f, 1) == node_of[t.topology().edgeTo(e).index()]);
    split_walls += f > first;
    ++f;
  }
  for (EdgeId e : t.edges()) CHECK(done[e.index()]);
  CHECK(split_walls > 0);  // the size bound split walls (Voronoi walls are longer than 0.2)
}

TEST_CASE("without refinement the mesh is the constrained triangulation of the walls", "[mesh][planar]") {
  const Tissue t = rectangularGrid(3, 2);
  MeshOptions o;
  o.min_angle_degrees = 0.0;
  const FeMesh mesh = meshTissue(t, o);
  CHECK(mesh.numElements() == 12);  // two triangles per square, no Steiner points
  CHECK(mesh.numNodes() == 12);
  CHECK((mesh.node_vertex.array() >= 0).all());
  requireMeasuresMatch(t, mesh);
  requireConforming(mesh);
}

TEST_CASE("non-convex cells and holes between cells", "[mesh][planar]") {
  // A ring of four L-shaped and rectangular cells around an empty square hole
  // [1,2]x[1,2] inside [0,3]x[0,3]: the hole must stay empty.
  const std::vector<Vec3> p = {{0, 0, 0}, {3, 0, 0}, {3, 3, 0}, {0, 3, 0},  // 0-3 outer corners
                               {1, 1, 0}, {2, 1, 0}, {2, 2, 0}, {1, 2, 0},  // 4-7 hole corners
                               {2, 0, 0}, {3, 2, 0}, {1, 3, 0}, {0, 1, 0}}; // 8-11 on the outer sides
  const std::vector<std::vector<Index>> cells = {
      {0, 8, 5, 4, 7, 11},  // L-shaped: bottom strip plus left part, non-convex at 4
      {8, 1, 9, 6, 5},      // right strip
      {6, 9, 2, 10, 7},     // top strip
      {11, 7, 10, 3},       // left strip
  };
  const Tissue t = buildPolygonTissue(p, cells);
  MeshOptions o;
  o.max_edge_length = 0.25;
  const FeMesh mesh = meshTissue(t, o);
  requireMeasuresMatch(t, mesh);
  CHECK(relativelyClose(totalMeasureOfMesh(mesh), 8.0));  // 9 minus the hole
  requireWallsMatch(t, mesh);
  requireConforming(mesh);
  requireQuality(mesh, o);
}

TEST_CASE("bad planar geometry is reported with the cell or wall ids", "[mesh][planar][errors]") {
  SECTION("an inverted (clockwise) cell") {
    const std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}, {2, 1, 0}};
    // Cell 1 runs clockwise: it lies on top of cell 0's mirror image.
    const Tissue t = buildPolygonTissue(p, {{0, 1, 2, 3}, {1, 5, 4}});
    try {
      meshTissue(t);
      FAIL("no error");
    } catch (const GeometryError& e) {
      CHECK_THAT(e.what(), Catch::Contains("cell 1") && Catch::Contains("inverted"));
    }
  }
  SECTION("a self-intersecting (bow-tie) cell") {
    const std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    const Tissue t = buildPolygonTissue(p, {{0, 1, 2, 3}});
    CHECK_THROWS_AS(meshTissue(t), GeometryError);
    try {
      meshTissue(t);
    } catch (const GeometryError& e) {
      CHECK_THAT(e.what(), Catch::Contains("intersect") || Catch::Contains("zero area"));
    }
  }
  SECTION("overlapping cells") {
    const std::vector<Vec3> p = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0},
                                 {1, 1, 0}, {3, 1, 0}, {3, 3, 0}, {1, 3, 0}};
    const Tissue t = buildPolygonTissue(p, {{0, 1, 2, 3}, {4, 5, 6, 7}});
    try {
      meshTissue(t);
      FAIL("no error");
    } catch (const GeometryError& e) {
      CHECK_THAT(e.what(), Catch::Contains("walls (edges)") && Catch::Contains("intersect"));
    }
  }
  SECTION("a zero-length wall") {
    const std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    const Tissue t = buildPolygonTissue(p, {{0, 1, 2, 3, 4}});
    try {
      meshTissue(t);
      FAIL("no error");
    } catch (const GeometryError& e) {
      CHECK_THAT(e.what(), Catch::Contains("zero length") && Catch::Contains("vertices 1 and 2"));
    }
  }
}

TEST_CASE("mesh options are validated", "[mesh][errors]") {
  const Tissue t = rectangularGrid(1, 1);
  MeshOptions o;
  o.min_angle_degrees = 40;
  CHECK_THROWS_AS(meshTissue(t, o), InputError);
  o = {};
  o.max_edge_length = -1;
  CHECK_THROWS_AS(meshTissue(t, o), InputError);
  o = {};
  o.radius_edge_ratio = 1.0;
  CHECK_THROWS_AS(meshTissue(boxGrid(1, 1, 1), o), InputError);
  CHECK_THROWS_AS(meshVolumeTissue(t), InputError);
  CHECK_THROWS_AS(meshPlanarTissue(boxGrid(1, 1, 1)), InputError);
}

TEST_CASE("the zero-size check refuses slivers, not small well-shaped cells", "[mesh][planar][errors]") {
  // A 1e-5 square in the corner of a 100 x 100 tissue: its area (1e-10) is
  // far below tolerance x diagonal^2 (2e-6), but it is a fine square.
  const double s = 1e-5;
  const std::vector<Vec3> p = {{0, 0, 0}, {s, 0, 0}, {s, s, 0}, {0, s, 0}, {100, 0, 0}, {100, 100, 0}, {0, 100, 0}};
  const Tissue small = buildPolygonTissue(p, {{0, 1, 2, 3}, {1, 4, 5, 6, 3, 2}});
  const MeshabilityReport fine = findGeometryDefects(small);
  INFO(fine.message);
  REQUIRE(fine.ok);
  const FeMesh mesh = meshTissue(small);
  const auto areas = cellMeasuresOfMesh(mesh, small.cellSlots());
  CHECK(areas[0] == Approx(s * s).epsilon(1e-9));
  CHECK(areas[1] == Approx(1e4 - s * s).epsilon(1e-9));

  // A needle 100 long and 1e-9 high (no short edge) is thinner than the
  // length tolerance (1.4e-8): refused.
  const double h = 1e-9;
  const std::vector<Vec3> q = {{0, 0, 0}, {100, 0, 0}, {50, h, 0}, {100, 100, 0}, {0, 100, 0}};
  const Tissue sliver = buildPolygonTissue(q, {{0, 1, 2}, {0, 2, 1, 3, 4}});
  const MeshabilityReport report = findGeometryDefects(sliver);
  REQUIRE_FALSE(report.ok);
  CHECK_THAT(report.message, Catch::Contains("cell 0") && Catch::Contains("zero area"));
}
