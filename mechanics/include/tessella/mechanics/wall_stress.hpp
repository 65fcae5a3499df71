// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The stress a cell's walls carry, from their tensions (docs/mechanics.md,
// "Stress per cell"): the virial average over the cell,
//   sigma_c = (1 / A_c) sum_{w in c} (T_w L_w / n_w) u_w u_w^T,
// n_w the number of cells sharing wall w (1 on the boundary, 2 inside), u_w
// its unit direction. At equilibrium sum_c A_c sigma_c = (sum_c P_c A_c) I,
// and a regular ring's sigma is P I.

#include "tessella/tissue/handles.hpp"
#include "tessella/tissue/vec3.hpp"

namespace tessella {
class Tissue;
}

namespace tessella::mechanics {

inline constexpr const char* kWallStressName = "wall_stress";        ///< cell, Sym3
inline constexpr const char* kStressMaxName = "stress_max";          ///< cell, double: larger principal value
inline constexpr const char* kStressMinName = "stress_min";          ///< cell, double: smaller principal value
inline constexpr const char* kStressDirectionName = "stress_direction";  ///< cell, Vec3: unit, of stress_max

/// sigma_c of a planar tissue's cell from the wall_tension column (wall_state.hpp).
Mat3 cellWallStress(const Tissue& tissue, CellId cell);

/// Writes wall_stress, stress_max, stress_min and stress_direction of every
/// live cell (columns added with policy Copy when missing).
void writeCellWallStress(Tissue& tissue);

}  // namespace tessella::mechanics
