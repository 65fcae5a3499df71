// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// DivisionRule: where a cell divides. A rule returns the cutting plane for a
// cell; Tissue::splitCell does the cut (2D, surface and 3D alike). On a
// surface tissue the plane contains the cell's normal, so it cuts the
// (non-planar) polygon along a line across the sheet.

#include <random>
#include <string>
#include <vector>

#include "tessella/tissue/tissue.hpp"
#include "tessella/tissue/vec3.hpp"

namespace tessella::growth {

/// The random engine of every stochastic part of growth/ (reproducible from a seed).
using Rng = std::mt19937_64;

class DivisionRule {
 public:
  virtual ~DivisionRule() = default;
  /// The plane dividing cell c. Throws GeometryError (naming the cell) when
  /// the rule has no answer for this cell (e.g. a fixed direction normal to
  /// a surface cell).
  virtual Plane plane(const Tissue& t, CellId c, Rng& rng) const = 0;
  /// The planes the rule would take for cell c, best first: plane() first,
  /// then the rule's next choices (shortest_wall: its other local minima, by
  /// area). On a 3D tissue the scheduler divides by the first whose new walls
  /// cross no other wall (division_crossings.hpp). By default plane() alone.
  virtual std::vector<Plane> planes(const Tissue& t, CellId c, Rng& rng) const { return {plane(t, c, rng)}; }
  /// True when plane() may run on several threads at once and draws nothing
  /// from `rng`: the scheduler then finds a step's planes in parallel. A rule
  /// that draws, keeps state or calls back (Python) says false (the default)
  /// and its planes are found one after the other, in the order of the cells.
  virtual bool concurrent() const { return false; }
  /// The rule's configuration name ("main_axis", "shortest_wall", ...).
  virtual std::string name() const = 0;
};

}  // namespace tessella::growth
