// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/generators/grids.hpp"

#include <cmath>
#include <string>
#include <unordered_map>

#include "tessella/tissue/builders.hpp"
#include "tessella/tissue/errors.hpp"

namespace tessella {

namespace {

void requireCount(std::size_t n, const char* name) {
  if (n == 0) throw InputError(std::string("grid size ") + name + " must be at least 1");
  if (n > (1u << 20)) throw InputError(std::string("grid size ") + name + " = " + std::to_string(n) + " is too large");
}

void requireLength(double v, const char* name) {
  if (!(v > 0) || !std::isfinite(v))
    throw InputError(std::string("grid ") + name + " must be a positive finite length, got " + std::to_string(v));
}

}  // namespace

Tissue rectangularGrid(std::size_t nx, std::size_t ny, double dx, double dy, const Vec3& origin) {
  requireCount(nx, "nx");
  requireCount(ny, "ny");
  requireLength(dx, "dx");
  requireLength(dy, "dy");
  std::vector<Vec3> pos;
  pos.reserve((nx + 1) * (ny + 1));
  for (std::size_t j = 0; j <= ny; ++j)
    for (std::size_t i = 0; i <= nx; ++i) pos.push_back(origin + Vec3(i * dx, j * dy, 0));
  auto id = [&](std::size_t i, std::size_t j) { return static_cast<Index>(j * (nx + 1) + i); };
  std::vector<std::vector<Index>> polys;
  polys.reserve(nx * ny);
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = 0; i < nx; ++i) polys.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  return buildPolygonTissue(pos, polys, Embedding::Planar);
}

Tissue cylinderGrid(std::size_t around, std::size_t along, double radius, double length, const Vec3& origin) {
  requireCount(around, "around");
  requireCount(along, "along");
  if (around < 3) throw InputError("cylinder: around = " + std::to_string(around) + " must be at least 3");
  requireLength(radius, "radius");
  requireLength(length, "length");
  std::vector<Vec3> pos;
  pos.reserve(around * (along + 1));
  const double pi = std::acos(-1.0);
  for (std::size_t j = 0; j <= along; ++j)
    for (std::size_t i = 0; i < around; ++i) {
      const double a = 2.0 * pi * static_cast<double>(i) / static_cast<double>(around);
      pos.push_back(origin + Vec3(radius * std::cos(a), radius * std::sin(a),
                                  length * static_cast<double>(j) / static_cast<double>(along)));
    }
  auto id = [&](std::size_t i, std::size_t j) { return static_cast<Index>(j * around + i % around); };
  std::vector<std::vector<Index>> polys;
  polys.reserve(around * along);
  for (std::size_t j = 0; j < along; ++j)
    for (std::size_t i = 0; i < around; ++i) polys.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  return buildPolygonTissue(pos, polys, Embedding::Surface);
}

Tissue hexagonalGrid(std::size_t nx, std::size_t ny, double radius, const Vec3& origin) {
  requireCount(nx, "nx");
  requireCount(ny, "ny");
  requireLength(radius, "radius");
  const double w = std::sqrt(3.0) * radius;
  // Shared corners are found by their position on a lattice of half-steps.
  std::unordered_map<std::int64_t, Index> corner;
  std::vector<Vec3> pos;
  std::vector<std::vector<Index>> polys;
  polys.reserve(nx * ny);
  const std::int64_t stride = 4 * static_cast<std::int64_t>(nx + 2);
  for (std::size_t j = 0; j < ny; ++j) {
    for (std::size_t i = 0; i < nx; ++i) {
      const double cx = w * (i + 0.5 * (j % 2)), cy = 1.5 * radius * j;
      std::vector<Index> loop;
      for (int k = 0; k < 6; ++k) {
        const double a = M_PI / 6 + k * M_PI / 3;
        const Vec3 p = origin + Vec3(cx + radius * std::cos(a), cy + radius * std::sin(a), 0);
        // Exact lattice key: x in units of w/2, y in units of r/2.
        const std::int64_t kx = std::llround((p.x() - origin.x()) / (0.5 * w)) + 2;
        const std::int64_t ky = std::llround((p.y() - origin.y()) / (0.5 * radius)) + 2;
        const std::int64_t key = ky * stride + kx;
        auto [it, fresh] = corner.emplace(key, static_cast<Index>(pos.size()));
        if (fresh) pos.push_back(p);
        loop.push_back(it->second);
      }
      polys.push_back(std::move(loop));
    }
  }
  return buildPolygonTissue(pos, polys, Embedding::Planar);
}

Tissue boxGrid(std::size_t nx, std::size_t ny, std::size_t nz, double dx, double dy, double dz,
               const Vec3& origin) {
  requireCount(nx, "nx");
  requireCount(ny, "ny");
  requireCount(nz, "nz");
  requireLength(dx, "dx");
  requireLength(dy, "dy");
  requireLength(dz, "dz");
  std::vector<Vec3> pos;
  pos.reserve((nx + 1) * (ny + 1) * (nz + 1));
  for (std::size_t k = 0; k <= nz; ++k)
    for (std::size_t j = 0; j <= ny; ++j)
      for (std::size_t i = 0; i <= nx; ++i) pos.push_back(origin + Vec3(i * dx, j * dy, k * dz));
  auto v = [&](std::size_t i, std::size_t j, std::size_t k) {
    return static_cast<Index>((k * (ny + 1) + j) * (nx + 1) + i);
  };
  std::vector<std::vector<Index>> faces;
  // Face numbering: x-normal faces, then y-normal, then z-normal; each loop's
  // normal points along +axis.
  auto xf = [&](std::size_t i, std::size_t j, std::size_t k) { return static_cast<Index>((k * ny + j) * (nx + 1) + i); };
  const std::size_t nxf = (nx + 1) * ny * nz;
  auto yf = [&](std::size_t i, std::size_t j, std::size_t k) { return static_cast<Index>(nxf + (k * (ny + 1) + j) * nx + i); };
  const std::size_t nyf = nx * (ny + 1) * nz;
  auto zf = [&](std::size_t i, std::size_t j, std::size_t k) { return static_cast<Index>(nxf + nyf + (k * ny + j) * nx + i); };
  faces.resize(nxf + nyf + nx * ny * (nz + 1));
  for (std::size_t k = 0; k < nz; ++k)
    for (std::size_t j = 0; j < ny; ++j)
      for (std::size_t i = 0; i <= nx; ++i) faces[xf(i, j, k)] = {v(i, j, k), v(i, j + 1, k), v(i, j + 1, k + 1), v(i, j, k + 1)};
  for (std::size_t k = 0; k < nz; ++k)
    for (std::size_t j = 0; j <= ny; ++j)
      for (std::size_t i = 0; i < nx; ++i) faces[yf(i, j, k)] = {v(i, j, k), v(i, j, k + 1), v(i + 1, j, k + 1), v(i + 1, j, k)};
  for (std::size_t k = 0; k <= nz; ++k)
    for (std::size_t j = 0; j < ny; ++j)
      for (std::size_t i = 0; i < nx; ++i) faces[zf(i, j, k)] = {v(i, j, k), v(i + 1, j, k), v(i + 1, j + 1, k), v(i, j + 1, k)};
  std::vector<std::vector<CellFace>> cells;
  cells.reserve(nx * ny * nz);
  for (std::size_t k = 0; k < nz; ++k)
    for (std::size_t j = 0; j < ny; ++j)
      for (std::size_t i = 0; i < nx; ++i)
        cells.push_back({{xf(i, j, k), true}, {xf(i + 1, j, k), false}, {yf(i, j, k), true},
                         {yf(i, j + 1, k), false}, {zf(i, j, k), true}, {zf(i, j, k + 1), false}});
  return buildPolyhedralTissue(pos, faces, cells);
}

}  // namespace tessella
