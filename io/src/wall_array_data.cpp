// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "wall_array_data.hpp"

#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkSmartPointer.h>

namespace tessella::io::detail {

void addWallArrays(vtkCellData* data, const WallArrays& arrays, const std::vector<std::size_t>& rows) {
  const auto n = static_cast<vtkIdType>(rows.size());
  for (const auto& [name, values] : arrays.scalars) {
    auto a = vtkSmartPointer<vtkDoubleArray>::New();
    a->SetName(name.c_str());
    a->SetNumberOfTuples(n);
    for (vtkIdType i = 0; i < n; ++i) a->SetValue(i, values[rows[i]]);
    data->AddArray(a);
  }
  for (const auto& [name, values] : arrays.vectors) {
    auto a = vtkSmartPointer<vtkDoubleArray>::New();
    a->SetName(name.c_str());
    a->SetNumberOfComponents(3);
    a->SetNumberOfTuples(n);
    for (vtkIdType i = 0; i < n; ++i) {
      const Vec3& v = values[rows[i]];
      a->SetTuple3(i, v.x(), v.y(), v.z());
    }
    data->AddArray(a);
  }
  for (const auto& [name, values] : arrays.tensors) {
    auto a = vtkSmartPointer<vtkDoubleArray>::New();
    a->SetName(name.c_str());
    a->SetNumberOfComponents(6);
    a->SetNumberOfTuples(n);
    for (vtkIdType i = 0; i < n; ++i) {
      // Sym3 holds xx yy zz xy xz yz; VTK's symmetric tensors are XX YY ZZ XY YZ XZ.
      const Sym3& s = values[rows[i]];
      const double tuple[6] = {s.v[0], s.v[1], s.v[2], s.v[3], s.v[5], s.v[4]};
      a->SetTuple(i, tuple);
    }
    data->AddArray(a);
  }
}

}  // namespace tessella::io::detail
