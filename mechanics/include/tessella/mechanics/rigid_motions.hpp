// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The rigid motions a mask of fixed degrees of freedom leaves free
// (docs/mechanics.md, "Supports of membranes"). Positions are three dofs per
// vertex slot (spatialDofs); a rigid motion u(p) = t + w x (p - c) moves the
// fixed dof k of vertex v by e_k . u(p_v), so the motions that move no fixed
// dof are the null space of those rows. Any left free makes the equilibrium's
// tangent singular: the energy of a pressurised body does not change under them.

#include <cstdint>
#include <string>
#include <vector>

#include "tessella/tissue/handles.hpp"
#include "tessella/tissue/vec3.hpp"

namespace tessella {
class Tissue;
}

namespace tessella::mechanics {

/// u(p) = translation + rotation x (p - centre).
struct RigidMotion {
  Vec3 translation = Vec3::Zero();
  Vec3 rotation = Vec3::Zero();
  Vec3 centre = Vec3::Zero();
  /// "translation along (0, 0, 1)", "rotation about the axis along (0, 0, 1) through (0, 0, 0)" or
  /// a screw.
  std::string describe() const;
};

/// A basis of the rigid motions of the tissue's live vertices that move none
/// of the dofs flagged in `fixed` (3 per vertex slot; dead slots ignored):
/// empty when the supports remove all six. A direction counts as held when the
/// fixed rows move it by more than 1e-5 of the tissue's extent (relative
/// eigenvalue 1e-10 of their Gram matrix).
std::vector<RigidMotion> freeRigidMotions(const Tissue& tissue,
                                          const std::vector<std::uint8_t>& fixed);

/// MechanicsError naming `what` (the supports), the free motions and the
/// singular tangent when freeRigidMotions is not empty; `context` (a step and
/// time, or empty) is named too.
void requireNoRigidMotion(const Tissue& tissue, const std::vector<std::uint8_t>& fixed,
                          const std::string& what, const std::string& context = {});

/// The vertices a one-point support of a closed body uses.
struct PointSupport {
  VertexId anchor;  ///< nearest the point: its components fixed where they remove a free motion
                    ///< (all 3 alone)
  VertexId second;  ///< farthest from the anchor: up to two components across the line to it
  VertexId third;   ///< farthest from that line: up to one component, against the rotation about it
  int fixed_components = 0;  ///< dofs this support fixed (6 when nothing else holds the tissue)
};

/// Fixes in `fixed` the fewest components of three vertices (the anchor
/// nearest `point`, the vertex farthest from it, the vertex farthest from the
/// line through both) that remove the rigid motions `fixed` still leaves: with
/// no other support, the anchor's three, two of the second vertex's across the
/// line and one of the third's (3 + 2 + 1 = 6, a statically determinate
/// support: it does no work against a self-equilibrated load such as turgor
/// on a closed body). A candidate is taken only when it holds a free motion
/// (more than 1e-3 of its row in the free space), best-conditioned first.
/// MechanicsError for a tissue with fewer than three vertices.
PointSupport fixPointSupport(const Tissue& tissue, const Vec3& point,
                             std::vector<std::uint8_t>& fixed);

}  // namespace tessella::mechanics
