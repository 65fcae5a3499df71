// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// What dividing a cell by a plane will do, decided without changing anything:
// Tissue::splitCell plans with these functions, then applies the plan. A plan
// names the crossed edges and walls, where the new vertices go and which side
// each part of the cell goes to; every check (a plane missing the cell,
// running along a wall, leaving a sliver, ...) is made while planning, so a
// refused division throws before the tissue is touched. A plan records the
// tissue's topology and geometry versions it was made at: Tissue::splitCell
// applies it only to a tissue in that state (the same tissue unchanged since,
// or a copy of it), so a caller can plan, inspect the plan (growth's crossing
// check) and apply it without planning again.

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "tessella/tissue/tissue.hpp"

namespace tessella {

/// A corner of the cut: an existing vertex on the plane, or a new vertex at
/// `point` on the crossed edge `edge`.
struct CutNode {
  VertexId vertex;  ///< the existing vertex; invalid for a new one
  EdgeId edge;      ///< the edge a new vertex splits; invalid for an existing vertex
  Vec3 point;       ///< where the new vertex goes (the existing vertex's position otherwise)
  bool isNew() const { return !vertex; }
};

/// Dividing a 2D cell: a chord between two points of its boundary.
struct CellSplitPlan2D {
  CellId cell;  ///< the cell divided
  /// The tissue's topologyVersion() and geometryVersion() when planned.
  std::uint64_t topology_version = 0, geometry_version = 0;
  /// The plane (unit normal) and the distance within which a vertex counts as
  /// on it: Tissue::splitCells reuses a vertex another cell of the batch makes
  /// on a shared edge when it lies that close to this plane.
  Plane plane;
  double snap_distance = 0;
  /// The chord's ends, in the order of the cell's loop (new vertices are made
  /// in this order).
  CutNode a, b;
  /// The part of the loop from `a` to `b` lies on the plane normal's positive
  /// side: it becomes the daughter; otherwise the part from `b` to `a` does.
  bool daughter_from_a_to_b = false;
  /// The mother's share of the cell's area.
  double mother_fraction = 0.5;
};

/// Dividing a 3D cell: a polygon across it whose corners split its edges or
/// reuse vertices on the plane, and whose sides split its walls.
struct CellSplitPlan3D {
  CellId cell;  ///< the cell divided
  /// The tissue's topologyVersion() and geometryVersion() when planned.
  std::uint64_t topology_version = 0, geometry_version = 0;
  /// The cut polygon, counter-clockwise seen from the positive side.
  std::vector<CutNode> ring;
  /// A crossed wall is split between two corners of the ring (indices): it
  /// keeps the part of its loop from `from` to `to`, which holds
  /// `kept_fraction` of its area (its properties are divided by it).
  struct WallCut {
    FaceId wall;
    std::size_t from, to;
    double kept_fraction = 0.5;
  };
  /// In the order of the cell's walls.
  std::vector<WallCut> wall_cuts;
  /// Signed distance to the plane of each of the cell's vertices, 0 within
  /// the snap tolerance: the walls with a positive vertex go to the daughter.
  std::vector<std::pair<VertexId, double>> distances;
};

/// The plan of Tissue::splitCell for a cell of a 2D (planar or surface)
/// tissue, with splitCell's checks: InputError for options out of range,
/// TopologyError for a dead cell, GeometryError for a plane that cannot
/// divide the cell (docs/ARCHITECTURE.md, "Editing primitives"). Not the
/// checks of the edits that apply it (a new vertex within 1e-12 of its edge's
/// end, possible with snap tolerance 0): Tissue::splitCells takes such plans,
/// and Tissue::splitCell makes those checks before its first edit.
CellSplitPlan2D planCellSplit2D(const Tissue& tissue, CellId c, const Plane& plane,
                                const SplitOptions& options = {});

/// The plan of Tissue::splitCell for a cell of a 3D tissue, with its checks,
/// including those of the edits that apply it (each new vertex strictly inside
/// its edge, each crossed wall split into two parts of positive area on its
/// side, two corners of a crossed wall not already joined by an edge), so
/// applying the plan cannot fail half-way.
CellSplitPlan3D planCellSplit3D(const Tissue& tissue, CellId c, const Plane& plane,
                                const SplitOptions& options = {});

}  // namespace tessella
