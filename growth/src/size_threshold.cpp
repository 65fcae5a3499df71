// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/growth/size_threshold.hpp"

#include <omp.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include "tessella/growth/parallel_threshold.hpp"
#include "tessella/growth/positive_normal_draws.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"
#include "tessella/tissue/uninitialized_vector.hpp"

namespace tessella::growth {

namespace {
// The live cells for which `pred` holds, in slot order (threads scan
// contiguous blocks in thread order, so the list is the serial one).
template <typename Pred>
std::vector<CellId> cellsWhere(const Tissue& t, Pred pred) {
  const std::ptrdiff_t slots = static_cast<std::ptrdiff_t>(t.cellSlots());
  std::vector<std::vector<CellId>> parts;
#pragma omp parallel if (slots >= kParallelMinItems)
  {
#pragma omp single
    parts.resize(static_cast<std::size_t>(omp_get_num_threads()));
    std::vector<CellId>& mine = parts[static_cast<std::size_t>(omp_get_thread_num())];
#pragma omp for schedule(static)
    for (std::ptrdiff_t i = 0; i < slots; ++i) {
      const CellId c(static_cast<Index>(i));
      if (t.alive(c) && pred(c)) mine.push_back(c);
    }
  }
  std::vector<CellId> out;
  for (const auto& part : parts) out.insert(out.end(), part.begin(), part.end());
  return out;
}
}  // namespace

SizeThreshold SizeThreshold::fixed(double size) {
  if (!(size > 0) || !std::isfinite(size))
    throw InputError("division threshold: size = " + formatNumber(size) +
                     " must be positive and finite");
  SizeThreshold s;
  s.kind_ = Kind::Fixed;
  s.size_ = size;
  return s;
}

SizeThreshold SizeThreshold::fromProperty(std::string name) {
  if (name.empty()) throw InputError("division threshold: property name must not be empty");
  SizeThreshold s;
  s.kind_ = Kind::Property;
  s.property_ = std::move(name);
  return s;
}

SizeThreshold SizeThreshold::noisy(double mean, double stddev, std::string property) {
  if (!(mean > 0) || !std::isfinite(mean))
    throw InputError("division threshold: mean = " + formatNumber(mean) +
                     " must be positive and finite");
  if (!(stddev >= 0) || !std::isfinite(stddev))
    throw InputError("division threshold: stddev = " + formatNumber(stddev) +
                     " must be >= 0 and finite");
  if (property.empty()) throw InputError("division threshold: property name must not be empty");
  SizeThreshold s;
  s.kind_ = Kind::Noisy;
  s.size_ = mean;
  s.stddev_ = stddev;
  s.property_ = std::move(property);
  return s;
}

void SizeThreshold::prepare(Tissue& t, Rng& rng) const {
  PropertyStore& cells = t.cellProperties();
  if (kind_ == Kind::Property) {
    cells.get<double>(property_);  // throws InputError naming the property if missing / mistyped
    return;
  }
  if (kind_ != Kind::Noisy) return;
  if (!cells.has(property_))
    cells.add<double>(property_, std::numeric_limits<double>::quiet_NaN(), DivisionPolicy::Reset);
  auto& column = cells.get<double>(property_);
  // NaN marks "not drawn yet"; a value that is no size (0 from a column
  // read back without its default, say) is redrawn too, never used. Found in
  // parallel, drawn in cell order from one normal distribution, each redrawn
  // until positive (a size threshold must be positive).
  const std::vector<CellId> undrawn = cellsWhere(t, [&](CellId c) {
    const double v = column[c];
    return !(v > 0 && std::isfinite(v));
  });
  UninitializedVector<double> drawn(undrawn.size());  // written whole by the draws
  drawPositiveNormals(rng, size_, stddev_, drawn);
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(undrawn.size());
#pragma omp parallel for schedule(static) if (n >= kParallelMinItems)
  for (std::ptrdiff_t i = 0; i < n; ++i) column[undrawn[i]] = drawn[i];
}

double SizeThreshold::threshold(const Tissue& t, CellId c) const {
  if (kind_ == Kind::Fixed) return size_;
  return t.cellProperties().get<double>(property_)[c];
}

std::vector<CellId> SizeThreshold::cellsDue(Tissue& t, const GeometryCache& g, Rng& rng) const {
  prepare(t, rng);
  if (kind_ == Kind::Fixed) return cellsWhere(t, [&](CellId c) { return g.cellMeasure(t, c) > size_; });
  const auto& column = t.cellProperties().get<double>(property_);
  return cellsWhere(t, [&](CellId c) { return g.cellMeasure(t, c) > column[c]; });  // NaN never triggers
}

std::string SizeThreshold::describe() const {
  std::ostringstream s;
  switch (kind_) {
    case Kind::Fixed: s << "size > " << size_; break;
    case Kind::Property: s << "size > property '" << property_ << "'"; break;
    case Kind::Noisy: s << "size > N(" << size_ << ", " << stddev_ << ") drawn at birth"; break;
  }
  return s.str();
}

}  // namespace tessella::growth
