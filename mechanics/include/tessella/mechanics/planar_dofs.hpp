// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Positions of a planar 2D tissue as a vector of degrees of freedom: (x, y) of
// vertex slot i at entries 2i, 2i+1 (tombstone slots included, and fixed).

#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace tessella {
class Tissue;
}

namespace tessella::mechanics {

/// Throws InputError unless the tissue is 2D and planar.
void requirePlanar(const Tissue& tissue, const char* who);
Eigen::VectorXd planarDofs(const Tissue& tissue);
/// Writes x back (z = 0); bumps the geometry version.
void setPlanarDofs(Tissue& tissue, const Eigen::VectorXd& x);
/// The fixed-dof mask with only the tombstone slots fixed.
std::vector<std::uint8_t> deadSlotMask(const Tissue& tissue);

}  // namespace tessella::mechanics
