// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/mechanics/fan_membrane_model.hpp"

#include "membrane_kinematics.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <string>

namespace tessella::mechanics {
namespace {

using detail::cross;
using detail::point;
using detail::strainMatrix;
using detail::stressTensor;

Eigen::Vector3d loopMean(const Eigen::VectorXd& x, const std::vector<Index>& loop) {
  Eigen::Vector3d a = Eigen::Vector3d::Zero();
  for (Index v : loop) a += point(x, v);
  return a / static_cast<double>(loop.size());
}

// The apex of a loop: its vertex mean (the mean fan), or sum_k w_k x_k.
Eigen::Vector3d apexPoint(const Eigen::VectorXd& x, const std::vector<Index>& loop, const MembraneTriangulation& t) {
  if (t.kind != MembraneTriangulation::Kind::KernelFan) return loopMean(x, loop);
  Eigen::Vector3d a = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < loop.size(); ++k) a += t.apex_weights[k] * point(x, loop[k]);
  return a;
}

// The corners of triangle i of a loop (apex computed by the caller).
std::array<Eigen::Vector3d, 3> triangleCorners(const Eigen::VectorXd& x, const std::vector<Index>& loop,
                                               const MembraneTriangulation& t, const Eigen::Vector3d& apex,
                                               std::size_t i) {
  const std::array<int, 3> c = t.triangle(i, loop.size());
  std::array<Eigen::Vector3d, 3> out;
  for (int a = 0; a < 3; ++a)
    out[a] = c[a] == MembraneTriangulation::kApex ? apex : point(x, loop[static_cast<std::size_t>(c[a])]);
  return out;
}

}  // namespace

std::vector<RestMetric> FanMembraneModel::currentMetrics(const Eigen::VectorXd& x, const std::vector<Index>& loop,
                                                         const MembraneTriangulation& triangulation) {
  const Eigen::Vector3d a = apexPoint(x, loop, triangulation);
  std::vector<RestMetric> m(triangulation.size(loop.size()));
  for (std::size_t i = 0; i < m.size(); ++i) {
    const auto c = triangleCorners(x, loop, triangulation, a, i);
    const Eigen::Vector3d d1 = c[1] - c[0], d2 = c[2] - c[0];
    m[i] = RestMetric(d1.squaredNorm(), d1.dot(d2), d2.squaredNorm());
  }
  return m;
}

FanMembraneModel::FanMembraneModel(const Eigen::VectorXd& positions, std::vector<MembranePolygon> polygons,
                                   MembraneMaterial material, const Vec3& origin)
    : size_(positions.size()), polygons_(std::move(polygons)), material_(material), origin_(origin) {
  material_.check();
  const Index points = static_cast<Index>(size_ / 3);
  first_element_.assign(1, 0);
  for (std::size_t f = 0; f < polygons_.size(); ++f) {
    const MembranePolygon& p = polygons_[f];
    const std::string name = "membrane polygon " + std::to_string(f);
    if (p.loop.size() < 3) throw InputError(name + ": a loop of " + std::to_string(p.loop.size()) + " vertices");
    p.triangulation.check(p.loop.size(), name);
    const std::size_t triangles = p.triangulation.size(p.loop.size());
    if (p.elastic && p.rest.size() != triangles)
      throw InputError(name + ": " + std::to_string(p.rest.size()) + " rest metrics for " +
                       std::to_string(triangles) + " triangles");
    if (!(p.young_scale > 0.0 && std::isfinite(p.young_scale)))
      throw InputError(name + ": Young's modulus scale " + formatNumber(p.young_scale) + " must be > 0");
    if (!std::isfinite(p.pressure)) throw InputError(name + ": pressure " + formatNumber(p.pressure));
    MembraneMaterial own = material_;
    if (p.fibre_ratio != 0.0) {
      own.fibre_ratio = p.fibre_ratio;
      try {
        own.check();
      } catch (const InputError& e) {
        throw InputError(name + ": " + e.what());
      }
    }
    laws_.push_back(MembraneElementLaw::of(own, p.young_scale));
    for (Index v : p.loop)
      if (v >= points) throw InputError(name + ": vertex slot " + std::to_string(v) + " out of range");
    const Eigen::Vector3d apex = apexPoint(positions, p.loop, p.triangulation);
    if (!p.elastic) {  // a lid: elements without area carry no elastic energy
      Element e;
      e.setRestShape(Eigen::Matrix2d::Identity());
      e.area = 0.0;
      elements_.insert(elements_.end(), triangles, e);
      first_element_.push_back(elements_.size());
      continue;
    }
    for (std::size_t i = 0; i < triangles; ++i) {
      const auto corner = triangleCorners(positions, p.loop, p.triangulation, apex, i);
      Eigen::Matrix<double, 3, 2> E;
      E.col(0) = corner[1] - corner[0];
      E.col(1) = corner[2] - corner[0];
      const Eigen::Vector3d normal = E.col(0).cross(E.col(1));
      if (!(normal.norm() > 1e-14 * (E.col(0).squaredNorm() + E.col(1).squaredNorm()) + 1e-300))
        throw InputError(name + ": triangle " + std::to_string(i) + " is degenerate");
      const Eigen::Vector3d n = normal.normalized();
      Eigen::Vector2d a(1.0, 0.0);  // the fibre in the edge basis: the first edge by default
      const Eigen::Vector3d fp = p.fibre - p.fibre.dot(n) * n;
      if (fp.norm() > 1e-8 * p.fibre.norm() && fp.norm() > 0.0)
        a = (E.transpose() * E).ldlt().solve(E.transpose() * fp);
      const RestMetric& c = p.rest[i];
      Eigen::Matrix2d C;
      C << c(0), c(1), c(1), c(2);
      if (!(c(0) > 0.0 && C.determinant() > 1e-14 * c(0) * c(2) && std::isfinite(C.sum())))
        throw InputError(name + ": rest metric of triangle " + std::to_string(i) + " (" + formatNumber(c(0)) +
                         ", " + formatNumber(c(1)) + ", " + formatNumber(c(2)) + ") is not positive definite");
      const Eigen::Matrix2d D0 = Eigen::LLT<Eigen::Matrix2d>(C).matrixU();
      const Eigen::Vector2d u = (D0 * a).normalized();
      Eigen::Matrix2d R;
      R << u(0), u(1), -u(1), u(0);
      Element e;
      e.setRestShape(R * D0);
      elements_.push_back(e);
    }
    first_element_.push_back(elements_.size());
  }
}

std::array<Eigen::Vector3d, 3> FanMembraneModel::corners(const Eigen::VectorXd& x, std::size_t f,
                                                         std::size_t i) const {
  const MembranePolygon& p = polygons_[f];
  return triangleCorners(x, p.loop, p.triangulation, apexPoint(x, p.loop, p.triangulation), i);
}

FanMembraneModel::Mat32 FanMembraneModel::deformationGradient(const std::array<Eigen::Vector3d, 3>& c,
                                                              const Element& e) const {
  Mat32 F = Mat32::Zero();
  for (int a = 0; a < 3; ++a) F += c[a] * e.g[a].transpose();
  return F;
}

double FanMembraneModel::coneVolume(const Eigen::VectorXd& x, std::size_t f) const {
  double v = 0.0;
  for (std::size_t i = 0; i < numTriangles(f); ++i) {
    const auto c = corners(x, f, i);
    v += (c[0] - origin_).dot((c[1] - origin_).cross(c[2] - origin_));
  }
  return v / 6.0;
}

std::vector<RestMetric> FanMembraneModel::restMetrics(std::size_t f) const {
  std::vector<RestMetric> m;
  for (std::size_t e = first_element_[f]; e < first_element_[f + 1]; ++e) {
    const Eigen::Matrix2d C = elements_[e].D.transpose() * elements_[e].D;
    m.emplace_back(C(0, 0), C(0, 1), C(1, 1));
  }
  return m;
}

double FanMembraneModel::polygonTerms(const Eigen::VectorXd& x, std::size_t f, Eigen::VectorXd* grad,
                                      Eigen::VectorXd* magnitude, Eigen::MatrixXd* tangent,
                                      double* energy_magnitude) const {
  const MembranePolygon& poly = polygons_[f];
  const int n = static_cast<int>(poly.loop.size());
  const int triangles = static_cast<int>(numTriangles(f));
  // The apex's weight at loop vertex k.
  auto w_apex = [&poly](int k) { return poly.triangulation.apexWeight(static_cast<std::size_t>(k), poly.loop.size()); };
  const double t = material_.thickness;
  const MembraneElementLaw& law = laws_[f];
  const double p = poly.pressure;
  double energy = 0.0;
  Eigen::Matrix3d apex_apex = Eigen::Matrix3d::Zero();  // sum_i H_00 over corners at the apex
  // apex_row[l] = sum H_0b over corners b at loop vertex l; apex_col[k] likewise for H_a0.
  std::vector<Eigen::Matrix3d> apex_row(tangent ? n : 0, Eigen::Matrix3d::Zero()), apex_col = apex_row;
  // Corner a of triangle i maps to loop positions: the apex to all (weights w_apex), others to their own.
  std::array<int, 3> tri{};
  auto scatter = [&](Eigen::VectorXd& v, int, int a, const Eigen::Vector3d& value) {
    if (tri[a] == MembraneTriangulation::kApex) {
      for (int k = 0; k < n; ++k) v.segment<3>(3 * k) += w_apex(k) * value;
    } else {
      v.segment<3>(3 * tri[a]) += value;
    }
  };
  for (int i = 0; i < triangles; ++i) {
    tri = poly.triangulation.triangle(static_cast<std::size_t>(i), poly.loop.size());
    const Element& el = elements_[first_element_[f] + static_cast<std::size_t>(i)];
    const auto c = corners(x, f, static_cast<std::size_t>(i));
    const Mat32 F = deformationGradient(c, el);
    const MembraneResponse response = poly.elastic ? law.at(F, tangent != nullptr) : MembraneResponse{};
    const double w = poly.elastic ? t * el.area * response.energy : 0.0;
    const std::array<Eigen::Vector3d, 3> r = {c[0] - origin_, c[1] - origin_, c[2] - origin_};
    const double pv = p * r[0].dot(r[1].cross(r[2])) / 6.0;
    energy += w - pv;
    if (energy_magnitude) *energy_magnitude += std::abs(w) + std::abs(pv);
    if (!grad && !magnitude && !tangent) continue;
    const Eigen::Matrix2d S = poly.elastic ? stressTensor(response.stress) : Eigen::Matrix2d::Zero();
    std::array<Eigen::Vector3d, 3> elastic, pressure;
    for (int a = 0; a < 3; ++a) {
      elastic[a] = t * el.area * F * (S * el.g[a]);
      pressure[a] = -p / 6.0 * r[(a + 1) % 3].cross(r[(a + 2) % 3]);
    }
    if (grad)
      for (int a = 0; a < 3; ++a) scatter(*grad, i, a, elastic[a] + pressure[a]);
    if (magnitude)
      for (int a = 0; a < 3; ++a) scatter(*magnitude, i, a, elastic[a].cwiseAbs() + pressure[a].cwiseAbs());
    if (!tangent) continue;
    std::array<Eigen::Matrix3d, 3> B;
    for (int a = 0; a < 3; ++a) B[a] = strainMatrix(F, el.g[a]);
    std::array<std::array<Eigen::Matrix3d, 3>, 3> H;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        H[a][b] = t * el.area *
                  (B[a].transpose() * response.tangent * B[b] + el.g[a].dot(S * el.g[b]) * Eigen::Matrix3d::Identity());
    for (int a = 0; a < 3; ++a) {
      const int b = (a + 1) % 3, cc = (a + 2) % 3;
      H[a][b] += p / 6.0 * cross(r[cc]);
      H[a][cc] -= p / 6.0 * cross(r[b]);
    }
    // Chain rule: K_kl += sum_ab w_ak w_bl H_ab. The apex terms are summed
    // over the fan first and spread once (below): O(n^2) blocks per polygon.
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        const bool ap = tri[a] == MembraneTriangulation::kApex, bp = tri[b] == MembraneTriangulation::kApex;
        if (ap && bp)
          apex_apex += H[a][b];
        else if (ap)
          apex_row[tri[b]] += H[a][b];
        else if (bp)
          apex_col[tri[a]] += H[a][b];
        else
          tangent->block<3, 3>(3 * tri[a], 3 * tri[b]) += H[a][b];
      }
  }
  if (tangent && poly.triangulation.hasApex())
    for (int k = 0; k < n; ++k)
      for (int l = 0; l < n; ++l)
        tangent->block<3, 3>(3 * k, 3 * l) +=
            w_apex(k) * w_apex(l) * apex_apex + w_apex(k) * apex_row[l] + w_apex(l) * apex_col[k];
  return energy;
}

double FanMembraneModel::energy(const Eigen::VectorXd& x) const {
  double e = 0.0;
  for (std::size_t f = 0; f < polygons_.size(); ++f) e += polygonTerms(x, f, nullptr, nullptr, nullptr, nullptr);
  return e;
}

double FanMembraneModel::energyScale(const Eigen::VectorXd& x) const {
  double m = 0.0;
  for (std::size_t f = 0; f < polygons_.size(); ++f) polygonTerms(x, f, nullptr, nullptr, nullptr, &m);
  return m;
}

void FanMembraneModel::gradient(const Eigen::VectorXd& x, Eigen::VectorXd& g) const {
  g.setZero(size_);
  Eigen::VectorXd local;
  for (std::size_t f = 0; f < polygons_.size(); ++f) {
    const auto& loop = polygons_[f].loop;
    local.setZero(3 * static_cast<Eigen::Index>(loop.size()));
    polygonTerms(x, f, &local, nullptr, nullptr, nullptr);
    for (std::size_t k = 0; k < loop.size(); ++k)
      g.segment<3>(3 * static_cast<Eigen::Index>(loop[k])) += local.segment<3>(3 * static_cast<Eigen::Index>(k));
  }
}

double FanMembraneModel::forceScale(const Eigen::VectorXd& x) const {
  Eigen::VectorXd s = Eigen::VectorXd::Zero(size_), local;
  for (std::size_t f = 0; f < polygons_.size(); ++f) {
    const auto& loop = polygons_[f].loop;
    local.setZero(3 * static_cast<Eigen::Index>(loop.size()));
    polygonTerms(x, f, nullptr, &local, nullptr, nullptr);
    for (std::size_t k = 0; k < loop.size(); ++k)
      s.segment<3>(3 * static_cast<Eigen::Index>(loop[k])) += local.segment<3>(3 * static_cast<Eigen::Index>(k));
  }
  return s.norm();
}

void FanMembraneModel::hessian(const Eigen::VectorXd& x, std::vector<Triplet>& entries) const {
  Eigen::MatrixXd K;
  for (std::size_t f = 0; f < polygons_.size(); ++f) {
    const auto& loop = polygons_[f].loop;
    const Eigen::Index m = 3 * static_cast<Eigen::Index>(loop.size());
    K.setZero(m, m);
    polygonTerms(x, f, nullptr, nullptr, &K, nullptr);
    for (Eigen::Index r = 0; r < m; ++r)
      for (Eigen::Index c = 0; c < m; ++c)
        entries.emplace_back(static_cast<int>(3 * loop[r / 3] + r % 3), static_cast<int>(3 * loop[c / 3] + c % 3),
                             K(r, c));
  }
}

Eigen::Matrix3d FanMembraneModel::tension(const Eigen::VectorXd& x, std::size_t f, std::size_t i) const {
  const Element& el = elements_[first_element_[f] + i];
  const Mat32 F = deformationGradient(corners(x, f, i), el);
  const Eigen::Matrix2d S = stressTensor(laws_[f].at(F, false).stress);
  const double J = std::sqrt((F.transpose() * F).determinant());
  return material_.thickness / J * F * S * F.transpose();
}

template <class PerTriangle>
Eigen::Matrix3d FanMembraneModel::fanMean(const Eigen::VectorXd& x, std::size_t f, PerTriangle per_triangle,
                                          Vec3* normal) const {
  Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
  Eigen::Vector3d vector_area = Eigen::Vector3d::Zero();
  double area = 0.0;
  for (std::size_t i = 0; i < numTriangles(f); ++i) {
    const auto c = corners(x, f, i);
    const Eigen::Vector3d a = 0.5 * (c[1] - c[0]).cross(c[2] - c[0]);
    vector_area += a;
    area += a.norm();
    sum += a.norm() * per_triangle(i);
  }
  if (normal) *normal = vector_area.normalized();
  return sum / area;
}

Eigen::Matrix3d FanMembraneModel::meanTension(const Eigen::VectorXd& x, std::size_t f, Vec3* normal) const {
  return fanMean(x, f, [&](std::size_t i) { return tension(x, f, i); }, normal);
}

Eigen::Matrix3d FanMembraneModel::strain(const Eigen::VectorXd& x, std::size_t f, std::size_t i) const {
  const Mat32 F = deformationGradient(corners(x, f, i), elements_[first_element_[f] + i]);
  const Eigen::Matrix3d projector = F * (F.transpose() * F).inverse() * F.transpose();
  return 0.5 * (F * F.transpose() - projector);
}

Eigen::Matrix3d FanMembraneModel::meanStrain(const Eigen::VectorXd& x, std::size_t f) const {
  return fanMean(x, f, [&](std::size_t i) { return strain(x, f, i); }, nullptr);
}

double FanMembraneModel::fanArea(const Eigen::VectorXd& x, std::size_t f) const {
  double area = 0.0;
  for (std::size_t i = 0; i < numTriangles(f); ++i) {
    const auto c = corners(x, f, i);
    area += 0.5 * (c[1] - c[0]).cross(c[2] - c[0]).norm();
  }
  return area;
}

double FanMembraneModel::restArea(std::size_t f) const {
  double area = 0.0;
  for (std::size_t e = first_element_[f]; e < first_element_[f + 1]; ++e) area += elements_[e].area;
  return area;
}

double FanMembraneModel::growRestShape(const Eigen::VectorXd& x, const StrainGrowthLaw& base_law, double dt,
                                       const std::vector<double>& extensibility) {
  base_law.check();
  if (!(dt >= 0.0 && std::isfinite(dt))) throw InputError("membrane growth: dt " + formatNumber(dt) + " must be >= 0");
  if (!extensibility.empty() && extensibility.size() != polygons_.size())
    throw InputError("membrane growth: " + std::to_string(extensibility.size()) + " extensibilities for " +
                     std::to_string(polygons_.size()) + " polygons");
  double fastest = 0.0;
  for (std::size_t f = 0; f < polygons_.size(); ++f) {
    StrainGrowthLaw law = base_law;
    if (!extensibility.empty()) {
      law.extensibility = extensibility[f];
      law.check();
    }
    for (std::size_t i = 0; i < numTriangles(f) && polygons_[f].elastic; ++i) {
      Element& el = elements_[first_element_[f] + i];
      const Mat32 F = deformationGradient(corners(x, f, i), el);
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(F.transpose() * F);
      Eigen::Matrix2d G = Eigen::Matrix2d::Zero();
      for (int k = 0; k < 2; ++k) {
        const double rate = law.relativeRate(std::sqrt(std::max(eig.eigenvalues()[k], 0.0)) - 1.0);
        fastest = std::max(fastest, rate);
        G += std::exp(rate * dt) * eig.eigenvectors().col(k) * eig.eigenvectors().col(k).transpose();
      }
      el.setRestShape(G * el.D);
    }
  }
  return fastest;
}

}  // namespace tessella::mechanics
