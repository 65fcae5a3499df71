// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// NewWallMeasure: the length (2D) or area (3D) of the wall a plane through a
// given point would create in a cell, evaluated many times per cell by the
// shortest-wall searches, so the cell's geometry is gathered once.
//
// 2D: the cell loop is projected on its tangent plane; the wall is the chord
// of the cut line that contains the plane point (for a concave cell crossed
// more than twice, the piece through the point, as Tissue::splitCell cuts).
// 3D: the area of the polyhedron's section by the plane (all pieces of the
// section of a non-convex cell), from the divergence theorem over the
// boundary segments where the plane crosses each wall, and its exact
// gradient as the normal turns (for the 3D search's descent).

#include <cstdint>
#include <span>
#include <vector>

#include "tessella/growth/cell_frame.hpp"
#include "tessella/tissue/tissue.hpp"

namespace tessella::growth {

class NewWallMeasure {
 public:
  /// Gathers the cell; `point` is the point every plane passes through
  /// (the centroid unless given).
  NewWallMeasure(const Tissue& t, CellId c);
  NewWallMeasure(const Tissue& t, CellId c, const Vec3& point);

  int dim() const { return dim_; }
  const CellFrame& frame() const { return frame_; }
  const Vec3& point() const { return point_; }

  /// 2D: length of the new wall for the plane with in-plane normal at angle
  /// theta from frame().e1 (pi-periodic).
  double length(double theta) const;
  /// 2D and 3D: measure of the new wall for the plane with this normal.
  double measure(const Vec3& normal) const;
  /// 3D: section area for the unit normal n and, in `gradient`, its exact
  /// derivative as n turns (tangent to the sphere at n): wherever the plane
  /// passes through no vertex, A(n + dn) = A(n) + gradient . dn + O(|dn|^2)
  /// for tangent dn.
  double measureAndGradient(const Vec3& n, Vec3& gradient) const;

  /// 2D: the chord of the line through the point with in-plane normal
  /// (nx, ny): its ends as abscissae along the direction (-ny, nx), the loop
  /// edges they lie on (edge i runs from loop vertex i to vertex i + 1), and
  /// whether the point lies on it (else it is the nearest piece of the line
  /// inside the cell). crossings < 2 when the line misses the cell.
  struct Chord {
    double lo = 0, hi = 0;
    int edge_lo = -1, edge_hi = -1;
    bool contains_point = false;
    std::size_t crossings = 0;
  };
  Chord chord(double nx, double ny) const;
  /// 2D: the loop in tangent coordinates about the point.
  std::span<const double> loopU() const { return u_; }
  std::span<const double> loopV() const { return v_; }

  /// The plane with this (3D) normal or (2D) normal angle.
  Plane plane(const Vec3& normal) const { return Plane{point_, normal.normalized()}; }
  Plane plane(double theta) const { return Plane{point_, frame_.direction(theta)}; }

 private:
  template <bool kGradient>
  double section(const Vec3& n, Vec3* gradient) const;

  int dim_;
  CellFrame frame_;
  Vec3 point_;
  std::vector<double> u_, v_;             // 2D: loop in tangent coordinates about point_
  std::vector<Vec3> points_;               // 3D: the cell's vertices relative to point_
  std::vector<std::uint32_t> loops_;       //     outward-oriented wall loops as indices into points_,
  std::vector<std::uint32_t> loop_start_;  //     back to back; loop i is [start[i], start[i + 1])
};

}  // namespace tessella::growth
