// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

#include "tessella/growth/bump_field.hpp"
#include "tessella/growth/linear_field.hpp"
#include "tessella/growth/meristem_field.hpp"
#include "tessella/growth/radial_field.hpp"
#include "tessella/tissue/errors.hpp"

using namespace tessella;
using namespace tessella::growth;

TEST_CASE("uniform expansion is v = r (x - c)", "[growth][fields]") {
  const LinearField f = uniformExpansion(0.3, Vec3(1, 2, 3));
  const Vec3 v = f.velocity(Vec3(2, 0, 3), 5.0);
  CHECK(v.isApprox(Vec3(0.3, -0.6, 0.0)));
}

TEST_CASE("anisotropic growth scales each axis at its own rate", "[growth][fields]") {
  const LinearField f = anisotropicGrowth(Vec3(1, 0.5, 0));
  CHECK(f.velocity(Vec3(2, 2, 2), 0).isApprox(Vec3(2, 1, 0)));
  CHECK_THROWS_AS(LinearField(Mat3::Constant(NAN)), InputError);
}

TEST_CASE("batched velocities equal pointwise ones", "[growth][fields]") {
  Mat3 g;
  g << 0.1, 0.2, 0, -0.3, 0.05, 0, 0, 0, 0.4;
  const LinearField f(g, Vec3(0.5, 0.5, 0));
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-5, 5);
  std::vector<Vec3> x(1000), out(1000);
  for (auto& p : x) p = Vec3(u(rng), u(rng), u(rng));
  f.velocities(x, 1.0, out);
  const RadialField r(RadialFieldParams{.center = Vec3::Zero(), .axis = Vec3::Zero(), .rate = 2.0,
                                        .exponent = 1.5});
  std::vector<Vec3> out_r(1000);
  r.velocities(x, 1.0, out_r);
  for (std::size_t i = 0; i < x.size(); ++i) {
    CHECK(out[i] == f.velocity(x[i], 1.0));
    CHECK(out_r[i] == r.velocity(x[i], 1.0));
  }
}

TEST_CASE("radial growth moves away from the centre or axis", "[growth][fields]") {
  SECTION("exponent 1 about the z axis is planar uniform expansion") {
    const RadialField f(RadialFieldParams{.center = Vec3(1, 1, 0), .axis = Vec3(0, 0, 2), .rate = 0.5,
                                          .exponent = 1.0});
    CHECK(f.velocity(Vec3(3, 1, 7), 0).isApprox(Vec3(1, 0, 0)));
    CHECK(f.velocity(Vec3(1, 1, 7), 0) == Vec3::Zero());
  }
  SECTION("exponent 0 is a constant outward speed") {
    const RadialField f(RadialFieldParams{.rate = 0.25, .exponent = 0.0});
    for (const Vec3& p : {Vec3(1, 0, 0), Vec3(0, 10, 0), Vec3(3, 4, 12)}) {
      const Vec3 v = f.velocity(p, 0);
      CHECK(v.norm() == Approx(0.25));
      CHECK(v.normalized().dot(p.normalized()) == Approx(1.0));
    }
  }
  SECTION("exponent 2 grows speed with the square of the distance") {
    const RadialField f(RadialFieldParams{.rate = 1.0, .exponent = 2.0});
    CHECK(f.velocity(Vec3(3, 0, 0), 0).x() == Approx(9.0));
  }
  CHECK_THROWS_AS(RadialField(RadialFieldParams{.exponent = -1.0}), InputError);
}

TEST_CASE("the bump field is the time derivative of its exact displacement", "[growth][fields]") {
  const BumpField f(BumpFieldParams{.a = 0.7, .b = 0.4, .h = 1.5, .x0 = 0.25});
  // v_y = d/dt [a t exp(-x^2/(h+bt))]: compare with a central difference of
  // the closed-form displacement (an independent derivation of the formula).
  for (double x : {-3.0, -1.0, 0.25, 0.8, 2.5})
    for (double t : {0.0, 0.5, 3.0}) {
      const double eps = 1e-5;
      const double fd = f.displacement(x, t - eps, t + eps) / (2 * eps);
      const Vec3 v = f.velocity(Vec3(x, 9.0, 1.0), t);
      CHECK(v.x() == 0.0);
      CHECK(v.z() == 0.0);
      CHECK(v.y() == Approx(fd).epsilon(1e-8));
    }
  // At the bump's centre the speed is a; far away it vanishes.
  CHECK(f.velocity(Vec3(0.25, 0, 0), 2.0).y() == Approx(0.7));
  CHECK(f.velocity(Vec3(40, 0, 0), 2.0).y() == Approx(0.0).margin(1e-100));
  CHECK_THROWS_AS(BumpField(BumpFieldParams{.h = 0.0}), InputError);
  CHECK_THROWS_AS(BumpField(BumpFieldParams{.b = -1.0}), InputError);
}

TEST_CASE("the meristem field grows slowly in the central zone", "[growth][fields]") {
  const MeristemField f(MeristemFieldParams{.apex = Vec3(0, 0, 1), .axis = Vec3::UnitZ(),
                                            .central_radius = 0.3, .transition_width = 0.02,
                                            .central_rate = 0.01, .peripheral_rate = 0.2});
  CHECK(f.rateAt(0.0) == Approx(0.01).epsilon(1e-6));
  CHECK(f.rateAt(0.3) == Approx(0.105));  // half-way at the zone's edge
  CHECK(f.rateAt(1.0) == Approx(0.2).epsilon(1e-12));
  // Points move away from the apex, at the rate of their distance to the axis.
  const Vec3 p(0.6, 0.0, 0.8);
  CHECK(f.velocity(p, 0).isApprox(f.rateAt(0.6) * (p - Vec3(0, 0, 1))));
  CHECK_THROWS_AS(MeristemField(MeristemFieldParams{.central_radius = 0}), InputError);
  CHECK_THROWS_AS(MeristemField(MeristemFieldParams{.transition_width = -1}), InputError);
  CHECK_THROWS_AS(MeristemField(MeristemFieldParams{.axis = Vec3::Zero()}), InputError);
}
