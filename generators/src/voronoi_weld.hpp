// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Private: VertexWelder gives one id to all points within a tolerance of each
// other. The clipped Voronoi cells are computed one by one, so a vertex shared
// by k cells is computed k times (with different rounding); welding makes the
// complex conforming, and it also merges the zero-length edges that cocircular
// (2D) or cospherical (3D) seeds produce.
//
// Points are bucketed on a grid much coarser than the tolerance, so almost
// every query reads one bucket (an open-addressing table, no per-point heap
// allocation); a point near a bucket face also reads the neighbour bucket.

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "tessella/tissue/handles.hpp"
#include "tessella/tissue/vec3.hpp"

namespace tessella::detail {

class VertexWelder {
 public:
  VertexWelder(const Vec3& origin, double tolerance, std::size_t expected_points)
      : origin_(origin), tolerance_(tolerance), bucket_(tolerance * 1024) {
    std::size_t capacity = 64;
    while (capacity < 2 * expected_points + 16) capacity *= 2;
    table_.assign(capacity, Slot{});
    positions_.reserve(expected_points);
    next_.reserve(expected_points);
  }

  /// The id of a point within tolerance of p, or a new id for p.
  Index weld(const Vec3& p) {
    std::array<std::int64_t, 3> cell;
    std::array<int, 3> near{};  // -1 / +1: p is within tolerance of the lower / upper bucket face
    for (int a = 0; a < 3; ++a) {
      const double q = (p[a] - origin_[a]) / bucket_;
      const double f = std::floor(q);
      cell[a] = static_cast<std::int64_t>(f);
      const double frac = (q - f) * bucket_;
      near[a] = frac < tolerance_ ? -1 : (bucket_ - frac < tolerance_ ? 1 : 0);
    }
    const double tol2 = tolerance_ * tolerance_;
    // Own bucket first, then the (rarely needed) neighbours.
    for (int mask = 0; mask < 8; ++mask) {
      std::array<std::int64_t, 3> c = cell;
      bool skip = false;
      for (int a = 0; a < 3; ++a) {
        if (mask & (1 << a)) {
          if (near[a] == 0) skip = true;
          c[a] += near[a];
        }
      }
      if (skip) continue;
      const Slot* slot = find(c);
      if (!slot) continue;
      for (Index v = slot->head; v != kInvalidIndex; v = next_[v])
        if ((positions_[v] - p).squaredNorm() <= tol2) return v;
    }
    const Index id = static_cast<Index>(positions_.size());
    positions_.push_back(p);
    Slot& slot = findOrInsert(cell);
    next_.push_back(slot.head);
    slot.head = id;
    return id;
  }

  const std::vector<Vec3>& positions() const { return positions_; }
  std::vector<Vec3> takePositions() { return std::move(positions_); }

 private:
  struct Slot {
    std::array<std::int64_t, 3> cell{};
    Index head = kInvalidIndex;  // kInvalidIndex: empty slot
  };

  static std::uint64_t hash(const std::array<std::int64_t, 3>& c) {
    std::uint64_t h = static_cast<std::uint64_t>(c[0]) * 0x9E3779B97F4A7C15ull;
    h ^= static_cast<std::uint64_t>(c[1]) * 0xC2B2AE3D27D4EB4Full + (h << 6) + (h >> 2);
    h ^= static_cast<std::uint64_t>(c[2]) * 0x165667B19E3779F9ull + (h << 6) + (h >> 2);
    return h ^ (h >> 29);
  }

  const Slot* find(const std::array<std::int64_t, 3>& c) const {
    const std::size_t mask = table_.size() - 1;
    for (std::size_t i = hash(c) & mask;; i = (i + 1) & mask) {
      const Slot& s = table_[i];
      if (s.head == kInvalidIndex) return nullptr;
      if (s.cell == c) return &s;
    }
  }

  Slot& findOrInsert(const std::array<std::int64_t, 3>& c) {
    if (2 * (used_ + 1) > table_.size()) grow();
    const std::size_t mask = table_.size() - 1;
    for (std::size_t i = hash(c) & mask;; i = (i + 1) & mask) {
      Slot& s = table_[i];
      if (s.head == kInvalidIndex) {
        s.cell = c;
        ++used_;
        return s;
      }
      if (s.cell == c) return s;
    }
  }

  void grow() {
    std::vector<Slot> old = std::move(table_);
    table_.assign(old.size() * 2, Slot{});
    const std::size_t mask = table_.size() - 1;
    for (const Slot& s : old) {
      if (s.head == kInvalidIndex) continue;
      std::size_t i = hash(s.cell) & mask;
      while (table_[i].head != kInvalidIndex) i = (i + 1) & mask;
      table_[i] = s;
    }
  }

  Vec3 origin_;
  double tolerance_;
  double bucket_;
  std::vector<Slot> table_;
  std::size_t used_ = 0;
  std::vector<Vec3> positions_;
  std::vector<Index> next_;  // chains of points sharing a bucket
};

}  // namespace tessella::detail
