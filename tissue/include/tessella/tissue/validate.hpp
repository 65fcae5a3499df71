// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// validate(): checks every invariant of a tissue and reports the first
// violation with the element ids involved. Tests call it after every edit;
// building with -DTESSELLA_PARANOID=ON calls it inside every editing primitive.

#include <string>

#include "tessella/tissue/tissue.hpp"

namespace tessella {

struct ValidateOptions {
  /// Check the Euler characteristic: per piece (cells connected through
  /// walls; pieces touching only at a vertex or along an edge are counted
  /// apart, each with its own copy of what they share), V-E+F = 2 - b in 2D
  /// (a sphere with b holes, i.e. genus 0) and V-E+F-C = 1 in 3D (a solid
  /// ball). Disable for tissues with handles or cavities.
  bool check_euler = true;
  /// Check that every live edge, face and cell has a positive measure.
  bool check_measures = true;
  /// Check that every polygon (2D cell, 3D wall) is not pinched (two
  /// non-adjacent vertices within 1e-12 of its size) and, with
  /// check_self_intersection, not self-intersecting in its best-fit plane
  /// (checked where the projection measures it: planar cells, and polygons
  /// whose fan from the vertex mean folds) — and that no two neighbouring
  /// cells of a curved sheet overlap (normals pointing opposite ways across
  /// their wall: a cell folded over or inverted). Planar inverted cells are
  /// reported by check_measures.
  bool check_shapes = true;
  /// With check_shapes: also refuse a polygon whose outline crosses or touches
  /// itself. Off by default for now: the growth of configs/figure17.yaml
  /// inverts a short wall edge at t = 1.6 (two edges of one cell then cross),
  /// which the growth integrator does not detect yet, and a run validated at
  /// every step would stop there. The meshers always refuse such cells.
  bool check_self_intersection = false;
  /// Check that 2D cells sharing an edge traverse it in opposite directions
  /// (a consistently oriented sheet).
  bool check_orientation = true;
};

struct ValidationReport {
  bool ok = true;
  std::string message;  ///< first violation, naming the element ids
  ElementId element;    ///< the offending element, where there is one
  explicit operator bool() const { return ok; }
};

ValidationReport validate(const Tissue& t, const ValidateOptions& options = {});

/// validate() that throws TopologyError with the report's message.
void validateOrThrow(const Tissue& t, const ValidateOptions& options = {});

}  // namespace tessella
