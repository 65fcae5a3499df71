// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// The stress a cell's walls carry (virial average of the wall tensions)
// against two closed forms: a regular ring's stress is P I, and over a whole
// tissue in equilibrium sum_c A_c sigma_c = (sum_c P_c A_c) I (the virial
// theorem: the pressure forces are P_c grad A_c and sum_i x_i grad_i A = A I).
#include <catch2/catch.hpp>

#include "ring.hpp"
#include "tessella/generators/voronoi.hpp"
#include "tessella/mechanics/turgor_growth_step.hpp"
#include "tessella/mechanics/wall_state.hpp"
#include "tessella/mechanics/wall_stress.hpp"
#include "tessella/tissue/geometry.hpp"

#include <random>

using namespace tessella;
using namespace tessella::mechanics;

TEST_CASE("wall stress: a pressurised regular ring carries the isotropic stress P I", "[mechanics]") {
  for (int n : {4, 7, 10}) {
    CAPTURE(n);
    Tissue ring = test::ringTissue(n, 1.0);
    TurgorGrowthParams params;
    params.pressure = 0.3;
    params.supports.pin = true;
    params.supports.pin_point = ring.position(VertexId(0));
    params.solver.relative_tolerance = 1e-13;
    turgorGrowthStep(ring, params, 0.0);
    writeCellWallStress(ring);
    const CellId cell = *ring.cells().begin();
    const Mat3 s = ring.cellProperties().get<Sym3>(kWallStressName)[cell].matrix();
    CHECK((s.topLeftCorner<2, 2>() - 0.3 * Eigen::Matrix2d::Identity()).norm() < 1e-10);
    CHECK(ring.cellProperties().get<double>(kStressMaxName)[cell] == Approx(0.3).epsilon(1e-10));
    CHECK(ring.cellProperties().get<double>(kStressMinName)[cell] == Approx(0.3).epsilon(1e-10));
  }
}

TEST_CASE("wall stress: over a tissue in equilibrium the area-weighted stress is the pressures' sum (virial)",
          "[mechanics]") {
  Rectangle domain{Vec3(0, 0, 0), Vec3(5, 4, 0)};
  Tissue tissue = voronoiTissue(randomSeeds(domain, 30, 13), domain, VoronoiOptions{.lloyd_iterations = 1});
  TurgorGrowthParams params;
  params.supports.pin = true;
  params.supports.pin_point = Vec3(2.5, 2, 0);
  params.solver.relative_tolerance = 1e-13;
  prepareTurgorState(tissue, params);
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> u(0.05, 0.2);
  auto& pressure = tissue.cellProperties().get<double>(kTurgorPressureName);
  for (CellId c : tissue.cells()) pressure[c] = u(rng);
  turgorGrowthStep(tissue, params, 0.0);
  writeCellWallStress(tissue);
  Mat3 sum = Mat3::Zero();
  double work = 0.0;
  const auto& stress = tissue.cellProperties().get<Sym3>(kWallStressName);
  for (CellId c : tissue.cells()) {
    sum += cellMeasure(tissue, c) * stress[c].matrix();
    work += pressure[c] * cellMeasure(tissue, c);
  }
  CHECK((sum.topLeftCorner<2, 2>() - work * Eigen::Matrix2d::Identity()).norm() < 1e-9 * work);
  // Uneven pressures: the cells' stresses differ and are not all isotropic.
  const auto& high = tissue.cellProperties().get<double>(kStressMaxName);
  const auto& low = tissue.cellProperties().get<double>(kStressMinName);
  double anisotropy = 0.0;
  for (CellId c : tissue.cells()) anisotropy = std::max(anisotropy, (high[c] - low[c]) / high[c]);
  CHECK(anisotropy > 0.05);
}
