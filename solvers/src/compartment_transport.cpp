// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/solvers/compartment_transport.hpp"

#include "tessella/solvers/errors.hpp"
#include "tessella/tissue/format.hpp"

#include <cmath>
#include <sstream>

namespace tessella::solvers {

namespace {

[[noreturn]] void bad(const std::string& what) { throw InvalidProblemError("CompartmentTransport: " + what); }

bool nonneg(double v) { return std::isfinite(v) && v >= 0.0; }

}  // namespace

CompartmentTransport::CompartmentTransport(CompartmentNetwork network, TimeScheme scheme)
    : network_(std::move(network)), scheme_(scheme) {
  const auto n = network_.volume.size();
  for (Eigen::Index i = 0; i < n; ++i)
    if (!(std::isfinite(network_.volume[i]) && network_.volume[i] > 0.0)) {
      std::ostringstream msg;
      msg << "volume of cell " << i << " is " << formatNumber(network_.volume[i]) << "; it must be > 0";
      bad(msg.str());
    }
  if (network_.decay.size() != 0 && network_.decay.size() != n) bad("decay must be empty or have one value per cell");
  if (network_.production.size() != 0 && network_.production.size() != n)
    bad("production must be empty or have one value per cell");
  if (network_.decay.size() && !network_.decay.unaryExpr([](double v) { return nonneg(v) ? 0.0 : 1.0; }).isZero())
    bad("decay must be finite and >= 0");
  if (network_.production.size() && !network_.production.allFinite()) bad("production must be finite");

  std::vector<Eigen::Triplet<double>> t;
  for (std::size_t w = 0; w < network_.walls.size(); ++w) {
    const CompartmentWall& wall = network_.walls[w];
    std::ostringstream where;
    where << "wall " << w << " (cells " << wall.cell_i << ", " << wall.cell_j << ")";
    if (wall.cell_i < 0 || wall.cell_j < 0 || wall.cell_i >= n || wall.cell_j >= n || wall.cell_i == wall.cell_j)
      bad(where.str() + ": cell indices must be distinct and in [0, " + std::to_string(n) + ")");
    if (!nonneg(wall.area) || !nonneg(wall.permeability) || !nonneg(wall.polar_ij) || !nonneg(wall.polar_ji))
      bad(where.str() + ": area, permeability and polar rates must be finite and >= 0");
    const int i = wall.cell_i, j = wall.cell_j;
    const double pa = wall.permeability * wall.area;
    const double tij = wall.polar_ij * wall.area, tji = wall.polar_ji * wall.area;
    // Each column (source cell) gets -x on its own row and +x on the other: column sums are 0.
    t.emplace_back(i, i, -pa - tij);
    t.emplace_back(j, i, pa + tij);
    t.emplace_back(j, j, -pa - tji);
    t.emplace_back(i, j, pa + tji);
  }
  source_ = Eigen::VectorXd::Zero(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    if (network_.decay.size()) t.emplace_back(i, i, -network_.decay[i] * network_.volume[i]);
    if (network_.production.size()) source_[i] = network_.production[i] * network_.volume[i];
  }
  B_.resize(n, n);
  B_.setFromTriplets(t.begin(), t.end());
}

Eigen::VectorXd CompartmentTransport::rate(const Eigen::VectorXd& c) const {
  if (c.size() != network_.volume.size()) bad("concentration vector has the wrong size");
  return (B_ * c + source_).cwiseQuotient(network_.volume);
}

void CompartmentTransport::step(Eigen::VectorXd& c, double dt) {
  if (c.size() != network_.volume.size()) bad("concentration vector has the wrong size");
  if (!(dt > 0.0) || !std::isfinite(dt)) bad("dt must be > 0");
  const double theta = scheme_ == TimeScheme::ImplicitEuler ? 1.0 : 0.5;
  if (factor_dt_ != dt) {
    // (V - theta dt B) c^{n+1} = (V + (1 - theta) dt B) c^n + dt s: summing rows,
    // the B terms cancel (zero column sums), so sum V c is conserved.
    Eigen::SparseMatrix<double> lhs = -theta * dt * B_;
    for (Eigen::Index i = 0; i < lhs.rows(); ++i) lhs.coeffRef(i, i) += network_.volume[i];
    lhs.makeCompressed();
    factor_dt_ = 0.0;
    lu_.compute(lhs);
    if (lu_.info() != Eigen::Success) throw FactorizationError("CompartmentTransport: sparse LU failed: " + lu_.lastErrorMessage());
    factor_dt_ = dt;
  }
  Eigen::VectorXd b = network_.volume.cwiseProduct(c) + dt * source_;
  if (theta < 1.0) b += (1.0 - theta) * dt * (B_ * c);
  Eigen::VectorXd next = lu_.solve(b);
  if (lu_.info() != Eigen::Success || !next.allFinite()) throw FactorizationError("CompartmentTransport: solve failed");
  c = std::move(next);
}

void CompartmentTransport::advance(Eigen::VectorXd& c, double duration, double dt) {
  if (!(duration >= 0.0) || !(dt > 0.0)) bad("advance needs duration >= 0 and dt > 0");
  const auto steps = static_cast<long>(std::ceil(duration / dt * (1.0 - 1e-12)));
  for (long k = 0; k < steps; ++k) step(c, duration / static_cast<double>(steps));
}

double CompartmentTransport::totalAmount(const Eigen::VectorXd& c) const {
  if (c.size() != network_.volume.size()) bad("concentration vector has the wrong size");
  return network_.volume.dot(c);
}

}  // namespace tessella::solvers
