// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// MeshOptions: the size and quality targets of a tissue mesh, in the tissue's
// own length units. See docs/meshing.md for what each bound guarantees.

#include <cstddef>

#include "tessella/tissue/enum_table.hpp"

namespace tessella::mesh {

/// Default MeshOptions::max_elements: a mesh of more elements takes minutes
/// and gigabytes (a typo such as a size of 1e-6 must not exhaust memory).
inline constexpr std::size_t kDefaultMaxElements = 20'000'000;

/// Default MeshOptions::cell_time_limit (seconds): a cell's TetGen run takes
/// milliseconds; one that runs for a minute is stuck (never-ending flips), and
/// the first try gets half of this.
inline constexpr double kDefaultCellTimeLimit = 120.0;
/// Default MeshOptions::time_limit (seconds): the TetGen runs of one mesh
/// together (10 000 Voronoi cells take under a minute on two cores).
inline constexpr double kDefaultTimeLimit = 3600.0;

/// How a 3D tissue is filled with tetrahedra (docs/meshing.md).
enum class VolumeMethod {
  /// Walls meshed first, once, to the size and angle bounds; then one TetGen
  /// run per cell that keeps those wall triangles, cells in parallel. Time
  /// grows linearly with the number of cells.
  CellByCell,
  /// One TetGen run on all walls, which TetGen refines itself. TetGen 1.5's
  /// facet repair makes this grow quadratically with the number of walls:
  /// for small tissues only.
  WholeTissue,
};

/// "cell_by_cell", "whole_tissue": the names config keys, the CLI and Python use.
const EnumTable<VolumeMethod>& volumeMethods();

struct MeshOptions {
  /// 2D and surface tissues (and the walls of 3D tissues meshed cell by
  /// cell): lower bound on every triangle angle, in degrees
  /// (CGAL Delaunay refinement). Termination is proven up to 20.7 degrees;
  /// values up to 33 usually work. Angles of the input (two walls meeting at
  /// a sharp corner) cannot be improved, so triangles at such corners may be
  /// sharper.
  double min_angle_degrees = 20.0;
  /// 2D and surface tissues: upper bound on every triangle edge length; 3D
  /// tissues meshed cell by cell: the same bound on the wall triangles.
  /// 0 = no size bound (only the quality bound refines).
  double max_edge_length = 0.0;
  /// 3D tissues: upper bound on every tetrahedron volume (TetGen -a).
  /// 0 = no volume bound.
  double max_volume = 0.0;
  /// 3D tissues: upper bound on the circumradius / shortest edge ratio of
  /// every tetrahedron (TetGen -q). Must be > 1; 2 is proven to terminate,
  /// 1.2 - 1.5 is the usual choice.
  double radius_edge_ratio = 1.5;
  /// 3D tissues: TetGen's lower bound on dihedral angles (degrees) used
  /// together with the radius-edge ratio (the second number of -q). 0 = off.
  double min_dihedral_degrees = 0.0;
  /// Relative tolerance; times the tissue's bounding-box diagonal it is a
  /// length tol: a wall within tol of its plane counts as planar (meshed as
  /// one polygon in 3D), and the geometry check refuses an edge shorter than
  /// tol and a polygon or cell thinner than tol (mean width 2 area/perimeter,
  /// 2 volume/surface), so small but well-shaped cells of large tissues pass.
  double tolerance = 1e-10;
  /// 3D tissues: how the tetrahedra are made. CellByCell bounds the wall
  /// triangles by max_edge_length if set, else by the edge of the regular
  /// tetrahedron of volume max_volume, and by min_angle_degrees.
  VolumeMethod volume_method = VolumeMethod::CellByCell;
  /// Refuse (InputError) before meshing when the size bounds ask for more
  /// elements than this (estimatedElementCount, mesh_tissue.hpp). 0 = no limit.
  std::size_t max_elements = kDefaultMaxElements;
  /// 3D tissues meshed cell by cell: wall-clock seconds one cell's TetGen runs
  /// may take together. A cell whose run fails is tried again with other
  /// tolerances (docs/meshing.md); try k of the five may run for 1/2^k of
  /// this, the last as long as the one before. 0 = no limit.
  double cell_time_limit = kDefaultCellTimeLimit;
  /// 3D tissues: wall-clock seconds all TetGen runs of one mesh may take
  /// together (every cell and its tries; the one whole-tissue run). 0 = no limit.
  double time_limit = kDefaultTimeLimit;
};

/// Throws InputError naming the field and value when an option is out of range.
void validateMeshOptions(const MeshOptions& options);

}  // namespace tessella::mesh
