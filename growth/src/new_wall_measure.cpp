// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/growth/new_wall_measure.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "tessella/tissue/geometry.hpp"

namespace tessella::growth {

NewWallMeasure::NewWallMeasure(const Tissue& t, CellId c) : NewWallMeasure(t, c, cellFrame(t, c).centroid) {}

NewWallMeasure::NewWallMeasure(const Tissue& t, CellId c, const Vec3& point)
    : dim_(t.dim()), frame_(cellFrame(t, c)), point_(point) {
  const CellComplex& k = t.topology();
  if (dim_ == 2) {
    const auto loop = k.faceVertices(t.cellFace(c));
    u_.reserve(loop.size());
    v_.reserve(loop.size());
    for (VertexId v : loop) {
      const Vec3 d = t.position(v) - point_;
      u_.push_back(d.dot(frame_.e1));
      v_.push_back(d.dot(frame_.e2));
    }
    return;
  }
  // Each vertex once (a cell's vertex lies on three walls or more): a plane's
  // signed distances are computed once per vertex, not once per loop entry.
  const VolumeId vol = t.cellVolume(c);
  std::vector<VertexId> unique;
  for (OrientedFace of : k.volumeFaces(vol))
    for (VertexId v : k.faceVertices(of.handle())) unique.push_back(v);
  std::sort(unique.begin(), unique.end());
  unique.erase(std::unique(unique.begin(), unique.end()), unique.end());
  points_.reserve(unique.size());
  for (VertexId v : unique) points_.push_back(t.position(v) - point_);
  loop_start_.push_back(0);
  for (OrientedFace of : k.volumeFaces(vol)) {
    const std::size_t first = loops_.size();
    for (VertexId v : k.faceVertices(of.handle()))
      loops_.push_back(static_cast<std::uint32_t>(std::lower_bound(unique.begin(), unique.end(), v) - unique.begin()));
    // Orient every loop outward: a reversed face is traversed backwards.
    if (of.reversed()) std::reverse(loops_.begin() + first, loops_.end());
    loop_start_.push_back(static_cast<std::uint32_t>(loops_.size()));
  }
}

double NewWallMeasure::length(double theta) const {
  const Chord c = chord(std::cos(theta), std::sin(theta));
  return c.hi - c.lo;
}

double NewWallMeasure::measure(const Vec3& normal) const {
  if (dim_ == 2) {
    const Chord c = chord(normal.dot(frame_.e1), normal.dot(frame_.e2));
    return c.hi - c.lo;
  }
  return section<false>(normal.normalized(), nullptr);
}

NewWallMeasure::Chord NewWallMeasure::chord(double nx, double ny) const {
  // Crossings of the line {n . p = 0} with the loop, as abscissae along the
  // line direction d = (-ny, nx); the chord through the origin (the plane
  // point) is the pair of consecutive crossings enclosing 0.
  const double norm = std::sqrt(nx * nx + ny * ny);  // (not hypot: slower, and no overflow risk here)
  nx /= norm;
  ny /= norm;
  const std::size_t n = u_.size();
  struct Crossing {
    double tau;
    int edge;
  };
  std::array<Crossing, 64> small;  // no allocation for cells of up to 64 sides
  std::vector<Crossing> large;
  Crossing* x = small.data();
  if (n > small.size()) {
    large.resize(n);
    x = large.data();
  }
  std::size_t count = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = i + 1 == n ? 0 : i + 1;
    const double si = nx * u_[i] + ny * v_[i], sj = nx * u_[j] + ny * v_[j];
    if ((si > 0) == (sj > 0)) continue;  // half-open: a vertex on the line counts once
    const double a = si / (si - sj);
    const double pu = u_[i] + a * (u_[j] - u_[i]), pv = v_[i] + a * (v_[j] - v_[i]);
    x[count++] = Crossing{-ny * pu + nx * pv, static_cast<int>(i)};
  }
  Chord out;
  out.crossings = count;
  if (count < 2) return out;
  // Insertion sort: 2 crossings for a convex cell, a handful otherwise.
  for (std::size_t i = 1; i < count; ++i)
    for (std::size_t j = i; j > 0 && x[j].tau < x[j - 1].tau; --j) std::swap(x[j], x[j - 1]);
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + 1 < count; i += 2) {
    const bool contains = x[i].tau <= 0 && 0 <= x[i + 1].tau;
    const double gap = contains ? 0.0 : std::min(std::abs(x[i].tau), std::abs(x[i + 1].tau));
    if (gap < best) {  // the point is outside the cell: the nearest piece
      best = gap;
      out = Chord{x[i].tau, x[i + 1].tau, x[i].edge, x[i + 1].edge, contains, count};
    }
    if (contains) break;
  }
  return out;
}

double NewWallMeasure::measureAndGradient(const Vec3& n, Vec3& gradient) const {
  const double area = section<true>(n, &gradient);
  gradient -= n.dot(gradient) * n;  // tangent part (the radial part is the area itself)
  return area;
}

namespace {

// A crossing x = p + t (q - p) of the plane {n . x = 0} with the edge p -> q,
// t = s_p / (s_p - s_q) (s = n . vertex), and for the gradient the edge
// vector d = q - p and dt/dn = (s_p q - s_q p) / (s_p - s_q)^2.
struct Crossing {
  Vec3 x = Vec3::Zero(), d, dt;
};

template <bool kGradient>
Crossing crossing(const Vec3& p, const Vec3& q, double sp, double sq) {
  const double inv = 1.0 / (sp - sq);
  const Vec3 d = q - p;
  Crossing c;
  c.x = p + (sp * inv) * d;
  if constexpr (kGradient) {
    c.d = d;
    c.dt = (inv * inv) * (sp * q - sq * p);
  }
  return c;
}

// Twice the chord's area term n . (b x a) and, for the gradient, its
// derivative in n: (b x a) + db/dn^T (a x n) + da/dn^T (n x b), where
// dx/dn^T v = dt/dn (d . v) (b and a move along their edges as n turns).
template <bool kGradient>
double chordTerm(const Vec3& n, const Crossing& b, const Crossing& a, Vec3& gradient) {
  const Vec3 ba = b.x.cross(a.x);
  if constexpr (kGradient)
    gradient += ba + b.d.dot(a.x.cross(n)) * b.dt + a.d.dot(n.cross(b.x)) * a.dt;
  return n.dot(ba);
}

}  // namespace

template <bool kGradient>
double NewWallMeasure::section(const Vec3& n, Vec3* gradient) const {
  // Section area = sum over walls of (1/2) n . (b x a), where on each outward
  // wall loop b is a crossing from the positive to the negative side and a
  // the next crossing back: the chord b -> a is the section's boundary
  // traversed counter-clockwise about n. Pairing crossings in loop order
  // instead of along the line gives the same sum (it is linear in the
  // crossings' abscissae), so non-convex walls are handled too.
  std::array<double, 256> small;  // no allocation for cells of up to 256 vertices
  std::vector<double> large;
  double* s = small.data();
  if (points_.size() > small.size()) {
    large.resize(points_.size());
    s = large.data();
  }
  for (std::size_t v = 0; v < points_.size(); ++v) s[v] = n.dot(points_[v]);
  double twice_area = 0.0;
  Vec3 twice_gradient = Vec3::Zero();
  for (std::size_t f = 0; f + 1 < loop_start_.size(); ++f) {
    const std::uint32_t* q = loops_.data() + loop_start_[f];
    const std::size_t m = loop_start_[f + 1] - loop_start_[f];
    bool have_b = false, pending_a_before_b = false;
    Crossing b, first_a;
    double sj = s[q[0]];
    for (std::size_t i = 0; i < m; ++i) {
      const std::size_t j = i + 1 == m ? 0 : i + 1;
      const double si = sj;
      sj = s[q[j]];
      const bool pi = si > 0, pj = sj > 0;
      if (pi == pj) continue;
      const Crossing x = crossing<kGradient>(points_[q[i]], points_[q[j]], si, sj);
      if (pi) {  // + -> -: start of a section boundary segment
        b = x;
        have_b = true;
      } else if (have_b) {  // - -> +: end of the segment that started at the last b
        twice_area += chordTerm<kGradient>(n, b, x, twice_gradient);
      } else {
        pending_a_before_b = true;  // pairs with the loop's last b (wrap-around)
        first_a = x;
      }
    }
    if (pending_a_before_b && have_b) twice_area += chordTerm<kGradient>(n, b, first_a, twice_gradient);
  }
  if constexpr (kGradient) *gradient = 0.5 * twice_gradient;
  return 0.5 * twice_area;
}

}  // namespace tessella::growth
