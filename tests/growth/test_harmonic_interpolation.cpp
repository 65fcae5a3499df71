// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include <catch2/catch.hpp>

#include <vector>

#include "tessella/growth/harmonic_interpolation.hpp"
#include "tessella/tissue/builders.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/generators/grids.hpp"

using namespace tessella;
using namespace tessella::growth;

namespace {

template <typename F>
std::vector<Vec3> boundaryValues(const Tissue& t, F f) {
  std::vector<Vec3> values(t.slots(0), Vec3::Constant(1e9));  // interior must be overwritten
  for (VertexId v : boundaryVertices(t)) values[v.index()] = f(t.position(v));
  return values;
}

template <typename F>
double maxInteriorError(Tissue& t, F f) {
  HarmonicInterpolator h;
  std::vector<Vec3> values = boundaryValues(t, f);
  h.interpolate(t, values);
  double err = 0;
  for (VertexId v : t.vertices()) err = std::max(err, (values[v.index()] - f(t.position(v))).norm());
  return err;
}

}  // namespace

TEST_CASE("boundary vertices of grids", "[growth][harmonic]") {
  CHECK(boundaryVertices(rectangularGrid(4, 3)).size() == 14);   // 5x4 lattice minus 3x2 interior
  CHECK(boundaryVertices(boxGrid(3, 3, 3)).size() == 64 - 8);    // 4^3 lattice minus 2^3 interior
}

TEST_CASE("affine boundary fields are reproduced exactly inside regular grids", "[growth][harmonic]") {
  Mat3 A;
  A << 0.3, -1.2, 0.5, 2.0, 0.1, -0.7, 0.4, 0.9, 1.1;
  const Vec3 b(0.5, -2.0, 3.0);
  auto affine = [&](const Vec3& x) -> Vec3 { return A * x + b; };
  SECTION("2D, anisotropic cells") {
    Tissue t = rectangularGrid(9, 7, 1.0, 0.45, Vec3(-2, 1, 0));
    CHECK(maxInteriorError(t, affine) < 1e-11);
  }
  SECTION("3D box grid") {
    Tissue t = boxGrid(5, 4, 4, 0.5, 1.0, 0.8);
    CHECK(maxInteriorError(t, affine) < 1e-11);
  }
}

TEST_CASE("discrete-harmonic quadratics are reproduced on square grids", "[growth][harmonic]") {
  // x^2 - y^2 and x y have zero five-point Laplacian on a square lattice.
  Tissue t = rectangularGrid(10, 8, 0.25, 0.25);
  auto f = [](const Vec3& x) { return Vec3(x.x() * x.x() - x.y() * x.y(), x.x() * x.y(), 0.0); };
  CHECK(maxInteriorError(t, f) < 1e-12);
  // A non-harmonic field (x^2 + y^2) is not: the interpolant is off inside.
  auto g = [](const Vec3& x) { return Vec3(x.x() * x.x() + x.y() * x.y(), 0, 0); };
  CHECK(maxInteriorError(t, g) > 1e-3);
}

TEST_CASE("the factorisation is reused until the topology changes", "[growth][harmonic]") {
  Tissue t = rectangularGrid(4, 4);
  HarmonicInterpolator h;
  std::vector<Vec3> values = boundaryValues(t, [](const Vec3& x) { return x; });
  h.interpolate(t, values);
  t.mutablePositions()[0] += Vec3(0.01, 0, 0);  // geometry only
  h.interpolate(t, values);
  CHECK(h.factorisations() == 1);
  t.splitCell(CellId(5), Plane{Vec3(1.5, 1.5, 0), Vec3::UnitX()});
  std::vector<Vec3> more = boundaryValues(t, [](const Vec3& x) { return x; });
  h.interpolate(t, more);
  CHECK(h.factorisations() == 2);
}

TEST_CASE("chosen control vertices keep their values", "[growth][harmonic]") {
  Tissue t = rectangularGrid(4, 4);
  HarmonicInterpolator h;
  // The centre vertex (2, 2) and the corners drive the field.
  std::vector<VertexId> control;
  for (VertexId v : t.vertices()) {
    const Vec3& p = t.position(v);
    if ((p - Vec3(2, 2, 0)).norm() < 1e-12 || (std::fmod(p.x(), 4.0) == 0 && std::fmod(p.y(), 4.0) == 0))
      control.push_back(v);
  }
  REQUIRE(control.size() == 5);
  h.setControlVertices(control);
  std::vector<Vec3> values(t.slots(0), Vec3::Zero());
  for (VertexId v : control) values[v.index()] = (t.position(v) - Vec3(2, 2, 0)).norm() < 1e-12 ? Vec3(1, 0, 0) : Vec3::Zero();
  h.interpolate(t, values);
  for (VertexId v : t.vertices()) {
    const Vec3 p = t.position(v);
    if ((p - Vec3(2, 2, 0)).norm() < 1e-12) CHECK(values[v.index()] == Vec3(1, 0, 0));
    else {
      // Discrete maximum principle: strictly between the control values.
      const bool is_control = std::find(control.begin(), control.end(), v) != control.end();
      if (!is_control) {
        CHECK(values[v.index()].x() > 0.0);
        CHECK(values[v.index()].x() < 1.0);
      }
    }
  }
}

TEST_CASE("a part without control vertices is a GeometryError", "[growth][harmonic]") {
  // Two separate squares; control only on the first.
  const std::vector<Vec3> p = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0),
                               Vec3(3, 0, 0), Vec3(4, 0, 0), Vec3(4, 1, 0), Vec3(3, 1, 0)};
  Tissue t = buildPolygonTissue(p, {{0, 1, 2, 3}, {4, 5, 6, 7}});
  HarmonicInterpolator h;
  h.setControlVertices({VertexId(0), VertexId(1), VertexId(2), VertexId(3)});
  std::vector<Vec3> values(t.slots(0), Vec3::Zero());
  CHECK_THROWS_AS(h.interpolate(t, values), GeometryError);
  std::vector<Vec3> wrong_size(3);
  CHECK_THROWS_AS(h.interpolate(t, wrong_size), InputError);
}
