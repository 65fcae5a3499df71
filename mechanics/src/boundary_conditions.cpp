// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/mechanics/boundary_conditions.hpp"

#include "tessella/mechanics/planar_dofs.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/tissue.hpp"

#include <cmath>
#include <limits>
#include <string>

namespace tessella::mechanics {
namespace {
void checkSlot(const FixedDofs& fixed, VertexId v) {
  if (!v.valid() || 2 * static_cast<std::size_t>(v.index()) + 1 >= fixed.size())
    throw InputError("fixed dofs: vertex " + std::to_string(v.index()) + " out of range");
}
}  // namespace

void fixVertex(FixedDofs& fixed, VertexId v) {
  checkSlot(fixed, v);
  fixed[2 * v.index()] = fixed[2 * v.index() + 1] = 1;
}

void fixComponent(FixedDofs& fixed, VertexId v, int component) {
  checkSlot(fixed, v);
  if (component != 0 && component != 1)
    throw InputError("fixed dofs: component " + std::to_string(component) + " of a planar vertex (0: x, 1: y)");
  fixed[2 * v.index() + static_cast<std::size_t>(component)] = 1;
}

PinnedPoint pinPoint(const Tissue& tissue, const Vec3& point, FixedDofs& fixed) {
  requirePlanar(tissue, "pinPoint");
  if (tissue.numVertices() < 2) throw InputError("pinPoint: the tissue has fewer than two vertices");
  PinnedPoint pin;
  double best = std::numeric_limits<double>::infinity();
  for (VertexId v : tissue.vertices()) {
    const double d = (tissue.position(v) - point).head<2>().squaredNorm();
    if (d < best) best = d, pin.vertex = v;
  }
  const Vec3 p0 = tissue.position(pin.vertex);
  // A rotation about p0 moves vertex v by omega (-(y - y0), x - x0): fixing y
  // of the vertex farthest along x (or x of the one farthest along y) stops it.
  double far = -1.0;
  for (VertexId v : tissue.vertices()) {
    const Vec3 d = tissue.position(v) - p0;
    if (std::abs(d.x()) > far) far = std::abs(d.x()), pin.rotation_lock = v, pin.lock_component = 1;
    if (std::abs(d.y()) > far) far = std::abs(d.y()), pin.rotation_lock = v, pin.lock_component = 0;
  }
  fixVertex(fixed, pin.vertex);
  fixComponent(fixed, pin.rotation_lock, pin.lock_component);
  return pin;
}

std::size_t fixVerticesInBox(const Tissue& tissue, const Vec3& lo, const Vec3& hi, FixedDofs& fixed) {
  std::size_t count = 0;
  for (VertexId v : tissue.vertices()) {
    const Vec3& p = tissue.position(v);
    if (p.x() >= lo.x() && p.x() <= hi.x() && p.y() >= lo.y() && p.y() <= hi.y()) {
      fixVertex(fixed, v);
      ++count;
    }
  }
  return count;
}

}  // namespace tessella::mechanics

namespace tessella::mechanics {

FixedDofs supportMask(const Tissue& tissue, const Supports& supports) {
  FixedDofs fixed = deadSlotMask(tissue);
  if (supports.pin) pinPoint(tissue, supports.pin_point, fixed);
  if (supports.box) fixVerticesInBox(tissue, supports.box_lo, supports.box_hi, fixed);
  return fixed;
}

}  // namespace tessella::mechanics
