// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/mechanics/planar_dofs.hpp"

#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/tissue.hpp"

#include <string>

namespace tessella::mechanics {

void requirePlanar(const Tissue& tissue, const char* who) {
  if (tissue.dim() != 2 || tissue.embedding() != Embedding::Planar)
    throw InputError(std::string(who) + " needs a planar 2D tissue, not a " + std::to_string(tissue.dim()) +
                     "D " + embeddingName(tissue.embedding()) + " one");
}

Eigen::VectorXd planarDofs(const Tissue& tissue) {
  requirePlanar(tissue, "planarDofs");
  const auto positions = tissue.positions();
  Eigen::VectorXd x = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(2 * tissue.slots(0)));
  for (VertexId v : tissue.vertices()) {
    x[2 * v.index()] = positions[v.index()].x();
    x[2 * v.index() + 1] = positions[v.index()].y();
  }
  return x;
}

void setPlanarDofs(Tissue& tissue, const Eigen::VectorXd& x) {
  requirePlanar(tissue, "setPlanarDofs");
  if (x.size() != static_cast<Eigen::Index>(2 * tissue.slots(0)))
    throw InputError("setPlanarDofs: " + std::to_string(x.size()) + " values for " +
                     std::to_string(tissue.slots(0)) + " vertex slots");
  auto positions = tissue.mutablePositions();
  for (VertexId v : tissue.vertices()) positions[v.index()] = Vec3(x[2 * v.index()], x[2 * v.index() + 1], 0.0);
}

std::vector<std::uint8_t> deadSlotMask(const Tissue& tissue) {
  std::vector<std::uint8_t> fixed(2 * tissue.slots(0), 1);
  for (VertexId v : tissue.vertices()) fixed[2 * v.index()] = fixed[2 * v.index() + 1] = 0;
  return fixed;
}

}  // namespace tessella::mechanics
