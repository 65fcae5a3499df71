// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/sim/sections/mesh_section.hpp"

#include <utility>

#include "tessella/sim/config/registry_config.hpp"
#include "tessella/tissue/errors.hpp"

namespace tessella::sim {

void declareMeshSection(Schema& s) {
  s.section("mesh",
            "The finite-element mesh of the tissue (docs/meshing.md): triangles for 2D and curved "
            "tissues (CGAL), tetrahedra for 3D tissues (TetGen). Every element lies in one cell and "
            "cells sharing a wall share its nodes. Used by stages that solve on the tissue and by "
            "mesh.output.");
  s.key("mesh.max_edge_length", ValueType::Float,
        "2D and curved tissues: longest triangle edge, in the tissue's length unit; 3D tissues meshed "
        "cell by cell: longest wall-triangle edge. 0 = no size bound (only the angle bound refines).")
      .byDefault(0.0)
      .atLeast(0);
  s.key("mesh.min_angle", ValueType::Float,
        "2D and curved tissues, and the walls of 3D tissues meshed cell by cell: smallest triangle angle, "
        "in degrees. Refinement is proven to end up to 20.7; up to 33 is accepted. Sharper corners "
        "between walls stay as they are.")
      .byDefault(20.0)
      .atLeast(0)
      .atMost(33);
  s.key("mesh.max_volume", ValueType::Float,
        "3D tissues: largest tetrahedron volume (TetGen -a). 0 = no volume bound.")
      .byDefault(0.0)
      .atLeast(0);
  s.key("mesh.radius_edge_ratio", ValueType::Float,
        "3D tissues: bound on circumradius / shortest edge of every tetrahedron (TetGen -q); 2 is "
        "proven to end, 1.2 - 1.5 is usual.")
      .byDefault(1.5)
      .above(1);
  s.key("mesh.min_dihedral_angle", ValueType::Float,
        "3D tissues: TetGen's bound on the smallest dihedral angle, in degrees (second number of -q). "
        "0 = off.")
      .byDefault(0.0)
      .atLeast(0)
      .atMost(70)
      .max_exclusive = true;
  s.key("mesh.volume_method", ValueType::Enum,
        "3D tissues: `cell_by_cell` meshes the walls first (size max_edge_length, else the edge of the "
        "regular tetrahedron of volume max_volume; angle min_angle), then each cell with TetGen, keeping "
        "those wall triangles; time grows linearly with the cell count. `whole_tissue` gives TetGen all "
        "walls at once and lets it refine them, which grades tetrahedra along walls better but grows "
        "quadratically (TetGen 1.5): for tissues of up to a few hundred cells.")
      .oneOf(mesh::volumeMethods().names())
      .byDefault(std::string("cell_by_cell"));
  s.key("mesh.tolerance", ValueType::Float,
        "Relative to the tissue's bounding-box diagonal: below it a wall counts as planar, and the "
        "geometry check refuses shorter edges and thinner walls or cells (mean width).")
      .byDefault(1e-10)
      .above(0)
      .atMost(1e-3)
      .max_exclusive = true;
  s.key("mesh.max_elements", ValueType::Int,
        "Refuse, before meshing, a mesh the size bounds (max_edge_length; max_volume in 3D) would make larger "
        "than this many elements, estimated from the tissue's total area or volume (a lower bound: "
        "area / (sqrt(3)/4 max_edge_length^2) triangles, volume / max_volume tetrahedra). 0 = no limit.")
      .byDefault(static_cast<std::int64_t>(mesh::kDefaultMaxElements))
      .atLeast(0);
  s.key("mesh.cell_time_limit", ValueType::Float,
        "3D tissues meshed cell by cell: wall-clock seconds one cell's TetGen runs may take together. A cell "
        "whose run fails (a TetGen assertion, never-ending flips) is tried again with other coplanarity "
        "tolerances (the last two with the cell turned), up to seven tries; try k may run for 1/2^k of this "
        "limit, the last as long as the one before. A cell still failing is an error naming it and every try. "
        "0 = no limit.")
      .byDefault(mesh::kDefaultCellTimeLimit)
      .atLeast(0);
  s.key("mesh.time_limit", ValueType::Float,
        "3D tissues: wall-clock seconds all TetGen runs of one mesh may take together (every cell and its tries, "
        "or the whole-tissue run); once spent, the runs still going are stopped and the mesh is an error naming "
        "a cell and what was tried. 0 = no limit.")
      .byDefault(mesh::kDefaultTimeLimit)
      .atLeast(0);
  s.key("mesh.output", ValueType::Bool,
        "Write the mesh as a ParaView series DIR/mesh.pvd listing DIR/mesh_000000.vtu, ... beside the "
        "tissue series (cell and wall ids as data), and its wall facets as DIR/mesh_walls.pvd; with a `mechanics` "
        "section each wall facet also carries its wall's values of the walls file (tension, strain, fibre "
        "direction...; docs/output.md), and on a curved sheet each element its cell's mechanics values. The mesh "
        "is rebuilt when the tissue changed.")
      .byDefault(false);
  s.key("mesh.every", ValueType::Int,
        "With mesh.output: write a mesh every this many steps (the initial and final states always).")
      .atLeast(1)
      .whenAbsent("output.every");
}

mesh::MeshOptions meshOptionsFromConfig(const Config& c) {
  mesh::MeshOptions o;
  o.max_edge_length = c.getFloat("mesh.max_edge_length");
  o.min_angle_degrees = c.getFloat("mesh.min_angle");
  o.max_volume = c.getFloat("mesh.max_volume");
  o.radius_edge_ratio = c.getFloat("mesh.radius_edge_ratio");
  o.min_dihedral_degrees = c.getFloat("mesh.min_dihedral_angle");
  o.tolerance = c.getFloat("mesh.tolerance");
  o.volume_method = parseFromConfig(c, mesh::volumeMethods(), "mesh.volume_method");
  o.max_elements = static_cast<std::size_t>(c.getInt("mesh.max_elements"));
  o.cell_time_limit = c.getFloat("mesh.cell_time_limit");
  o.time_limit = c.getFloat("mesh.time_limit");
  mesh::validateMeshOptions(o);  // the schema's ranges are the same; this keeps them in step
  return o;
}

MeshSpec readMeshSection(const Config& c) {
  MeshSpec m;
  m.options = meshOptionsFromConfig(c);
  m.output = c.getBool("mesh.output");
  m.every = c.has("mesh.every") ? static_cast<std::size_t>(c.getInt("mesh.every")) : 0;
  if (m.output && c.has("output.name") && c.getString("output.name") == m.name)
    throw c.errorAt("output.name", "'" + m.name + "' is the mesh series' name (mesh.output is on); choose another");
  return m;
}

}  // namespace tessella::sim
