// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "wall_array_data.hpp"

#include <string>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkSmartPointer.h>

#include "tessella/tissue/errors.hpp"

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

WallArrays readWallArrays(vtkCellData* data, vtkIdType cells, const std::string& skip, const std::string& path,
                          const std::string& items) {
  WallArrays out;
  for (int k = 0; k < data->GetNumberOfArrays(); ++k) {
    vtkDataArray* a = data->GetArray(k);
    if (!a || !a->GetName() || std::string(a->GetName()) == skip) continue;
    if (a->GetNumberOfTuples() != cells)
      throw InputError("'" + path + "': array '" + a->GetName() + "' has " + std::to_string(a->GetNumberOfTuples()) +
                       " values for " + std::to_string(cells) + " " + items);
    if (a->GetNumberOfComponents() == 1) {
      auto& v = out.scalars[a->GetName()];
      for (vtkIdType c = 0; c < a->GetNumberOfTuples(); ++c) v.push_back(a->GetTuple1(c));
    } else if (a->GetNumberOfComponents() == 3) {
      auto& v = out.vectors[a->GetName()];
      for (vtkIdType c = 0; c < a->GetNumberOfTuples(); ++c) {
        const double* t = a->GetTuple3(c);
        v.emplace_back(t[0], t[1], t[2]);
      }
    } else if (a->GetNumberOfComponents() == 6) {
      auto& v = out.tensors[a->GetName()];
      double t[6];
      for (vtkIdType c = 0; c < a->GetNumberOfTuples(); ++c) {
        a->GetTuple(c, t);
        v.push_back(Sym3{{t[0], t[1], t[2], t[3], t[5], t[4]}});
      }
    }
  }
  return out;
}

}  // namespace tessella::io::detail
