// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Small tissues with known geometry, shared by the tissue tests.

#include <cmath>
#include <vector>

#include <Eigen/Geometry>

#include "tessella/tissue/builders.hpp"
#include "tessella/generators/grids.hpp"
#include "tessella/tissue/tissue.hpp"

namespace tessella::fixtures {

/// Rotation by `angle` about the (normalised) `axis`.
inline Mat3 rotation(double angle, Vec3 axis) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

/// A regular n-gon of circumradius r centred at the origin, counter-clockwise.
inline std::vector<Vec3> regularPolygon(int n, double r) {
  std::vector<Vec3> p;
  for (int k = 0; k < n; ++k) p.emplace_back(r * std::cos(2 * M_PI * k / n), r * std::sin(2 * M_PI * k / n), 0);
  return p;
}

/// One polygon tissue from a point loop (Planar if all z == 0, else Surface).
inline Tissue singlePolygon(const std::vector<Vec3>& pts, Embedding e = Embedding::Planar) {
  std::vector<Index> loop;
  for (Index i = 0; i < pts.size(); ++i) loop.push_back(i);
  return buildPolygonTissue(pts, {loop}, e);
}

/// One regular hexagon of circumradius 1.
inline Tissue hexagon() { return singlePolygon(regularPolygon(6, 1.0)); }

/// Three cells meeting at one vertex: three quadrilaterals around the origin.
inline Tissue threeCells() {
  std::vector<Vec3> p{{0, 0, 0}};
  for (int k = 0; k < 6; ++k) p.emplace_back(std::cos(k * M_PI / 3), std::sin(k * M_PI / 3), 0);
  return buildPolygonTissue(p, {{0, 1, 2, 3}, {0, 3, 4, 5}, {0, 5, 6, 1}});
}

/// An axis-aligned box [0,a]x[0,b]x[0,c] as one 3D cell, optionally moved.
inline Tissue box(double a, double b, double c, const Mat3& R = Mat3::Identity(), const Vec3& t = Vec3::Zero()) {
  Tissue g = boxGrid(1, 1, 1, a, b, c);
  for (VertexId v : g.vertices()) g.setPosition(v, R * g.position(v) + t);
  return g;
}

/// The tetrahedron with the given corners (any orientation: made outward).
inline Tissue tetrahedron(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const bool positive = (b - a).dot((c - a).cross(d - a)) > 0;
  std::vector<Vec3> p{a, b, c, d};
  // Faces listed with outward loops for a positively oriented tetrahedron.
  std::vector<std::vector<Index>> f{{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  std::vector<CellFace> cell;
  for (Index i = 0; i < 4; ++i) cell.push_back({i, !positive});
  return buildPolyhedralTissue(p, f, {cell});
}

/// A right prism over a regular n-gon (circumradius r), height h.
inline Tissue prism(int n, double r, double h) {
  std::vector<Vec3> p;
  for (const Vec3& q : regularPolygon(n, r)) p.push_back(q);
  for (const Vec3& q : regularPolygon(n, r)) p.push_back(q + Vec3(0, 0, h));
  std::vector<std::vector<Index>> faces;
  std::vector<Index> bottom, top;
  for (int k = n - 1; k >= 0; --k) bottom.push_back(k);  // normal -z: outward
  for (int k = 0; k < n; ++k) top.push_back(n + k);       // normal +z
  faces.push_back(bottom);
  faces.push_back(top);
  for (int k = 0; k < n; ++k) {
    const Index a = k, b = (k + 1) % n;
    faces.push_back({a, b, static_cast<Index>(n + b), static_cast<Index>(n + a)});
  }
  std::vector<CellFace> cell;
  for (Index i = 0; i < faces.size(); ++i) cell.push_back({i, false});
  return buildPolyhedralTissue(p, faces, {cell});
}

/// A curved sheet: an nx x ny grid of quads on the cylinder of radius R
/// (x along the axis, the grid wrapping `angle` radians around it).
inline Tissue curvedSheet(std::size_t nx, std::size_t ny, double R, double angle) {
  std::vector<Vec3> p;
  for (std::size_t j = 0; j <= ny; ++j)
    for (std::size_t i = 0; i <= nx; ++i) {
      const double th = angle * j / ny;
      p.emplace_back(double(i) / nx, R * std::sin(th), R * (1 - std::cos(th)));
    }
  std::vector<std::vector<Index>> polys;
  auto id = [&](std::size_t i, std::size_t j) { return static_cast<Index>(j * (nx + 1) + i); };
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = 0; i < nx; ++i) polys.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  return buildPolygonTissue(p, polys, Embedding::Surface);
}

inline std::size_t count(const Tissue& t, int degree) {
  return degree > t.dim() ? 0 : t.topology().count(degree);
}

}  // namespace tessella::fixtures
