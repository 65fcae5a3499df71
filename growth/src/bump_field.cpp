// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/growth/bump_field.hpp"

#include <cmath>
#include <sstream>

#include "tessella/growth/registries.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"

namespace tessella::growth {

BumpField::BumpField(const BumpFieldParams& params) : p_(params) {
  if (!std::isfinite(p_.a) || !std::isfinite(p_.b) || !std::isfinite(p_.h) || !std::isfinite(p_.x0))
    throw InputError("bump field: parameters a, b, h, x0 must be finite");
  if (p_.h <= 0)
    throw InputError("bump field: h = " + formatNumber(p_.h) + " must be > 0 (squared bump width)");
  if (p_.b < 0)
    throw InputError("bump field: b = " + formatNumber(p_.b) +
                     " must be >= 0 (the bump width h + b t would vanish)");
}

Vec3 BumpField::velocity(const Vec3& x, double t) const {
  const double w = p_.h + p_.b * t;  // squared width at time t
  if (w <= 0)
    throw InputError("bump field evaluated at t = " + formatNumber(t) + " where h + b t <= 0");
  const double dx = x.x() - p_.x0;
  const double x2 = dx * dx;
  return Vec3(0.0, p_.a * (1.0 + p_.b * t * x2 / (w * w)) * std::exp(-x2 / w), 0.0);
}

double BumpField::displacement(double x, double t0, double t1) const {
  const double dx = x - p_.x0;
  const double x2 = dx * dx;
  auto f = [&](double t) { return t * std::exp(-x2 / (p_.h + p_.b * t)); };
  return p_.a * (f(t1) - f(t0));
}

std::string BumpField::describe() const {
  std::ostringstream s;
  s << "bump field a=" << p_.a << " b=" << p_.b << " h=" << p_.h << " x0=" << p_.x0;
  return s.str();
}


VelocityFieldEntry bumpFieldEntry() {
  return {"bump",
          "The paper's bump field (figure 17): v = (0, a [1 + b t dx^2/(h + b t)^2] exp(-dx^2/(h + b t)), 0), "
          "dx = x - x0.",
          {ParamSpec("a", ParamType::Float, "Speed at the bump's centre.").byDefault(1.0),
           ParamSpec("b", ParamType::Float, "Widening rate of the bump.").byDefault(1.0).atLeast(0),
           ParamSpec("h", ParamType::Float, "Squared width of the bump at t = 0.").byDefault(1.0).above(0),
           ParamSpec("x0", ParamType::Float, "Abscissa of the bump's centre.").byDefault(0.0)},
          [](const ParamValues& p) {
            return blameParam("h", [&] {
              return std::make_shared<const BumpField>(BumpFieldParams{
                  .a = p.getFloat("a"), .b = p.getFloat("b"), .h = p.getFloat("h"), .x0 = p.getFloat("x0")});
            });
          }};
}

}  // namespace tessella::growth
