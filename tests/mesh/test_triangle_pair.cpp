// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// The pair test of wall triangles (tessella/mesh/triangle_pair.hpp) shared by
// the mesher's geometry check and growth's refusal of crossing 3D divisions,
// on hand-made pairs whose answer is known: crossing, disjoint, touching,
// sharing a vertex or an edge (hinged, flat, folded), coplanar overlap.
#include <catch2/catch.hpp>

#include <vector>

#include "tessella/mesh/triangle_pair.hpp"

using namespace tessella;
using tessella::mesh::TriangleIds;
using tessella::mesh::trianglesCross;

namespace {

// Both orders give the same answer.
bool cross(const std::vector<Vec3>& p, const TriangleIds& a, const TriangleIds& b) {
  const bool ab = trianglesCross(p, a, b), ba = trianglesCross(p, b, a);
  CHECK(ab == ba);
  return ab;
}

}  // namespace

TEST_CASE("two triangles without common ids cross when they meet at all", "[mesh][triangle_pair]") {
  // A: the triangle (0,0,0), (2,0,0), (0,2,0) in z = 0.
  std::vector<Vec3> p{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}};
  const TriangleIds a{0, 1, 2};
  SECTION("piercing: a vertical triangle through A's interior") {
    p.insert(p.end(), {{0.5, 0.5, -1}, {0.5, 0.5, 1}, {1.5, 1.5, 0.5}});
    CHECK(cross(p, a, {3, 4, 5}));
  }
  SECTION("disjoint: the same triangle moved beyond A's hypotenuse x + y = 2") {
    p.insert(p.end(), {{1.5, 1.5, -1}, {1.5, 1.5, 1}, {2.5, 2.5, 0.5}});
    CHECK_FALSE(cross(p, a, {3, 4, 5}));
  }
  SECTION("disjoint: parallel, one unit above") {
    p.insert(p.end(), {{0, 0, 1}, {2, 0, 1}, {0, 2, 1}});
    CHECK_FALSE(cross(p, a, {3, 4, 5}));
  }
  SECTION("touching: a vertex of B on A's interior, B above") {
    p.insert(p.end(), {{0.5, 0.5, 0}, {0.5, 0, 1}, {0, 0.5, 1}});
    CHECK(cross(p, a, {3, 4, 5}));
  }
  SECTION("touching: a vertex of B at A's corner (2,0,0) under another id") {
    p.insert(p.end(), {{2, 0, 0}, {3, 0, 1}, {3, 1, 1}});
    CHECK(cross(p, a, {3, 4, 5}));
  }
  SECTION("coplanar overlap: a smaller triangle inside A, in its plane") {
    p.insert(p.end(), {{0.2, 0.2, 0}, {1, 0.2, 0}, {0.2, 1, 0}});
    CHECK(cross(p, a, {3, 4, 5}));
  }
  SECTION("coplanar, apart: the mirror image of A across x + y = 2.5") {
    p.insert(p.end(), {{2.5, 2.5, 0}, {0.5, 2.5, 0}, {2.5, 0.5, 0}});
    CHECK_FALSE(cross(p, a, {3, 4, 5}));
  }
}

TEST_CASE("triangles sharing a vertex cross when anything else meets", "[mesh][triangle_pair]") {
  // Both contain vertex 0 = the origin; A lies in z = 0.
  std::vector<Vec3> p{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}};
  const TriangleIds a{0, 1, 2};
  SECTION("a fan: B in z = 0, in the opposite quadrant") {
    p.insert(p.end(), {{-2, 0, 0}, {0, -2, 0}});
    CHECK_FALSE(cross(p, a, {0, 3, 4}));
  }
  SECTION("B rising from the shared vertex, above A") {
    p.insert(p.end(), {{1, 0, 1}, {0, 1, 1}});
    CHECK_FALSE(cross(p, a, {0, 3, 4}));
  }
  SECTION("B's opposite edge passes through A's interior") {
    p.insert(p.end(), {{0.5, 0.5, -1}, {0.5, 0.5, 1}});
    CHECK(cross(p, a, {0, 3, 4}));
  }
  SECTION("B folded onto A in its plane (a coplanar overlap at the shared vertex)") {
    p.insert(p.end(), {{1, 0.2, 0}, {0.2, 1, 0}});
    CHECK(cross(p, a, {0, 3, 4}));
  }
}

TEST_CASE("triangles sharing an edge cross only when folded onto each other", "[mesh][triangle_pair]") {
  // The shared edge runs from (0,0,0) to (2,0,0); A's third vertex is (1,1,0).
  std::vector<Vec3> p{{0, 0, 0}, {2, 0, 0}, {1, 1, 0}};
  const TriangleIds a{0, 1, 2};
  SECTION("flat: B on the other side of the edge, in A's plane") {
    p.push_back({1, -1, 0});
    CHECK_FALSE(cross(p, a, {1, 0, 3}));
  }
  SECTION("hinged: B at a right angle") {
    p.push_back({1, 0, 1});
    CHECK_FALSE(cross(p, a, {1, 0, 3}));
  }
  SECTION("hinged almost shut: B just above A") {
    p.push_back({1, 1, 1e-9});
    CHECK_FALSE(cross(p, a, {1, 0, 3}));
  }
  SECTION("folded: B in A's plane on A's side of the edge") {
    p.push_back({1, 0.5, 0});
    CHECK(cross(p, a, {1, 0, 3}));
  }
  SECTION("the same triangle: all three ids shared") { CHECK(cross(p, a, {2, 0, 1})); }
}
