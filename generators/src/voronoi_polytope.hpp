// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Private: a convex polytope that can be cut by planes, each face remembering
// the plane that made it (a neighbour seed or a domain face). One Voronoi cell
// in 3D is a box cut by the bisector planes of its Delaunay neighbours.

#include <array>
#include <span>
#include <vector>

#include "tessella/tissue/vec3.hpp"

namespace tessella::detail {

class ClipPolytope {
 public:
  /// The axis-aligned box [lo, hi]; its faces get labels box_labels
  /// (-x, +x, -y, +y, -z, +z).
  void resetToBox(const Vec3& lo, const Vec3& hi, const std::array<int, 6>& box_labels);

  /// Keeps the part with normal.x <= offset (normal of unit length); the cut
  /// face gets `label`. Vertices within `on` of the plane are taken as lying
  /// on it, so a plane through a vertex or an edge cuts no sliver. Returns
  /// false when nothing was cut.
  bool clip(const Vec3& normal, double offset, int label, double on);

  std::size_t numFaces() const { return face_label_.size(); }
  int faceLabel(std::size_t f) const { return face_label_[f]; }
  /// Vertex indices of face f, counter-clockwise seen from outside.
  const int* faceBegin(std::size_t f) const { return loops_.data() + face_start_[f]; }
  const int* faceEnd(std::size_t f) const { return loops_.data() + face_start_[f + 1]; }
  const std::vector<Vec3>& vertices() const { return vertices_; }
  /// The labels of the planes through vertex v (at least 3; more where
  /// several planes meet at one point), in no particular order.
  std::span<const int> vertexLabels(std::size_t v) const {
    return {labels_[v].data(), static_cast<std::size_t>(label_count_[v])};
  }
  static constexpr int kMaxLabels = 12;

  /// Largest distance from p to a vertex.
  double reach(const Vec3& p) const;
  /// Volume and centroid (divergence theorem over fans of the faces).
  void volumeAndCentroid(double& volume, Vec3& centroid) const;

 private:
  using Labels = std::array<int, kMaxLabels>;
  void addLabel(std::vector<Labels>& labels, std::vector<int>& count, std::size_t v, int label);

  std::vector<Vec3> vertices_;
  std::vector<Labels> labels_;
  std::vector<int> label_count_;
  std::vector<int> face_start_{0};
  std::vector<int> loops_;
  std::vector<int> face_label_;
  // Scratch reused by clip() so that cells cost no heap allocation.
  std::vector<double> side_;
  std::vector<int> remap_;
  std::vector<Vec3> new_vertices_;
  std::vector<Labels> new_labels_;
  std::vector<int> new_label_count_;
  std::vector<int> new_start_, new_loops_, new_label_;
  std::vector<std::array<int, 3>> cut_edges_;  // (a, b, new vertex) on crossed edges
  std::vector<std::array<int, 2>> cap_;         // cap segments (from, to)
};

}  // namespace tessella::detail
