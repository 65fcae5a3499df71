// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Small tissues with known geometry for the growth tests.

#include <cmath>
#include <vector>

#include "tessella/tissue/builders.hpp"

namespace tessella::growth::testing {

/// One rectangular cell [0, w] x [0, h].
inline Tissue rectangleCell(double w, double h) {
  const std::vector<Vec3> p = {Vec3(0, 0, 0), Vec3(w, 0, 0), Vec3(w, h, 0), Vec3(0, h, 0)};
  return buildPolygonTissue(p, {{0, 1, 2, 3}});
}

/// One regular hexagon of circumradius r centred at the origin, rotated by phase.
inline Tissue hexagonCell(double r, double phase = 0.0) {
  std::vector<Vec3> p;
  std::vector<Index> loop;
  for (int i = 0; i < 6; ++i) {
    const double a = phase + i * M_PI / 3;
    p.emplace_back(r * std::cos(a), r * std::sin(a), 0);
    loop.push_back(static_cast<Index>(i));
  }
  return buildPolygonTissue(p, {loop});
}

/// One box cell [0, a] x [0, b] x [0, c].
inline Tissue boxCell(double a, double b, double c) {
  const std::vector<Vec3> p = {Vec3(0, 0, 0), Vec3(a, 0, 0), Vec3(a, b, 0), Vec3(0, b, 0),
                               Vec3(0, 0, c), Vec3(a, 0, c), Vec3(a, b, c), Vec3(0, b, c)};
  // Loops counter-clockwise seen from outside: outward normals.
  const std::vector<std::vector<Index>> faces = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                                 {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};
  std::vector<CellFace> cell;
  for (Index f = 0; f < 6; ++f) cell.push_back(CellFace{f, false});
  return buildPolyhedralTissue(p, faces, {cell});
}

/// An n x n grid of quads over [-w/2, w/2]^2 lifted onto the sphere of radius
/// R about the origin (upper cap): a curved-surface tissue.
inline Tissue sphericalCapGrid(int n, double w, double radius) {
  std::vector<Vec3> p;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x = -w / 2 + w * i / n, y = -w / 2 + w * j / n;
      p.emplace_back(x, y, std::sqrt(radius * radius - x * x - y * y));
    }
  std::vector<std::vector<Index>> quads;
  auto id = [&](int i, int j) { return static_cast<Index>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) quads.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  return buildPolygonTissue(p, quads, Embedding::Surface);
}

}  // namespace tessella::growth::testing
