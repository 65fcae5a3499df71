// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/io/field_state.hpp"

#include <zlib.h>

#include <filesystem>
#include <fstream>
#include <vector>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkTypeInt32Array.h>
#include <vtkTypeInt64Array.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>

#include "snapshot_checksum.hpp"
#include "tessella/io/mesh_vtu.hpp"
#include "tessella/tissue/errors.hpp"
#include "vtu_file.hpp"

namespace tessella::io {

namespace {

constexpr int kFieldStateVersion = 1;
constexpr const char* kVersionArray = "tessella_field_state_version";
constexpr const char* kDimArray = "tessella_mesh_dim";
constexpr const char* kFieldsArray = "tessella_fields";
constexpr const char* kCellArray = "cell_id";
constexpr const char* kVertexArray = "vertex_id";
constexpr const char* kFacetsArray = "wall_facets";
constexpr const char* kFacetWallArray = "facet_wall";
constexpr const char* kBoundaryArray = "facet_on_boundary";
constexpr const char* kLineageArray = "cell_lineage";

struct Source {
  std::string path;
  [[noreturn]] void fail(const std::string& problem) const { throw InputError("'" + path + "': " + problem); }
};

template <typename ArrayT, typename T>
vtkSmartPointer<ArrayT> arrayOf(const char* name, const T* values, vtkIdType tuples, int components = 1) {
  auto array = vtkSmartPointer<ArrayT>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(tuples);
  for (vtkIdType i = 0; i < tuples * components; ++i) array->SetValue(i, values[i]);
  return array;
}

// A one-component (or `components`) array of the grid's data, `tuples` long.
vtkDataArray* required(vtkFieldData* data, const char* where, const char* name, vtkIdType tuples, int components,
                       const Source& src) {
  vtkDataArray* array = data->GetArray(name);
  if (!array) src.fail(std::string(where) + " array '" + name + "' is missing (not a field state file?)");
  if (array->GetNumberOfTuples() != tuples || array->GetNumberOfComponents() != components)
    src.fail(std::string(where) + " array '" + name + "' has " + std::to_string(array->GetNumberOfTuples()) + " x " +
             std::to_string(array->GetNumberOfComponents()) + " values, expected " + std::to_string(tuples) + " x " +
             std::to_string(components));
  return array;
}

}  // namespace

std::string fieldStatePath(const std::string& snapshot_path) {
  std::filesystem::path path(snapshot_path);
  return (path.parent_path() / (path.stem().string() + ".fields.vtu")).string();
}

std::uint32_t fileChecksum(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot read '" + path + "'");
  uLong crc = crc32_z(0L, Z_NULL, 0);
  std::vector<char> buffer(1 << 16);
  while (in) {
    in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    const auto n = static_cast<std::size_t>(in.gcount());
    if (n > 0) crc = crc32_z(crc, reinterpret_cast<const Bytef*>(buffer.data()), n);
  }
  if (in.bad()) throw InputError("cannot read '" + path + "'");
  return static_cast<std::uint32_t>(crc);
}

std::uint32_t writeFieldState(const FieldState& state, const std::string& path, const VtuOptions& options) {
  const mesh::FeMesh& m = state.mesh;
  MeshFields fields;
  fields.point = state.fields;
  try {
    checkFeMesh(m, fields);
  } catch (const InputError& e) {
    throw InputError("cannot write '" + path + "': " + e.what());
  }
  if (m.node_vertex.size() != m.nodes.rows() || m.facet_on_boundary.size() != m.wall_facets.rows())
    throw InputError("cannot write '" + path + "': FeMesh::node_vertex and facet_on_boundary must have one entry "
                     "per node and per wall facet");
  for (Eigen::Index e = 0; e < m.element_cell.size(); ++e)
    if (m.element_cell[e] < 0 || static_cast<std::size_t>(m.element_cell[e]) >= state.cell_lineage.size())
      throw InputError("cannot write '" + path + "': element " + std::to_string(e) + " lies in cell " +
                       std::to_string(m.element_cell[e]) + ", which cell_lineage (" +
                       std::to_string(state.cell_lineage.size()) + " entries) does not list");

  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetData(arrayOf<vtkDoubleArray>("Points", m.nodes.data(), m.nodes.rows(), 3));
  grid->SetPoints(points);
  const int width = m.dim + 1;
  std::vector<vtkIdType> ids(static_cast<std::size_t>(width));
  grid->Allocate(m.elements.rows());
  for (Eigen::Index e = 0; e < m.elements.rows(); ++e) {
    for (int k = 0; k < width; ++k) ids[static_cast<std::size_t>(k)] = m.elements(e, k);
    grid->InsertNextCell(m.dim == 2 ? VTK_TRIANGLE : VTK_TETRA, width, ids.data());
  }
  grid->GetCellData()->AddArray(arrayOf<vtkTypeInt32Array>(kCellArray, m.element_cell.data(), m.element_cell.size()));
  grid->GetPointData()->AddArray(arrayOf<vtkTypeInt32Array>(kVertexArray, m.node_vertex.data(), m.node_vertex.size()));
  auto names = vtkSmartPointer<vtkStringArray>::New();
  names->SetName(kFieldsArray);
  for (const auto& [name, values] : state.fields) {
    if (name == kVertexArray) throw InputError("cannot write '" + path + "': a field may not be named " + name);
    names->InsertNextValue(name);
    grid->GetPointData()->AddArray(arrayOf<vtkDoubleArray>(name.c_str(), values.data(), values.size()));
  }
  vtkFieldData* field = grid->GetFieldData();
  const int version = kFieldStateVersion;
  field->AddArray(arrayOf<vtkIntArray>(kVersionArray, &version, 1));
  field->AddArray(arrayOf<vtkIntArray>(kDimArray, &m.dim, 1));
  field->AddArray(names);
  field->AddArray(arrayOf<vtkTypeInt32Array>(kFacetsArray, m.wall_facets.data(), m.wall_facets.rows(), m.dim));
  field->AddArray(arrayOf<vtkTypeInt32Array>(kFacetWallArray, m.facet_wall.data(), m.facet_wall.size()));
  std::vector<unsigned char> boundary(static_cast<std::size_t>(m.facet_on_boundary.size()));
  for (std::size_t f = 0; f < boundary.size(); ++f) boundary[f] = m.facet_on_boundary[static_cast<Eigen::Index>(f)];
  field->AddArray(arrayOf<vtkUnsignedCharArray>(kBoundaryArray, boundary.data(), m.facet_on_boundary.size()));
  field->AddArray(arrayOf<vtkTypeInt64Array>(kLineageArray, state.cell_lineage.data(),
                                             static_cast<vtkIdType>(state.cell_lineage.size())));
  detail::addChecksums(grid);
  detail::writeGridFile(grid, path, options);
  return fileChecksum(path);
}

FieldState readFieldState(const std::string& path) {
  const Source src{path};
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) src.fail("no such file");
  // Checked in the worker that parses the file, which then hands the grid over.
  vtkSmartPointer<vtkUnstructuredGrid> grid = detail::readGridFile(path, [&](vtkUnstructuredGrid* parsed) {
    detail::verifyChecksums(parsed, path);
    detail::checkCellArrays(parsed, path);
  });
  vtkFieldData* field = grid->GetFieldData();
  if (required(field, "field", kVersionArray, 1, 1, src)->GetComponent(0, 0) != kFieldStateVersion)
    src.fail(std::string(kVersionArray) + " is not " + std::to_string(kFieldStateVersion));
  FieldState state;
  mesh::FeMesh& m = state.mesh;
  const double dim = required(field, "field", kDimArray, 1, 1, src)->GetComponent(0, 0);
  if (dim != 2 && dim != 3) src.fail(std::string(kDimArray) + " = " + std::to_string(dim) + " (expected 2 or 3)");
  m.dim = static_cast<int>(dim);

  const vtkIdType num_nodes = grid->GetNumberOfPoints();
  m.nodes.resize(num_nodes, 3);
  for (vtkIdType n = 0; n < num_nodes; ++n) {
    double p[3];
    grid->GetPoint(n, p);
    m.nodes.row(n) << p[0], p[1], p[2];
  }
  const vtkIdType num_elements = grid->GetNumberOfCells();
  const int width = m.dim + 1;
  m.elements.resize(num_elements, width);
  vtkCellArray* cells = grid->GetCells();
  for (vtkIdType e = 0; e < num_elements; ++e) {
    if (grid->GetCellType(e) != (m.dim == 2 ? VTK_TRIANGLE : VTK_TETRA))
      src.fail("element " + std::to_string(e) + " has VTK cell type " + std::to_string(grid->GetCellType(e)) +
               ", not the " + (m.dim == 2 ? "triangle" : "tetrahedron") + " of a mesh of dimension " +
               std::to_string(m.dim));
    vtkIdType npts = 0;
    const vtkIdType* pts = nullptr;
    cells->GetCellAtId(e, npts, pts);
    if (npts != width) src.fail("element " + std::to_string(e) + " has " + std::to_string(npts) + " nodes");
    for (int k = 0; k < width; ++k) m.elements(e, k) = static_cast<int>(pts[k]);
  }
  auto ints = [](vtkDataArray* array, auto& out) {  // row by row (RowMatrix and vectors alike)
    const int nc = array->GetNumberOfComponents();
    for (vtkIdType t = 0; t < array->GetNumberOfTuples(); ++t)
      for (int k = 0; k < nc; ++k) out.data()[t * nc + k] = static_cast<int>(array->GetComponent(t, k));
  };
  m.element_cell.resize(num_elements);
  ints(required(grid->GetCellData(), "cell", kCellArray, num_elements, 1, src), m.element_cell);
  m.node_vertex.resize(num_nodes);
  ints(required(grid->GetPointData(), "point", kVertexArray, num_nodes, 1, src), m.node_vertex);
  vtkDataArray* facet_wall = field->GetArray(kFacetWallArray);
  if (!facet_wall) src.fail(std::string("field array '") + kFacetWallArray + "' is missing (not a field state file?)");
  const vtkIdType num_facets = facet_wall->GetNumberOfTuples();
  m.facet_wall.resize(num_facets);
  ints(required(field, "field", kFacetWallArray, num_facets, 1, src), m.facet_wall);
  m.wall_facets.resize(num_facets, m.dim);
  ints(required(field, "field", kFacetsArray, num_facets, m.dim, src), m.wall_facets);
  vtkDataArray* boundary = required(field, "field", kBoundaryArray, num_facets, 1, src);
  m.facet_on_boundary.resize(num_facets);
  for (vtkIdType f = 0; f < num_facets; ++f) m.facet_on_boundary[f] = boundary->GetComponent(f, 0) != 0;
  vtkDataArray* lineage = field->GetArray(kLineageArray);
  if (!lineage || lineage->GetNumberOfComponents() != 1)
    src.fail(std::string("field array '") + kLineageArray + "' is missing or has more than one component");
  state.cell_lineage.resize(static_cast<std::size_t>(lineage->GetNumberOfTuples()));
  for (std::size_t c = 0; c < state.cell_lineage.size(); ++c)
    state.cell_lineage[c] = static_cast<std::int64_t>(lineage->GetComponent(static_cast<vtkIdType>(c), 0));

  auto* names = vtkStringArray::SafeDownCast(field->GetAbstractArray(kFieldsArray));
  if (!names) src.fail(std::string("field data '") + kFieldsArray + "' is missing or not a string array");
  for (vtkIdType i = 0; i < names->GetNumberOfValues(); ++i) {
    const std::string name = names->GetValue(i);
    vtkDataArray* values = required(grid->GetPointData(), "point", name.c_str(), num_nodes, 1, src);
    Eigen::VectorXd v(num_nodes);
    for (vtkIdType n = 0; n < num_nodes; ++n) v[n] = values->GetComponent(n, 0);
    if (!state.fields.emplace(name, std::move(v)).second) src.fail("field '" + name + "' is listed twice");
  }
  try {
    checkFeMesh(m);
  } catch (const InputError& e) {
    src.fail(std::string("the mesh is inconsistent: ") + e.what());
  }
  for (Eigen::Index e = 0; e < m.element_cell.size(); ++e)
    if (m.element_cell[e] < 0 || static_cast<std::size_t>(m.element_cell[e]) >= state.cell_lineage.size())
      src.fail("element " + std::to_string(e) + " lies in cell " + std::to_string(m.element_cell[e]) +
               ", which cell_lineage (" + std::to_string(state.cell_lineage.size()) + " entries) does not list");
  return state;
}

}  // namespace tessella::io
