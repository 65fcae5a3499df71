// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/growth/shortest_wall_search.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <span>

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

double wrapAngle(double theta) {
  double w = std::fmod(theta, std::numbers::pi);
  if (w < 0) w += std::numbers::pi;
  return w;
}

// Sampled search, kept for cells whose point lies outside some chord (very
// concave cells, where the wall length is not piecewise convex): samples,
// brackets each sampled minimum by its neighbours, refines it by Brent.
std::vector<WallCandidate> minima2DSampled(const NewWallMeasure& m, const ShortestWallSearchOptions& o) {
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
                                       std::max(o.angle_tolerance, 1e-10));
    const double wrapped = wrapAngle(theta);
    addCandidate(out, WallCandidate{m.frame().direction(wrapped), m.length(wrapped), wrapped},
                 o.merge_angle);
  }
  if (out.empty()) out.push_back(WallCandidate{m.frame().direction(0.0), len[0], 0.0});
  return out;
}

// The chord's ends on two fixed loop edges a (behind the point) and b (ahead)
// as functions of the normal angle theta. An edge's line is {p : mu . p = c};
// the line through the point with direction d = (-sin, cos) meets it at
// tau = c / D, D = d . mu, with D' = -n . mu and D'' = -D, so
// tau' = -c D' / D^2 and tau'' = tau (D^2 + 2 D'^2) / D^2: tau'' has the sign
// of tau, hence g = tau_b - tau_a (tau_b > 0 > tau_a) is strictly convex.
struct EdgeLine {
  double mx, my, c;
};

struct PieceValue {
  double g, g1, g2;  // length and its first two derivatives in theta
};

class Piece {
 public:
  Piece(const EdgeLine& a, const EdgeLine& b) : a_(a), b_(b) {}
  PieceValue operator()(double theta) const { return at(std::cos(theta), std::sin(theta)); }
  /// At the angle whose cosine and sine are given.
  PieceValue at(double cs, double sn) const {
    double ta, ta1, ta2, tb, tb1, tb2;
    abscissa(a_, cs, sn, ta, ta1, ta2);
    abscissa(b_, cs, sn, tb, tb1, tb2);
    return PieceValue{tb - ta, tb1 - ta1, tb2 - ta2};
  }

 private:
  static void abscissa(const EdgeLine& e, double cs, double sn, double& t, double& t1, double& t2) {
    const double d = -sn * e.mx + cs * e.my, dp = -cs * e.mx - sn * e.my;
    const double r = dp / d;
    t = e.c / d;
    t1 = -t * r;
    t2 = t * (1 + 2 * r * r);
  }
  EdgeLine a_, b_;
};

// Minimum of a strictly convex piece on [lo, hi] whose slope goes from
// s_lo < 0 to s_hi > 0: Newton on g' = 0 from the secant root of g', kept
// inside a shrinking bracket (bisection when a step leaves it), to `tol`.
double convexMinimum(const Piece& f, double lo, double hi, double s_lo, double s_hi, double tol) {
  double x = lo + (hi - lo) * (-s_lo / (s_hi - s_lo));
  for (int it = 0; it < 100; ++it) {
    const PieceValue v = f(x);
    if (v.g1 == 0) return x;
    if (v.g1 > 0) hi = x; else lo = x;
    const double dx = v.g1 / v.g2;  // g2 > 0: strictly convex
    double next = x - dx;
    if (std::abs(dx) <= tol && next >= lo && next <= hi) return next;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (hi - lo <= tol) return 0.5 * (lo + hi);
    x = next;
  }
  return x;
}

// Exact search: the crossed edges change only where the line passes through a
// loop vertex, so the n vertex angles cut [0, pi) into pieces on each of which
// the chord through the point joins two fixed edges and its length is
// strictly convex (above). Each piece has one minimum (interior: Newton;
// or at an end); the local minima of L are the interior minima and the piece
// ends where L stops falling and starts rising. O(n) pieces of O(n) work.
// Returns false (and leaves `out` empty) when the point is not on every
// chord, where the pieces need not be convex.
bool minima2DExact(const NewWallMeasure& m, const ShortestWallSearchOptions& o,
                   std::vector<WallCandidate>& out) {
  const std::span<const double> u = m.loopU(), v = m.loopV();
  const std::size_t n = u.size();
  constexpr std::size_t kMax = 64;  // stack storage; larger cells take the sampled search
  if (n < 3 || n > kMax) return false;
  struct Cut {
    double theta, cs, sn;  // angle in [0, pi), its cosine and sine
  };
  std::array<Cut, kMax> cut;
  std::size_t nc = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = std::sqrt(u[i] * u[i] + v[i] * v[i]);
    if (!(r > 0)) return false;  // the point is a vertex
    // The normal perpendicular to the vertex direction, (-v, u) / r, turned
    // into [0, pi) (sin >= 0) by flipping it.
    double cs = -v[i] / r, sn = u[i] / r;
    if (sn < 0 || (sn == 0 && cs < 0)) {
      cs = -cs;
      sn = -sn;
    }
    cut[nc++] = Cut{std::atan2(sn, cs), cs, sn};
  }
  std::sort(cut.begin(), cut.begin() + nc, [](const Cut& a, const Cut& b) { return a.theta < b.theta; });
  std::size_t m_cuts = 0;
  for (std::size_t i = 0; i < nc; ++i)
    if (m_cuts == 0 || cut[i].theta - cut[m_cuts - 1].theta > 1e-13) cut[m_cuts++] = cut[i];
  if (m_cuts > 1 && cut[0].theta + std::numbers::pi - cut[m_cuts - 1].theta <= 1e-13) --m_cuts;
  if (m_cuts < 2) return false;

  auto edgeLine = [&](int i) {
    const std::size_t j = static_cast<std::size_t>(i) + 1 == n ? 0 : i + 1;
    const double mx = -(v[j] - v[i]), my = u[j] - u[i];
    return EdgeLine{mx, my, mx * u[i] + my * v[i]};
  };
  struct Info {
    double lo, hi;
    PieceValue at_lo, at_hi;
  };
  std::array<Info, kMax> info;
  const double tol = std::max(o.angle_tolerance, 1e-15);
  for (std::size_t k = 0; k < m_cuts; ++k) {
    // The last piece runs to the first cut + pi, where the normal is reversed.
    const bool last = k + 1 == m_cuts;
    const Cut& a = cut[k];
    const Cut b = last ? Cut{cut[0].theta + std::numbers::pi, -cut[0].cs, -cut[0].sn} : cut[k + 1];
    // The bisector of the piece (its ends are less than pi apart); chord()
    // normalises the normal.
    const NewWallMeasure::Chord c = m.chord(a.cs + b.cs, a.sn + b.sn);
    if (c.crossings < 2 || !c.contains_point) {
      out.clear();
      return false;
    }
    const Piece f(edgeLine(c.edge_lo), edgeLine(c.edge_hi));
    info[k] = Info{a.theta, b.theta, f.at(a.cs, a.sn), f.at(b.cs, b.sn)};
    if (info[k].at_lo.g1 < 0 && info[k].at_hi.g1 > 0) {
      // Evaluated before wrapping: past pi the line's direction is reversed.
      const double x = convexMinimum(f, a.theta, b.theta, info[k].at_lo.g1, info[k].at_hi.g1, tol);
      const double theta = wrapAngle(x);
      addCandidate(out, WallCandidate{m.frame().direction(theta), f(x).g, theta}, o.merge_angle);
    }
  }
  // Piece ends: cut k is the end of piece k - 1 and the start of piece k. Where
  // L jumps (a concave cell's reflex vertex crossing the line), the lower side
  // is the one to compare; its limit is approached from inside that piece.
  for (std::size_t k = 0; k < m_cuts; ++k) {
    const Info& left = info[(k + m_cuts - 1) % m_cuts];
    const Info& right = info[k];
    const double gl = left.at_hi.g, gr = right.at_lo.g;
    const bool same = std::abs(gl - gr) <= 1e-12 * std::max(gl, gr);
    const bool falls = left.at_hi.g1 <= 0, rises = right.at_lo.g1 >= 0;
    double theta = cut[k].theta;
    if (same) {
      if (!(falls && rises)) continue;
    } else if (gl < gr) {
      if (!falls) continue;
      theta -= std::min(1e-7, 0.25 * (left.hi - left.lo));
    } else {
      if (!rises) continue;
      theta += std::min(1e-7, 0.25 * (right.hi - right.lo));
    }
    theta = wrapAngle(theta);
    addCandidate(out, WallCandidate{m.frame().direction(theta), m.length(theta), theta}, o.merge_angle);
  }
  return !out.empty();
}

std::vector<WallCandidate> minima2D(const NewWallMeasure& m, const ShortestWallSearchOptions& o) {
  std::vector<WallCandidate> out;
  out.reserve(8);
  if (minima2DExact(m, o, out)) return out;
  return minima2DSampled(m, o);
}

// Nelder-Mead in the chart n(u, v) = normalise(n0 + u e1 + v e2) around n0,
// from a simplex of edge `step`, until the simplex is smaller than
// `size_tol` and the values agree to `spread_tol` (relative).
WallCandidate nelderMead(const NewWallMeasure& m, const Vec3& n0, double step, double size_tol,
                         double spread_tol, int max_iterations) {
  Vec3 e1 = n0.unitOrthogonal(), e2 = n0.cross(e1);
  auto normal = [&](const Eigen::Vector2d& p) { return (n0 + p[0] * e1 + p[1] * e2).normalized(); };
  auto f = [&](const Eigen::Vector2d& p) { return m.measure(normal(p)); };
  std::array<Eigen::Vector2d, 3> s = {Eigen::Vector2d(0, 0), Eigen::Vector2d(step, 0),
                                      Eigen::Vector2d(0, step)};
  std::array<double, 3> fs = {f(s[0]), f(s[1]), f(s[2])};
  for (int it = 0; it < max_iterations; ++it) {
    // Order best (0) .. worst (2).
    std::array<int, 3> idx = {0, 1, 2};
    std::sort(idx.begin(), idx.end(), [&](int a, int b) { return fs[a] < fs[b]; });
    s = {s[idx[0]], s[idx[1]], s[idx[2]]};
    fs = {fs[idx[0]], fs[idx[1]], fs[idx[2]]};
    const double size = std::max((s[1] - s[0]).norm(), (s[2] - s[0]).norm());
    if (fs[2] - fs[0] <= spread_tol * std::max(std::abs(fs[0]), 1e-300) && size < size_tol) break;
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

// Two phases: a coarse descent from every start (most starts fall into the
// same few basins), then the distinct coarse minima refined to the full
// tolerance from a small simplex. Coarse minima within kBasinAngle are one.
std::vector<WallCandidate> minima3D(const NewWallMeasure& m,
                                    const std::vector<Vec3>& starts,
                                    const ShortestWallSearchOptions& o) {
  constexpr double kCoarseSize = 1e-2, kBasinAngle = 0.05, kRefineStep = 0.05;
  std::vector<WallCandidate> coarse;
  for (const Vec3& n0 : starts)
    addCandidate(coarse, nelderMead(m, n0.normalized(), 0.25, kCoarseSize, 1e-6, o.max_iterations),
                 kBasinAngle);
  std::vector<WallCandidate> out;
  for (const WallCandidate& c : coarse)
    addCandidate(out, nelderMead(m, c.normal, kRefineStep, 1e-6, o.area_tolerance, o.max_iterations),
                 o.merge_angle);
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
