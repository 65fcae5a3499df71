// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// The cylinder generator: counts, vertices on the cylinder, outward loops,
// areas adding up to the prism inscribed in the cylinder, validate().
#include <catch2/catch.hpp>

#include "tessella/generators/generator_registry.hpp"
#include "tessella/generators/grids.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/tissue/validate.hpp"

#include <cmath>
#include <numbers>

using namespace tessella;

TEST_CASE("cylinder: a grid wrapped onto a cylinder", "[generators]") {
  const std::size_t around = 12, along = 5;
  const double r = 2.0, length = 3.0;
  const Tissue t = cylinderGrid(around, along, r, length, Vec3(1, -1, 0.5));
  CHECK(t.dim() == 2);
  CHECK(t.embedding() == Embedding::Surface);
  CHECK(t.numCells() == around * along);
  CHECK(t.numVertices() == around * (along + 1));
  CHECK(t.numEdges() == around * (along + 1) + around * along);  // rings + generatrices
  for (VertexId v : t.vertices()) {
    const Vec3 p = t.position(v) - Vec3(1, -1, 0.5);
    CHECK(std::hypot(p.x(), p.y()) == Approx(r).epsilon(1e-14));
    CHECK(p.z() >= -1e-14);
    CHECK(p.z() <= length + 1e-14);
  }
  // Each quad is a rectangle: chord 2 r sin(pi / around) by length / along, normal pointing out.
  const double chord = 2.0 * r * std::sin(std::numbers::pi / around);
  for (CellId c : t.cells()) {
    const PolygonMeasures m = polygonMeasures(t, t.cellFace(c));
    CHECK(m.area == Approx(chord * length / along).epsilon(1e-12));
    const Vec3 out = m.centroid - Vec3(1, -1, m.centroid.z());
    CHECK(m.normal.dot(out.normalized()) == Approx(1.0).epsilon(1e-12));
  }
  CHECK_NOTHROW(validateOrThrow(t));
  CHECK_THROWS_AS(cylinderGrid(2, 3), InputError);
  const Tissue g = generators().make("cylinder", {{"around", std::int64_t{8}}, {"along", std::int64_t{3}}}, 0);
  CHECK(g.numCells() == 24);
}
