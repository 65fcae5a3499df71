#include "tessella/growth/shortest_wall_search.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace tessella::growth {

namespace {

bool sameOrientation(const Vec3& a, const Vec3& b, double merge_angle) {
  // Planes with opposite normals are the same plane.
  return std::abs(a.dot(b)) >= std::cos(merge_angle);
}

void addCandidate(std::vector<WallCandidate>& out, const WallCandidate& c, double merge_angle) {
  for (WallCandidate& o : out)
    if (sameOrientation(o.normal, c.normal, merge_angle)) {
      if (c.measure < o.measure) o = c;
      return;
    }
  out.push_back(c);
}

std::vector<WallCandidate> minima2D(const NewWallMeasure& m, const ShortestWallSearchOptions& o) {
  const int n = std::max(o.samples, 6);
  const double step = std::numbers::pi / n;
  std::vector<double> len(n);
  for (int i = 0; i < n; ++i) len[i] = m.length(i * step);
  std::vector<WallCandidate> out;
  for (int i = 0; i < n; ++i) {
    const double prev = len[(i + n - 1) % n], next = len[(i + 1) % n];
    if (!(len[i] <= prev && len[i] < next)) continue;  // strict on one side: plateaus count once
    // L is pi-periodic, so the bracket may run past 0 or pi.
    const double lo = (i - 1) * step, hi = (i + 1) * step;
    const double theta = brentMinimize([&](double a) { return m.length(a); }, lo, hi,
                                       o.angle_tolerance);
    double wrapped = std::fmod(theta, std::numbers::pi);
    if (wrapped < 0) wrapped += std::numbers::pi;
    const double best = m.length(wrapped);
    addCandidate(out, WallCandidate{m.frame().direction(wrapped), best, wrapped}, o.merge_angle);
  }
  if (out.empty()) {  // constant length (cannot happen for a polygon, but stay total)
    out.push_back(WallCandidate{m.frame().direction(0.0), len[0], 0.0});
  }
  return out;
}

// Nelder-Mead in the chart n(u, v) = normalise(n0 + u e1 + v e2) around n0.
WallCandidate nelderMead(const NewWallMeasure& m, const Vec3& n0, const ShortestWallSearchOptions& o) {
  Vec3 e1 = n0.unitOrthogonal(), e2 = n0.cross(e1);
  auto normal = [&](const Eigen::Vector2d& p) { return (n0 + p[0] * e1 + p[1] * e2).normalized(); };
  auto f = [&](const Eigen::Vector2d& p) { return m.measure(normal(p)); };
  std::array<Eigen::Vector2d, 3> s = {Eigen::Vector2d(0, 0), Eigen::Vector2d(0.25, 0),
                                      Eigen::Vector2d(0, 0.25)};
  std::array<double, 3> fs = {f(s[0]), f(s[1]), f(s[2])};
  for (int it = 0; it < o.max_iterations; ++it) {
    // Order best (0) .. worst (2).
    std::array<int, 3> idx = {0, 1, 2};
    std::sort(idx.begin(), idx.end(), [&](int a, int b) { return fs[a] < fs[b]; });
    s = {s[idx[0]], s[idx[1]], s[idx[2]]};
    fs = {fs[idx[0]], fs[idx[1]], fs[idx[2]]};
    const double size = std::max((s[1] - s[0]).norm(), (s[2] - s[0]).norm());
    if (fs[2] - fs[0] <= o.area_tolerance * std::max(std::abs(fs[0]), 1e-300) && size < 1e-6) break;
    if (size < 1e-12) break;
    const Eigen::Vector2d centroid = 0.5 * (s[0] + s[1]);
    const Eigen::Vector2d xr = centroid + (centroid - s[2]);
    const double fr = f(xr);
    if (fr < fs[0]) {
      const Eigen::Vector2d xe = centroid + 2.0 * (centroid - s[2]);
      const double fe = f(xe);
      if (fe < fr) { s[2] = xe; fs[2] = fe; } else { s[2] = xr; fs[2] = fr; }
    } else if (fr < fs[1]) {
      s[2] = xr; fs[2] = fr;
    } else {
      const bool outside = fr < fs[2];
      const Eigen::Vector2d xc = outside ? Eigen::Vector2d(centroid + 0.5 * (xr - centroid))
                                         : Eigen::Vector2d(centroid + 0.5 * (s[2] - centroid));
      const double fc = f(xc);
      if (fc < (outside ? fr : fs[2])) {
        s[2] = xc; fs[2] = fc;
      } else {  // shrink towards the best vertex
        for (int k = 1; k < 3; ++k) {
          s[k] = s[0] + 0.5 * (s[k] - s[0]);
          fs[k] = f(s[k]);
        }
      }
    }
  }
  const int best = static_cast<int>(std::min_element(fs.begin(), fs.end()) - fs.begin());
  return WallCandidate{normal(s[best]), fs[best]};
}

std::vector<WallCandidate> minima3D(const NewWallMeasure& m,
                                    const std::vector<Vec3>& starts,
                                    const ShortestWallSearchOptions& o) {
  std::vector<WallCandidate> out;
  for (const Vec3& n0 : starts) addCandidate(out, nelderMead(m, n0.normalized(), o), o.merge_angle);
  return out;
}

}  // namespace

std::vector<WallCandidate> newWallLocalMinima(const NewWallMeasure& m,
                                              const ShortestWallSearchOptions& options) {
  std::vector<WallCandidate> out;
  if (m.dim() == 2) {
    out = minima2D(m, options);
  } else {
    // The 13 directions of a cube's faces, edges and corners (up to sign).
    std::vector<Vec3> starts;
    for (int x = -1; x <= 1; ++x)
      for (int y = -1; y <= 1; ++y)
        for (int z = -1; z <= 1; ++z) {
          const Vec3 d(x, y, z);
          if (d.isZero()) continue;
          // one of each +-pair: first non-zero coordinate positive
          const double lead = x != 0 ? x : (y != 0 ? y : z);
          if (lead > 0) starts.push_back(d);
        }
    out = minima3D(m, starts, options);
  }
  std::sort(out.begin(), out.end(),
            [](const WallCandidate& a, const WallCandidate& b) { return a.measure < b.measure; });
  return out;
}

}  // namespace tessella::growth
