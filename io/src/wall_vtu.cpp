// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/io/wall_vtu.hpp"

#include <filesystem>
#include <typeindex>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkIdList.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkTypeInt32Array.h>
#include <vtkUnstructuredGrid.h>

#include "tessella/tissue/errors.hpp"
#include "vtu_file.hpp"
#include "wall_array_data.hpp"

namespace tessella::io {

std::string besideSnapshotPath(const std::string& snapshot_path, const std::string& tag) {
  std::filesystem::path path(snapshot_path);
  return (path.parent_path() / (path.stem().string() + "." + tag + ".vtu")).string();
}

void writeWallsVtu(const Tissue& tissue, const std::string& path, const WallArrays& arrays,
                   const VtuOptions& options) {
  const std::size_t walls = tissue.numWalls();
  auto check = [&](const std::string& name, std::size_t size) {
    if (name.empty() || name == "wall_id")
      throw InputError("walls file '" + path + "': array name '" + name + "' is empty or reserved");
    if (size != walls)
      throw InputError("walls file '" + path + "': array '" + name + "' has " + std::to_string(size) +
                       " values for " + std::to_string(walls) + " walls");
  };
  for (const auto& [name, values] : arrays.scalars) check(name, values.size());
  for (const auto& [name, values] : arrays.vectors) check(name, values.size());
  for (const auto& [name, values] : arrays.tensors) check(name, values.size());
  // Points: the live vertices in slot order.
  std::vector<vtkIdType> point(tissue.topology().slots(0), -1);
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  for (VertexId v : tissue.vertices()) {
    point[v.index()] = points->GetNumberOfPoints();
    const Vec3& x = tissue.position(v);
    points->InsertNextPoint(x.x(), x.y(), x.z());
  }
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(points);
  grid->Allocate(static_cast<vtkIdType>(walls));
  auto ids = vtkSmartPointer<vtkTypeInt32Array>::New();
  ids->SetName("wall_id");
  auto list = vtkSmartPointer<vtkIdList>::New();
  for (WallId w : tissue.walls()) {
    list->Reset();
    if (tissue.dim() == 2) {
      for (VertexId v : tissue.topology().edgeVertices(EdgeId(w.index()))) list->InsertNextId(point[v.index()]);
      grid->InsertNextCell(VTK_LINE, list);
    } else {
      for (VertexId v : tissue.topology().faceVertices(FaceId(w.index()))) list->InsertNextId(point[v.index()]);
      grid->InsertNextCell(VTK_POLYGON, list);
    }
    ids->InsertNextValue(static_cast<int>(w.index()));
  }
  grid->GetCellData()->AddArray(ids);
  std::vector<std::size_t> rows(walls);
  for (std::size_t i = 0; i < walls; ++i) rows[i] = i;
  detail::addWallArrays(grid->GetCellData(), arrays, rows);
  detail::writeGridFile(grid, path, options);
}

namespace {

// The columns of `store` named in `names` (double, Vec3 or Sym3), one value per id of `ids` in order.
template <typename Ids>
WallArrays propertyArrays(const PropertyStore& store, const Ids& ids, const std::vector<std::string>& names,
                          const std::string& source, const std::string& kind) {
  WallArrays out;
  for (const std::string& name : names) {
    const PropertyColumnBase* column = nullptr;
    for (std::size_t k = 0; k < store.numColumns() && !column; ++k)
      if (store.column(k).name() == name) column = &store.column(k);
    if (!column) continue;
    const std::type_index type = column->type();
    if (type == typeid(Vec3)) {
      auto& v = out.vectors[name];
      const auto& c = store.get<Vec3>(name);
      for (auto id : ids) v.push_back(c[id]);
    } else if (type == typeid(Sym3)) {
      auto& v = out.tensors[name];
      const auto& c = store.get<Sym3>(name);
      for (auto id : ids) v.push_back(c[id]);
    } else if (type == typeid(double)) {
      auto& v = out.scalars[name];
      const auto& c = store.get<double>(name);
      for (auto id : ids) v.push_back(c[id]);
    } else {
      throw InputError(source + ": the " + kind + " property '" + name +
                       "' is not a number, a vector or a symmetric tensor per " + kind);
    }
  }
  return out;
}

}  // namespace

WallArrays wallPropertyArrays(const Tissue& tissue, const std::vector<std::string>& names) {
  return propertyArrays(tissue.wallProperties(), tissue.walls(), names, "walls file", "wall");
}

WallArrays cellPropertyArrays(const Tissue& tissue, const std::vector<std::string>& names) {
  return propertyArrays(tissue.cellProperties(), tissue.cells(), names, "mesh series", "cell");
}

WallsFile readWallsVtu(const std::string& path) {
  vtkSmartPointer<vtkUnstructuredGrid> grid = detail::readGridFile(path);
  detail::checkCellArrays(grid, path);
  WallsFile out;
  out.points = static_cast<std::size_t>(grid->GetNumberOfPoints());
  vtkCellData* data = grid->GetCellData();
  auto* ids = data->GetArray("wall_id");
  if (!ids || ids->GetNumberOfComponents() != 1 || ids->GetNumberOfTuples() != grid->GetNumberOfCells())
    throw InputError("'" + path + "': no wall_id array with one value per cell; not a walls file");
  auto points = vtkSmartPointer<vtkIdList>::New();
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
    out.wall_id.push_back(static_cast<int>(ids->GetTuple1(c)));
    grid->GetCellPoints(c, points);
    out.points_per_wall.push_back(static_cast<int>(points->GetNumberOfIds()));
  }
  out.arrays = detail::readWallArrays(data, grid->GetNumberOfCells(), "wall_id", path, "walls");
  return out;
}

}  // namespace tessella::io
