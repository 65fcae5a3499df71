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

// 3D: descent on the sphere of normals with the exact gradient of the section
// area (NewWallMeasure::measureAndGradient) by a Riemannian BFGS: a tangent
// frame (n, e1, e2) moves with the iterate (retraction n' = normalise(n + v),
// the frame turned by the rotation taking n to n' about n x v), steps are
// taken in the frame's coordinates, and the 2 x 2 inverse Hessian estimate
// is carried over unchanged (the rotation is the vector transport).
struct Frame {
  Vec3 n, e1, e2;
};

Frame frameAt(const Vec3& n) {
  const Vec3 e1 = n.unitOrthogonal();
  return Frame{n, e1, n.cross(e1)};
}

Frame moved(const Frame& f, const Eigen::Vector2d& c) {
  const Vec3 v = c[0] * f.e1 + c[1] * f.e2;
  const double r = v.norm();
  if (!(r > 0)) return f;
  const Vec3 d = v / r;
  const double cs = 1.0 / std::sqrt(1.0 + r * r), sn = r * cs;  // of the turn atan(r)
  Frame g;
  g.n = ((f.n + v) * cs).normalized();
  Vec3 e1 = f.e1 + f.e1.dot(d) * ((cs - 1.0) * d - sn * f.n);
  e1 = (e1 - g.n.dot(e1) * g.n).normalized();
  g.e1 = e1;
  g.e2 = g.n.cross(e1);
  return g;
}

struct Iterate {
  Frame f;
  double a;           // section area
  Eigen::Vector2d g;  // its gradient in the frame's coordinates
};

Iterate evaluate(const NewWallMeasure& m, const Frame& f) {
  Vec3 gradient;
  const double a = m.measureAndGradient(f.n, gradient);
  return Iterate{f, a, Eigen::Vector2d(gradient.dot(f.e1), gradient.dot(f.e2))};
}

// A descent that comes within kBasinAngle of a minimum already found, heading
// towards it (or within merge_angle of it), ends there. Steps are at most
// kMaxStep (tangent of the turn), so a descent follows its basin rather than
// jumping across the sphere. A point where the quadratic model predicts less
// than `area_tolerance` (relative) of further decrease, or where no step
// decreases the area above rounding, is checked by probes kProbeAngle away
// (descentDirection): at a saddle or a maximum (e.g. a start on a symmetry
// axis, where the gradient vanishes) the descent leaves along the direction
// they show, by the longest of kMaxStep, kMaxStep / 4, ... that lowers the
// area, and goes on.
constexpr double kBasinAngle = 0.05, kMaxStep = 0.25, kProbeAngle = 1e-3, kNegativeCurvature = 1e-6,
                 kStepTolerance = 1e-10, kSnapAngle = 1e-7;
constexpr int kProbes = 6, kMaxEscapes = 8;

// At a point where the descent stops: kProbes = 6 probes kProbeAngle away,
// in three antipodal pairs 60 degrees apart. Their second differences give
// the Hessian's curvature along three directions, hence the whole 2 x 2
// Hessian; a probe below the point, or a curvature below
// -kNegativeCurvature * A, shows a direction of descent (the lowest probe's,
// else the eigenvector of the negative curvature turned downhill).
bool descentDirection(const NewWallMeasure& m, const Iterate& x, Eigen::Vector2d& dir) {
  std::array<double, kProbes> f;
  std::array<Eigen::Vector2d, kProbes> d;
  int lowest = 0;
  for (int k = 0; k < kProbes; ++k) {
    const double phi = std::numbers::pi * k / 3;
    d[k] = Eigen::Vector2d(std::cos(phi), std::sin(phi));
    f[k] = m.measure(moved(x.f, kProbeAngle * d[k]).n);
    if (f[k] < f[lowest]) lowest = k;
  }
  if (f[lowest] < x.a * (1.0 - 1e-14)) {
    dir = d[lowest];
    return true;
  }
  // d^T H d along (1, 0), (1/2, sqrt(3)/2), (-1/2, sqrt(3)/2).
  const double h2 = kProbeAngle * kProbeAngle;
  const double c0 = (f[0] + f[3] - 2 * x.a) / h2, c1 = (f[1] + f[4] - 2 * x.a) / h2,
               c2 = (f[2] + f[5] - 2 * x.a) / h2;
  const double a = c0, b = (c1 - c2) / std::sqrt(3.0), c = (2 * (c1 + c2) - a) / 3;
  const double mean = 0.5 * (a + c), radius = std::hypot(0.5 * (a - c), b);
  const double lambda = mean - radius;
  if (!(lambda < -kNegativeCurvature * x.a)) return false;
  // Eigenvector of lambda: (b, lambda - a) or (lambda - c, b), the better conditioned.
  Eigen::Vector2d v = std::abs(lambda - a) > std::abs(lambda - c) ? Eigen::Vector2d(b, lambda - a)
                                                                 : Eigen::Vector2d(lambda - c, b);
  v.normalize();
  dir = x.g.dot(v) > 0 ? Eigen::Vector2d(-v) : v;
  return true;
}

bool headsTo(const Iterate& x, const Eigen::Vector2d& p, const std::vector<WallCandidate>& found,
             double merge_angle) {
  const double cos_basin = std::cos(kBasinAngle), cos_same = std::cos(merge_angle);
  for (const WallCandidate& w : found) {
    const double c = w.normal.dot(x.f.n);
    if (std::abs(c) < cos_basin) continue;
    const Vec3 to = (c < 0 ? -w.normal : w.normal) - x.f.n;  // opposite normals are the same plane
    if (to.dot(x.f.e1) * p[0] + to.dot(x.f.e2) * p[1] > 0 || std::abs(c) >= cos_same) return true;
  }
  return false;
}

// The local minimum the descent from n0 ends in, or false when it joins a
// minimum in `found`.
bool descend(const NewWallMeasure& m, const Vec3& n0, const std::vector<WallCandidate>& found,
             const ShortestWallSearchOptions& o, WallCandidate& out) {
  const Eigen::Matrix2d identity = Eigen::Matrix2d::Identity();
  Iterate x = evaluate(m, frameAt(n0));
  // The area's curvature at a minimum is of the order of the area (1 / cos
  // for a prism): the first step is the gradient scaled by 1 / A.
  Eigen::Matrix2d h = identity / x.a;
  bool scaled = false;
  int escapes = 0;
  for (int it = 0; it < o.max_iterations; ++it) {
    Eigen::Vector2d p = -h * x.g;
    double slope = x.g.dot(p);
    if (!(slope < 0)) {  // not a descent direction: restart from the scaled gradient
      h = identity / x.a;
      scaled = false;
      p = -x.g / x.a;
      slope = x.g.dot(p);
    }
    if (headsTo(x, p, found, o.merge_angle)) return false;
    // Go on while the model predicts more than the tolerance or the gradient
    // step |g| / A is above kStepTolerance: a minimum on a symmetry plane of
    // the cell (a box's axis) is then found to 1e-10 rad, and its plane meets
    // the vertices that lie on it within splitCell's snap tolerance (1e-9)
    // rather than 1e-8 beside them.
    if (-slope > 2.0 * o.area_tolerance * x.a || x.g.norm() > kStepTolerance * x.a) {
      const double len = p.norm();
      if (len > kMaxStep) {
        p *= kMaxStep / len;
        slope *= kMaxStep / len;
      }
      // Backtracking (Armijo) by quadratic interpolation, kept in [0.1, 0.5] of the last step.
      double alpha = 1.0;
      bool accepted = false;
      while (alpha * p.norm() > 1e-14) {
        const Eigen::Vector2d step = alpha * p;
        Iterate y = evaluate(m, moved(x.f, step));
        const double rise = y.a - x.a - alpha * slope;
        // Armijo; or, where area differences are rounding, a smaller gradient.
        const bool armijo = y.a <= x.a + 1e-4 * alpha * slope;
        if (armijo || (std::abs(y.a - x.a) <= 1e-15 * x.a && y.g.norm() < x.g.norm())) {
          // BFGS on the transported step (its geodesic length) and gradients.
          const double r = step.norm();
          const Eigen::Vector2d s = step * (std::atan(r) / r), yv = y.g - x.g;
          const double sy = s.dot(yv);
          if (sy > 1e-12 * s.norm() * yv.norm()) {
            if (!scaled) h = identity * (sy / yv.squaredNorm());  // Nocedal & Wright (6.20)
            scaled = true;
            const double rho = 1.0 / sy;
            const Eigen::Matrix2d v = identity - rho * yv * s.transpose();
            h = v.transpose() * h * v + rho * s * s.transpose();
          }
          x = y;
          accepted = true;
          break;
        }
        alpha *= std::clamp(-slope * alpha / (2.0 * rise), 0.1, 0.5);
      }
      if (accepted) continue;
    }
    // Converged, or no decrease above rounding: a local minimum unless the
    // probes around it show otherwise.
    Eigen::Vector2d dir;
    if (escapes == kMaxEscapes || !descentDirection(m, x, dir)) break;
    ++escapes;
    // Leave along it: the longest step (kMaxStep, then quartered) that lowers the area.
    bool left = false;
    for (double t = kMaxStep; t >= 0.5 * kProbeAngle && !left; t *= 0.25) {
      const Frame f = moved(x.f, t * dir);
      if (m.measure(f.n) < x.a) {
        x = evaluate(m, f);
        left = true;
      }
    }
    if (!left) break;
    h = identity / x.a;
    scaled = false;
  }
  out = WallCandidate{x.f.n, x.a};
  return true;
}

// Descents from the starts, lowest area first (the first usually ends in
// the global minimum and later ones join it early); minima within
// merge_angle are one.
std::vector<WallCandidate> minima3D(const NewWallMeasure& m, const std::vector<Vec3>& starts,
                                    const ShortestWallSearchOptions& o) {
  std::vector<std::pair<double, Vec3>> order;
  order.reserve(starts.size());
  for (const Vec3& s : starts) {
    const Vec3 n = s.normalized();
    order.emplace_back(m.measure(n), n);
  }
  std::stable_sort(order.begin(), order.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<WallCandidate> out;
  WallCandidate c;
  for (const auto& [a, n] : order)
    if (descend(m, n, out, o, c)) addCandidate(out, c, o.merge_angle);
  // Near a plane of symmetry the gradient is resolved only to ~1e-8 rad (edges
  // lying in the plane make the crossings ill-conditioned) while the area is
  // flat to rounding: a minimum within kSnapAngle of a start whose area is no
  // larger (to rounding) is that start, exactly. A box's minima are then its
  // axes, and their planes meet the vertices on them within splitCell's snap
  // tolerance rather than 1e-8 beside them.
  const double cos_snap = std::cos(kSnapAngle);
  for (WallCandidate& w : out)
    for (const auto& [a, n] : order)
      if (std::abs(w.normal.dot(n)) >= cos_snap && a <= w.measure * (1 + 1e-15)) {
        w = WallCandidate{w.normal.dot(n) < 0 ? Vec3(-n) : n, a};
        break;
      }
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
