// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/growth/division_walls.hpp"

namespace tessella::growth {

PropertyColumn<std::int64_t>& divisionWallTags(Tissue& t) {
  PropertyStore& walls = t.wallProperties();
  if (!walls.has(kDivisionWallProperty))
    return walls.add<std::int64_t>(kDivisionWallProperty, -1, DivisionPolicy::Copy);
  return walls.get<std::int64_t>(kDivisionWallProperty);
}

std::vector<WallId> birthWalls(const Tissue& t, CellId c) {
  std::vector<WallId> out;
  const std::int64_t parent = t.parentId(c);
  const PropertyStore& walls = t.wallProperties();
  if (parent < 0 || !walls.has(kDivisionWallProperty)) return out;
  const auto& tags = walls.get<std::int64_t>(kDivisionWallProperty);
  for (WallId w : t.cellWalls(c))
    if (tags[w] == parent) out.push_back(w);
  return out;
}

}  // namespace tessella::growth
