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
// boundary segments where the plane crosses each wall.

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

  /// The plane with this (3D) normal or (2D) normal angle.
  Plane plane(const Vec3& normal) const { return Plane{point_, normal.normalized()}; }
  Plane plane(double theta) const { return Plane{point_, frame_.direction(theta)}; }

 private:
  double chord(double nx, double ny) const;
  double section(const Vec3& n) const;

  int dim_;
  CellFrame frame_;
  Vec3 point_;
  std::vector<double> u_, v_;             // 2D: loop in tangent coordinates about point_
  std::vector<std::vector<Vec3>> faces_;  // 3D: outward-oriented wall loops relative to point_
};

}  // namespace tessella::growth
