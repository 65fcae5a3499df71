// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// SizeThreshold: when a cell divides. A cell is due when its size (area in
// 2D, volume in 3D) exceeds its threshold, which is
//   fixed      one value for every cell;
//   property   a per-cell double property the model maintains;
//   noisy      drawn for each cell at birth from a normal distribution
//              (mean, standard deviation; redrawn while <= 0), stored in a
//              cell property with policy Reset, so daughters get NaN and
//              draw their own (the "adder/sizer with noise" of cell-cycle
//              models; keeps divisions from synchronising).

#include <string>
#include <vector>

#include "tessella/growth/division_rule.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/tissue/tissue.hpp"

namespace tessella::growth {

class SizeThreshold {
 public:
  enum class Kind { Fixed, Property, Noisy };

  /// InputError for a non-positive or non-finite size.
  static SizeThreshold fixed(double size);
  /// The threshold is the cell property `name` (double); InputError at
  /// prepare() if it is missing or of another type.
  static SizeThreshold fromProperty(std::string name);
  /// InputError for mean <= 0 or stddev < 0.
  static SizeThreshold noisy(double mean, double stddev,
                             std::string property = "division_threshold");

  /// Registers the noisy property (if needed) and draws thresholds for the
  /// cells that have none (NaN, or any value that is not a positive size).
  /// Called by cellsDue().
  void prepare(Tissue& t, Rng& rng) const;
  /// The threshold of one cell (after prepare()).
  double threshold(const Tissue& t, CellId c) const;
  /// Cells whose measure in `geometry` (fresh) exceeds their threshold, in
  /// slot order.
  std::vector<CellId> cellsDue(Tissue& t, const GeometryCache& geometry, Rng& rng) const;

  Kind kind() const { return kind_; }
  std::string describe() const;

 private:
  Kind kind_ = Kind::Fixed;
  double size_ = 0;      // fixed; mean when noisy
  double stddev_ = 0;    // noisy
  std::string property_; // property / noisy
};

}  // namespace tessella::growth
