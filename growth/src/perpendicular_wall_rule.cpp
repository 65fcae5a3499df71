// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/growth/perpendicular_wall_rule.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tessella/growth/cell_frame.hpp"
#include "tessella/growth/division_walls.hpp"
#include "tessella/growth/main_axis_rule.hpp"
#include "tessella/growth/registries.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"
#include "tessella/tissue/geometry.hpp"

namespace tessella::growth {

PerpendicularWallRule::PerpendicularWallRule(double junction_tolerance,
                                             std::shared_ptr<const DivisionRule> fallback)
    : junction_tolerance_(junction_tolerance), fallback_(std::move(fallback)) {
  if (!(junction_tolerance >= 0) || !(junction_tolerance < 0.5))
    throw InputError("perpendicular_to_mother_wall rule: junction_tolerance = " +
                     formatNumber(junction_tolerance) + " must be in [0, 0.5)");
  if (!fallback_) fallback_ = std::make_shared<MainAxisRule>();
}

namespace {

// The smallest shift s along the unit normal such that no vertex at signed
// distance d[i] from the plane is closer than tol to the shifted plane.
double junctionFreeShift(const std::vector<double>& d, double tol) {
  auto clear = [&](double s) {
    for (double di : d)
      if (std::abs(di - s) < tol * (1 - 1e-9)) return false;
    return true;
  };
  if (clear(0.0)) return 0.0;
  double best = std::numeric_limits<double>::infinity();
  for (double di : d)
    for (double s : {di - tol, di + tol})
      if (std::abs(s) < std::abs(best) && clear(s)) best = s;
  return std::isfinite(best) ? best : 0.0;
}

}  // namespace

bool PerpendicularWallRule::concurrent() const { return fallback_->concurrent(); }

Plane PerpendicularWallRule::plane(const Tissue& t, CellId c, Rng& rng) const {
  const std::vector<WallId> birth = birthWalls(t, c);
  if (birth.empty()) return fallback_->plane(t, c, rng);
  const CellComplex& k = t.topology();
  Vec3 direction = Vec3::Zero();
  std::vector<VertexId> wall_vertices;
  double size;
  if (t.dim() == 2) {
    // The birth wall's chord: its pieces' edge vectors in the cell's loop order.
    for (OrientedEdge oe : k.faceEdges(t.cellFace(c))) {
      if (std::find(birth.begin(), birth.end(), WallId(oe.handle().index())) == birth.end()) continue;
      direction += t.position(k.head(oe)) - t.position(k.tail(oe));
      wall_vertices.push_back(k.tail(oe));
      wall_vertices.push_back(k.head(oe));
    }
    size = std::sqrt(cellMeasure(t, c));
  } else {
    const VolumeId vol = t.cellVolume(c);
    Vec3 wall_normal = Vec3::Zero();  // outward area vector of the birth wall
    for (WallId w : birth) {
      const FaceId f(w.index());
      const PolygonMeasures pm = polygonMeasures(t, f);
      wall_normal += k.faceSign(vol, f) * pm.area * pm.normal;
      for (VertexId v : k.faceVertices(f)) wall_vertices.push_back(v);
    }
    if (wall_normal.norm() == 0) return fallback_->plane(t, c, rng);
    wall_normal.normalize();
    // Planes containing the wall normal: normals perpendicular to it, the
    // one closest to the main axis (the next axis if the main one is normal).
    const PrincipalAxes axes = cellPrincipalAxes(t, c);
    for (int i = 0; i < 3 && direction.norm() < 1e-6; ++i) {
      const Vec3 a = axes.axes.col(i);
      direction = a - a.dot(wall_normal) * wall_normal;
    }
    size = std::cbrt(cellMeasure(t, c));
  }
  if (direction.norm() < 1e-12 * size) return fallback_->plane(t, c, rng);
  Plane p = planeThroughCentroid(t, c, direction, "perpendicular_to_mother_wall rule");
  std::vector<double> d;
  d.reserve(wall_vertices.size());
  for (VertexId v : wall_vertices) d.push_back(p.normal.dot(t.position(v) - p.point));
  p.point += junctionFreeShift(d, junction_tolerance_ * size) * p.normal;
  return p;
}

DivisionRuleEntry perpendicularWallRuleEntry() {
  return {"perpendicular_to_mother_wall",
          "The new wall meets the wall the cell was born through at right angles (Hofmeister/Sachs); founder "
          "cells divide across their main axis.",
          {ParamSpec("junction_tolerance", ParamType::Float,
                     "Hofmeister/Sachs: how far (relative to the cell size) the new wall keeps from existing "
                     "junctions on the mother wall, avoiding four-way junctions.")
               .byDefault(0.05)
               .atLeast(0)
               .atMost(0.45)},
          [](const ParamValues& p) {
            return blameParam("junction_tolerance", [&] {
              return std::make_shared<const PerpendicularWallRule>(p.getFloat("junction_tolerance"));
            });
          }};
}

}  // namespace tessella::growth
