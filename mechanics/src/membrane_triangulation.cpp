// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/mechanics/membrane_triangulation.hpp"

#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"
#include "tessella/tissue/geometry.hpp"

#include <cmath>

namespace tessella::mechanics {

void MembraneTriangulation::check(std::size_t n, const std::string& name) const {
  if (kind == Kind::KernelFan) {
    if (apex_weights.size() != n)
      throw InputError(name + ": " + std::to_string(apex_weights.size()) + " apex weights for a loop of " +
                       std::to_string(n) + " vertices");
    double sum = 0.0;
    for (double w : apex_weights) {
      if (!std::isfinite(w)) throw InputError(name + ": apex weight " + formatNumber(w) + " is not finite");
      sum += w;
    }
    if (!(std::abs(sum - 1.0) <= 1e-12))
      throw InputError(name + ": the apex weights sum to " + formatNumber(sum) + ", not 1");
  }
  if (kind == Kind::Ears) {
    if (ears.size() + 2 != n)
      throw InputError(name + ": " + std::to_string(ears.size()) + " triangles for a loop of " + std::to_string(n) +
                       " vertices (need " + std::to_string(n - 2) + ")");
    for (const auto& t : ears)
      for (int c : t)
        if (c < 0 || static_cast<std::size_t>(c) >= n)
          throw InputError(name + ": triangle corner " + std::to_string(c) + " is not a loop position (0 to " +
                           std::to_string(n - 1) + ")");
  }
}

std::vector<double> meanValueCoordinates(std::span<const std::array<double, 2>> loop,
                                         const std::array<double, 2>& point) {
  const std::size_t n = loop.size();
  std::vector<std::array<double, 2>> d(n);
  std::vector<double> r(n), tan_half(n);
  for (std::size_t k = 0; k < n; ++k) {
    d[k] = {loop[k][0] - point[0], loop[k][1] - point[1]};
    r[k] = std::hypot(d[k][0], d[k][1]);
    if (!(r[k] > 0.0)) return {};
  }
  for (std::size_t k = 0; k < n; ++k) {
    const auto &a = d[k], &b = d[(k + 1) % n];
    const double cross = a[0] * b[1] - a[1] * b[0], dot = a[0] * b[0] + a[1] * b[1];
    if (!(cross > 0.0)) return {};
    tan_half[k] = (r[k] * r[(k + 1) % n] - dot) / cross;  // tan(a_k / 2) = (1 - cos) / sin
  }
  std::vector<double> w(n);
  double sum = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    w[k] = (tan_half[(k + n - 1) % n] + tan_half[k]) / r[k];
    sum += w[k];
  }
  for (double& x : w) x /= sum;
  return w;
}

MembraneTriangulation membraneTriangulation(std::span<const Vec3> loop) {
  const PolygonTriangulation tri = polygonTriangulation(loop);
  MembraneTriangulation out;
  if (!tri.folded) return out;
  const std::size_t n = loop.size();
  if (tri.fan()) {
    // The kernel centroid lies in the plane through the vertex mean normal to the vector area.
    Vec3 mean = Vec3::Zero();
    for (const Vec3& p : loop) mean += p;
    mean /= static_cast<double>(n);
    const Vec3 e1 = tri.normal.unitOrthogonal(), e2 = tri.normal.cross(e1);
    std::vector<std::array<double, 2>> q(n);
    for (std::size_t k = 0; k < n; ++k) q[k] = {(loop[k] - mean).dot(e1), (loop[k] - mean).dot(e2)};
    const std::array<double, 2> c = {(tri.center - mean).dot(e1), (tri.center - mean).dot(e2)};
    std::vector<double> w = meanValueCoordinates(q, c);
    if (!w.empty()) {
      out.kind = MembraneTriangulation::Kind::KernelFan;
      out.apex_weights = std::move(w);
      return out;
    }
    // The tissue accepted the fan from the kernel centroid (every triangle's
    // area above 1e-12 of the fan's); the same triangles, projected, failed here.
    throw InputError("membrane triangulation: the kernel centroid of a folded loop of " + std::to_string(n) +
                     " vertices is not strictly inside its fan");
  }
  out.kind = MembraneTriangulation::Kind::Ears;
  out.ears = tri.triangles;
  return out;
}

}  // namespace tessella::mechanics
