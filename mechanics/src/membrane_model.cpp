// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/mechanics/membrane_model.hpp"

#include "membrane_kinematics.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <string>

namespace tessella::mechanics {
namespace {

using detail::cross;
using detail::Mat32;
using detail::point;
using detail::strainMatrix;
using detail::stressTensor;

}  // namespace

MembraneModel::MembraneModel(std::vector<Vec3> reference, std::vector<std::array<Index, 3>> triangles,
                             MembraneMaterial material, double pressure, const std::vector<Vec3>& fibres)
    : reference_(std::move(reference)), triangles_(std::move(triangles)), material_(material), pressure_(pressure) {
  material_.check();
  law_ = MembraneElementLaw::of(material_);
  if (!std::isfinite(pressure_)) throw InputError("membrane: pressure " + formatNumber(pressure_) + " is not finite");
  if (!fibres.empty() && fibres.size() != triangles_.size())
    throw InputError("membrane: " + std::to_string(fibres.size()) + " fibre directions for " +
                     std::to_string(triangles_.size()) + " triangles");
  elements_.resize(triangles_.size());
  for (std::size_t e = 0; e < triangles_.size(); ++e) {
    const auto& t = triangles_[e];
    for (Index i : t)
      if (i >= reference_.size())
        throw InputError("membrane triangle " + std::to_string(e) + ": point " + std::to_string(i) + " out of range");
    const Vec3 d1 = reference_[t[1]] - reference_[t[0]], d2 = reference_[t[2]] - reference_[t[0]];
    const Vec3 normal = d1.cross(d2);
    const double twice_area = normal.norm();
    if (!(twice_area > 1e-14 * d1.squaredNorm() + 1e-300))
      throw InputError("membrane triangle " + std::to_string(e) + " is degenerate (area " +
                       formatNumber(0.5 * twice_area) + ")");
    const Vec3 n = normal / twice_area;
    Vec3 e1 = d1.normalized();
    if (!fibres.empty()) {
      const Vec3 f = fibres[e] - fibres[e].dot(n) * n;
      if (f.norm() > 1e-8 * fibres[e].norm()) e1 = f.normalized();
    }
    const Vec3 e2 = n.cross(e1);
    Eigen::Matrix2d D;
    D << e1.dot(d1), e1.dot(d2), e2.dot(d1), e2.dot(d2);
    elements_[e].setRestShape(D);
  }
}

void MembraneTriangleRest::setRestShape(const Eigen::Matrix2d& edges) {
  D = edges;
  const Eigen::Matrix2d Dinv = D.inverse();
  g[1] = Dinv.row(0).transpose();
  g[2] = Dinv.row(1).transpose();
  g[0] = -g[1] - g[2];
  area = 0.5 * std::abs(D.determinant());
}

void MembraneModel::setPressure(double pressure) {
  if (!std::isfinite(pressure)) throw InputError("membrane: pressure " + formatNumber(pressure) + " is not finite");
  pressure_ = pressure;
}

double MembraneModel::growRestShape(const Eigen::VectorXd& x, const StrainGrowthLaw& law, double dt) {
  law.check();
  if (!(dt >= 0.0 && std::isfinite(dt))) throw InputError("membrane growth: dt " + formatNumber(dt) + " must be >= 0");
  double fastest = 0.0;
  for (std::size_t e = 0; e < triangles_.size(); ++e) {
    const Mat32 F = deformationGradient(x, e);
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(F.transpose() * F);
    Eigen::Matrix2d G = Eigen::Matrix2d::Zero();
    for (int i = 0; i < 2; ++i) {
      const double rate = law.relativeRate(std::sqrt(std::max(eig.eigenvalues()[i], 0.0)) - 1.0);
      fastest = std::max(fastest, rate);
      G += std::exp(rate * dt) * eig.eigenvectors().col(i) * eig.eigenvectors().col(i).transpose();
    }
    elements_[e].setRestShape(G * elements_[e].D);
  }
  return fastest;
}

Eigen::VectorXd MembraneModel::referenceDofs() const {
  Eigen::VectorXd x(size());
  for (std::size_t i = 0; i < reference_.size(); ++i) x.segment<3>(3 * static_cast<Eigen::Index>(i)) = reference_[i];
  return x;
}

Mat32 MembraneModel::deformationGradient(const Eigen::VectorXd& x, std::size_t e) const {
  Mat32 F = Mat32::Zero();
  for (int a = 0; a < 3; ++a) F += point(x, triangles_[e][a]) * elements_[e].g[a].transpose();
  return F;
}

double MembraneModel::volume(const Eigen::VectorXd& x) const {
  double v = 0.0;
  for (const auto& t : triangles_) v += point(x, t[0]).dot(point(x, t[1]).cross(point(x, t[2])));
  return v / 6.0;
}

double MembraneModel::energy(const Eigen::VectorXd& x) const {
  double w = 0.0;
  const double t = material_.thickness;
  for (std::size_t e = 0; e < triangles_.size(); ++e) {
    w += t * elements_[e].area * law_.at(deformationGradient(x, e), false).energy;
  }
  return w - pressure_ * volume(x);
}

double MembraneModel::energyScale(const Eigen::VectorXd& x) const {
  return energy(x) + 2.0 * std::abs(pressure_ * volume(x));
}

void MembraneModel::gradient(const Eigen::VectorXd& x, Eigen::VectorXd& g) const {
  g.setZero(size());
  const double t = material_.thickness;
  for (std::size_t e = 0; e < triangles_.size(); ++e) {
    const Mat32 F = deformationGradient(x, e);
    const Eigen::Matrix2d S = stressTensor(law_.at(F, false).stress);
    const auto& tri = triangles_[e];
    for (int a = 0; a < 3; ++a)
      g.segment<3>(3 * static_cast<Eigen::Index>(tri[a])) += t * elements_[e].area * F * (S * elements_[e].g[a]);
    // -P dV/dx_a = -P (x_b x x_c) / 6, (a, b, c) cyclic.
    for (int a = 0; a < 3; ++a)
      g.segment<3>(3 * static_cast<Eigen::Index>(tri[a])) -=
          pressure_ / 6.0 * point(x, tri[(a + 1) % 3]).cross(point(x, tri[(a + 2) % 3]));
  }
}

double MembraneModel::forceScale(const Eigen::VectorXd& x) const {
  Eigen::VectorXd s = Eigen::VectorXd::Zero(size());
  const double t = material_.thickness;
  for (std::size_t e = 0; e < triangles_.size(); ++e) {
    const Mat32 F = deformationGradient(x, e);
    const Eigen::Matrix2d S = stressTensor(law_.at(F, false).stress);
    const auto& tri = triangles_[e];
    for (int a = 0; a < 3; ++a) {
      const Eigen::Index i = 3 * static_cast<Eigen::Index>(tri[a]);
      s.segment<3>(i) += (t * elements_[e].area * F * (S * elements_[e].g[a])).cwiseAbs();
      s.segment<3>(i) +=
          (pressure_ / 6.0 * point(x, tri[(a + 1) % 3]).cross(point(x, tri[(a + 2) % 3]))).cwiseAbs();
    }
  }
  return s.norm();
}

// K_ab = t A0 (B_a^T D B_b + (g_a . S g_b) I), D = dS/dE (St Venant-Kirchhoff: Q);
// pressure: d2V/dx_a dx_b = -[x_c]x / 6, d2V/dx_a dx_c = [x_b]x / 6 for (a, b, c) cyclic.
void MembraneModel::hessian(const Eigen::VectorXd& x, std::vector<Triplet>& entries) const {
  entries.reserve(entries.size() + 2 * 81 * triangles_.size());
  const double t = material_.thickness;
  auto add = [&](Index a, Index b, const Eigen::Matrix3d& block) {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) entries.emplace_back(3 * a + i, 3 * b + j, block(i, j));
  };
  for (std::size_t e = 0; e < triangles_.size(); ++e) {
    const Mat32 F = deformationGradient(x, e);
    const MembraneResponse response = law_.at(F, true);
    const Eigen::Matrix2d S = stressTensor(response.stress);
    const Element& el = elements_[e];
    const auto& tri = triangles_[e];
    std::array<Eigen::Matrix3d, 3> B;
    for (int a = 0; a < 3; ++a) B[a] = strainMatrix(F, el.g[a]);
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        const Eigen::Matrix3d K = t * el.area *
                                  (B[a].transpose() * response.tangent * B[b] +
                                   el.g[a].dot(S * el.g[b]) * Eigen::Matrix3d::Identity());
        add(tri[a], tri[b], K);
      }
    for (int a = 0; a < 3; ++a) {
      const Index ia = tri[a], ib = tri[(a + 1) % 3], ic = tri[(a + 2) % 3];
      add(ia, ib, pressure_ / 6.0 * cross(point(x, ic)));   // -P * (-[x_c]x / 6)
      add(ia, ic, -pressure_ / 6.0 * cross(point(x, ib)));  // -P * ([x_b]x / 6)
    }
  }
}

Eigen::Matrix3d MembraneModel::tension(const Eigen::VectorXd& x, std::size_t e) const {
  const Mat32 F = deformationGradient(x, e);
  const Eigen::Matrix2d S = stressTensor(law_.at(F, false).stress);
  const double J = std::sqrt((F.transpose() * F).determinant());
  return material_.thickness / J * F * S * F.transpose();
}

}  // namespace tessella::mechanics
