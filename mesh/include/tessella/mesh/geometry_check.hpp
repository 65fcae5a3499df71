// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// checkMeshable(): finds the geometry a mesher cannot or must not mesh, and
// names the elements involved, before any mesher runs (TetGen in particular
// aborts or crashes on self-intersecting input).
//
// Checked: zero-length walls/edges and coincident vertices, zero-area walls
// (3D), inverted cells (clockwise 2D cells, negative or zero volumes),
// self-intersecting walls (two walls crossing or overlapping anywhere but at
// shared vertices and edges), and for curved sheets and non-planar 3D walls
// fan surfaces that fold over (a fan triangle facing against the polygon's
// mean normal), since the mesh reproduces that fan surface.

#include <string>

#include "tessella/mesh/mesh_options.hpp"
#include "tessella/tissue/handles.hpp"
#include "tessella/tissue/tissue.hpp"

namespace tessella::mesh {

struct MeshabilityReport {
  bool ok = true;
  std::string message;  ///< the first defect, naming element ids and values
  ElementId element;    ///< the offending element (a cell, wall, edge or vertex)
  explicit operator bool() const { return ok; }
};

MeshabilityReport findGeometryDefects(const Tissue& tissue, const MeshOptions& options = {});

/// findGeometryDefects() that throws GeometryError with the report's message.
void checkMeshable(const Tissue& tissue, const MeshOptions& options = {});

}  // namespace tessella::mesh
