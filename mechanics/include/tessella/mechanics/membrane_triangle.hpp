// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The rest state of one constant-strain membrane triangle, shared by the
// membrane models on triangle meshes (membrane_model.hpp) and on a tissue's
// fans (fan_membrane_model.hpp): docs/mechanics.md, "Membranes".

#include <array>

#include <Eigen/Core>

namespace tessella::mechanics {

struct MembraneTriangleRest {
  Eigen::Matrix2d D = Eigen::Matrix2d::Identity();  ///< rest edge vectors (x1 - x0, x2 - x0) in the fibre frame
  std::array<Eigen::Vector2d, 3> g;                  ///< gradients of the shape functions in that frame
  double area = 0.0;                                 ///< rest area A0
  /// Sets D, g and the area from the rest edges (columns) in the fibre frame.
  void setRestShape(const Eigen::Matrix2d& edges);
};

}  // namespace tessella::mechanics
