// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/growth/radial_field.hpp"

#include <cmath>
#include <sstream>

#include "tessella/growth/registries.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"

namespace tessella::growth {

RadialField::RadialField(const RadialFieldParams& params) : p_(params) {
  if (!p_.center.allFinite() || !p_.axis.allFinite() || !std::isfinite(p_.rate) ||
      !std::isfinite(p_.exponent))
    throw InputError("radial growth field: centre, axis, rate and exponent must be finite");
  if (p_.exponent < 0)
    throw InputError("radial growth field: exponent = " + formatNumber(p_.exponent) +
                     " must be >= 0 (a negative one is singular at the centre)");
  if (p_.axis.norm() > 0) p_.axis.normalize();
}

Vec3 RadialField::velocity(const Vec3& x, double) const {
  Vec3 d = x - p_.center;
  if (p_.axis.squaredNorm() > 0) d -= d.dot(p_.axis) * p_.axis;
  const double r = d.norm();
  if (r == 0) return Vec3::Zero();  // the centre does not move (for any exponent)
  // speed = rate * r^exponent along d / r
  return p_.rate * std::pow(r, p_.exponent - 1.0) * d;
}

std::string RadialField::describe() const {
  std::ostringstream s;
  s << "radial field rate " << p_.rate << " exponent " << p_.exponent << " from ("
    << p_.center.transpose() << ")";
  if (p_.axis.squaredNorm() > 0) s << " axis (" << p_.axis.transpose() << ")";
  return s.str();
}


VelocityFieldEntry radialFieldEntry() {
  return {"radial", "Radial growth: points move away from a centre (or an axis) at speed rate * distance^exponent.",
          {ParamSpec("center", ParamType::Vec3, "Centre of the growth.").byDefault(std::vector<double>{0, 0, 0}),
           ParamSpec("axis", ParamType::Vec3,
                     "Zero: spherical growth from the centre; otherwise growth away from this axis through the centre.")
               .byDefault(std::vector<double>{0, 0, 0}),
           ParamSpec("rate", ParamType::Float, "Speed factor.").byDefault(0.1),
           ParamSpec("exponent", ParamType::Float,
                     "1: uniform expansion; 0: constant outward speed; > 1: growth concentrated at the rim.")
               .byDefault(1.0)
               .atLeast(0)},
          [](const ParamValues& p) {
            return blameParam("rate", [&] {
              return std::make_shared<const RadialField>(
                  RadialFieldParams{.center = p.getVec3("center"), .axis = p.getVec3("axis"),
                                    .rate = p.getFloat("rate"), .exponent = p.getFloat("exponent")});
            });
          }};
}

}  // namespace tessella::growth
