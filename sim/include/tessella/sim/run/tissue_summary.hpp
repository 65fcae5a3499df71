// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// TissueSummary: what `tessella info` reports about a tissue: element counts,
// total size, the distribution of cell sizes and whether validate() passes.

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "tessella/io/import.hpp"
#include "tessella/tissue/tissue.hpp"
#include "tessella/tissue/validate.hpp"

namespace tessella::sim {

/// Order statistics and moments of a sample. Quartiles interpolate linearly
/// between order statistics (the "type 7" rule of R and NumPy); the
/// coefficient of variation is the population standard deviation / mean.
struct Distribution {
  std::size_t count = 0;
  double min = 0, q1 = 0, median = 0, q3 = 0, max = 0;
  double mean = 0, cv = 0;
};

/// Throws InputError for an empty sample.
Distribution distributionOf(std::vector<double> values);

struct TissueSummary {
  int dim = 2;
  Embedding embedding = Embedding::Planar;
  std::array<std::size_t, 4> counts{};  ///< live vertices, edges, faces, volumes
  std::size_t cells = 0;
  std::size_t walls = 0;
  std::size_t boundary_cells = 0;  ///< cells with a wall on the tissue's boundary
  double total_measure = 0;  ///< area (2D) or volume (3D)
  Distribution cell_sizes;   ///< cell areas (2D) or volumes (3D); empty tissue: count 0
  ValidationReport validation;
};

TissueSummary summarizeTissue(const Tissue& tissue);

/// The summary as `tessella info` prints it, one "key  value" line each:
/// tissue (dimension, embedding, time), elements, cells (walls, boundary
/// cells), total size, the cell size distribution, validate.
std::string formatTissueSummary(const TissueSummary& summary, double time);

/// What `tessella import` prints about an import: the file, the format, the
/// file's counts, simplification, every repair and note, then the tissue's
/// summary (formatTissueSummary).
std::string formatImportSummary(const io::ImportReport& report, const TissueSummary& summary, double time);

}  // namespace tessella::sim
