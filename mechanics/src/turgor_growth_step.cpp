// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/mechanics/turgor_growth_step.hpp"

#include "tessella/mechanics/planar_dofs.hpp"
#include "tessella/mechanics/tissue_membranes.hpp"
#include "tessella/mechanics/wall_spring_model.hpp"
#include "tessella/mechanics/wall_state.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"
#include "tessella/tissue/tissue.hpp"

#include <algorithm>
#include <cmath>

namespace tessella::mechanics {

void TurgorGrowthParams::check() const {
  auto positive = [](const char* name, double v) {
    if (!(v > 0.0 && std::isfinite(v)))
      throw InputError(std::string("mechanics: ") + name + " " + formatNumber(v) + " must be > 0 and finite");
  };
  positive("youngs_modulus", youngs_modulus);
  positive("thickness", thickness);
  if (!std::isfinite(pressure)) throw InputError("mechanics: pressure " + formatNumber(pressure) + " must be finite");
  growth.check();
}

void prepareTurgorState(Tissue& tissue, const TurgorGrowthParams& params) {
  requirePlanar(tissue, "the mechanics step");
  params.check();
  restLengths(tissue);
  wallOutput(tissue, kWallStrainName);
  wallOutput(tissue, kWallTensionName);
  wallOutput(tissue, kGrowthRateName);
  cellOutput(tissue, kTurgorPressureName, params.pressure);
}

TurgorStepReport turgorGrowthStep(Tissue& tissue, const TurgorGrowthParams& params, double dt) {
  if (!(dt >= 0.0 && std::isfinite(dt))) throw InputError("mechanics: step dt " + formatNumber(dt) + " must be >= 0");
  prepareTurgorState(tissue, params);
  TurgorStepReport report;
  report.walls_initialised = initialiseRestLengths(tissue);

  PropertyColumn<double>& rest = restLengths(tissue);
  const std::vector<double> stiffness(tissue.slots(1), params.youngs_modulus * params.thickness);
  const PropertyColumn<double>& pressure = tissue.cellProperties().get<double>(kTurgorPressureName);
  const WallSpringModel model = WallSpringModel::fromTissue(tissue, rest.values(), stiffness, pressure.values());

  Eigen::VectorXd x = planarDofs(tissue);
  report.equilibrium = solveEquilibrium(model, x, supportMask(tissue, params.supports), params.solver);
  setPlanarDofs(tissue, x);

  PropertyColumn<double>& strain = wallOutput(tissue, kWallStrainName);
  PropertyColumn<double>& tension = wallOutput(tissue, kWallTensionName);
  PropertyColumn<double>& growth_rate = wallOutput(tissue, kGrowthRateName);
  const auto& element = model.springElement();
  const std::vector<double> phi = wallExtensibilities(tissue, params.growth.extensibility);
  double rate_sum = 0.0;
  for (std::size_t i = 0; i < model.springs().size(); ++i) {
    const Index w = element[i];
    const double e = model.strain(x, i);
    strain[w] = e;
    tension[w] = model.tension(x, i);
    report.max_strain = i == 0 ? e : std::max(report.max_strain, e);
    StrainGrowthLaw law = params.growth;
    law.extensibility = phi[w];
    rate_sum += law.relativeRate(e);
    const double before = rest[w];
    rest[w] = law.grownRestLength(before, e, dt);
    growth_rate[w] = dt > 0.0 && before > 0.0 ? (rest[w] - before) / (before * dt) : 0.0;
  }
  if (!model.springs().empty()) report.mean_growth_rate = rate_sum / static_cast<double>(model.springs().size());
  return report;
}

}  // namespace tessella::mechanics
