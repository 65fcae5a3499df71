// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// The element-count estimate and MeshOptions::max_elements: a mesh the size
// bounds make too large is refused before any meshing.

#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>

#include "tessella/mesh/mesh_tissue.hpp"
#include "tessella/generators/dome.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/generators/grids.hpp"
#include "tessella/generators/voronoi.hpp"

using namespace tessella;
using namespace tessella::mesh;
using Catch::Matchers::Contains;

TEST_CASE("estimatedElementCount: area / equilateral triangle, volume / regular tetrahedron",
          "[mesh][limit]") {
  const Tissue grid = rectangularGrid(4, 3, 1.0, 1.0);     // area 12
  CHECK(estimatedElementCount(grid, MeshOptions{}) == 0);  // no size bound
  CHECK(estimatedElementCount(grid, MeshOptions{.max_edge_length = 0.1}) ==
        Approx(12.0 / (std::sqrt(3.0) / 4.0 * 0.01)));
  const Tissue box = boxGrid(2, 2, 2, 1.0, 1.0, 1.0);  // volume 8
  CHECK(estimatedElementCount(box, MeshOptions{}) == 0);
  CHECK(estimatedElementCount(box, MeshOptions{.max_volume = 0.01}) == Approx(800));
  // Cell by cell: 8 cubes of surface 6, wall triangles of edge <= 0.5, four faces per tetrahedron.
  const double walls = 48 / (std::sqrt(3.0) / 4.0 * 0.25) / 4;
  CHECK(estimatedElementCount(box, MeshOptions{.max_edge_length = 0.5}) == Approx(walls));
  CHECK(estimatedElementCount(box, MeshOptions{.max_edge_length = 0.5, .max_volume = 1.0}) ==
        Approx(walls));
  CHECK(estimatedElementCount(box, MeshOptions{.max_edge_length = 0.5, .max_volume = 0.01}) ==
        Approx(800));
  // TetGen on the whole tissue is not bound by max_edge_length.
  CHECK(estimatedElementCount(box, MeshOptions{.max_edge_length = 0.5,
                                               .volume_method = VolumeMethod::WholeTissue}) == 0);
}

TEST_CASE("the estimate is a lower bound on the meshes actually made", "[mesh][limit]") {
  const Rectangle rect{Vec3(0, 0, 0), Vec3(2, 1, 0)};
  const Tissue flat = voronoiTissue(randomSeeds(rect, 30, 3), rect);
  const MeshOptions o2{.max_edge_length = 0.05};
  CHECK(meshTissue(flat, o2).numElements() >= estimatedElementCount(flat, o2));
  const Disk footprint{Vec3(0, 0, 0), 1.0, 64};
  const Tissue dome =
      domeTissue(randomSeeds(footprint, 20, 4), Dome{}, VoronoiOptions{.lloyd_iterations = 2});
  const MeshOptions os{.max_edge_length = 0.1};
  CHECK(meshTissue(dome, os).numElements() >= estimatedElementCount(dome, os));
  const Tissue box = boxGrid(2, 1, 1);
  for (const MeshOptions& o3 : {MeshOptions{.max_edge_length = 0.4, .max_volume = 0.01},
                                MeshOptions{.max_edge_length = 0.2}})
    CHECK(meshTissue(box, o3).numElements() >= estimatedElementCount(box, o3));
}

TEST_CASE("a mesh estimated above max_elements is refused at once, naming estimate, size and limit",
          "[mesh][limit]") {
  const Tissue grid = rectangularGrid(4, 3, 1.0, 1.0);
  const auto t0 = std::chrono::steady_clock::now();
  // 1e-6 on an area of 12: ~2.8e13 triangles; refused before CGAL starts.
  CHECK_THROWS_AS(meshTissue(grid, MeshOptions{.max_edge_length = 1e-6}), InputError);
  CHECK_THROWS_WITH(meshTissue(grid, MeshOptions{.max_edge_length = 1e-6}),
                    Contains("max_edge_length = 1e-06") &&
                        Contains("at least 2.77128e+13 triangles") && Contains("total area 12") &&
                        Contains("max_elements = 2e+07"));
  CHECK(std::chrono::steady_clock::now() - t0 < std::chrono::seconds(5));
  // The limit is an option: lower it and a small mesh is refused, raise it (0 = none) and it is
  // made.
  const MeshOptions small{.max_edge_length = 0.2, .max_elements = 100};
  CHECK_THROWS_WITH(meshTissue(grid, small), Contains("max_elements = 100"));
  CHECK_THROWS_WITH(meshPlanarTissue(grid, small), Contains("max_elements = 100"));
  CHECK(meshTissue(grid, MeshOptions{.max_edge_length = 0.2, .max_elements = 0}).numElements() >
        100);
  CHECK(meshTissue(grid, MeshOptions{.max_edge_length = 0.2, .max_elements = 1000}).numElements() >
        100);
  // 3D: the volume bound, and the wall size of the cell-by-cell method.
  const Tissue box = boxGrid(2, 2, 2);
  CHECK_THROWS_WITH(
      meshTissue(box, MeshOptions{.max_volume = 1e-9}),
      Contains("max_volume = 1e-09") && Contains("8e+09 tetrahedra") && Contains("total volume 8"));
  CHECK_THROWS_WITH(
      meshVolumeTissue(box, MeshOptions{.max_edge_length = 0.1, .max_elements = 1000}),
      Contains("max_edge_length = 0.1") && Contains("tetrahedra"));
}
