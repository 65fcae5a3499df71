// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/sim/run/tissue_summary.hpp"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>

#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"
#include "tessella/tissue/geometry.hpp"

namespace tessella::sim {

namespace {
// Type-7 quantile of sorted values: linear between order statistics.
double quantile(const std::vector<double>& sorted, double p) {
  const double h = p * static_cast<double>(sorted.size() - 1);
  const auto lo = static_cast<std::size_t>(std::floor(h));
  const std::size_t hi = std::min(lo + 1, sorted.size() - 1);
  return sorted[lo] + (h - static_cast<double>(lo)) * (sorted[hi] - sorted[lo]);
}
}  // namespace

Distribution distributionOf(std::vector<double> values) {
  if (values.empty()) throw InputError("distributionOf: empty sample");
  std::sort(values.begin(), values.end());
  Distribution d;
  d.count = values.size();
  d.min = values.front();
  d.max = values.back();
  d.q1 = quantile(values, 0.25);
  d.median = quantile(values, 0.5);
  d.q3 = quantile(values, 0.75);
  double sum = 0;
  for (double v : values) sum += v;
  d.mean = sum / static_cast<double>(d.count);
  double squares = 0;
  for (double v : values) squares += (v - d.mean) * (v - d.mean);
  const double sd = std::sqrt(squares / static_cast<double>(d.count));
  d.cv = d.mean != 0 ? sd / std::abs(d.mean) : 0.0;
  return d;
}

TissueSummary summarizeTissue(const Tissue& tissue) {
  TissueSummary s;
  s.dim = tissue.dim();
  s.embedding = tissue.embedding();
  s.counts = {tissue.numVertices(), tissue.numEdges(), tissue.numFaces(), tissue.numVolumes()};
  s.cells = tissue.numCells();
  s.walls = tissue.numWalls();
  std::vector<char> on_boundary(tissue.slots(tissue.dim()), 0);
  for (WallId w : tissue.walls())
    if (tissue.isBoundaryWall(w))
      for (CellId c : tissue.wallCells(w)) on_boundary[c.index()] = 1;
  for (CellId c : tissue.cells()) s.boundary_cells += on_boundary[c.index()] != 0;
  std::vector<double> sizes;
  sizes.reserve(s.cells);
  for (CellId c : tissue.cells()) sizes.push_back(cellMeasure(tissue, c));
  for (double v : sizes) s.total_measure += v;
  if (!sizes.empty()) s.cell_sizes = distributionOf(std::move(sizes));
  s.validation = validate(tissue);
  return s;
}

namespace {
std::string printed(const char* format, ...) __attribute__((format(printf, 1, 2)));
std::string printed(const char* format, ...) {
  char buffer[512];
  va_list args;
  va_start(args, format);
  std::vsnprintf(buffer, sizeof buffer, format, args);
  va_end(args);
  return buffer;
}
}  // namespace

std::string formatTissueSummary(const TissueSummary& s, double time) {
  const char* measure = s.dim == 2 ? "area" : "volume";
  std::string out = printed("tissue       %dD, %s, time %s\n", s.dim, embeddingName(s.embedding),
                            formatNumber(time).c_str());
  out += printed("elements     %zu vertices, %zu edges, %zu faces", s.counts[0], s.counts[1], s.counts[2]);
  if (s.dim == 3) out += printed(", %zu volumes", s.counts[3]);
  out += printed("\ncells        %zu\n", s.cells);
  out += printed("walls        %zu (%zu cells touch the boundary)\n", s.walls, s.boundary_cells);
  out += printed("total %-6s %.6g\n", measure, s.total_measure);
  if (s.cell_sizes.count > 0) {
    const Distribution& d = s.cell_sizes;
    out += printed("cell %-7s min %.6g  q1 %.6g  median %.6g  q3 %.6g  max %.6g\n", measure, d.min, d.q1, d.median,
                   d.q3, d.max);
    out += printed("             mean %.6g  CV %.4f\n", d.mean, d.cv);
  }
  out += s.validation.ok ? std::string("validate     ok\n") : "validate     FAILED: " + s.validation.message + "\n";
  return out;
}

std::string formatImportSummary(const io::ImportReport& r, const TissueSummary& s, double time) {
  std::string out = "file         " + r.path + "\n";
  out += "format       " + r.format + " (" + std::to_string(r.file_vertices) + " vertices, " +
         std::to_string(r.file_faces) + " " + r.file_faces_noun + " in the file)\n";
  if (r.simplified_vertices > 0)
    out += "simplify     " + std::to_string(r.simplified_vertices) + " wall vertices removed\n";
  out += "repairs      " + std::to_string(r.repairs.size()) + "\n";
  for (const std::string& repair : r.repairs) out += "  repaired   " + repair + "\n";
  for (const std::string& note : r.notes) out += "note         " + note + "\n";
  return out + formatTissueSummary(s, time);
}

}  // namespace tessella::sim
