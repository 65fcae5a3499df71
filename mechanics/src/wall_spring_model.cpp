// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/mechanics/wall_spring_model.hpp"

#include "tessella/mechanics/planar_dofs.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"
#include "tessella/tissue/tissue.hpp"

#include <cmath>
#include <string>

namespace tessella::mechanics {
namespace {

struct SpringGeometry {
  double dx, dy, length;
};

SpringGeometry springGeometry(const Eigen::VectorXd& x, const WallSpring& s) {
  const double dx = x[2 * s.b] - x[2 * s.a];
  const double dy = x[2 * s.b + 1] - x[2 * s.a + 1];
  return {dx, dy, std::hypot(dx, dy)};
}

}  // namespace

WallSpringModel::WallSpringModel(std::size_t num_points, std::vector<WallSpring> springs,
                                 std::vector<PressurisedCell> cells)
    : num_points_(num_points), springs_(std::move(springs)), cells_(std::move(cells)) {
  for (std::size_t i = 0; i < springs_.size(); ++i) {
    const WallSpring& s = springs_[i];
    const std::string name = "wall spring " + std::to_string(i);
    if (s.a >= num_points_ || s.b >= num_points_ || s.a == s.b)
      throw InputError(name + ": end points " + std::to_string(s.a) + ", " + std::to_string(s.b) +
                       " must be distinct and below " + std::to_string(num_points_));
    if (!(s.rest_length > 0.0 && std::isfinite(s.rest_length)))
      throw InputError(name + ": rest length " + formatNumber(s.rest_length) + " must be > 0");
    if (!(s.stiffness > 0.0 && std::isfinite(s.stiffness)))
      throw InputError(name + ": stiffness " + formatNumber(s.stiffness) + " must be > 0");
  }
  for (std::size_t j = 0; j < cells_.size(); ++j) {
    const PressurisedCell& c = cells_[j];
    const std::string name = "pressurised cell " + std::to_string(j);
    if (c.loop.size() < 3) throw InputError(name + ": a loop needs at least 3 points");
    for (Index p : c.loop)
      if (p >= num_points_) throw InputError(name + ": point " + std::to_string(p) + " out of range");
    if (!std::isfinite(c.pressure))
      throw InputError(name + ": pressure " + formatNumber(c.pressure) + " is not finite");
  }
  spring_element_.resize(springs_.size());
  for (std::size_t i = 0; i < springs_.size(); ++i) spring_element_[i] = static_cast<Index>(i);
}

WallSpringModel WallSpringModel::fromTissue(const Tissue& tissue, const std::vector<double>& rest_length,
                                            const std::vector<double>& stiffness,
                                            const std::vector<double>& pressure) {
  requirePlanar(tissue, "the wall-spring model");
  const CellComplex& topo = tissue.topology();
  if (rest_length.size() < tissue.slots(1) || stiffness.size() < tissue.slots(1))
    throw InputError("the wall-spring model: rest lengths and stiffnesses need one value per wall slot (" +
                     std::to_string(tissue.slots(1)) + ")");
  if (pressure.size() < tissue.cellSlots())
    throw InputError("the wall-spring model: pressures need one value per cell slot (" +
                     std::to_string(tissue.cellSlots()) + ")");
  std::vector<WallSpring> springs;
  std::vector<Index> element;
  springs.reserve(tissue.numEdges());
  for (EdgeId e : tissue.edges()) {
    const auto ends = topo.edgeVertices(e);
    const double L0 = rest_length[e.index()], S = stiffness[e.index()];
    if (!(L0 > 0.0 && std::isfinite(L0)))
      throw InputError("the wall-spring model: wall " + std::to_string(e.index()) + " has rest length " +
                       formatNumber(L0) + " (must be > 0)");
    if (!(S > 0.0 && std::isfinite(S)))
      throw InputError("the wall-spring model: wall " + std::to_string(e.index()) + " has stiffness " +
                       formatNumber(S) + " (must be > 0)");
    springs.push_back({ends[0].index(), ends[1].index(), L0, S});
    element.push_back(e.index());
  }
  std::vector<PressurisedCell> cells;
  cells.reserve(tissue.numCells());
  for (FaceId f : tissue.faces()) {
    const auto loop = topo.faceVertices(f);
    PressurisedCell c;
    c.loop.reserve(loop.size());
    for (VertexId v : loop) c.loop.push_back(v.index());
    c.pressure = pressure[f.index()];
    cells.push_back(std::move(c));
  }
  WallSpringModel model(tissue.slots(0), std::move(springs), std::move(cells));
  model.spring_element_ = std::move(element);
  return model;
}

double WallSpringModel::length(const Eigen::VectorXd& x, std::size_t i) const {
  return springGeometry(x, springs_[i]).length;
}

double WallSpringModel::strain(const Eigen::VectorXd& x, std::size_t i) const {
  return (length(x, i) - springs_[i].rest_length) / springs_[i].rest_length;
}

double WallSpringModel::tension(const Eigen::VectorXd& x, std::size_t i) const {
  return springs_[i].stiffness * strain(x, i);
}

double WallSpringModel::area(const Eigen::VectorXd& x, std::size_t j) const {
  const auto& loop = cells_[j].loop;
  double twice = 0.0;
  for (std::size_t i = 0, n = loop.size(); i < n; ++i) {
    const Index p = loop[i], q = loop[(i + 1) % n];
    twice += x[2 * p] * x[2 * q + 1] - x[2 * q] * x[2 * p + 1];
  }
  return 0.5 * twice;
}

double WallSpringModel::energy(const Eigen::VectorXd& x) const {
  double e = 0.0;
  for (const WallSpring& s : springs_) {
    const double stretch = springGeometry(x, s).length - s.rest_length;
    e += 0.5 * (s.stiffness / s.rest_length) * stretch * stretch;
  }
  for (std::size_t j = 0; j < cells_.size(); ++j) e -= cells_[j].pressure * area(x, j);
  return e;
}

double WallSpringModel::energyScale(const Eigen::VectorXd& x) const {
  double e = 0.0;
  for (const WallSpring& s : springs_) {
    const double stretch = springGeometry(x, s).length - s.rest_length;
    e += 0.5 * (s.stiffness / s.rest_length) * stretch * stretch;
  }
  for (std::size_t j = 0; j < cells_.size(); ++j) e += std::abs(cells_[j].pressure * area(x, j));
  return e;
}

// dA/dx_i = (y_{i+1} - y_{i-1}) / 2, dA/dy_i = (x_{i-1} - x_{i+1}) / 2.
void WallSpringModel::gradient(const Eigen::VectorXd& x, Eigen::VectorXd& g) const {
  g.setZero(size());
  for (const WallSpring& s : springs_) {
    const SpringGeometry sg = springGeometry(x, s);
    const double f = (s.stiffness / s.rest_length) * (sg.length - s.rest_length) / sg.length;  // T / L
    g[2 * s.b] += f * sg.dx;
    g[2 * s.b + 1] += f * sg.dy;
    g[2 * s.a] -= f * sg.dx;
    g[2 * s.a + 1] -= f * sg.dy;
  }
  for (const PressurisedCell& c : cells_) {
    const std::size_t n = c.loop.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Index p = c.loop[i], next = c.loop[(i + 1) % n], prev = c.loop[(i + n - 1) % n];
      g[2 * p] -= c.pressure * 0.5 * (x[2 * next + 1] - x[2 * prev + 1]);
      g[2 * p + 1] -= c.pressure * 0.5 * (x[2 * prev] - x[2 * next]);
    }
  }
}

double WallSpringModel::forceScale(const Eigen::VectorXd& x) const {
  Eigen::VectorXd a = Eigen::VectorXd::Zero(size());
  for (const WallSpring& s : springs_) {
    const SpringGeometry sg = springGeometry(x, s);
    const double t = std::abs((s.stiffness / s.rest_length) * (sg.length - s.rest_length));
    a[2 * s.a] += t;
    a[2 * s.a + 1] += t;
    a[2 * s.b] += t;
    a[2 * s.b + 1] += t;
  }
  for (const PressurisedCell& c : cells_) {
    const std::size_t n = c.loop.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Index p = c.loop[i], next = c.loop[(i + 1) % n], prev = c.loop[(i + n - 1) % n];
      a[2 * p] += std::abs(c.pressure * 0.5 * (x[2 * next + 1] - x[2 * prev + 1]));
      a[2 * p + 1] += std::abs(c.pressure * 0.5 * (x[2 * prev] - x[2 * next]));
    }
  }
  return a.norm();
}

// Spring: with u = d / L, K = k [u u^T + (1 - L0 / L) (I - u u^T)] on (b, b)
// and (a, a), -K on (a, b) and (b, a). Area: d2A/dx_i dy_{i+1} = 1/2,
// d2A/dy_i dx_{i+1} = -1/2 (and the symmetric entries).
void WallSpringModel::hessian(const Eigen::VectorXd& x, std::vector<Triplet>& entries) const {
  entries.reserve(entries.size() + 16 * springs_.size());
  for (const WallSpring& s : springs_) {
    const SpringGeometry sg = springGeometry(x, s);
    const double k = s.stiffness / s.rest_length;
    const double ux = sg.dx / sg.length, uy = sg.dy / sg.length;
    const double c = 1.0 - s.rest_length / sg.length;
    const double kxx = k * (ux * ux + c * (1.0 - ux * ux));
    const double kyy = k * (uy * uy + c * (1.0 - uy * uy));
    const double kxy = k * (1.0 - c) * ux * uy;
    const Index dofs[2] = {s.a, s.b};
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) {
        const double sign = i == j ? 1.0 : -1.0;
        const Index r = 2 * dofs[i], q = 2 * dofs[j];
        entries.emplace_back(r, q, sign * kxx);
        entries.emplace_back(r, q + 1, sign * kxy);
        entries.emplace_back(r + 1, q, sign * kxy);
        entries.emplace_back(r + 1, q + 1, sign * kyy);
      }
  }
  for (const PressurisedCell& c : cells_) {
    const double h = -0.5 * c.pressure;  // of -P A
    const std::size_t n = c.loop.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Index p = c.loop[i], q = c.loop[(i + 1) % n];
      entries.emplace_back(2 * p, 2 * q + 1, h);
      entries.emplace_back(2 * q + 1, 2 * p, h);
      entries.emplace_back(2 * p + 1, 2 * q, -h);
      entries.emplace_back(2 * q, 2 * p + 1, -h);
    }
  }
}

}  // namespace tessella::mechanics
