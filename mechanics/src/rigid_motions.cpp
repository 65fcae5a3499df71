// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/mechanics/rigid_motions.hpp"

#include "tessella/mechanics/errors.hpp"
#include "tessella/tissue/format.hpp"
#include "tessella/tissue/tissue.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace tessella::mechanics {
namespace {

using Vector6 = Eigen::Matrix<double, 6, 1>;

// The frame the rows are written in: positions relative to the vertex mean c,
// divided by the largest distance L from it, so translations and rotations
// (w = L omega) weigh alike.
struct Frame {
  Vec3 centre = Vec3::Zero();
  double scale = 1.0;
};

Frame frameOf(const Tissue& tissue) {
  Frame f;
  std::size_t n = 0;
  for (VertexId v : tissue.vertices()) {
    f.centre += tissue.position(v);
    ++n;
  }
  if (n > 0) f.centre /= static_cast<double>(n);
  double far = 0.0;
  for (VertexId v : tissue.vertices()) far = std::max(far, (tissue.position(v) - f.centre).norm());
  if (far > 0.0) f.scale = far;
  return f;
}

// The change of dof k of a vertex at p under the motion (t, w): t_k + w . (q x e_k), q = (p - c) /
// L.
Vector6 row(const Frame& f, const Vec3& p, int k) {
  const Vec3 q = (p - f.centre) / f.scale;
  const Vec3 e = Vec3::Unit(k);
  Vector6 r;
  r << e, q.cross(e);
  return r;
}

// An orthonormal basis (columns) of the motions the fixed dofs do not move.
Eigen::MatrixXd freeSpace(const Tissue& tissue, const Frame& f,
                          const std::vector<std::uint8_t>& fixed) {
  Eigen::Matrix<double, 6, 6> gram = Eigen::Matrix<double, 6, 6>::Zero();
  for (VertexId v : tissue.vertices())
    for (int k = 0; k < 3; ++k) {
      const std::size_t dof = 3 * static_cast<std::size_t>(v.index()) + static_cast<std::size_t>(k);
      if (dof < fixed.size() && fixed[dof]) {
        const Vector6 r = row(f, tissue.position(v), k);
        gram += r * r.transpose();
      }
    }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eig(gram);
  const double top = eig.eigenvalues()[5];
  std::vector<int> free;
  for (int i = 0; i < 6; ++i)
    if (!(top > 0.0) || eig.eigenvalues()[i] <= 1e-10 * top) free.push_back(i);
  Eigen::MatrixXd basis(6, static_cast<Eigen::Index>(free.size()));
  for (std::size_t j = 0; j < free.size(); ++j)
    basis.col(static_cast<Eigen::Index>(j)) = eig.eigenvectors().col(free[j]);
  return basis;
}

RigidMotion motionOf(const Frame& f, Vector6 m) {
  for (int i = 0; i < 6; ++i)
    if (std::abs(m[i]) < 1e-9) m[i] = 0.0;  // round-off of a unit eigenvector
  RigidMotion r;
  r.translation = m.head<3>();
  r.rotation = m.tail<3>() / f.scale;
  r.centre = f.centre;
  return r;
}

std::string rounded(const Vec3& v) {
  return "(" + formatNumber(v.x(), 4) + ", " + formatNumber(v.y(), 4) + ", " +
         formatNumber(v.z(), 4) + ")";
}

}  // namespace

std::string RigidMotion::describe() const {
  const double w = rotation.norm();
  if (!(w > 0.0)) return "translation along " + rounded(translation.normalized());
  const Vec3 axis = rotation / w;
  // u(p) = t + omega x (p - c) = slide axis + omega x (p - a), a = c + omega x t / |omega|^2.
  const Vec3 through = centre + rotation.cross(translation) / (w * w);
  const double slide = translation.dot(axis);
  std::string text =
      "rotation about the axis along " + rounded(axis) + " through " + rounded(through);
  if (std::abs(slide) > 1e-9 * std::max(translation.norm(), 1e-300))
    text += " with a slide along it";
  return text;
}

std::vector<RigidMotion> freeRigidMotions(const Tissue& tissue,
                                          const std::vector<std::uint8_t>& fixed) {
  const Frame f = frameOf(tissue);
  const Eigen::MatrixXd basis = freeSpace(tissue, f, fixed);
  std::vector<RigidMotion> motions;
  for (Eigen::Index j = 0; j < basis.cols(); ++j) motions.push_back(motionOf(f, basis.col(j)));
  return motions;
}

void requireNoRigidMotion(const Tissue& tissue, const std::vector<std::uint8_t>& fixed,
                          const std::string& what, const std::string& context) {
  const std::vector<RigidMotion> free = freeRigidMotions(tissue, fixed);
  if (free.empty()) return;
  std::string list;
  for (const RigidMotion& m : free) list += (list.empty() ? "" : "; ") + m.describe();
  throw MechanicsError("mechanics" + (context.empty() ? std::string() : " (" + context + ")") +
                       ": " + what + " leaves " + std::to_string(free.size()) + " rigid motion" +
                       (free.size() > 1 ? "s" : "") + " free (" + list +
                       "): the tangent system of the equilibrium would be singular (the energy "
                       "does not change under them); fix more vertices, add symmetry planes or use "
                       "the point support");
}

PointSupport fixPointSupport(const Tissue& tissue, const Vec3& point,
                             std::vector<std::uint8_t>& fixed) {
  if (tissue.numVertices() < 3)
    throw MechanicsError("mechanics: the point support needs three vertices; the tissue has " +
                         std::to_string(tissue.numVertices()));
  PointSupport s;
  double best = std::numeric_limits<double>::infinity();
  for (VertexId v : tissue.vertices()) {
    const double d = (tissue.position(v) - point).squaredNorm();
    if (d < best) best = d, s.anchor = v;
  }
  const Vec3 a = tissue.position(s.anchor);
  double far = -1.0;
  for (VertexId v : tissue.vertices()) {
    const double d = (tissue.position(v) - a).squaredNorm();
    if (d > far) far = d, s.second = v;
  }
  const Vec3 r = tissue.position(s.second) - a;
  const Vec3 u = r.norm() > 0.0 ? Vec3(r.normalized()) : Vec3::UnitX();
  far = -1.0;
  for (VertexId v : tissue.vertices()) {
    const Vec3 d = tissue.position(v) - a;
    const double off = (d - d.dot(u) * u).squaredNorm();
    if (off > far) far = off, s.third = v;
  }
  // Candidates, best-conditioned first: the anchor's x, y, z; the second
  // vertex's components across the line (smallest |r_k| first); the third's
  // along the motion a rotation about the line gives it (largest first).
  std::vector<std::pair<VertexId, int>> candidates = {{s.anchor, 0}, {s.anchor, 1}, {s.anchor, 2}};
  std::array<int, 3> order = {0, 1, 2};
  std::stable_sort(order.begin(), order.end(),
                   [&](int i, int j) { return std::abs(r[i]) < std::abs(r[j]); });
  for (int k : order) candidates.emplace_back(s.second, k);
  const Vec3 d = tissue.position(s.third) - a;
  const Vec3 swing = u.cross(d);
  order = {0, 1, 2};
  std::stable_sort(order.begin(), order.end(),
                   [&](int i, int j) { return std::abs(swing[i]) > std::abs(swing[j]); });
  for (int k : order) candidates.emplace_back(s.third, k);

  const Frame f = frameOf(tissue);
  Eigen::MatrixXd basis = freeSpace(tissue, f, fixed);
  for (const auto& [v, k] : candidates) {
    if (basis.cols() == 0) break;
    const std::size_t dof = 3 * static_cast<std::size_t>(v.index()) + static_cast<std::size_t>(k);
    if (fixed[dof]) continue;
    const Vector6 row_k = row(f, tissue.position(v), k).normalized();
    const Eigen::VectorXd held = basis.transpose() * row_k;  // the free motions this dof would hold
    if (!(held.norm() > 1e-3)) continue;
    fixed[dof] = 1;
    ++s.fixed_components;
    // The free space loses the direction basis * held.
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(held);
    const Eigen::MatrixXd q = qr.householderQ();
    basis = (basis * q.rightCols(basis.cols() - 1)).eval();
  }
  return s;
}

}  // namespace tessella::mechanics
