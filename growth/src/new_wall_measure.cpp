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
  const VolumeId vol = t.cellVolume(c);
  for (OrientedFace of : k.volumeFaces(vol)) {
    const auto loop = k.faceVertices(of.handle());
    std::vector<Vec3> q;
    q.reserve(loop.size());
    for (VertexId v : loop) q.push_back(t.position(v) - point_);
    // Orient every loop outward: a reversed face is traversed backwards.
    if (of.reversed()) std::reverse(q.begin(), q.end());
    faces_.push_back(std::move(q));
  }
}

double NewWallMeasure::length(double theta) const { return chord(std::cos(theta), std::sin(theta)); }

double NewWallMeasure::measure(const Vec3& normal) const {
  if (dim_ == 2) return chord(normal.dot(frame_.e1), normal.dot(frame_.e2));
  return section(normal.normalized());
}

double NewWallMeasure::chord(double nx, double ny) const {
  // Crossings of the line {n . p = 0} with the loop, as abscissae along the
  // line direction d = (-ny, nx); the chord through the origin (the plane
  // point) is the pair of consecutive crossings enclosing 0.
  const double norm = std::hypot(nx, ny);
  nx /= norm;
  ny /= norm;
  const std::size_t n = u_.size();
  std::array<double, 64> small;
  std::vector<double> large;
  double* tau = small.data();
  if (n > small.size()) {
    large.resize(n);
    tau = large.data();
  }
  std::size_t count = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = i + 1 == n ? 0 : i + 1;
    const double si = nx * u_[i] + ny * v_[i], sj = nx * u_[j] + ny * v_[j];
    if ((si > 0) == (sj > 0)) continue;  // half-open: a vertex on the line counts once
    const double a = si / (si - sj);
    const double pu = u_[i] + a * (u_[j] - u_[i]), pv = v_[i] + a * (v_[j] - v_[i]);
    tau[count++] = -ny * pu + nx * pv;
  }
  if (count < 2) return 0.0;
  std::sort(tau, tau + count);
  double best = std::numeric_limits<double>::infinity(), best_len = 0.0;
  for (std::size_t i = 0; i + 1 < count; i += 2) {
    if (tau[i] <= 0 && 0 <= tau[i + 1]) return tau[i + 1] - tau[i];
    const double gap = std::min(std::abs(tau[i]), std::abs(tau[i + 1]));
    if (gap < best) {
      best = gap;
      best_len = tau[i + 1] - tau[i];
    }
  }
  return best_len;  // the point is outside the cell: the nearest piece
}

double NewWallMeasure::section(const Vec3& n) const {
  // Section area = sum over walls of (1/2) n . (b x a), where on each outward
  // wall loop b is a crossing from the positive to the negative side and a
  // the next crossing back: the chord b -> a is the section's boundary
  // traversed counter-clockwise about n. Pairing crossings in loop order
  // instead of along the line gives the same sum (it is linear in the
  // crossings' abscissae), so non-convex walls are handled too.
  double twice_area = 0.0;
  for (const auto& q : faces_) {
    const std::size_t m = q.size();
    bool have_b = false;
    Vec3 first_b = Vec3::Zero(), b = Vec3::Zero();
    bool pending_a_before_b = false;
    Vec3 first_a = Vec3::Zero();
    for (std::size_t i = 0; i < m; ++i) {
      const std::size_t j = i + 1 == m ? 0 : i + 1;
      const double si = n.dot(q[i]), sj = n.dot(q[j]);
      const bool pi = si > 0, pj = sj > 0;
      if (pi == pj) continue;
      const Vec3 x = q[i] + (si / (si - sj)) * (q[j] - q[i]);
      if (pi) {  // + -> -: start of a section boundary segment
        b = x;
        if (!have_b) first_b = x;
        have_b = true;
      } else {   // - -> +: end of the segment that started at the last b
        if (have_b) {
          twice_area += n.dot(b.cross(x));
        } else {
          pending_a_before_b = true;  // pairs with the loop's last b (wrap-around)
          first_a = x;
        }
      }
    }
    if (pending_a_before_b && have_b) twice_area += n.dot(b.cross(first_a));
    (void)first_b;
  }
  return 0.5 * twice_area;
}

}  // namespace tessella::growth
