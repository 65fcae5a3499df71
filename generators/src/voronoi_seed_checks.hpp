// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Private: input checks shared by the Voronoi generators. Each throws
// InputError naming the seed index and coordinates.

#include <span>
#include <string>

#include "tessella/generators/voronoi.hpp"
#include "tessella/tissue/vec3.hpp"
#include "voronoi_domain.hpp"

namespace tessella::detail {

/// "seed 7 at (0.25, 0.5, 0)"
std::string describeSeed(std::size_t index, const Vec3& p);

/// Option ranges (lloyd_iterations, duplicate_tolerance).
void checkOptions(const VoronoiOptions& options);

/// Count, finite coordinates, z = 0, inside the polygon (up to kOnTolerance).
void checkSeeds2(std::span<const Vec3> seeds, const ConvexDomain2& domain);
/// Count, finite coordinates, inside the polyhedron (up to kOnTolerance).
void checkSeeds3(std::span<const Vec3> seeds, const ConvexDomain3& domain);

/// Throws for seeds a and b closer than tolerance (both named, with their distance).
[[noreturn]] void throwDuplicate(std::span<const Vec3> seeds, std::size_t a, std::size_t b);

}  // namespace tessella::detail
