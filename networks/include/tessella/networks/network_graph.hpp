// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// NetworkGraph: what a network reads of a tissue, as plain arrays: each
// cell's measure (area in 2D, volume in 3D) and centroid, the values of the
// cell properties its reactions read, and the interfaces between neighbouring
// cells. An interface joins the walls two cells share (usually one) into one
// exchange surface: its measure is their summed length (2D) or area (3D) and
// its normal the measure-weighted mean of their unit normals, pointing from
// cell_i into cell_j. Boundary walls carry no transport.

#include <map>
#include <string>
#include <vector>

#include "tessella/tissue/geometry.hpp"
#include "tessella/tissue/tissue.hpp"
#include "tessella/tissue/vec3.hpp"

namespace tessella::networks {

struct NetworkInterface {
  int cell_i = -1;
  int cell_j = -1;  ///< cell_i < cell_j
  double measure = 0.0;
  Vec3 normal = Vec3::Zero();  ///< unit, from cell_i into cell_j
};

struct NetworkGraph {
  std::vector<double> measure;  ///< per cell, > 0
  std::vector<Vec3> centroid;   ///< per cell
  std::vector<NetworkInterface> interfaces;
  std::map<std::string, std::vector<double>> properties;  ///< per cell, by name

  std::size_t numCells() const { return measure.size(); }
  /// Throws InputError naming the cell / interface / property at fault.
  void validate() const;
};

/// One wall of an interface: its handle, its measure, and whether the
/// interface's cell_i is on the wall's positive side (onPositiveSide).
struct InterfaceWall {
  WallId wall;
  double measure = 0.0;
  bool i_positive = true;
};

/// Whether `cell` (one of the wall's cells) is on the positive side of
/// `wall`: 2D, the cell's loop runs along the edge from its first vertex to
/// its second; 3D, the face's normal points out of the cell. Each wall of a
/// valid tissue has at most one cell on either side, and splitting walls
/// keeps the sides, so per-side wall properties follow divisions.
bool onPositiveSide(const Tissue& tissue, WallId wall, CellId cell);

/// The graph of the live cells of `tissue` in their iteration order
/// (`cells`, if given, receives them), reading measures, centroids, wall
/// lengths / areas and normals from `geometry` (required here) and the double
/// cell properties named in `properties` (InputError when one is missing or
/// does not hold doubles). `walls`, if given, receives per interface the
/// walls it joins.
NetworkGraph networkGraph(const Tissue& tissue, GeometryCache& geometry, const std::vector<std::string>& properties,
                          std::vector<CellId>* cells = nullptr,
                          std::vector<std::vector<InterfaceWall>>* walls = nullptr);

}  // namespace tessella::networks
