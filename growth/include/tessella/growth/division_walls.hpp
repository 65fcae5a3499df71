// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Division walls: every wall made by a division is tagged with the lineage
// id of the cell that divided (wall property "division_of", -1 for walls
// that no division made, policy Copy so the pieces of a wall split by a
// neighbour's division keep the tag). A cell's birth wall is then the set of
// its walls tagged with its parent's lineage id: the wall it was born
// through, which the Hofmeister/Sachs rule needs.

#include <cstdint>
#include <vector>

#include "tessella/tissue/tissue.hpp"

namespace tessella::growth {

inline constexpr const char* kDivisionWallProperty = "division_of";

/// Registers the tag column if missing; returns it.
PropertyColumn<std::int64_t>& divisionWallTags(Tissue& t);

/// The walls of c made by its mother's division (empty for founder cells or
/// when the tag column is absent).
std::vector<WallId> birthWalls(const Tissue& t, CellId c);

}  // namespace tessella::growth
