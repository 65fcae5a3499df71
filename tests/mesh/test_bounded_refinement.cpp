// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// The refinement budget behind the planar and surface meshers: a refinement
// that needs more vertices than allowed stops with the caller's error instead
// of running on (mesh/src/bounded_refinement.hpp, internal).

#include <catch2/catch.hpp>

#include <stdexcept>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "../../mesh/src/bounded_refinement.hpp"

namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Tds = CGAL::Triangulation_data_structure_2<CGAL::Delaunay_mesh_vertex_base_2<K>, CGAL::Delaunay_mesh_face_base_2<K>>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;
using Criteria = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;
using Mesher = CGAL::Delaunay_mesher_2<Cdt, Criteria>;

/// The unit square as a constrained triangulation.
Cdt unitSquare() {
  Cdt cdt;
  const auto a = cdt.insert({0, 0}), b = cdt.insert({1, 0}), c = cdt.insert({1, 1}), d = cdt.insert({0, 1});
  cdt.insert_constraint(a, b);
  cdt.insert_constraint(b, c);
  cdt.insert_constraint(c, d);
  cdt.insert_constraint(d, a);
  return cdt;
}
}  // namespace

TEST_CASE("refinement within budget gives CGAL's own mesh", "[mesh][budget]") {
  Cdt reference = unitSquare(), bounded = unitSquare();
  CGAL::refine_Delaunay_mesh_2(reference, Criteria(0.125, 0.1));
  Mesher mesher(bounded, Criteria(0.125, 0.1));
  bool exceeded = false;
  tessella::mesh::detail::refineWithinBudget(mesher, bounded, 100000, [&](std::size_t) { exceeded = true; });
  CHECK_FALSE(exceeded);
  CHECK(bounded.number_of_vertices() == reference.number_of_vertices());
  CHECK(bounded.number_of_faces() == reference.number_of_faces());
}

TEST_CASE("a refinement past its budget stops with the caller's error", "[mesh][budget]") {
  Cdt cdt = unitSquare();
  Mesher mesher(cdt, Criteria(0.125, 0.001));  // about 10^6 vertices
  std::size_t seen = 0;
  CHECK_THROWS_AS(tessella::mesh::detail::refineWithinBudget(mesher, cdt, 500,
                                                             [&](std::size_t vertices) {
                                                               seen = vertices;
                                                               throw std::runtime_error("budget");
                                                             }),
                  std::runtime_error);
  CHECK(seen == 501);  // checked before every insertion
}

TEST_CASE("the budget grows with the input and the size bound", "[mesh][budget]") {
  using tessella::mesh::detail::refinementBudget;
  const std::size_t base = refinementBudget(4, 1.0, 1.0, 1.0, 0.0);
  CHECK(base >= 10000);
  CHECK(refinementBudget(400, 1.0, 1.0, 1.0, 0.0) > base);
  CHECK(refinementBudget(4, 1.0, 1.0, 1e-6, 0.0) > base);  // a close pair of input points grades the mesh
  // The size bound alone needs area / (sqrt(3)/4 h^2) vertices; the budget is 100x that.
  CHECK(refinementBudget(4, 1.0, 1.0, 1.0, 0.01) >= 100 * 1.0 / (0.4330127018922193 * 1e-4));
}
