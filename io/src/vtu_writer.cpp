// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// writeTissueVtu: a tissue as a vtkUnstructuredGrid, built straight into
// preallocated VTK buffers (no per-item InsertNext), then written by VTK.

#include "tessella/io/vtu.hpp"

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkTypeInt64Array.h>
#include <vtkTypeUInt32Array.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>

#include "finite_values.hpp"
#include "vtu_property_arrays.hpp"
#include "snapshot_checksum.hpp"
#include "snapshot_format.hpp"
#include "tessella/tissue/geometry.hpp"
#include "vtu_file.hpp"

namespace tessella::io {

namespace {

static_assert(sizeof(Vec3) == 3 * sizeof(double), "positions are read as packed xyz triples");

using detail::RowSelection;

vtkSmartPointer<vtkPoints> pointsOf(const Tissue& t, const RowSelection& vertex_rows) {
  auto coords = vtkSmartPointer<vtkDoubleArray>::New();
  coords->SetNumberOfComponents(3);
  const auto n = static_cast<vtkIdType>(vertex_rows.count);
  const double* all = t.positions().empty() ? nullptr : t.positions().front().data();
  if (vertex_rows.identity && n > 0) {
    coords->SetArray(const_cast<double*>(all), 3 * n, 1);  // zero copy; save = 1: VTK must not free it
  } else {
    double* out = coords->WritePointer(0, 3 * n);
    for (vtkIdType r = 0; r < n; ++r)
      std::memcpy(out + 3 * r, all + 3 * vertex_rows.slot(static_cast<std::size_t>(r)), 3 * sizeof(double));
  }
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetData(coords);
  return points;
}

// Output point id of every vertex slot (identity when no vertex was removed).
std::vector<vtkIdType> pointIdsOf(const Tissue& t, const RowSelection& vertex_rows) {
  if (vertex_rows.identity) return {};
  std::vector<vtkIdType> ids(t.slots(0), -1);
  for (std::size_t r = 0; r < vertex_rows.count; ++r) ids[vertex_rows.slots[r]] = static_cast<vtkIdType>(r);
  return ids;
}

struct PointIdMap {
  const std::vector<vtkIdType>& ids;
  vtkIdType operator()(VertexId v) const { return ids.empty() ? static_cast<vtkIdType>(v.index()) : ids[v.index()]; }
};

vtkSmartPointer<vtkCellArray> cellArray(vtkIdTypeArray* offsets, vtkIdTypeArray* connectivity) {
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(offsets, connectivity);
  return cells;
}

vtkSmartPointer<vtkUnsignedCharArray> uniformTypes(std::size_t n, unsigned char type) {
  auto types = vtkSmartPointer<vtkUnsignedCharArray>::New();
  unsigned char* out = types->WritePointer(0, static_cast<vtkIdType>(n));
  std::fill(out, out + n, type);
  return types;
}

// 2D: one polygon per cell, its vertex loop as stored (all loops run the same way).
void setPolygonCells(vtkUnstructuredGrid* grid, const Tissue& t, const RowSelection& cells,
                     const PointIdMap& point_id) {
  const CellComplex& topo = t.topology();
  const auto n = static_cast<vtkIdType>(cells.count);
  auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
  vtkIdType* off = offsets->WritePointer(0, n + 1);
  off[0] = 0;
  for (vtkIdType r = 0; r < n; ++r)
    off[r + 1] = off[r] + static_cast<vtkIdType>(topo.faceVertices(FaceId(cells.slot(static_cast<std::size_t>(r)))).size());
  auto connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
  vtkIdType* conn = connectivity->WritePointer(0, off[n]);
#pragma omp parallel for schedule(static)
  for (vtkIdType r = 0; r < n; ++r) {
    vtkIdType k = off[r];
    for (VertexId v : topo.faceVertices(FaceId(cells.slot(static_cast<std::size_t>(r))))) conn[k++] = point_id(v);
  }
  grid->SetCells(uniformTypes(cells.count, VTK_POLYGON), cellArray(offsets, connectivity));
}

// 3D: one polyhedron per cell. Its point list is its distinct vertices, and
// its face stream lists every wall loop oriented outward (reversed where the
// wall's own normal points into the cell), as VTK expects.
void setPolyhedronCells(vtkUnstructuredGrid* grid, const Tissue& t, const RowSelection& cells,
                        const PointIdMap& point_id) {
  const CellComplex& topo = t.topology();
  const auto n = static_cast<vtkIdType>(cells.count);
  auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
  vtkIdType* off = offsets->WritePointer(0, n + 1);
  auto connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
  auto face_locations = vtkSmartPointer<vtkIdTypeArray>::New();
  vtkIdType* loc = face_locations->WritePointer(0, n);
  auto faces = vtkSmartPointer<vtkIdTypeArray>::New();

  // Sizes first, so that both streams are allocated once.
  vtkIdType stream_size = 0;
  for (vtkIdType r = 0; r < n; ++r) {
    loc[r] = stream_size;
    const auto cell_faces = topo.volumeFaces(VolumeId(cells.slot(static_cast<std::size_t>(r))));
    stream_size += 1 + static_cast<vtkIdType>(cell_faces.size());
    for (OrientedFace of : cell_faces) stream_size += static_cast<vtkIdType>(topo.faceVertices(of.handle()).size());
  }
  vtkIdType* stream = faces->WritePointer(0, stream_size);

  std::vector<vtkIdType> distinct;
  std::vector<vtkIdType> conn;
  conn.reserve(static_cast<std::size_t>(stream_size) / 2);
  off[0] = 0;
  for (vtkIdType r = 0; r < n; ++r) {
    const auto cell_faces = topo.volumeFaces(VolumeId(cells.slot(static_cast<std::size_t>(r))));
    vtkIdType k = loc[r];
    stream[k++] = static_cast<vtkIdType>(cell_faces.size());
    distinct.clear();
    for (OrientedFace of : cell_faces) {
      const auto loop = topo.faceVertices(of.handle());
      stream[k++] = static_cast<vtkIdType>(loop.size());
      if (of.reversed())
        for (auto it = loop.rbegin(); it != loop.rend(); ++it) stream[k++] = point_id(*it);
      else
        for (VertexId v : loop) stream[k++] = point_id(v);
      for (VertexId v : loop) distinct.push_back(point_id(v));
    }
    std::sort(distinct.begin(), distinct.end());
    distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
    conn.insert(conn.end(), distinct.begin(), distinct.end());
    off[r + 1] = static_cast<vtkIdType>(conn.size());
  }
  vtkIdType* c = connectivity->WritePointer(0, static_cast<vtkIdType>(conn.size()));
  std::copy(conn.begin(), conn.end(), c);
  grid->SetCells(uniformTypes(cells.count, VTK_POLYHEDRON), cellArray(offsets, connectivity), face_locations,
                 faces);
}

vtkSmartPointer<vtkDoubleArray> cellMeasures(const Tissue& t, const RowSelection& cells, const char* name,
                                             GeometryCache& geometry) {
  geometry.require(t, kCellMeasures);
  const std::vector<double>& measure = t.dim() == 2 ? geometry.face_area : geometry.volume;
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name);
  double* out = array->WritePointer(0, static_cast<vtkIdType>(cells.count));
  for (std::size_t r = 0; r < cells.count; ++r) out[r] = measure[cells.slot(r)];
  return array;
}

// Every writable column as an array; returns the names written.
/// Adds the writable columns as arrays; lists their names, policies and
/// defaults in the field data, so that a restart divides them as the run did.
void addProperties(vtkDataSetAttributes* data, vtkFieldData* field, const PropertyStore& store,
                   const RowSelection& rows, const char* list_name, const char* policies_name,
                   const char* default_prefix) {
  auto names = vtkSmartPointer<vtkStringArray>::New();
  names->SetName(list_name);
  auto policies = vtkSmartPointer<vtkStringArray>::New();
  policies->SetName(policies_name);
  for (std::size_t i = 0; i < store.numColumns(); ++i) {
    const PropertyColumnBase& column = store.column(i);
    if (auto array = detail::columnToArray(column, rows)) {
      data->AddArray(array);
      names->InsertNextValue(column.name());
      policies->InsertNextValue(divisionPolicyName(column.policy()));
      field->AddArray(detail::defaultToArray(column, default_prefix + column.name()));
    }
  }
  field->AddArray(names);
  field->AddArray(policies);
}

template <typename ArrayT, typename T>
vtkSmartPointer<ArrayT> singleValue(const char* name, T value) {
  auto array = vtkSmartPointer<ArrayT>::New();
  array->SetName(name);
  array->InsertNextValue(value);
  return array;
}

vtkSmartPointer<vtkStringArray> runStateArray(const RunState& state, const std::string& path) {
  auto array = vtkSmartPointer<vtkStringArray>::New();
  array->SetName(detail::kRunStateArray);
  for (const auto& [key, value] : state) {
    if (key.empty() || key.find('=') != std::string::npos)
      throw InputError("cannot write '" + path + "': run state key '" + key + "' is empty or holds '='");
    array->InsertNextValue(key + "=" + value);
  }
  return array;
}

// The complex's numbering and list orders, which the cells alone do not fix
// (snapshot_format.hpp).
void addTopologyLayout(vtkFieldData* field, const CellComplex& topology) {
  const ComplexLayout layout = topology.layout();
  detail::forEachLayoutList(layout, [&](const char* list, const std::vector<Index>& items) {
    auto array = vtkSmartPointer<vtkTypeUInt32Array>::New();
    array->SetName((std::string(detail::kTopologyPrefix) + list).c_str());
    std::copy(items.begin(), items.end(), array->WritePointer(0, static_cast<vtkIdType>(items.size())));
    field->AddArray(array);
  });
}

}  // namespace

void writeTissueVtu(const Tissue& tissue, const std::string& path, const VtuOptions& options,
                    const RunState& state, GeometryCache* geometry) {
  const CellComplex& topo = tissue.topology();
  const RowSelection vertex_rows = detail::liveRows(topo.aliveFlags(0), tissue.numVertices());
  const RowSelection cell_rows = detail::liveRows(topo.aliveFlags(tissue.dim()), tissue.numCells());
  detail::requireFinitePositions(tissue.positions(), vertex_rows, path);  // nothing is written otherwise
  detail::requireFiniteProperties(tissue, vertex_rows, cell_rows, path);
  const std::vector<vtkIdType> point_ids = pointIdsOf(tissue, vertex_rows);

  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(pointsOf(tissue, vertex_rows));
  if (tissue.dim() == 2)
    setPolygonCells(grid, tissue, cell_rows, PointIdMap{point_ids});
  else
    setPolyhedronCells(grid, tissue, cell_rows, PointIdMap{point_ids});

  vtkFieldData* field = grid->GetFieldData();
  addProperties(grid->GetCellData(), field, tissue.cellProperties(), cell_rows, detail::kCellPropertiesArray,
                detail::kCellPoliciesArray, detail::kCellDefaultPrefix);
  addProperties(grid->GetPointData(), field, tissue.properties(0), vertex_rows, detail::kVertexPropertiesArray,
                detail::kVertexPoliciesArray, detail::kVertexDefaultPrefix);
  // The derived measure, unless a property already uses its name (the
  // property list in the field data tells readers which is which).
  const char* measure_name = tissue.dim() == 2 ? detail::kAreaArray : detail::kVolumeArray;
  if (!tissue.cellProperties().has(measure_name)) {
    GeometryCache own;
    grid->GetCellData()->AddArray(cellMeasures(tissue, cell_rows, measure_name, geometry ? *geometry : own));
  }

  field->AddArray(singleValue<vtkIntArray>(detail::kFormatVersionArray, detail::kSnapshotFormatVersion));
  field->AddArray(singleValue<vtkDoubleArray>(detail::kTimeArray, tissue.time()));
  field->AddArray(singleValue<vtkIntArray>(detail::kDimArray, tissue.dim()));
  field->AddArray(singleValue<vtkStringArray>(detail::kEmbeddingArray,
                                              vtkStdString(detail::embeddingTag(tissue.embedding()))));
  field->AddArray(singleValue<vtkTypeInt64Array>(detail::kNextLineageArray,
                                                 static_cast<vtkTypeInt64>(tissue.nextLineageId())));
  if (!state.empty()) field->AddArray(runStateArray(state, path));
  addTopologyLayout(field, topo);

  // Last: the checksums cover every array added above.
  detail::addChecksums(grid);
  detail::writeGridFile(grid, path, options);
}

}  // namespace tessella::io
