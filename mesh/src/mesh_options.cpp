// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/mesh/mesh_options.hpp"

#include <cmath>
#include <string>

#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"

namespace tessella::mesh {
namespace {

void require(bool ok, const char* field, double value, const char* range) {
  if (!ok)
    throw InputError(std::string("mesh option ") + field + " = " + formatNumber(value) + " is out of range: " + range);
}

}  // namespace

const EnumTable<VolumeMethod>& volumeMethods() {
  static const EnumTable<VolumeMethod> table(
      "volume method", {{"cell_by_cell", VolumeMethod::CellByCell, "Walls first, then each cell with TetGen."},
                        {"whole_tissue", VolumeMethod::WholeTissue, "One TetGen run on all walls at once."}});
  return table;
}

void validateMeshOptions(const MeshOptions& o) {
  // CGAL's Delaunay refinement provably terminates up to 20.7 degrees and in
  // practice up to about 33; beyond, it can run forever.
  require(std::isfinite(o.min_angle_degrees) && o.min_angle_degrees >= 0.0 && o.min_angle_degrees <= 33.0,
          "min_angle_degrees", o.min_angle_degrees, "[0, 33]");
  require(std::isfinite(o.max_edge_length) && o.max_edge_length >= 0.0, "max_edge_length", o.max_edge_length,
          ">= 0 (0 = no bound)");
  require(std::isfinite(o.max_volume) && o.max_volume >= 0.0, "max_volume", o.max_volume, ">= 0 (0 = no bound)");
  require(std::isfinite(o.radius_edge_ratio) && o.radius_edge_ratio > 1.0, "radius_edge_ratio",
          o.radius_edge_ratio, "> 1 (2 is proven to terminate)");
  require(std::isfinite(o.min_dihedral_degrees) && o.min_dihedral_degrees >= 0.0 && o.min_dihedral_degrees < 70.0,
          "min_dihedral_degrees", o.min_dihedral_degrees, "[0, 70)");
  require(std::isfinite(o.tolerance) && o.tolerance > 0.0 && o.tolerance < 1e-3, "tolerance", o.tolerance,
          "(0, 1e-3)");
  require(std::isfinite(o.cell_time_limit) && o.cell_time_limit >= 0.0, "cell_time_limit", o.cell_time_limit,
          ">= 0 seconds (0 = no limit)");
  require(std::isfinite(o.time_limit) && o.time_limit >= 0.0, "time_limit", o.time_limit,
          ">= 0 seconds (0 = no limit)");
}

}  // namespace tessella::mesh
