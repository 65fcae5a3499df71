// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/mechanics/wall_state.hpp"

#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/tissue/tissue.hpp"

#include <cmath>
#include <string>

namespace tessella::mechanics {

PropertyColumn<double>& restLengths(Tissue& tissue) {
  PropertyStore& walls = tissue.wallProperties();
  if (!walls.has(kRestLengthName)) return walls.add<double>(kRestLengthName, 0.0, DivisionPolicy::SplitByMeasure);
  return walls.get<double>(kRestLengthName);
}

PropertyColumn<double>& wallOutput(Tissue& tissue, const char* name) {
  PropertyStore& walls = tissue.wallProperties();
  if (!walls.has(name)) return walls.add<double>(name, 0.0, DivisionPolicy::Copy);
  return walls.get<double>(name);
}

PropertyColumn<double>& cellOutput(Tissue& tissue, const char* name, double value) {
  PropertyStore& cells = tissue.cellProperties();
  if (!cells.has(name)) return cells.add<double>(name, value, DivisionPolicy::Copy);
  return cells.get<double>(name);
}

std::vector<double> wallExtensibilities(const Tissue& tissue, double fallback) {
  std::vector<double> phi(tissue.slots(tissue.dim() - 1), fallback);
  const PropertyStore& cells = tissue.cellProperties();
  if (!cells.has(kExtensibilityName)) return phi;
  const auto& value = cells.get<double>(kExtensibilityName);
  for (CellId c : tissue.cells())
    if (!(value[c] >= 0.0 && std::isfinite(value[c])))
      throw InputError("mechanics: cell " + std::to_string(c.index()) + " (lineage " +
                       std::to_string(tissue.lineageId(c)) + ") has extensibility " + formatNumber(value[c]) +
                       "; it must be >= 0 and finite");
  for (WallId w : tissue.walls()) {
    const std::vector<CellId> two = tissue.wallCells(w);
    if (two.empty()) continue;
    double sum = 0.0;
    for (CellId c : two) sum += value[c];
    phi[w.index()] = sum / static_cast<double>(two.size());
  }
  return phi;
}

std::size_t initialiseRestLengths(Tissue& tissue) {
  PropertyColumn<double>& rest = restLengths(tissue);
  std::size_t count = 0;
  for (WallId w : tissue.walls())
    if (!(rest[w] > 0.0)) {
      rest[w] = wallMeasure(tissue, w);
      ++count;
    }
  return count;
}

}  // namespace tessella::mechanics
