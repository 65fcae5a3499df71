// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The mesher's test of two wall triangles, on its own: a header-only part of
// mesh/ (target tessella::triangle_pair, CGAL's exact predicates) that the
// geometry check (geometry_check.cpp) and growth's test of a planned 3D
// division (growth/src/division_crossings.cpp) both use, so a division is
// refused exactly when the mesher would refuse the walls it makes.

#include <algorithm>
#include <array>
#include <span>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include "tessella/tissue/vec3.hpp"

namespace tessella::mesh {

/// A triangle as three ids into a list of points; triangles of a wall
/// triangulation that share a vertex give it the same id.
using TriangleIds = std::array<int, 3>;

/// Whether two triangles of wall surfaces cross: they may meet only at the
/// vertices and edges they share (by id). With three ids in common they are
/// the same triangle (crossing); with two (an edge) they cross when folded
/// flat onto each other (coplanar, on the same side of the edge); with one (a
/// vertex) when either meets the other's edge opposite that vertex; with none
/// when they meet at all, touching included. Exact (CGAL's exact predicates on
/// the double coordinates).
inline bool trianglesCross(std::span<const Vec3> points, const TriangleIds& a, const TriangleIds& b) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  const auto P = [&](int id) {
    const Vec3& p = points[static_cast<std::size_t>(id)];
    return K::Point_3(p.x(), p.y(), p.z());
  };
  std::array<int, 3> shared{};
  int n_shared = 0;
  for (int v : a)
    if (std::find(b.begin(), b.end(), v) != b.end()) shared[n_shared++] = v;
  // The ids of a triangle not shared with the other, in order.
  const auto others = [&](const TriangleIds& t) {
    std::array<int, 3> o{};
    int n = 0;
    for (int v : t)
      if (std::find(shared.begin(), shared.begin() + n_shared, v) == shared.begin() + n_shared) o[n++] = v;
    return o;
  };
  if (n_shared == 3) return true;
  if (n_shared == 2) {
    const int r = others(a)[0], s = others(b)[0];
    return CGAL::coplanar(P(shared[0]), P(shared[1]), P(r), P(s)) &&
           CGAL::coplanar_orientation(P(shared[0]), P(shared[1]), P(r), P(s)) == CGAL::POSITIVE;
  }
  const K::Triangle_3 ta(P(a[0]), P(a[1]), P(a[2])), tb(P(b[0]), P(b[1]), P(b[2]));
  if (n_shared == 1) {
    const auto oa = others(a), ob = others(b);
    return CGAL::do_intersect(tb, K::Segment_3(P(oa[0]), P(oa[1]))) ||
           CGAL::do_intersect(ta, K::Segment_3(P(ob[0]), P(ob[1])));
  }
  return CGAL::do_intersect(ta, tb);
}

}  // namespace tessella::mesh
