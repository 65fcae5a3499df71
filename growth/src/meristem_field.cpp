// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/growth/meristem_field.hpp"

#include <cmath>
#include <sstream>

#include "tessella/growth/registries.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"

namespace tessella::growth {

MeristemField::MeristemField(const MeristemFieldParams& params) : p_(params) {
  if (!p_.apex.allFinite() || !p_.axis.allFinite() || !std::isfinite(p_.central_radius) ||
      !std::isfinite(p_.transition_width) || !std::isfinite(p_.central_rate) ||
      !std::isfinite(p_.peripheral_rate))
    throw InputError("meristem field: all parameters must be finite");
  if (p_.axis.norm() == 0) throw InputError("meristem field: axis must be non-zero");
  if (p_.central_radius <= 0)
    throw InputError("meristem field: central_radius = " + formatNumber(p_.central_radius) +
                     " must be > 0");
  if (p_.transition_width <= 0)
    throw InputError("meristem field: transition_width = " + formatNumber(p_.transition_width) +
                     " must be > 0");
  p_.axis.normalize();
}

double MeristemField::rateAt(double rho) const {
  const double s = 0.5 * (1.0 + std::tanh((rho - p_.central_radius) / p_.transition_width));
  return p_.central_rate + (p_.peripheral_rate - p_.central_rate) * s;
}

Vec3 MeristemField::velocity(const Vec3& x, double) const {
  const Vec3 d = x - p_.apex;
  const double rho = (d - d.dot(p_.axis) * p_.axis).norm();
  return rateAt(rho) * d;
}

std::string MeristemField::describe() const {
  std::ostringstream s;
  s << "meristem field apex (" << p_.apex.transpose() << ") central zone radius "
    << p_.central_radius << " rates " << p_.central_rate << " -> " << p_.peripheral_rate;
  return s.str();
}


VelocityFieldEntry meristemFieldEntry() {
  return {"meristem",
          "Shoot apical meristem, a dome with a slow central zone: v = k(rho) (x - apex), k rising smoothly (tanh) "
          "from central_rate inside the central zone to peripheral_rate outside; rho is the distance from the axis.",
          {ParamSpec("apex", ParamType::Vec3, "Summit of the dome.").byDefault(std::vector<double>{0, 0, 0}),
           ParamSpec("axis", ParamType::Vec3, "Axis of the dome.").byDefault(std::vector<double>{0, 0, 1}),
           ParamSpec("central_radius", ParamType::Float, "Radius of the slow central zone.").byDefault(1.0).above(0),
           ParamSpec("transition_width", ParamType::Float, "Width of the transition between the zones.")
               .byDefault(0.2)
               .above(0),
           ParamSpec("central_rate", ParamType::Float, "Relative growth rate in the central zone.").byDefault(0.02),
           ParamSpec("peripheral_rate", ParamType::Float, "Relative growth rate in the peripheral zone.")
               .byDefault(0.1)},
          [](const ParamValues& p) {
            return blameParam("axis", [&] {
              return std::make_shared<const MeristemField>(MeristemFieldParams{
                  .apex = p.getVec3("apex"), .axis = p.getVec3("axis"),
                  .central_radius = p.getFloat("central_radius"), .transition_width = p.getFloat("transition_width"),
                  .central_rate = p.getFloat("central_rate"), .peripheral_rate = p.getFloat("peripheral_rate")});
            });
          }};
}

}  // namespace tessella::growth
