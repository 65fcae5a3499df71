// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Property columns <-> VTK data arrays, keeping each column's value type:
//
//   arithmetic T (not bool)  1 component of the matching VTK type
//   Eigen::Vector2d          2 x Float64
//   Vec3                     3 x Float64 (a vector in ParaView)
//   Sym3                     6 x Float64 in VTK's symmetric-tensor order
//                            (XX, YY, ZZ, XY, YZ, XZ)
//   Mat3                     9 x Float64, row by row (a tensor in ParaView)
//
// Other types (strings, user structs) have no faithful VTK array: they are
// skipped by the writer and listed by unwritableProperties().

#include <cstdint>
#include <string>
#include <vector>

#include <vtkDataArray.h>
#include <vtkSmartPointer.h>

#include "tessella/tissue/handles.hpp"
#include "tessella/tissue/properties.hpp"

namespace tessella::io::detail {

/// Which slots of a store become output rows, in order. `identity` when
/// every slot is live (row i = slot i), so arrays can share the column's memory.
struct RowSelection {
  bool identity = true;
  std::size_t count = 0;
  std::vector<Index> slots;  // filled only when !identity
  Index slot(std::size_t row) const { return identity ? static_cast<Index>(row) : slots[row]; }
};

RowSelection liveRows(const std::vector<std::uint8_t>& alive_flags, std::size_t live_count);

/// The column as a named VTK array over the selected rows, or nullptr when
/// its type cannot be written. With an identity selection, scalar arrays
/// point straight into the column (zero copy): the column must outlive them.
vtkSmartPointer<vtkDataArray> columnToArray(const PropertyColumnBase& column, const RowSelection& rows);

/// The column's default value as a one-tuple array named `array_name`, of
/// the type columnToArray gives the column (nullptr when it has none).
vtkSmartPointer<vtkDataArray> defaultToArray(const PropertyColumnBase& column, const std::string& array_name);

/// Registers a column `name` with division policy `policy` in `store`, with
/// the type the array stands for and its values (row i -> slot i), and the
/// default held by `default_value` (a one-tuple array of the same type; the
/// type's zero when null). Throws InputError starting with `where` when the
/// array's type or component count has no column type or the default does
/// not match it.
void addColumnFromArray(PropertyStore& store, const std::string& name, vtkDataArray* array,
                        const std::string& where, DivisionPolicy policy, vtkDataArray* default_value = nullptr);

/// Exact copies of an integer or floating array's first component.
std::vector<std::int64_t> integerValues(vtkDataArray* array);
std::vector<double> doubleValues(vtkDataArray* array);

}  // namespace tessella::io::detail
