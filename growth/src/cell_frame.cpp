// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/growth/cell_frame.hpp"

#include <cmath>
#include <string>

#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/geometry.hpp"

namespace tessella::growth {

Vec3 CellFrame::direction(double theta) const { return std::cos(theta) * e1 + std::sin(theta) * e2; }

CellFrame cellFrame(const Tissue& t, CellId c) {
  CellFrame f;
  if (t.dim() == 3) {
    f.centroid = cellCentroid(t, c);
    return f;
  }
  const PolygonMeasures m = polygonMeasures(t, t.cellFace(c));
  if (!(m.area > 0))
    throw GeometryError("cell " + std::to_string(c.index()) + " (lineage id " +
                            std::to_string(t.lineageId(c)) + ") has no area: no division frame",
                        ElementId{2, c.index()});
  f.centroid = m.centroid;
  if (t.embedding() == Embedding::Planar) return f;  // exactly +z, x, y
  f.normal = m.normal.normalized();
  // e1: the world axis least aligned with the normal, made tangent.
  Vec3 axis = Vec3::UnitX();
  if (std::abs(f.normal.y()) < std::abs(f.normal.dot(axis))) axis = Vec3::UnitY();
  if (std::abs(f.normal.z()) < std::abs(f.normal.dot(axis))) axis = Vec3::UnitZ();
  f.e1 = (axis - axis.dot(f.normal) * f.normal).normalized();
  f.e2 = f.normal.cross(f.e1);
  return f;
}

Plane planeThroughCentroid(const Tissue& t, CellId c, const Vec3& direction, const char* rule) {
  const CellFrame f = cellFrame(t, c);
  Vec3 n = direction;
  if (t.dim() == 2) n -= n.dot(f.normal) * f.normal;  // the plane must contain the cell normal
  const double len = n.norm();
  if (!(len > 1e-12 * direction.norm()) || !std::isfinite(len))
    throw GeometryError(std::string(rule) + ": no cutting plane for cell " +
                            std::to_string(c.index()) + " (lineage id " +
                            std::to_string(t.lineageId(c)) +
                            "): the direction is normal to the cell or zero",
                        ElementId{t.dim(), c.index()});
  return Plane{f.centroid, n / len};
}

}  // namespace tessella::growth
