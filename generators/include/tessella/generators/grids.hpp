// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Grid tissues: rectangular and hexagonal sheets, boxes of boxes.

#include <cstddef>

#include "tessella/tissue/tissue.hpp"

namespace tessella {

/// nx x ny rectangular cells of size dx x dy, lower-left corner at `origin`.
Tissue rectangularGrid(std::size_t nx, std::size_t ny, double dx = 1.0, double dy = 1.0,
                       const Vec3& origin = Vec3::Zero());

/// nx x ny regular hexagons (pointy side up, offset rows) of circumradius
/// `radius`; neighbouring hexagons share edges.
Tissue hexagonalGrid(std::size_t nx, std::size_t ny, double radius = 1.0,
                     const Vec3& origin = Vec3::Zero());

/// nx x ny x nz box cells of size dx x dy x dz.
Tissue boxGrid(std::size_t nx, std::size_t ny, std::size_t nz, double dx = 1.0, double dy = 1.0,
               double dz = 1.0, const Vec3& origin = Vec3::Zero());

/// A cylindrical sheet (Embedding::Surface): a rectangular grid of `around` x
/// `along` cells wrapped onto the cylinder of `radius` about the vertical axis
/// through `origin`, from z = origin.z to origin.z + length. Vertex (i, j) is at
/// angle 2 pi i / around and height j length / along; every cell is a planar
/// quad, its loop counter-clockwise seen from outside (normals point out).
/// Both ends are open. around >= 3.
Tissue cylinderGrid(std::size_t around, std::size_t along, double radius = 1.0, double length = 1.0,
                    const Vec3& origin = Vec3::Zero());

}  // namespace tessella
