// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// A snapshot holds finite numbers only: a NaN or infinite coordinate or
// floating-point property value is refused when a snapshot is written and
// when it is read, naming the element, the property and the value.

#include <span>
#include <string>

#include "vtu_property_arrays.hpp"
#include "tessella/tissue/tissue.hpp"

namespace tessella::io::detail {

/// InputError "'path': vertex V has the non-finite position (x, y, z)" for
/// the first selected row with a non-finite coordinate.
void requireFinitePositions(std::span<const Vec3> positions, const RowSelection& rows, const std::string& path);

/// InputError naming the property, the element (a cell also by its lineage
/// id) and the value, for the first non-finite value of a floating-point
/// (double, float, tuple) cell or vertex property over the selected rows.
void requireFiniteProperties(const Tissue& tissue, const RowSelection& vertex_rows, const RowSelection& cell_rows,
                             const std::string& path);

}  // namespace tessella::io::detail
