// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// FeMesh -> .vtu. The mesh's Eigen arrays are handed to VTK without copies
// where their layout allows (node coordinates, connectivity, cell ids).

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkTypeInt32Array.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>

#include "tessella/io/mesh_vtu.hpp"
#include "tessella/tissue/errors.hpp"
#include "vtu_file.hpp"
#include "wall_array_data.hpp"

namespace tessella::io {

namespace {

std::string sizes(Eigen::Index got, Eigen::Index expected) {
  return "has " + std::to_string(got) + " entries, expected " + std::to_string(expected);
}

void checkConnectivity(const mesh::RowMatrix<int>& rows, int width, int num_nodes, const char* what) {
  if (rows.rows() > 0 && rows.cols() != width)
    throw InputError(std::string("FeMesh::") + what + " has rows of " + std::to_string(rows.cols()) +
                     " node indices, expected " + std::to_string(width));
  for (Eigen::Index r = 0; r < rows.rows(); ++r)
    for (Eigen::Index c = 0; c < rows.cols(); ++c)
      if (rows(r, c) < 0 || rows(r, c) >= num_nodes)
        throw InputError(std::string("FeMesh::") + what + " row " + std::to_string(r) + " refers to node " +
                         std::to_string(rows(r, c)) + " but the mesh has " + std::to_string(num_nodes) + " nodes");
}

void checkFields(const std::map<std::string, Eigen::VectorXd>& fields, Eigen::Index expected, const char* kind) {
  for (const auto& [name, values] : fields) {
    if (name.empty()) throw InputError(std::string(kind) + " field with an empty name");
    if (values.size() != expected)
      throw InputError(std::string(kind) + " field '" + name + "' " + sizes(values.size(), expected));
  }
}

// The row of `arrays` of every mesh item (wall facet or element) whose tissue wall or cell is owner(i)
// (empty without arrays); `reserved` lists the item file's own array names.
template <typename Owner>
std::vector<std::size_t> rowsOf(const WallArrays& arrays, const std::vector<int>& ids, const Owner& owner,
                                const std::vector<std::string>& reserved,
                                const std::map<std::string, Eigen::VectorXd>& fields, const std::string& kind,
                                const std::string& item) {
  if (arrays.scalars.empty() && arrays.vectors.empty() && arrays.tensors.empty()) return {};
  const std::size_t n = ids.size();
  const std::string list = "MeshFields::" + kind + "_ids";
  auto check = [&](const std::string& name, std::size_t size) {
    if (name.empty() || std::find(reserved.begin(), reserved.end(), name) != reserved.end() || fields.count(name))
      throw InputError(kind + " array name '" + name + "' is empty or taken by the " + item + "s' own arrays");
    if (size != n)
      throw InputError(kind + " array '" + name + "' has " + std::to_string(size) + " values for " +
                       std::to_string(n) + " " + kind + "s (" + list + ")");
  };
  for (const auto& [name, values] : arrays.scalars) check(name, values.size());
  for (const auto& [name, values] : arrays.vectors) check(name, values.size());
  for (const auto& [name, values] : arrays.tensors) check(name, values.size());
  std::map<int, std::size_t> row_of;
  for (std::size_t i = 0; i < n; ++i)
    if (!row_of.emplace(ids[i], i).second)
      throw InputError(list + " lists " + kind + " " + std::to_string(ids[i]) + " twice");
  std::vector<std::size_t> rows(static_cast<std::size_t>(owner.size()));
  for (Eigen::Index f = 0; f < owner.size(); ++f) {
    const auto it = row_of.find(owner(f));
    if (it == row_of.end())
      throw InputError(item + " " + std::to_string(f) + " lies on " + kind + " " + std::to_string(owner(f)) +
                       ", which has no values in the " + kind + " arrays (" + list + ")");
    rows[static_cast<std::size_t>(f)] = it->second;
  }
  return rows;
}

// The row of fields.walls of every wall facet, of fields.cells of every element.
std::vector<std::size_t> facetWallRows(const mesh::FeMesh& mesh, const MeshFields& fields) {
  return rowsOf(fields.walls, fields.wall_ids, mesh.facet_wall, {"wall_id", "on_boundary"}, fields.facet, "wall",
                "wall facet");
}
std::vector<std::size_t> elementCellRows(const mesh::FeMesh& mesh, const MeshFields& fields) {
  return rowsOf(fields.cells, fields.cell_ids, mesh.element_cell, {"cell_id"}, fields.element, "cell", "element");
}

vtkSmartPointer<vtkPoints> nodesOf(const mesh::FeMesh& mesh) {
  auto coords = vtkSmartPointer<vtkDoubleArray>::New();
  coords->SetNumberOfComponents(3);
  if (mesh.numNodes() > 0)  // RowMatrix: xyz of each node back to back
    coords->SetArray(const_cast<double*>(mesh.nodes.data()), 3 * mesh.nodes.rows(), 1);
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetData(coords);
  return points;
}

template <typename Vector>
vtkSmartPointer<vtkTypeInt32Array> int32View(const char* name, const Vector& values) {
  auto array = vtkSmartPointer<vtkTypeInt32Array>::New();
  array->SetName(name);
  if (values.size() > 0) array->SetArray(const_cast<int*>(values.data()), values.size(), 1);
  return array;
}

void addFields(vtkDataSetAttributes* data, const std::map<std::string, Eigen::VectorXd>& fields) {
  for (const auto& [name, values] : fields) {
    auto array = vtkSmartPointer<vtkDoubleArray>::New();
    array->SetName(name.c_str());
    if (values.size() > 0) array->SetArray(const_cast<double*>(values.data()), values.size(), 1);
    data->AddArray(array);
  }
}

// Fixed-size cells straight from a row-major index matrix.
void setUniformCells(vtkUnstructuredGrid* grid, const mesh::RowMatrix<int>& rows, int width, unsigned char type) {
  auto connectivity = vtkSmartPointer<vtkTypeInt32Array>::New();
  if (rows.rows() > 0) connectivity->SetArray(const_cast<int*>(rows.data()), rows.size(), 1);
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(static_cast<vtkIdType>(width), connectivity);
  auto types = vtkSmartPointer<vtkUnsignedCharArray>::New();
  unsigned char* t = types->WritePointer(0, rows.rows());
  std::fill(t, t + rows.rows(), type);
  grid->SetCells(types, cells);
}

vtkSmartPointer<vtkUnstructuredGrid> gridWithNodes(const mesh::FeMesh& mesh, const MeshFields& fields) {
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(nodesOf(mesh));
  if (mesh.node_vertex.size() > 0) grid->GetPointData()->AddArray(int32View("vertex_id", mesh.node_vertex));
  addFields(grid->GetPointData(), fields.point);
  return grid;
}

}  // namespace

void checkFeMesh(const mesh::FeMesh& mesh, const MeshFields& fields) {
  if (mesh.dim != 2 && mesh.dim != 3) throw InputError("FeMesh::dim = " + std::to_string(mesh.dim) + " (expected 2 or 3)");
  if (mesh.nodes.rows() > 0 && mesh.nodes.cols() != 3)
    throw InputError("FeMesh::nodes has " + std::to_string(mesh.nodes.cols()) + " columns, expected 3");
  checkConnectivity(mesh.elements, mesh.dim + 1, mesh.numNodes(), "elements");
  checkConnectivity(mesh.wall_facets, mesh.dim, mesh.numNodes(), "wall_facets");
  if (mesh.element_cell.size() != mesh.elements.rows())
    throw InputError("FeMesh::element_cell " + sizes(mesh.element_cell.size(), mesh.elements.rows()));
  if (mesh.facet_wall.size() != mesh.wall_facets.rows())
    throw InputError("FeMesh::facet_wall " + sizes(mesh.facet_wall.size(), mesh.wall_facets.rows()));
  if (mesh.facet_on_boundary.size() != 0 && mesh.facet_on_boundary.size() != mesh.wall_facets.rows())
    throw InputError("FeMesh::facet_on_boundary " + sizes(mesh.facet_on_boundary.size(), mesh.wall_facets.rows()));
  if (mesh.node_vertex.size() != 0 && mesh.node_vertex.size() != mesh.nodes.rows())
    throw InputError("FeMesh::node_vertex " + sizes(mesh.node_vertex.size(), mesh.nodes.rows()));
  checkFields(fields.point, mesh.nodes.rows(), "point");
  checkFields(fields.element, mesh.elements.rows(), "element");
  checkFields(fields.facet, mesh.wall_facets.rows(), "facet");
  facetWallRows(mesh, fields);
  elementCellRows(mesh, fields);
}

void writeFeMeshVtu(const mesh::FeMesh& mesh, const std::string& path, const MeshFields& fields, const VtuOptions& options) {
  checkFeMesh(mesh, fields);
  auto grid = gridWithNodes(mesh, fields);
  setUniformCells(grid, mesh.elements, mesh.dim + 1, mesh.dim == 2 ? VTK_TRIANGLE : VTK_TETRA);
  grid->GetCellData()->AddArray(int32View("cell_id", mesh.element_cell));
  addFields(grid->GetCellData(), fields.element);
  detail::addWallArrays(grid->GetCellData(), fields.cells, elementCellRows(mesh, fields));
  detail::writeGridFile(grid, path, options);
}

FeMeshElementsFile readFeMeshElementsVtu(const std::string& path) {
  vtkSmartPointer<vtkUnstructuredGrid> grid = detail::readGridFile(path);
  detail::checkCellArrays(grid, path);
  vtkCellData* data = grid->GetCellData();
  auto* ids = data->GetArray("cell_id");
  if (!ids || ids->GetNumberOfComponents() != 1 || ids->GetNumberOfTuples() != grid->GetNumberOfCells())
    throw InputError("'" + path + "': no cell_id array with one value per cell; not a mesh elements file");
  FeMeshElementsFile out;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) out.cell_id.push_back(static_cast<int>(ids->GetTuple1(c)));
  out.arrays = detail::readWallArrays(data, grid->GetNumberOfCells(), "cell_id", path, "elements");
  return out;
}

void writeWallFacetsVtu(const mesh::FeMesh& mesh, const std::string& path, const MeshFields& fields,
                        const VtuOptions& options) {
  checkFeMesh(mesh, fields);
  auto grid = gridWithNodes(mesh, fields);
  setUniformCells(grid, mesh.wall_facets, mesh.dim, mesh.dim == 2 ? VTK_LINE : VTK_TRIANGLE);
  grid->GetCellData()->AddArray(int32View("wall_id", mesh.facet_wall));
  if (mesh.facet_on_boundary.size() > 0) {
    auto boundary = vtkSmartPointer<vtkUnsignedCharArray>::New();
    boundary->SetName("on_boundary");
    unsigned char* b = boundary->WritePointer(0, mesh.facet_on_boundary.size());
    for (Eigen::Index i = 0; i < mesh.facet_on_boundary.size(); ++i) b[i] = mesh.facet_on_boundary[i] ? 1 : 0;
    grid->GetCellData()->AddArray(boundary);
  }
  addFields(grid->GetCellData(), fields.facet);
  detail::addWallArrays(grid->GetCellData(), fields.walls, facetWallRows(mesh, fields));
  detail::writeGridFile(grid, path, options);
}

}  // namespace tessella::io
