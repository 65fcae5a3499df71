#include "tessella/growth/main_axis_rule.hpp"

#include "tessella/growth/cell_frame.hpp"
#include "tessella/tissue/geometry.hpp"

namespace tessella::growth {

Plane MainAxisRule::plane(const Tissue& t, CellId c, Rng&) const {
  const PrincipalAxes axes = cellPrincipalAxes(t, c);
  return planeThroughCentroid(t, c, axes.axes.col(0), "main_axis rule");
}

}  // namespace tessella::growth
