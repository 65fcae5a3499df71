// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "growth_fixtures.hpp"
#include "tessella/growth/bump_field.hpp"
#include "tessella/growth/expression_field.hpp"
#include "tessella/growth/growth_integrator.hpp"
#include "tessella/growth/linear_field.hpp"
#include "tessella/growth/meristem_field.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/generators/grids.hpp"
#include "tessella/tissue/validate.hpp"

using namespace tessella;
using namespace tessella::growth;
using Catch::Matchers::Contains;

namespace {

// Relative error of the total measure after growing to time T with n steps.
double expansionError(Tissue t, IntegrationScheme scheme, double rate, double T, int n) {
  const double m0 = totalMeasure(t);
  GrowthIntegrator g(std::make_shared<LinearField>(uniformExpansion(rate, Vec3(0.3, 0.2, 0.1))),
                     GrowthOptions{.scheme = scheme});
  for (int i = 0; i < n; ++i) g.step(t, T / n);
  const double exact = m0 * std::exp(t.dim() * rate * T);
  return std::abs(totalMeasure(t) - exact) / exact;
}

double observedOrder(const Tissue& t, IntegrationScheme scheme) {
  const double e1 = expansionError(t, scheme, 0.8, 1.0, 20);
  const double e2 = expansionError(t, scheme, 0.8, 1.0, 40);
  return std::log2(e1 / e2);
}

}  // namespace

TEST_CASE("uniform expansion multiplies area by exp(2rt) at the scheme's order", "[growth][integrator]") {
  const Tissue grid = rectangularGrid(4, 3, 1.0, 0.5);
  CHECK(expansionError(grid, IntegrationScheme::Heun, 0.8, 1.0, 40) < 2e-3);
  CHECK(observedOrder(grid, IntegrationScheme::Euler) == Approx(1.0).margin(0.1));
  CHECK(observedOrder(grid, IntegrationScheme::Heun) == Approx(2.0).margin(0.1));
}

TEST_CASE("uniform expansion multiplies volume by exp(3rt) at the scheme's order", "[growth][integrator]") {
  const Tissue box = boxGrid(2, 2, 2, 1.0, 0.5, 0.25);
  CHECK(expansionError(box, IntegrationScheme::Heun, 0.8, 1.0, 40) < 3e-3);
  CHECK(observedOrder(box, IntegrationScheme::Euler) == Approx(1.0).margin(0.1));
  CHECK(observedOrder(box, IntegrationScheme::Heun) == Approx(2.0).margin(0.1));
}

TEST_CASE("vertices follow the bump field's exact trajectories", "[growth][integrator]") {
  const BumpFieldParams bp{.a = 0.5, .b = 2.0, .h = 4.0, .x0 = 10.0};
  auto field = std::make_shared<BumpField>(bp);
  const Tissue start = rectangularGrid(20, 5);
  auto maxError = [&](IntegrationScheme scheme, int n) {
    Tissue t = start;
    t.setTime(0.5);
    GrowthIntegrator g(field, GrowthOptions{.scheme = scheme});
    for (int i = 0; i < n; ++i) g.step(t, 2.0 / n);
    REQUIRE(t.time() == Approx(2.5));
    double err = 0;
    for (VertexId v : t.vertices()) {
      const Vec3& p0 = start.position(v);
      const Vec3 exact(p0.x(), p0.y() + field->displacement(p0.x(), 0.5, 2.5), 0.0);
      err = std::max(err, (t.position(v) - exact).norm());
    }
    REQUIRE(validate(t).ok);
    return err;
  };
  const double e_euler = maxError(IntegrationScheme::Euler, 16), e_euler2 = maxError(IntegrationScheme::Euler, 32);
  const double e_heun = maxError(IntegrationScheme::Heun, 16), e_heun2 = maxError(IntegrationScheme::Heun, 32);
  CHECK(std::log2(e_euler / e_euler2) == Approx(1.0).margin(0.1));
  CHECK(std::log2(e_heun / e_heun2) == Approx(2.0).margin(0.15));
  CHECK(e_heun2 < 1e-3);
}

TEST_CASE("planar tissues stay at z = 0", "[growth][integrator]") {
  Tissue t = rectangularGrid(3, 3);
  auto field = std::make_shared<ExpressionField>(ExpressionFieldParams{.vx = "0.1*x", .vy = "0", .vz = "1"});
  GrowthIntegrator g(field);
  const std::uint64_t before = t.geometryVersion();
  g.step(t, 0.5);
  CHECK(t.geometryVersion() > before);
  for (VertexId v : t.vertices()) CHECK(t.position(v).z() == 0.0);
  CHECK(totalMeasure(t) == Approx(9.0 * (1 + 0.05 + 0.5 * 0.05 * 0.05)));  // Heun on v = 0.1 x
}

TEST_CASE("a surface projection keeps a curved tissue on its sphere", "[growth][integrator]") {
  const double R = 2.0;
  Tissue t = testing::sphericalCapGrid(6, 1.2, R);
  auto field = std::make_shared<MeristemField>(MeristemFieldParams{
      .apex = Vec3(0, 0, R), .central_radius = 0.2, .transition_width = 0.05,
      .central_rate = 0.05, .peripheral_rate = 0.3});
  GrowthIntegrator g(field, GrowthOptions{.projection = sphereProjection(Vec3::Zero(), R)});
  const double a0 = totalMeasure(t);
  for (int i = 0; i < 10; ++i) g.step(t, 0.1);
  for (VertexId v : t.vertices()) CHECK(t.position(v).norm() == Approx(R).epsilon(1e-13));
  CHECK(totalMeasure(t) > a0);
  CHECK(validate(t).ok);
}

TEST_CASE("paraboloid projection returns the nearest surface point", "[growth][integrator]") {
  const double k = 0.8;
  const SurfaceProjection proj = paraboloidProjection(Vec3(0, 0, 1), k);
  for (const Vec3& p : {Vec3(0.3, 0.1, 1.2), Vec3(1.0, -0.5, 0.0), Vec3(0, 0, 0.5), Vec3(2, 2, -3)}) {
    const Vec3 q = proj(p);
    const double rho = std::hypot(q.x(), q.y());
    CHECK(q.z() == Approx(1 - k * rho * rho).margin(1e-12));
    // Nearest point: p - q is normal to the surface, i.e. parallel to the gradient
    // of F = z - 1 + k rho^2, which is (2k x, 2k y, 1).
    const Vec3 grad(2 * k * q.x(), 2 * k * q.y(), 1.0);
    CHECK((p - q).cross(grad).norm() <= 1e-10 * (1 + (p - q).norm()));
  }
  CHECK_THROWS_AS(paraboloidProjection(Vec3::Zero(), 0.0), InputError);
  CHECK_THROWS_AS(sphereProjection(Vec3::Zero(), -1.0), InputError);
}

TEST_CASE("a step that inverts a cell is refused and undone", "[growth][integrator]") {
  Tissue t = rectangularGrid(2, 2);
  const std::vector<Vec3> before(t.positions().begin(), t.positions().end());
  // v = -3 x for one step of 1: x -> -2 x mirrors every cell.
  GrowthIntegrator g(std::make_shared<LinearField>(anisotropicGrowth(Vec3(-3, 0, 0))),
                     GrowthOptions{.scheme = IntegrationScheme::Euler});
  t.setTime(4.0);
  try {
    g.step(t, 1.0);
    FAIL("no error");
  } catch (const GeometryError& e) {
    CHECK_THAT(e.what(), Contains("lineage id") && Contains("t = 4") && Contains("cell"));
    // x -> -2x: each unit square becomes a 2 x 1 rectangle turned over, signed area -2 as in 3D below.
    CHECK_THAT(e.what(), Contains("signed area -2 (normal (0, 0, -1) instead of +z)"));
    CHECK(e.element().degree == 2);
  }
  CHECK(t.time() == 4.0);
  for (VertexId v : t.vertices()) CHECK(t.position(v) == before[v.index()]);

  SECTION("3D: a negative volume") {
    Tissue box = boxGrid(1, 1, 2);
    GrowthIntegrator g3(std::make_shared<LinearField>(anisotropicGrowth(Vec3(0, 0, -3))),
                        GrowthOptions{.scheme = IntegrationScheme::Euler});
    // z -> -2z: each unit cube becomes a 1 x 1 x 2 box turned inside out, signed volume -2.
    CHECK_THROWS_WITH(g3.step(box, 1.0), Contains("signed volume -2;"));
  }
  SECTION("a surface cell turned over") {
    Tissue cap = testing::sphericalCapGrid(3, 1.0, 3.0);
    GrowthIntegrator gs(std::make_shared<LinearField>(anisotropicGrowth(Vec3(-3, 0, 0))),
                        GrowthOptions{.scheme = IntegrationScheme::Euler});
    CHECK_THROWS_WITH(gs.step(cap, 1.0), Contains("signed area -") && Contains("turned against its previous normal"));
  }
}

TEST_CASE("bad time steps are input errors", "[growth][integrator]") {
  Tissue t = rectangularGrid(1, 1);
  GrowthIntegrator g(std::make_shared<LinearField>(uniformExpansion(1.0)));
  CHECK_THROWS_AS(g.step(t, 0.0), InputError);
  CHECK_THROWS_AS(g.step(t, -1.0), InputError);
  CHECK_THROWS_AS(g.step(t, NAN), InputError);
  CHECK_THROWS_AS(parseScheme("rk4"), InputError);
  CHECK(parseScheme("rk2") == IntegrationScheme::Heun);
}

TEST_CASE("boundary-driven growth equals field growth for a linear field on a grid",
          "[growth][integrator][harmonic]") {
  // Harmonic interpolation reproduces affine fields on a regular grid, so
  // driving only the boundary gives the same motion as the field everywhere.
  Mat3 G;
  G << 0.3, 0.1, 0, -0.05, 0.2, 0, 0, 0, 0;
  auto field = std::make_shared<LinearField>(G, Vec3(1, 1, 0));
  Tissue a = rectangularGrid(6, 5, 1.0, 0.7), b = a;
  GrowthIntegrator everywhere(field), boundary(field, GrowthOptions{.source = VelocitySource::HarmonicFromControl});
  for (int i = 0; i < 5; ++i) {
    everywhere.step(a, 0.1);
    boundary.step(b, 0.1);
  }
  for (VertexId v : a.vertices()) CHECK((a.position(v) - b.position(v)).norm() < 1e-12);
  CHECK(boundary.interpolator().factorisations() == 1);  // topology never changed
}

TEST_CASE("the dome projection fixes the dome's own surface", "[growth][integrator]") {
  for (Dome::Shape shape : {Dome::Shape::SphericalCap, Dome::Shape::Paraboloid}) {
    Dome dome;
    dome.shape = shape;
    dome.base_radius = 5.0;
    dome.height = 2.0;
    dome.base_center = Vec3(1, -1, 0.5);
    const SurfaceProjection proj = domeProjection(dome);
    // Points the generator puts on the dome stay where they are...
    for (double r : {0.0, 1.0, 3.0, 4.9}) {
      const Vec3 on = dome.lift(dome.base_center + Vec3(r * 0.6, r * 0.8, 0));
      CHECK((proj(on) - on).norm() < 1e-12);
    }
    // ... and points beyond the base land on the continued surface.
    const Vec3 out = proj(dome.base_center + Vec3(7, 0, 0));
    if (shape == Dome::Shape::SphericalCap) {
      const double R = (25.0 + 4.0) / 4.0;
      CHECK((out - (dome.base_center + Vec3(0, 0, 2.0 - R))).norm() == Approx(R));
    } else {
      const double rho = std::hypot(out.x() - 1, out.y() + 1);
      CHECK(out.z() == Approx(0.5 + 2.0 * (1 - rho * rho / 25.0)));
    }
  }
}

TEST_CASE("a non-finite velocity is an error naming the field, the expression, the vertex and the time",
          "[growth][integrator][finite]") {
  for (const bool check_inversion : {true, false}) {
    for (const IntegrationScheme scheme : {IntegrationScheme::Euler, IntegrationScheme::Heun}) {
      INFO("check_inversion " << check_inversion << ", scheme " << schemeName(scheme));
      Tissue t = rectangularGrid(2, 2);
      t.setTime(0.5);
      const std::vector<Vec3> before(t.positions().begin(), t.positions().end());
      GrowthIntegrator g(std::make_shared<ExpressionField>(ExpressionFieldParams{.vx = "x / (t - 0.5)", .vy = "y"}),
                         GrowthOptions{.scheme = scheme, .check_inversion = check_inversion});
      try {
        g.step(t, 0.1);
        FAIL("no error");
      } catch (const GeometryError& e) {
        // Vertex 0 sits at x = 0: 0 / 0.
        CHECK_THAT(e.what(), Contains("expression field") && Contains("vx = \"x / (t - 0.5)\" gives nan") &&
                                 Contains("vertex 0, position (0, 0, 0), t = 0.5") && !Contains("vy ="));
        CHECK(e.element().degree == 0);
        CHECK(e.element().index == 0);
      }
      CHECK(t.time() == 0.5);
      for (VertexId v : t.vertices()) CHECK(t.position(v) == before[v.index()]);
    }
  }
}

TEST_CASE("a velocity that overflows in Heun's second stage is refused and undone", "[growth][integrator][finite]") {
  for (const bool check_inversion : {true, false}) {
    Tissue t = rectangularGrid(2, 2);
    const std::vector<Vec3> before(t.positions().begin(), t.positions().end());
    // v(1) = 1e300 is finite; at the predictor, x ~ 1e299, v = inf.
    GrowthIntegrator g(std::make_shared<ExpressionField>(ExpressionFieldParams{.vx = "1e300*x*x"}),
                       GrowthOptions{.scheme = IntegrationScheme::Heun, .check_inversion = check_inversion});
    try {
      g.step(t, 0.1);
      FAIL("no error");
    } catch (const GeometryError& e) {
      CHECK_THAT(e.what(), Contains("vx = \"1e300*x*x\" gives inf") && Contains("t = 0.1") && Contains("vertex 1,"));
    }
    CHECK(t.time() == 0.0);
    for (VertexId v : t.vertices()) CHECK(t.position(v) == before[v.index()]);
  }
}

namespace {
// A field that fails like a Python field raising an exception: at the
// predictor's time, in Heun's second stage, after the vertices have moved.
class FailingLaterField final : public VelocityField {
 public:
  Vec3 velocity(const Vec3& x, double t) const override {
    if (t > 0) throw std::runtime_error("field failed at t > 0");
    return 0.5 * x;
  }
  void velocities(std::span<const Vec3> x, double t, std::span<Vec3> out) const override {
    for (std::size_t i = 0; i < x.size(); ++i) out[i] = velocity(x[i], t);
  }
  std::string describe() const override { return "failing field"; }
};
}  // namespace

TEST_CASE("any exception during a step leaves positions and clock as they were", "[growth][integrator]") {
  Tissue t = rectangularGrid(2, 2);
  const std::vector<Vec3> before(t.positions().begin(), t.positions().end());
  GrowthIntegrator g(std::make_shared<FailingLaterField>(), GrowthOptions{.scheme = IntegrationScheme::Heun});
  CHECK_THROWS_WITH(g.step(t, 0.1), Contains("field failed"));
  CHECK(t.time() == 0.0);
  for (VertexId v : t.vertices()) CHECK(t.position(v) == before[v.index()]);
}

TEST_CASE("a step that moves a vertex to a non-finite position is refused and undone", "[growth][integrator][finite]") {
  // A built-in field with finite velocities 1e307 x that overflow x + dt v.
  Tissue t = rectangularGrid(2, 2);
  const std::vector<Vec3> before(t.positions().begin(), t.positions().end());
  GrowthIntegrator g(std::make_shared<LinearField>(uniformExpansion(1e307)),
                     GrowthOptions{.scheme = IntegrationScheme::Euler, .check_inversion = false});
  try {
    g.step(t, 100.0);
    FAIL("no error");
  } catch (const GeometryError& e) {
    CHECK_THAT(e.what(), Contains("linear field") && Contains("moved vertex 1 from (1, 0, 0) to the non-finite") &&
                             Contains("positions restored"));
    CHECK(e.element().degree == 0);
  }
  CHECK(t.time() == 0.0);
  for (VertexId v : t.vertices()) CHECK(t.position(v) == before[v.index()]);
}

TEST_CASE("a non-finite velocity at a control vertex is reported at that vertex", "[growth][integrator][finite]") {
  Tissue t = rectangularGrid(3, 3);
  GrowthIntegrator g(std::make_shared<ExpressionField>(ExpressionFieldParams{.vy = "1/(x-3)"}),
                     GrowthOptions{.source = VelocitySource::HarmonicFromControl, .check_inversion = false});
  try {
    g.step(t, 0.1);
    FAIL("no error");
  } catch (const GeometryError& e) {
    CHECK_THAT(e.what(), Contains("vy = \"1/(x-3)\" gives inf") && Contains("vertex 3, position (3, 0, 0)"));
  }
}
