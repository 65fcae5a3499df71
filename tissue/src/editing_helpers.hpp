// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Private helpers of the editing primitives (tissue_editing.cpp) and of the
// division planner (cell_split_plan.cpp). Internal to the tissue module.

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "polygon_kernels.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"
#include "tessella/tissue/handles.hpp"
#include "tessella/tissue/vec3.hpp"

namespace tessella::detail {

/// A point for messages: "(x, y, z)" with 12 digits.
inline std::string pointText(const Vec3& p) { return formatPoint(p, 12); }

/// Edge parameter of `point` on a -> b (edge e), required strictly inside (by
/// 1e-12): Tissue::splitEdge's check, which planCellSplit3D makes for every new
/// vertex of a plan before the plan's edits run.
inline double edgeParameter(const Vec3& a, const Vec3& b, const Vec3& point, EdgeId e) {
  const Vec3 ab = b - a;
  const double l2 = ab.squaredNorm();
  if (!(l2 > 0)) throw GeometryError("edge " + std::to_string(e.index()) + " has zero length", {1, e.index()});
  if (!point.allFinite())
    throw GeometryError("split point of edge " + std::to_string(e.index()) + " is not finite", {1, e.index()});
  const double t = (point - a).dot(ab) / l2;
  constexpr double kEps = 1e-12;
  if (!(t > kEps && t < 1 - kEps))
    throw GeometryError("split point " + pointText(point) + " of edge " + std::to_string(e.index()) +
                            " is not strictly between its vertices (parameter " + formatNumber(t) + ")",
                        {1, e.index()});
  return t;
}

/// Area and normal of a loop of points, with the tissue's kernel.
struct LoopArea {
  double area;
  Vec3 normal;
};
inline LoopArea loopArea(const std::vector<Vec3>& pts, bool planar) {
  double a;
  Vec3 c, nrm;
  polygonKernel(
      pts.size(), [&](std::size_t i) -> const Vec3& { return pts[i]; }, planar, false, a, c, nrm, nullptr);
  return {a, nrm};
}

/// A tiny map over a handful of keys (a cell's vertices, the nodes of one
/// cut): linear search in a vector beats hashing at these sizes and does not
/// allocate per entry.
template <typename K, typename V>
class SmallMap {
 public:
  V& operator[](const K& k) {
    for (auto& [key, value] : items_)
      if (key == k) return value;
    items_.emplace_back(k, V{});
    return items_.back().second;
  }
  void set(const K& k, const V& v) {
    for (auto& [key, value] : items_)
      if (key == k) {
        value = v;
        return;
      }
    items_.emplace_back(k, v);
  }
  const V& at(const K& k) const {
    for (const auto& [key, value] : items_)
      if (key == k) return value;
    throw std::out_of_range("SmallMap::at");
  }
  const V* find(const K& k) const {
    for (const auto& [key, value] : items_)
      if (key == k) return &value;
    return nullptr;
  }
  auto begin() const { return items_.begin(); }
  auto end() const { return items_.end(); }
  std::size_t size() const { return items_.size(); }

 private:
  std::vector<std::pair<K, V>> items_;
};

}  // namespace tessella::detail
