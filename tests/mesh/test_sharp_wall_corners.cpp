// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// 3D cell by cell: planar walls with a corner sharper than the angle bound are refined inside only, so the
// side splits of their wedges do not bounce between the walls around the corner (docs/meshing.md, "Sharp
// corners"; the crop of docs/import.md whose cell TetGen crashed on).

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "mesh_test_support.hpp"
#include "tessella/mesh/mesh_tissue.hpp"
#include "tessella/tissue/builders.hpp"
#include "tessella/tissue/validate.hpp"

using namespace tessella;
using namespace tessella::mesh;
using namespace tessella::test;

namespace {

/// Two unit cubes, A = [0,1]^3 and B = [-1,0] x [0,1]^2. The three faces of A at the origin are fans of
/// triangular walls from the origin with angles of 7.7 to 19.4 degrees there (the face x = 0 is shared
/// with B); every other face is one planar wall through every vertex on its border.
struct FanCubes {
  std::vector<Vec3> p;
  std::vector<std::vector<Index>> faces;
  std::vector<std::vector<CellFace>> cells{2};
  std::vector<std::pair<Index, Index>> spokes;  // tissue edges (origin, far end) inside the fanned faces

  Index point(const Vec3& x) {
    for (std::size_t i = 0; i < p.size(); ++i)
      if ((p[i] - x).norm() < 1e-12) return static_cast<Index>(i);
    p.push_back(x);
    return static_cast<Index>(p.size() - 1);
  }
  // Adds a wall to the cells on either side, its loop's normal pointing out of each.
  void addWall(const std::vector<Index>& loop, const std::vector<std::pair<int, Vec3>>& cells_outward) {
    Vec3 n = Vec3::Zero();
    for (std::size_t i = 0; i < loop.size(); ++i) n += p[loop[i]].cross(p[loop[(i + 1) % loop.size()]]);
    faces.push_back(loop);
    for (const auto& [c, outward] : cells_outward)
      cells[static_cast<std::size_t>(c)].push_back({static_cast<Index>(faces.size() - 1), n.dot(outward) < 0});
  }
};

Tissue fanCubes(FanCubes& b) {
  const std::array<std::vector<double>, 3> fans = {std::vector<double>{0, 9, 18, 30, 45, 52, 61, 70, 80, 90},
                                                   std::vector<double>{0, 8, 17, 27, 36, 45, 56, 68, 79, 90},
                                                   std::vector<double>{0, 7.7, 17.4, 28, 36, 45, 54, 63, 72, 81, 90}};
  const Index o = b.point(Vec3::Zero());
  for (int d = 0; d < 3; ++d) {  // the face of A normal to axis d, in the axes (a, c)
    const int a = (d + 1) % 3, c = (d + 2) % 3;
    std::vector<Index> ring;
    for (double phi : fans[static_cast<std::size_t>(d)]) {
      Vec3 x = Vec3::Zero();
      x[a] = phi <= 45 ? 1.0 : std::tan((90 - phi) * std::numbers::pi / 180);
      x[c] = phi >= 45 ? 1.0 : std::tan(phi * std::numbers::pi / 180);
      ring.push_back(b.point(x));
    }
    for (std::size_t k = 0; k + 1 < ring.size(); ++k) {
      std::vector<std::pair<int, Vec3>> sides{{0, -Vec3::Unit(d)}};
      if (d == 0) sides.push_back({1, Vec3::Unit(0)});
      b.addWall({o, ring[k], ring[k + 1]}, sides);
    }
    for (std::size_t k = 1; k + 1 < ring.size(); ++k) b.spokes.emplace_back(o, ring[k]);  // inside the face
  }
  // The other faces: A's three far faces, B's five others (every vertex on their border, in order).
  const auto box_face = [&](int cell, int d, double at, const Vec3& lo, const Vec3& hi, const Vec3& outward) {
    const int a = (d + 1) % 3, c = (d + 2) % 3;
    for (double u : {lo[a], hi[a]})
      for (double v : {lo[c], hi[c]}) {
        Vec3 x;
        x[d] = at, x[a] = u, x[c] = v;
        b.point(x);
      }
    std::vector<std::pair<double, Index>> on;
    for (std::size_t i = 0; i < b.p.size(); ++i) {
      const Vec3& x = b.p[i];
      if (x[d] == at && x[a] >= lo[a] && x[a] <= hi[a] && x[c] >= lo[c] && x[c] <= hi[c])
        on.emplace_back(std::atan2(x[c] - 0.5 * (lo[c] + hi[c]), x[a] - 0.5 * (lo[a] + hi[a])), static_cast<Index>(i));
    }
    std::sort(on.begin(), on.end());
    std::vector<Index> loop;
    for (const auto& q : on) loop.push_back(q.second);
    b.addWall(loop, {{cell, outward}});
  };
  const Vec3 a_lo(0, 0, 0), a_hi(1, 1, 1), b_lo(-1, 0, 0), b_hi(0, 1, 1);
  for (int d = 0; d < 3; ++d) box_face(0, d, 1.0, a_lo, a_hi, Vec3::Unit(d));
  box_face(1, 0, -1.0, b_lo, b_hi, -Vec3::Unit(0));
  for (int d = 1; d < 3; ++d) {
    box_face(1, d, 0.0, b_lo, b_hi, -Vec3::Unit(d));
    box_face(1, d, 1.0, b_lo, b_hi, Vec3::Unit(d));
  }
  return buildPolyhedralTissue(b.p, b.faces, b.cells);
}

double segmentDistance(const Vec3& x, const Vec3& a, const Vec3& b) {
  const double t = std::clamp((x - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
  return (a + t * (b - a) - x).norm();
}

}  // namespace

TEST_CASE("cell by cell: walls with corners sharper than the angle bound never split the sides they share",
          "[mesh][volume]") {
  FanCubes b;
  const Tissue t = fanCubes(b);
  REQUIRE(validate(t).ok);
  REQUIRE(relativelyClose(cellMeasure(t, CellId(0)), 1.0));
  REQUIRE(relativelyClose(cellMeasure(t, CellId(1)), 1.0));
  const FeMesh mesh = meshTissue(t, MeshOptions{});  // the default angle bound, 20 degrees; no size bound
  requireGoodMesh(t, mesh);  // conforming, each cell's tetrahedra adding up to its volume, each wall's facets to its area
  // Each spoke inside a fanned face (the origin to a vertex on a far edge) lies between two walls that are sharper
  // than the bound at the origin and no other, so no refinement puts a point on it: no node the mesher added lies on a spoke. Before,
  // CGAL's refinement of each wedge put points on its sides and the walls around the origin passed them on to
  // each other round after round.
  for (int n = 0; n < mesh.numNodes(); ++n) {
    if (mesh.node_vertex(n) >= 0) continue;
    const Vec3 x = mesh.nodes.row(n).transpose();
    for (const auto& [o, r] : b.spokes) {
      INFO("node " << n << " at " << x.transpose() << ", spoke to " << b.p[r].transpose());
      REQUIRE(segmentDistance(x, b.p[o], b.p[r]) > 1e-9);
    }
  }
}
