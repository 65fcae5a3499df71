// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Input checks shared by the Voronoi generators.

#include "voronoi_seed_checks.hpp"

#include <cmath>

#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"

namespace tessella::detail {
namespace {

void checkCountAndFinite(std::span<const Vec3> seeds, std::size_t minimum, const char* dim_name) {
  if (seeds.size() < minimum)
    throw InputError(std::string("a ") + dim_name + " Voronoi tissue needs at least " +
                     std::to_string(minimum) + " seeds, got " + std::to_string(seeds.size()));
  if (seeds.size() >= kInvalidIndex / 2)
    throw InputError("too many seeds: " + std::to_string(seeds.size()));
  for (std::size_t i = 0; i < seeds.size(); ++i)
    if (!seeds[i].allFinite())
      throw InputError(describeSeed(i, seeds[i]) + " has a non-finite coordinate");
}

}  // namespace

std::string describeSeed(std::size_t index, const Vec3& p) {
  return "seed " + std::to_string(index) + " at " + formatPoint(p);
}

void checkOptions(const VoronoiOptions& options) {
  if (options.lloyd_iterations < 0 || options.lloyd_iterations > 100000)
    throw InputError("lloyd_iterations must be in [0, 100000], got " +
                     std::to_string(options.lloyd_iterations));
  if (!std::isfinite(options.duplicate_tolerance) ||
      options.duplicate_tolerance < kMinDuplicateTolerance || options.duplicate_tolerance > 0.1)
    throw InputError("duplicate_tolerance must be in [" + formatNumber(kMinDuplicateTolerance) +
                     ", 0.1] (relative to the domain size), got " +
                     formatNumber(options.duplicate_tolerance));
}

void checkSeeds2(std::span<const Vec3> seeds, const ConvexDomain2& domain) {
  checkCountAndFinite(seeds, 3, "2D");
  const double slack = kOnTolerance * domain.scale;
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    const Vec3& p = seeds[i];
    if (p.z() != 0)
      throw InputError(describeSeed(i, p) + " is not in the z = 0 plane of the 2D domain");
    if (domain.excess(Vec2(p.x(), p.y())) > slack)
      throw InputError(describeSeed(i, p) + " lies outside the domain" +
                       (domain.is_rectangle ? std::string()
                                            : std::string(" (its boundary polygon of ") +
                                                  std::to_string(domain.corners.size()) +
                                                  " segments)"));
  }
}

void checkSeeds3(std::span<const Vec3> seeds, const ConvexDomain3& domain) {
  checkCountAndFinite(seeds, 4, "3D");
  const double slack = kOnTolerance * domain.scale;
  for (std::size_t i = 0; i < seeds.size(); ++i)
    if (domain.excess(seeds[i]) > slack)
      throw InputError(describeSeed(i, seeds[i]) + " lies outside the domain" +
                       (domain.is_box ? std::string()
                                      : std::string(" (its boundary polyhedron of ") +
                                            std::to_string(domain.faces.size()) + " faces)"));
}

void throwDuplicate(std::span<const Vec3> seeds, std::size_t a, std::size_t b) {
  if (a > b) std::swap(a, b);
  throw InputError("duplicate seeds: " + describeSeed(a, seeds[a]) + " and " +
                   describeSeed(b, seeds[b]) + " are " + formatNumber((seeds[a] - seeds[b]).norm()) +
                   " apart (below duplicate_tolerance)");
}

}  // namespace tessella::detail
