// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// fixed_angle_to_main_axis: the main-axis plane turned by a fixed angle, for
// cells that divide obliquely to their long axis at a set angle (docs/growth.md).
//   2D cells (planar or on a curved sheet): the main-axis rule's plane normal
//   a1 (the longest principal axis) turned by `angle` about the cell normal N,
//   n = cos(angle) a1 + sin(angle) N x a1, counter-clockwise seen from the
//   side N points to (+z on planar tissues); the new wall is the main-axis
//   wall turned by the same angle.
//   3D cells: a1 turned by `angle` about the shortest principal axis a3,
//   oriented so that its largest component is positive: the plane always
//   contains a3, and angle 90 cuts the cell along its longest axis.
// Angle 0 is the main-axis rule, bit for bit.
#include <cmath>
#include <numbers>

#include "tessella/growth/cell_frame.hpp"
#include "tessella/growth/registries.hpp"
#include "tessella/tissue/geometry.hpp"

namespace tessella::growth {

namespace {

class FixedAngleToMainAxisRule final : public DivisionRule {
 public:
  explicit FixedAngleToMainAxisRule(double angle_degrees)
      : cos_(std::cos(angle_degrees * std::numbers::pi / 180.0)),
        sin_(std::sin(angle_degrees * std::numbers::pi / 180.0)) {}

  Plane plane(const Tissue& t, CellId c, Rng&) const override {
    const PrincipalAxes axes = cellPrincipalAxes(t, c);
    const Vec3 a1 = axes.axes.col(0);
    Vec3 pivot;
    if (t.dim() == 2) {
      pivot = cellFrame(t, c).normal;
    } else {
      pivot = axes.axes.col(2);
      Eigen::Index largest = 0;
      pivot.cwiseAbs().maxCoeff(&largest);
      if (pivot[largest] < 0) pivot = -pivot;
    }
    // planeThroughCentroid makes it tangent to a 2D cell: exactly a1's tangent part turned about N.
    return planeThroughCentroid(t, c, cos_ * a1 + sin_ * pivot.cross(a1), "fixed_angle_to_main_axis rule");
  }
  bool concurrent() const override { return true; }
  std::string name() const override { return "fixed_angle_to_main_axis"; }

 private:
  double cos_, sin_;
};

}  // namespace

DivisionRuleEntry fixedAngleToMainAxisRuleEntry() {
  return {"fixed_angle_to_main_axis",
          "The main-axis plane turned by `angle` degrees about the cell normal (2D, curved sheets) or the "
          "shortest principal axis (3D); 0 is main_axis, 90 cuts along the longest axis.",
          {ParamSpec("angle", ParamType::Float,
                     "Angle in degrees between the division plane and the main-axis plane, counter-clockwise "
                     "about the cell normal (rule: fixed_angle_to_main_axis).")
               .byDefault(0.0)
               .atLeast(-90)
               .atMost(90)},
          [](const ParamValues& p) { return std::make_shared<const FixedAngleToMainAxisRule>(p.getFloat("angle")); }};
}

}  // namespace tessella::growth
