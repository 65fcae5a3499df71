#include "tessella/growth/meristem_field.hpp"

#include <cmath>
#include <sstream>

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

}  // namespace tessella::growth
