// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "finite_values.hpp"

#include <cmath>

#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"

namespace tessella::io::detail {

namespace {

bool finite(double x) { return std::isfinite(x); }
bool finite(float x) { return std::isfinite(x); }
template <typename Derived>
bool finite(const Eigen::MatrixBase<Derived>& m) {
  return m.allFinite();
}
bool finite(const Sym3& s) {
  for (double x : s.v)
    if (!std::isfinite(x)) return false;
  return true;
}

// A value of the data, quoted exactly.
std::string text(double x) { return formatNumber(x); }
std::string text(float x) { return text(static_cast<double>(x)); }
template <typename Derived>
std::string text(const Eigen::MatrixBase<Derived>& m) {  // row by row
  std::string s = "(";
  for (Eigen::Index i = 0; i < m.size(); ++i) s += (i ? ", " : "") + text(m(i / m.cols(), i % m.cols()));
  return s + ")";
}
std::string text(const Sym3& v) { return text(Eigen::Matrix<double, 6, 1>(v.v.data())); }

// The first selected row of a column of type T with a non-finite value;
// false if the column is of another type or all its values are finite.
template <typename T>
bool firstNonFinite(const PropertyColumnBase& base, const RowSelection& rows, Index& slot, std::string& value) {
  if (base.type() != typeid(T)) return false;
  const auto& values = static_cast<const PropertyColumn<T>&>(base).values();
  for (std::size_t r = 0; r < rows.count; ++r) {
    const Index s = rows.slot(r);
    if (!finite(values[s])) {
      slot = s;
      value = text(values[s]);
      return true;
    }
  }
  return false;
}

void requireFiniteColumns(const PropertyStore& store, const RowSelection& rows, const char* kind,
                          const Tissue* lineage_of, const std::string& path) {
  for (std::size_t i = 0; i < store.numColumns(); ++i) {
    const PropertyColumnBase& column = store.column(i);
    Index slot = kInvalidIndex;
    std::string value;
    if (firstNonFinite<double>(column, rows, slot, value) || firstNonFinite<float>(column, rows, slot, value) ||
        firstNonFinite<Eigen::Vector2d>(column, rows, slot, value) ||
        firstNonFinite<Vec3>(column, rows, slot, value) || firstNonFinite<Sym3>(column, rows, slot, value) ||
        firstNonFinite<Mat3>(column, rows, slot, value)) {
      std::string element = std::string(kind) + " " + std::to_string(slot);
      if (lineage_of) element += " (lineage id " + std::to_string(lineage_of->lineageId(CellId(slot))) + ")";
      throw InputError("'" + path + "': " + kind + " property '" + column.name() + "' of " + element + " is " +
                       value + "; a snapshot holds finite values only");
    }
  }
}

}  // namespace

void requireFinitePositions(std::span<const Vec3> positions, const RowSelection& rows, const std::string& path) {
  for (std::size_t r = 0; r < rows.count; ++r) {
    const Index s = rows.slot(r);
    if (!positions[s].allFinite())
      throw InputError("'" + path + "': vertex " + std::to_string(s) + " has the non-finite position " +
                       text(positions[s]) + "; a snapshot holds finite coordinates only");
  }
}

void requireFiniteProperties(const Tissue& tissue, const RowSelection& vertex_rows, const RowSelection& cell_rows,
                             const std::string& path) {
  requireFiniteColumns(tissue.cellProperties(), cell_rows, "cell", &tissue, path);
  requireFiniteColumns(tissue.properties(0), vertex_rows, "vertex", nullptr, path);
}

}  // namespace tessella::io::detail
