// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Boundary conditions of a planar tissue as a mask of fixed degrees of
// freedom (planar_dofs.hpp): fixed vertices, fixed components, a pinned point
// (one vertex fixed and the rotation about it removed).

#include <array>
#include <cstdint>
#include <vector>

#include "tessella/tissue/handles.hpp"
#include "tessella/tissue/vec3.hpp"

namespace tessella {
class Tissue;
}

namespace tessella::mechanics {

using FixedDofs = std::vector<std::uint8_t>;

void fixVertex(FixedDofs& fixed, VertexId v);
/// Fixes one component (0: x, 1: y) of v.
void fixComponent(FixedDofs& fixed, VertexId v, int component);

struct PinnedPoint {
  VertexId vertex;          ///< the live vertex nearest the point: both components fixed
  VertexId rotation_lock;   ///< the vertex whose component `lock_component` is fixed
  int lock_component = 1;
};

/// Pins the tissue at `point`: the nearest live vertex is fixed, and the
/// rotation about it is removed by fixing one component of a second vertex
/// (the one farthest from it along x, its y; or along y, its x, if farther).
/// With translation and rotation gone the elastic problem has no rigid mode.
/// Throws InputError for a tissue with fewer than two live vertices.
PinnedPoint pinPoint(const Tissue& tissue, const Vec3& point, FixedDofs& fixed);

/// Fixes every live vertex inside the axis-aligned box [lo, hi] (x and y);
/// returns their number.
std::size_t fixVerticesInBox(const Tissue& tissue, const Vec3& lo, const Vec3& hi, FixedDofs& fixed);

}  // namespace tessella::mechanics

namespace tessella::mechanics {

/// The supports a configuration names, turned into a mask for the tissue as
/// it is now (vertex slots change with divisions): a pinned point and/or the
/// vertices in a box.
struct Supports {
  bool pin = false;
  Vec3 pin_point = Vec3::Zero();
  bool box = false;
  Vec3 box_lo = Vec3::Zero();
  Vec3 box_hi = Vec3::Zero();
};

/// deadSlotMask(tissue) plus the supports.
FixedDofs supportMask(const Tissue& tissue, const Supports& supports);

}  // namespace tessella::mechanics
