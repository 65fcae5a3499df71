// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// How a membrane polygon is cut into triangles (docs/mechanics.md,
// "Triangulation"). Chosen once, at the polygon's reference (when its rest
// state is created or reset), and kept fixed while its rest state lives, so
// that the energy stays a smooth function of the vertex positions:
//
// - MeanFan: the fan (a, x_i, x_{i+1}) from the loop's vertex mean
//   a = (1/n) sum_k x_k (what the tissue measures when that fan does not fold);
// - KernelFan: the fan from an apex a = sum_k w_k x_k with FIXED weights w, the
//   mean value coordinates (Floater 2003) of the centroid of the kernel of the
//   loop's projection on its best-fit plane, computed at the reference: there
//   the apex projects on the kernel centroid the tissue measures the polygon
//   from; later it follows the loop linearly (w sum to 1, all positive);
// - Ears: the loop's ear-clipped triangles (tissue/geometry.hpp), for a loop
//   whose projection has no kernel: elements on the loop vertices only.
//
// In every case the corners are linear in the loop's vertices, so the chain
// rule carries element forces and tangents to them (the apex with weights w).

#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "tessella/tissue/handles.hpp"
#include "tessella/tissue/vec3.hpp"

namespace tessella::mechanics {

struct MembraneTriangulation {
  enum class Kind { MeanFan, KernelFan, Ears };
  /// A triangle corner that is the apex (not a loop position).
  static constexpr int kApex = -1;
  Kind kind = Kind::MeanFan;
  /// KernelFan: the apex's weights, one per loop vertex (sum 1); empty otherwise.
  std::vector<double> apex_weights;
  /// Ears: the triangles as loop positions (counter-clockwise with the loop); empty otherwise.
  std::vector<std::array<int, 3>> ears;

  /// The number of triangles of a loop of n vertices: n for a fan, n - 2 for ears.
  std::size_t size(std::size_t n) const { return kind == Kind::Ears ? ears.size() : n; }
  bool hasApex() const { return kind != Kind::Ears; }
  /// Triangle i of a loop of n vertices: loop positions or kApex; a fan's
  /// triangle i is (apex, i, i + 1 mod n), corner 0 the apex.
  std::array<int, 3> triangle(std::size_t i, std::size_t n) const {
    if (kind == Kind::Ears) return ears[i];
    return {kApex, static_cast<int>(i), static_cast<int>((i + 1) % n)};
  }
  /// The weight of loop vertex k in the apex (1/n for the mean fan; 0 without apex).
  double apexWeight(std::size_t k, std::size_t n) const {
    if (kind == Kind::MeanFan) return 1.0 / static_cast<double>(n);
    return kind == Kind::KernelFan ? apex_weights[k] : 0.0;
  }
  /// InputError naming `name` unless the triangulation fits a loop of n vertices
  /// (weights: n finite values summing to 1 within 1e-12; ears: corners in range).
  void check(std::size_t n, const std::string& name) const;
  bool operator==(const MembraneTriangulation&) const = default;
};

/// The triangulation of a loop at its reference positions: the mean fan
/// unless it folds (tessella::polygonTriangulation, the tissue's own test),
/// then the fan from the kernel centroid with its mean value coordinates, or
/// the ears when the kernel is empty. InputError if the tissue's kernel
/// centroid is not strictly inside every fan triangle (it checks that itself).
MembraneTriangulation membraneTriangulation(std::span<const Vec3> loop);

/// Mean value coordinates of `point` with respect to the closed planar polygon
/// `loop` (2D points, counter-clockwise): w_k = (tan(a_{k-1}/2) + tan(a_k/2)) / r_k,
/// normalised, a_k the angle at the point from loop[k] to loop[k+1], r_k the
/// distance to loop[k]. Reproduces linear functions (sum_k w_k loop[k] = point).
/// Empty when the point is not strictly inside every triangle (point, k, k+1)
/// (not in the polygon's kernel's interior).
std::vector<double> meanValueCoordinates(std::span<const std::array<double, 2>> loop,
                                         const std::array<double, 2>& point);

}  // namespace tessella::mechanics
