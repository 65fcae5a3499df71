#include "tessella/sim/tissue_summary.hpp"

#include <algorithm>
#include <cmath>

#include "tessella/tissue/errors.hpp"
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
  std::vector<double> sizes;
  sizes.reserve(s.cells);
  for (CellId c : tissue.cells()) sizes.push_back(cellMeasure(tissue, c));
  for (double v : sizes) s.total_measure += v;
  if (!sizes.empty()) s.cell_sizes = distributionOf(std::move(sizes));
  s.validation = validate(tissue);
  return s;
}

}  // namespace tessella::sim
