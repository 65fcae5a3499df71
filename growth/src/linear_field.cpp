// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/growth/linear_field.hpp"

#include <sstream>

#include "tessella/growth/parallel_threshold.hpp"
#include "tessella/growth/registries.hpp"
#include "tessella/tissue/errors.hpp"

namespace tessella::growth {

LinearField::LinearField(const Mat3& rate, const Vec3& center) : rate_(rate), center_(center) {
  if (!rate_.allFinite() || !center_.allFinite())
    throw InputError("linear growth field: the rate tensor and centre must be finite");
}

Vec3 LinearField::velocity(const Vec3& x, double) const { return rate_ * (x - center_); }

void LinearField::velocities(std::span<const Vec3> x, double, std::span<Vec3> out) const {
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(x.size());
#pragma omp parallel for schedule(static, kInterleavedChunk) if(n >= kParallelMinItems)
  for (std::ptrdiff_t i = 0; i < n; ++i) out[i] = rate_ * (x[i] - center_);
}

std::string LinearField::describe() const {
  std::ostringstream s;
  s << "linear field G = [" << rate_.row(0) << "; " << rate_.row(1) << "; " << rate_.row(2)
    << "] about (" << center_.transpose() << ")";
  return s.str();
}

LinearField uniformExpansion(double rate, const Vec3& center) {
  return LinearField(rate * Mat3::Identity(), center);
}

LinearField anisotropicGrowth(const Vec3& axis_rates, const Vec3& center) {
  return LinearField(axis_rates.asDiagonal().toDenseMatrix(), center);
}


VelocityFieldEntry uniformFieldEntry() {
  return {"uniform", "Uniform expansion: v = rate (x - center).",
          {ParamSpec("rate", ParamType::Float, "Relative growth rate of lengths (areas grow at 2 rate).")
               .byDefault(0.1),
           ParamSpec("center", ParamType::Vec3, "Fixed point of the expansion.")
               .byDefault(std::vector<double>{0, 0, 0})},
          [](const ParamValues& p) {
            return blameParam("rate", [&] {
              return std::make_shared<const LinearField>(uniformExpansion(p.getFloat("rate"), p.getVec3("center")));
            });
          }};
}

VelocityFieldEntry anisotropicFieldEntry() {
  return {"anisotropic", "Anisotropic (per-axis) growth: v = diag(rates) (x - center).",
          {ParamSpec("rates", ParamType::Vec3, "Relative growth rates along x, y and z.")
               .byDefault(std::vector<double>{0.1, 0.0, 0.0}),
           ParamSpec("center", ParamType::Vec3, "Fixed point of the growth.").byDefault(std::vector<double>{0, 0, 0})},
          [](const ParamValues& p) {
            return blameParam("rates", [&] {
              return std::make_shared<const LinearField>(anisotropicGrowth(p.getVec3("rates"), p.getVec3("center")));
            });
          }};
}

}  // namespace tessella::growth
