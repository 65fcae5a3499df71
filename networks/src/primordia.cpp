// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/networks/primordia.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"

namespace tessella::networks {

void PrimordiumOptions::validate() const {
  if (!(min_radius >= 0)) throw InputError("primordia: min_radius = " + formatNumber(min_radius) + " is not >= 0");
  if (!(max_radius > min_radius))
    throw InputError("primordia: max_radius = " + formatNumber(max_radius) + " is not above min_radius = " +
                     formatNumber(min_radius));
  if (!(min_separation >= 0))
    throw InputError("primordia: min_separation = " + formatNumber(min_separation) + " is not >= 0");
  if (!std::isfinite(threshold)) throw InputError("primordia: threshold is not finite");
  if (!(axis.norm() > 0) || !axis.allFinite())
    throw InputError("primordia: axis " + formatPoint(axis) + " has no direction");
}

AxialPosition axialPosition(const Vec3& point, const Vec3& apex, const Vec3& axis) {
  const Vec3 n = axis.normalized();
  Vec3 e1 = Vec3(1, 0, 0) - n.x() * n;
  if (e1.norm() < 1e-8) e1 = Vec3(0, 1, 0) - n.y() * n;
  e1.normalize();
  const Vec3 e2 = n.cross(e1);
  const Vec3 d = point - apex;
  const Vec3 h = d - d.dot(n) * n;
  AxialPosition p;
  p.radius = h.norm();
  p.distance = d.norm();
  double a = std::atan2(h.dot(e2), h.dot(e1)) * 180.0 / std::numbers::pi;
  if (a < 0) a += 360.0;
  if (a >= 360.0) a -= 360.0;
  p.angle_deg = a;
  return p;
}

double divergenceDeg(double previous_angle_deg, double angle_deg) {
  double d = std::fmod(angle_deg - previous_angle_deg, 360.0);
  if (d < 0) d += 360.0;
  if (d >= 360.0) d -= 360.0;
  return d;
}

std::vector<int> findPrimordia(const NetworkGraph& graph, const std::vector<double>& concentration,
                               const PrimordiumOptions& options, const std::vector<Vec3>& existing) {
  const std::size_t n = graph.numCells();
  if (concentration.size() != n)
    throw InputError("primordia: " + std::to_string(concentration.size()) + " concentrations for " +
                     std::to_string(n) + " cells");
  std::vector<char> peak(n, 1);
  for (const NetworkInterface& f : graph.interfaces) {
    const double a = concentration[static_cast<std::size_t>(f.cell_i)];
    const double b = concentration[static_cast<std::size_t>(f.cell_j)];
    if (!(a > b)) peak[static_cast<std::size_t>(f.cell_i)] = 0;
    if (!(b > a)) peak[static_cast<std::size_t>(f.cell_j)] = 0;
  }
  std::vector<int> candidates;
  for (std::size_t k = 0; k < n; ++k) {
    if (!peak[k] || !(concentration[k] > options.threshold)) continue;
    const double r = (graph.centroid[k] - options.apex).norm();
    if (r < options.min_radius || r > options.max_radius) continue;
    candidates.push_back(static_cast<int>(k));
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [&](int a, int b) { return concentration[static_cast<std::size_t>(a)] >
                                              concentration[static_cast<std::size_t>(b)]; });
  std::vector<Vec3> taken = existing;
  std::vector<int> chosen;
  for (int k : candidates) {
    const Vec3& x = graph.centroid[static_cast<std::size_t>(k)];
    const bool free = std::none_of(taken.begin(), taken.end(),
                                   [&](const Vec3& p) { return (p - x).norm() < options.min_separation; });
    if (!free) continue;
    chosen.push_back(k);
    taken.push_back(x);
  }
  return chosen;
}

}  // namespace tessella::networks
