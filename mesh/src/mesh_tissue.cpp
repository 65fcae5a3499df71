// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/mesh/mesh_tissue.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"
#include "tessella/tissue/geometry.hpp"

namespace tessella::mesh {

namespace {

// Options, an estimate and a measure: six significant digits say enough.
std::string text(double v) { return formatNumber(v, 6); }

}  // namespace

double estimatedElementCount(const Tissue& tissue, const MeshOptions& options) {
  const double h = options.max_edge_length;
  const double triangle = std::sqrt(3.0) / 4.0 * h * h;  // the largest triangle with edges <= h
  if (tissue.dim() != 3) return h > 0 ? totalMeasure(tissue) / triangle : 0.0;
  double tetrahedra = options.max_volume > 0 ? totalMeasure(tissue) / options.max_volume : 0.0;
  if (h > 0 && options.volume_method == VolumeMethod::CellByCell) {
    // Each cell's walls are triangles with edges <= h, each a face of one of
    // the cell's tetrahedra, which have four faces.
    double sides = 0;  // wall area, counted once per cell it bounds
    for (WallId w : tissue.walls()) sides += wallMeasure(tissue, w) * static_cast<double>(tissue.wallCells(w).size());
    tetrahedra = std::max(tetrahedra, sides / triangle / 4.0);
  }
  return tetrahedra;
}

void checkElementLimit(const Tissue& tissue, const MeshOptions& options) {
  if (options.max_elements == 0) return;
  const double estimate = estimatedElementCount(tissue, options);
  const auto limit = static_cast<double>(options.max_elements);
  if (!(estimate > limit)) return;
  const bool volume = tissue.dim() == 3;
  std::string size;
  if (options.max_edge_length > 0 && (!volume || options.volume_method == VolumeMethod::CellByCell))
    size = "max_edge_length = " + text(options.max_edge_length);
  if (volume && options.max_volume > 0)
    size += (size.empty() ? "" : ", ") + ("max_volume = " + text(options.max_volume));
  throw InputError("mesh: the size bounds (" + size + ") ask for at least " + text(estimate) + " " +
                   (volume ? "tetrahedra" : "triangles") + " on a tissue of total " + (volume ? "volume " : "area ") +
                   text(totalMeasure(tissue)) + ", more than the limit max_elements = " + text(limit) +
                   "; use a larger size, or raise max_elements (0 = no limit) if the memory and time are there");
}

FeMesh meshTissue(const Tissue& tissue, const MeshOptions& options) {
  switch (tissue.embedding()) {
    case Embedding::Planar: return meshPlanarTissue(tissue, options);
    case Embedding::Surface: return meshSurfaceTissue(tissue, options);
    case Embedding::Volume: return meshVolumeTissue(tissue, options);
  }
  return meshVolumeTissue(tissue, options);  // unreachable: every embedding is handled above
}

}  // namespace tessella::mesh
