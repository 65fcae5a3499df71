// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Curved-sheet tissues -> triangles on each cell's fan surface.

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>

#include "mesh_test_support.hpp"
#include "tessella/mesh/mesh_tissue.hpp"
#include "tessella/tissue/builders.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/generators/grids.hpp"

using namespace tessella;
using namespace tessella::mesh;
using namespace tessella::test;

namespace {

/// A hexagonal sheet lifted onto the paraboloid z = k (x^2 + y^2): every cell
/// is a non-planar hexagon.
Tissue curvedHexSheet(std::size_t nx, std::size_t ny, double k) {
  const Tissue flat = hexagonalGrid(nx, ny, 1.0);
  std::vector<Vec3> p;
  std::vector<Index> slot(flat.slots(0), kInvalidIndex);
  for (VertexId v : flat.vertices()) {
    const Vec3 q = flat.position(v) - Vec3(nx * 0.8, ny * 0.7, 0);
    slot[v.index()] = static_cast<Index>(p.size());
    p.emplace_back(q.x(), q.y(), k * q.squaredNorm());
  }
  std::vector<std::vector<Index>> loops;
  for (CellId c : flat.cells()) {
    std::vector<Index> loop;
    for (VertexId v : flat.topology().faceVertices(flat.cellFace(c))) loop.push_back(slot[v.index()]);
    loops.push_back(loop);
  }
  return buildPolygonTissue(p, loops, Embedding::Surface);
}

}  // namespace

TEST_CASE("curved hexagonal sheet: fan-surface areas, conformity, quality", "[mesh][surface]") {
  const Tissue t = curvedHexSheet(4, 3, 0.15);
  MeshOptions o;
  o.min_angle_degrees = 20.0;
  o.max_edge_length = 0.3;
  const FeMesh mesh = meshTissue(t, o);
  CHECK(mesh.dim == 2);
  requireMeasuresMatch(t, mesh);
  requireConforming(mesh);
  requireWallsMatch(t, mesh);
  for (int e = 0; e < mesh.numElements(); ++e) {
    CHECK(triangleMinAngleDegrees(mesh, e) >= o.min_angle_degrees - 1e-6);
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d a = mesh.nodes.row(mesh.elements(e, k));
      const Eigen::Vector3d b = mesh.nodes.row(mesh.elements(e, (k + 1) % 3));
      CHECK((b - a).norm() <= o.max_edge_length * (1 + 1e-9));
    }
  }
  // Triangles face the same way as their cell (counter-clockwise about its normal).
  for (int e = 0; e < mesh.numElements(); ++e) {
    const Eigen::Vector3d a = mesh.nodes.row(mesh.elements(e, 0));
    const Eigen::Vector3d n = (Eigen::Vector3d(mesh.nodes.row(mesh.elements(e, 1))) - a)
                                  .cross(Eigen::Vector3d(mesh.nodes.row(mesh.elements(e, 2))) - a);
    CHECK(n.z() > 0);
  }
}

TEST_CASE("curved sheet without a size bound", "[mesh][surface]") {
  const Tissue t = curvedHexSheet(3, 3, 0.3);
  MeshOptions o;
  o.min_angle_degrees = 0.0;
  const FeMesh mesh = meshTissue(t, o);
  CHECK(mesh.numElements() == static_cast<int>(6 * t.numCells()));  // exactly the fans
  requireMeasuresMatch(t, mesh);
  requireConforming(mesh);
  requireWallsMatch(t, mesh);
}

TEST_CASE("a very short wall does not blow up the refinement", "[mesh][surface]") {
  // Two cells of a curved sheet sharing a 1e-5 long wall far from their
  // centres: the fan triangles on it have a ~1e-5 rad angle, which no
  // refinement can improve. Regression: Delaunay refinement of such a sliver
  // put O(1/angle) points on its spokes and spread them to the neighbours
  // (seen on dome tissues: never finished).
  const double k = 0.2;
  std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {1, 1e-5, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}, {2, 1, 0}};
  for (Vec3& q : p) q.z() = k * (q.x() * q.x() + q.y() * q.y());
  const Tissue t = buildPolygonTissue(p, {{0, 1, 2, 3, 4}, {1, 5, 6, 3, 2}}, Embedding::Surface);
  MeshOptions o;
  o.min_angle_degrees = 20.0;
  o.max_edge_length = 0.05;
  const FeMesh mesh = meshTissue(t, o);
  requireMeasuresMatch(t, mesh);
  requireConforming(mesh);
  requireWallsMatch(t, mesh);
  // The same two cells without the short wall mesh to about as many
  // triangles: the sliver may add a few, never thousands.
  const Tissue plain = buildPolygonTissue(p, {{0, 1, 3, 4}, {1, 5, 6, 3}}, Embedding::Surface);
  const FeMesh plain_mesh = meshTissue(plain, o);
  CHECK(mesh.numElements() < 1.2 * plain_mesh.numElements());
  // The angle bound holds outside the sharp fan triangles (those with an angle
  // below the bound, here the two on the short wall): elements below it cover
  // at most their area.
  double sliver_area = 0;
  for (CellId c : t.cells()) {
    std::vector<Vec3> loop;
    for (VertexId v : t.topology().faceVertices(t.cellFace(c))) loop.push_back(t.position(v));
    Vec3 centre = Vec3::Zero();
    for (const Vec3& q : loop) centre += q / static_cast<double>(loop.size());
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const std::array<Vec3, 3> tri = {centre, loop[i], loop[(i + 1) % loop.size()]};
      double smallest = 180;
      for (std::size_t j = 0; j < 3; ++j) {
        const Vec3 a = tri[(j + 1) % 3] - tri[j], b = tri[(j + 2) % 3] - tri[j];
        smallest = std::min(smallest, std::atan2(a.cross(b).norm(), a.dot(b)) * 180 / M_PI);
      }
      if (smallest < o.min_angle_degrees) sliver_area += 0.5 * (tri[1] - tri[0]).cross(tri[2] - tri[0]).norm();
    }
  }
  REQUIRE(sliver_area > 0);
  REQUIRE(sliver_area < 1e-5);
  double sharp_area = 0;
  for (int e = 0; e < mesh.numElements(); ++e)
    if (triangleMinAngleDegrees(mesh, e) < o.min_angle_degrees - 1e-6) sharp_area += elementMeasure(mesh, e);
  CHECK(sharp_area <= sliver_area * (1 + 1e-9));
}

TEST_CASE("a surface cell whose fan from the vertex mean folds is meshed", "[mesh][surface]") {
  // A non-planar quad whose vertex mean lies outside it (a deep dart): it was
  // refused ("folds over"); it is measured and meshed on the fan from its kernel.
  const std::vector<Vec3> p = {{0, 0, 0}, {4, 0, 0.1}, {0.2, 0.2, 0}, {0, 4, 0.1}};
  const Tissue t = buildPolygonTissue(p, {{0, 1, 2, 3}}, Embedding::Surface);
  const FeMesh mesh = meshTissue(t);
  requireGoodMesh(t, mesh);
}
