// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Seeds for the Voronoi generators: reproducible uniform random points in a
// domain, and CSV files of coordinates.
//
// Random seeds use std::mt19937_64 (its output sequence is fixed by the C++
// standard) and our own mapping to [0, 1) -- the top 53 bits times 2^-53 --
// instead of std::uniform_real_distribution, whose algorithm differs between
// standard libraries. Disks and balls are sampled by rejection from their
// bounding box, which needs no trigonometry, so the same rng_seed gives
// bit-identical seeds on every platform with IEEE doubles.

#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "tessella/generators/voronoi.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/excerpt.hpp"
#include "voronoi_domain.hpp"

namespace tessella {
namespace {

class UniformSource {
 public:
  explicit UniformSource(std::uint64_t seed) : engine_(seed) {}
  double next() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  double between(double lo, double hi) { return lo + next() * (hi - lo); }

 private:
  std::mt19937_64 engine_;
};

void checkCount(std::size_t count) {
  if (count > (std::size_t{1} << 31))
    throw InputError("randomSeeds: count " + std::to_string(count) + " is too large (at most 2^31)");
}

template <typename Inside>
std::vector<Vec3> rejectionSample(const Vec3& lo, const Vec3& hi, bool flat, std::size_t count,
                                  std::uint64_t rng_seed, Inside inside) {
  checkCount(count);
  UniformSource u(rng_seed);
  std::vector<Vec3> seeds;
  seeds.reserve(count);
  while (seeds.size() < count) {
    const double x = u.between(lo.x(), hi.x());
    const double y = u.between(lo.y(), hi.y());
    const double z = flat ? 0.0 : u.between(lo.z(), hi.z());
    const Vec3 p(x, y, z);
    if (inside(p)) seeds.push_back(p);
  }
  return seeds;
}

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r");
  return s.substr(first, last - first + 1);
}

std::vector<std::string_view> splitFields(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  while (true) {
    const auto comma = line.find(',', start);
    fields.push_back(trim(line.substr(start, comma == std::string_view::npos ? std::string_view::npos
                                                                              : comma - start)));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return fields;
}

bool parseNumber(std::string_view field, double& value) {
  if (!field.empty() && field.front() == '+') field.remove_prefix(1);
  const char* end = field.data() + field.size();
  const auto [ptr, ec] = std::from_chars(field.data(), end, value);
  return ec == std::errc() && ptr == end && !field.empty();
}

/// A column name of a header row: it starts with a letter or '_' and is not a
/// number (so "nan" and "inf" are numbers, "1x" is a bad number, not a name).
bool isColumnName(std::string_view field) {
  double value = 0;
  if (field.empty() || !(std::isalpha(static_cast<unsigned char>(field.front())) || field.front() == '_'))
    return false;
  return !parseNumber(field, value);
}

}  // namespace

std::vector<Vec3> randomSeeds(const Rectangle& domain, std::size_t count, std::uint64_t rng_seed) {
  const detail::ConvexDomain2 d = detail::makeDomain(domain);  // validates
  return rejectionSample(Vec3(d.lo.x(), d.lo.y(), 0), Vec3(d.hi.x(), d.hi.y(), 0), true, count,
                         rng_seed, [](const Vec3&) { return true; });
}

std::vector<Vec3> randomSeeds(const Disk& domain, std::size_t count, std::uint64_t rng_seed) {
  // Uniform in the boundary polygon (the Voronoi domain), not the exact disk.
  const detail::ConvexDomain2 d = detail::makeDomain(domain);
  return rejectionSample(Vec3(d.lo.x(), d.lo.y(), 0), Vec3(d.hi.x(), d.hi.y(), 0), true, count,
                         rng_seed, [&](const Vec3& p) {
                           const detail::Vec2 q(p.x(), p.y());
                           return (q - d.center).norm() < d.inner_radius || d.excess(q) < 0;
                         });
}

std::vector<Vec3> randomSeeds(const Box& domain, std::size_t count, std::uint64_t rng_seed) {
  const detail::ConvexDomain3 d = detail::makeDomain(domain);
  return rejectionSample(d.lo, d.hi, false, count, rng_seed, [](const Vec3&) { return true; });
}

std::vector<Vec3> randomSeeds(const Ball& domain, std::size_t count, std::uint64_t rng_seed) {
  // Uniform in the icosphere (the Voronoi domain), not the exact ball.
  const detail::ConvexDomain3 d = detail::makeDomain(domain);
  return rejectionSample(d.lo, d.hi, false, count, rng_seed, [&](const Vec3& p) {
    const double r = (p - d.center).norm();
    if (r < d.inner_radius) return true;
    return r < domain.radius && d.excess(p) < 0;
  });
}

std::vector<Vec3> readSeedsCsv(const std::string& path, int dim) {
  if (dim != 2 && dim != 3)
    throw InputError("readSeedsCsv: dim must be 2 or 3, got " + std::to_string(dim));
  std::ifstream in(path);
  if (!in) throw InputError("cannot open seed file '" + path + "'");
  const char* columns = dim == 2 ? "x,y" : "x,y,z";
  std::vector<Vec3> seeds;
  std::string line;
  std::size_t line_number = 0;
  bool first_row = true;
  while (std::getline(in, line)) {
    ++line_number;
    const std::string_view text = trim(line);
    if (text.empty() || text.front() == '#') continue;
    const auto fields = splitFields(text);
    const std::string where = path + ":" + std::to_string(line_number);
    double value = 0;
    if (first_row) {
      first_row = false;
      // A header names every column; a row mixing names and numbers is neither.
      std::size_t names = 0;
      for (const auto field : fields) names += isColumnName(field) ? 1 : 0;
      if (names == fields.size()) continue;
      if (names > 0) {
        std::size_t c = 0;
        while (!isColumnName(fields[c])) ++c;
        throw InputError(where + ", column " + std::to_string(c + 1) + ": '" + std::string(fields[c]) +
                         "' is not a number, but the row also holds numbers; a header row names every column (" +
                         columns + "), a data row holds numbers only");
      }
    }
    if (fields.size() != static_cast<std::size_t>(dim))
      throw InputError(where + ": expected " + std::to_string(dim) + " comma-separated values (" +
                       columns + "), got " + std::to_string(fields.size()) + ": '" + excerpt(text) +
                       "'");
    Vec3 p = Vec3::Zero();
    for (int c = 0; c < dim; ++c) {
      if (!parseNumber(fields[c], value))
        throw InputError(where + ", column " + std::to_string(c + 1) + ": '" + excerpt(fields[c]) +
                         "' is not a number");
      if (!std::isfinite(value))
        throw InputError(where + ", column " + std::to_string(c + 1) + ": '" + excerpt(fields[c]) +
                         "' is not a finite number");
      p[c] = value;
    }
    seeds.push_back(p);
  }
  if (in.bad()) throw InputError("error while reading seed file '" + path + "'");
  if (seeds.empty()) throw InputError("seed file '" + path + "' contains no seeds");
  return seeds;
}

}  // namespace tessella
