// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Convex polytope clipping for the 3D Voronoi cells.

#include "voronoi_polytope.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/Geometry>

#include "tessella/tissue/errors.hpp"

namespace tessella::detail {

void ClipPolytope::resetToBox(const Vec3& lo, const Vec3& hi, const std::array<int, 6>& box_labels) {
  vertices_.clear();
  labels_.assign(8, Labels{});
  label_count_.assign(8, 3);
  for (int v = 0; v < 8; ++v) {
    vertices_.emplace_back(v & 1 ? hi.x() : lo.x(), v & 2 ? hi.y() : lo.y(), v & 4 ? hi.z() : lo.z());
    labels_[v][0] = box_labels[v & 1 ? 1 : 0];
    labels_[v][1] = box_labels[v & 2 ? 3 : 2];
    labels_[v][2] = box_labels[v & 4 ? 5 : 4];
  }
  // Counter-clockwise seen from outside: -x, +x, -y, +y, -z, +z.
  static constexpr int kLoops[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                       {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  loops_.clear();
  face_start_.assign(1, 0);
  face_label_.clear();
  for (int f = 0; f < 6; ++f) {
    loops_.insert(loops_.end(), kLoops[f], kLoops[f] + 4);
    face_start_.push_back(static_cast<int>(loops_.size()));
    face_label_.push_back(box_labels[f]);
  }
}

bool ClipPolytope::clip(const Vec3& normal, double offset, int label, double on) {
  const std::size_t nv = vertices_.size();
  side_.resize(nv);
  bool any_out = false;
  for (std::size_t v = 0; v < nv; ++v) {
    side_[v] = normal.dot(vertices_[v]) - offset;
    any_out |= side_[v] > on;
  }
  if (!any_out) return false;

  remap_.assign(nv, -1);
  new_vertices_.clear();
  new_labels_.clear();
  new_label_count_.clear();
  for (std::size_t v = 0; v < nv; ++v) {
    if (side_[v] <= on) {
      remap_[v] = static_cast<int>(new_vertices_.size());
      new_vertices_.push_back(vertices_[v]);
      new_labels_.push_back(labels_[v]);
      new_label_count_.push_back(label_count_[v]);
      // A vertex taken as lying on the plane is on it: remember the plane.
      if (side_[v] >= -on) addLabel(new_labels_, new_label_count_, new_vertices_.size() - 1, label);
    }
  }
  cut_edges_.clear();
  cap_.clear();
  // The point where edge (a, b) crosses the plane, computed once per edge and
  // from its lower-numbered end so both faces of the edge get the same vertex.
  auto cutVertex = [&](int a, int b) {
    const int lo = std::min(a, b), hi = std::max(a, b);
    for (const auto& c : cut_edges_)
      if (c[0] == lo && c[1] == hi) return c[2];
    const double s_lo = side_[lo], s_hi = side_[hi];
    new_vertices_.push_back(vertices_[lo] + (vertices_[hi] - vertices_[lo]) * (s_lo / (s_lo - s_hi)));
    const int id = static_cast<int>(new_vertices_.size()) - 1;
    // On the planes shared by both ends (those of the edge) and on the cut.
    new_labels_.emplace_back();
    new_label_count_.push_back(0);
    for (int k = 0; k < label_count_[lo]; ++k) {
      const int l = labels_[lo][k];
      const auto hi_begin = labels_[hi].begin();
      if (std::find(hi_begin, hi_begin + label_count_[hi], l) != hi_begin + label_count_[hi])
        addLabel(new_labels_, new_label_count_, static_cast<std::size_t>(id), l);
    }
    addLabel(new_labels_, new_label_count_, static_cast<std::size_t>(id), label);
    cut_edges_.push_back({lo, hi, id});
    return id;
  };

  new_start_.assign(1, 0);
  new_loops_.clear();
  new_label_.clear();
  for (std::size_t f = 0; f < face_label_.size(); ++f) {
    const int* loop = loops_.data() + face_start_[f];
    const int m = face_start_[f + 1] - face_start_[f];
    const std::size_t begin = new_loops_.size();
    int exit_point = -1, entry_point = -1;
    for (int k = 0; k < m; ++k) {
      const int a = loop[k], b = loop[(k + 1) % m];
      const double sa = side_[a], sb = side_[b];
      if (sa <= on) new_loops_.push_back(remap_[a]);
      const bool crossing = (sa < -on && sb > on) || (sa > on && sb < -on);
      const int c = crossing ? cutVertex(a, b) : -1;
      if (crossing) new_loops_.push_back(c);
      if (sa <= on && sb > on) exit_point = crossing ? c : remap_[a];
      if (sa > on && sb <= on) entry_point = crossing ? c : remap_[b];
    }
    if (new_loops_.size() - begin >= 3) {
      new_start_.push_back(static_cast<int>(new_loops_.size()));
      new_label_.push_back(face_label_[f]);
    } else {
      new_loops_.resize(begin);
    }
    // This face now runs exit -> entry along the plane; the cap runs back.
    if (exit_point >= 0 && entry_point >= 0 && exit_point != entry_point)
      cap_.push_back({entry_point, exit_point});
  }

  if (cap_.size() >= 3) {
    const std::size_t begin = new_loops_.size();
    int current = cap_[0][0];
    for (std::size_t step = 0; step < cap_.size(); ++step) {
      new_loops_.push_back(current);
      auto next = std::find_if(cap_.begin(), cap_.end(),
                               [&](const std::array<int, 2>& s) { return s[0] == current; });
      if (next == cap_.end())
        throw GeometryError("Voronoi cell clipping: the cut by the plane of label " +
                            std::to_string(label) + " does not close (degenerate seeds?)");
      current = (*next)[1];
    }
    if (current != cap_[0][0])
      throw GeometryError("Voronoi cell clipping: the cut by the plane of label " +
                          std::to_string(label) + " is not a single loop (degenerate seeds?)");
    if (new_loops_.size() - begin >= 3) {
      new_start_.push_back(static_cast<int>(new_loops_.size()));
      new_label_.push_back(label);
    } else {
      new_loops_.resize(begin);
    }
  }

  // Drop vertices no face uses any more.
  remap_.assign(new_vertices_.size(), -1);
  for (int v : new_loops_) remap_[v] = 0;
  vertices_.clear();
  labels_.clear();
  label_count_.clear();
  for (std::size_t v = 0; v < new_vertices_.size(); ++v) {
    if (remap_[v] < 0) continue;
    remap_[v] = static_cast<int>(vertices_.size());
    vertices_.push_back(new_vertices_[v]);
    labels_.push_back(new_labels_[v]);
    label_count_.push_back(new_label_count_[v]);
  }
  for (int& v : new_loops_) v = remap_[v];
  loops_.swap(new_loops_);
  face_start_.swap(new_start_);
  face_label_.swap(new_label_);
  return true;
}

void ClipPolytope::addLabel(std::vector<Labels>& labels, std::vector<int>& count, std::size_t v,
                            int label) {
  int& n = count[v];
  for (int k = 0; k < n; ++k)
    if (labels[v][k] == label) return;
  if (n < kMaxLabels) labels[v][n++] = label;
}

double ClipPolytope::reach(const Vec3& p) const {
  double r2 = 0;
  for (const Vec3& v : vertices_) r2 = std::max(r2, (v - p).squaredNorm());
  return std::sqrt(r2);
}

void ClipPolytope::volumeAndCentroid(double& volume, Vec3& centroid) const {
  const Vec3 origin = vertices_.empty() ? Vec3::Zero() : vertices_[0];
  volume = 0;
  Vec3 moment = Vec3::Zero();
  for (std::size_t f = 0; f < face_label_.size(); ++f) {
    const int* loop = faceBegin(f);
    const int m = static_cast<int>(faceEnd(f) - loop);
    const Vec3 a = vertices_[loop[0]] - origin;
    for (int k = 1; k + 1 < m; ++k) {
      const Vec3 b = vertices_[loop[k]] - origin, c = vertices_[loop[k + 1]] - origin;
      const double v6 = a.dot(b.cross(c));
      volume += v6;
      moment += v6 * (a + b + c) / 4;
    }
  }
  centroid = origin + moment / volume;
  volume /= 6;
}

}  // namespace tessella::detail
