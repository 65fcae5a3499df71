// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// readTissueVtu: a snapshot back into a Tissue, through the same builders
// the generators use, so the result is an ordinary, validated tissue.

#include "tessella/io/vtu.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkStringArray.h>
#include <vtkType.h>
#include <vtkUnstructuredGrid.h>

#include "finite_values.hpp"
#include "vtu_property_arrays.hpp"
#include "snapshot_checksum.hpp"
#include "snapshot_format.hpp"
#include "tessella/tissue/builders.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"
#include "tessella/tissue/validate.hpp"
#include "vtu_file.hpp"

namespace tessella::io {

namespace {

// Every message starts with the file, so the user knows which one is bad.
struct Source {
  std::string path;
  [[noreturn]] void fail(const std::string& problem) const { throw InputError("'" + path + "': " + problem); }
};

vtkDataArray* requiredField(vtkFieldData* field, const char* name, const Source& src) {
  vtkDataArray* array = field->GetArray(name);
  if (!array || array->GetNumberOfTuples() < 1 || array->GetNumberOfComponents() < 1)
    src.fail(std::string("field data '") + name + "' is missing (not a Tessella snapshot?)");
  return array;
}

std::vector<std::string> stringList(vtkFieldData* field, const char* name, const Source& src) {
  auto* array = vtkStringArray::SafeDownCast(field->GetAbstractArray(name));
  if (!array) src.fail(std::string("field data '") + name + "' is missing or not a string array");
  std::vector<std::string> out;
  for (vtkIdType i = 0; i < array->GetNumberOfValues(); ++i) out.push_back(array->GetValue(i));
  return out;
}

std::vector<Vec3> positionsOf(vtkUnstructuredGrid* grid) {
  std::vector<Vec3> positions(static_cast<std::size_t>(grid->GetNumberOfPoints()));
  vtkDataArray* data = grid->GetPoints()->GetData();
  if (data->GetDataType() == VTK_DOUBLE && data->HasStandardMemoryLayout() && data->GetNumberOfComponents() == 3) {
    const auto* xyz = static_cast<const double*>(data->GetVoidPointer(0));  // x0 y0 z0 x1 ...: Vec3 by Vec3
    for (std::size_t i = 0; i < positions.size(); ++i) positions[i] = Vec3(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
    return positions;
  }
  vtkPoints* points = grid->GetPoints();
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i) points->GetPoint(i, positions[static_cast<std::size_t>(i)].data());
  return positions;
}

std::vector<Index> pointList(vtkIdType n, const vtkIdType* ids, vtkIdType num_points, vtkIdType cell,
                             const Source& src) {
  std::vector<Index> out(static_cast<std::size_t>(n));
  for (vtkIdType k = 0; k < n; ++k) {
    if (ids[k] < 0 || ids[k] >= num_points)
      src.fail("cell " + std::to_string(cell) + " refers to point " + std::to_string(ids[k]) + " but there are " +
               std::to_string(num_points) + " points");
    out[static_cast<std::size_t>(k)] = static_cast<Index>(ids[k]);
  }
  return out;
}

/// Calls visit(c, n, ids) for every cell of a 2D file, after checking that
/// it is a polygon whose points exist.
template <typename Visit>
void forEachPolygon(vtkUnstructuredGrid* grid, const Source& src, Visit visit) {
  const vtkIdType n = grid->GetNumberOfCells();
  const vtkIdType num_points = grid->GetNumberOfPoints();
  vtkCellArray* cells = grid->GetCells();
  vtkIdType npts = 0;
  const vtkIdType* pts = nullptr;
  for (vtkIdType c = 0; c < n; ++c) {
    const int type = grid->GetCellType(c);
    if (type != VTK_POLYGON && type != VTK_TRIANGLE && type != VTK_QUAD)
      src.fail("cell " + std::to_string(c) + " has VTK cell type " + std::to_string(type) +
               " but a 2D tissue needs polygons");
    cells->GetCellAtId(c, npts, pts);
    for (vtkIdType k = 0; k < npts; ++k)
      if (pts[k] < 0 || pts[k] >= num_points)
        src.fail("cell " + std::to_string(c) + " refers to point " + std::to_string(pts[k]) + " but there are " +
                 std::to_string(num_points) + " points");
    visit(c, npts, pts);
  }
}

std::vector<std::vector<Index>> polygonsOf(vtkUnstructuredGrid* grid, const Source& src) {
  std::vector<std::vector<Index>> polygons(static_cast<std::size_t>(grid->GetNumberOfCells()));
  forEachPolygon(grid, src, [&](vtkIdType c, vtkIdType n, const vtkIdType* ids) {
    polygons[static_cast<std::size_t>(c)].assign(ids, ids + n);
  });
  return polygons;
}

struct SortedKeyHash {
  std::size_t operator()(const std::vector<Index>& key) const {
    std::size_t h = key.size();
    for (Index i : key) h ^= std::hash<Index>()(i) + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
    return h;
  }
};

// +1 if `loop` is `reference` up to a cyclic shift, -1 if it is reversed, 0 otherwise.
int cyclicOrientation(const std::vector<Index>& reference, const std::vector<Index>& loop) {
  const std::size_t n = reference.size();
  if (loop.size() != n || n == 0) return 0;
  const auto start = std::find(reference.begin(), reference.end(), loop[0]);
  if (start == reference.end()) return 0;
  const std::size_t p = static_cast<std::size_t>(start - reference.begin());
  bool same = true, reversed = true;
  for (std::size_t k = 0; k < n; ++k) {
    same = same && reference[(p + k) % n] == loop[k];
    reversed = reversed && reference[(p + n - k) % n] == loop[k];
  }
  return same ? 1 : reversed ? -1 : 0;
}

// Polyhedra -> shared walls. Each face of the stream is outward from its
// cell; a wall is identified by its vertex set, and the second cell that
// lists it must list it reversed.
void polyhedraOf(vtkUnstructuredGrid* grid, const Source& src, std::vector<std::vector<Index>>& faces,
                 std::vector<std::vector<CellFace>>& cells) {
  const vtkIdType n = grid->GetNumberOfCells();
  vtkIdTypeArray* stream = grid->GetFaces();
  vtkIdTypeArray* locations = grid->GetFaceLocations();
  if (n > 0 && (!stream || !locations || locations->GetNumberOfValues() != n))
    src.fail("a 3D tissue needs polyhedron cells with their faces, and the face arrays are missing");
  struct Use {
    Index face;
    int count;
  };
  std::unordered_map<std::vector<Index>, Use, SortedKeyHash> by_vertex_set;
  std::vector<vtkIdType> owner;  // first cell listing each face, for error messages
  cells.resize(static_cast<std::size_t>(n));
  const vtkIdType stream_size = n > 0 ? stream->GetNumberOfValues() : 0;
  auto at = [&](vtkIdType k, vtkIdType cell) {
    if (k < 0 || k >= stream_size) src.fail("the face stream of cell " + std::to_string(cell) + " runs past its end");
    return stream->GetValue(k);
  };
  for (vtkIdType c = 0; c < n; ++c) {
    if (grid->GetCellType(c) != VTK_POLYHEDRON)
      src.fail("cell " + std::to_string(c) + " has VTK cell type " + std::to_string(grid->GetCellType(c)) +
               " but a 3D tissue needs polyhedra");
    vtkIdType k = locations->GetValue(c);
    const vtkIdType num_faces = at(k++, c);
    if (num_faces < 4) src.fail("cell " + std::to_string(c) + " has " + std::to_string(num_faces) + " faces (a polyhedron needs 4 or more)");
    for (vtkIdType f = 0; f < num_faces; ++f) {
      const vtkIdType size = at(k++, c);
      if (size < 3) src.fail("face " + std::to_string(f) + " of cell " + std::to_string(c) + " has " + std::to_string(size) + " vertices");
      if (size > stream_size - k) at(stream_size, c);  // the loop runs past the end
      std::vector<Index> loop = pointList(size, stream->GetPointer(k), grid->GetNumberOfPoints(), c, src);
      k += size;
      std::vector<Index> key = loop;
      std::sort(key.begin(), key.end());
      auto [it, inserted] = by_vertex_set.try_emplace(std::move(key), Use{static_cast<Index>(faces.size()), 0});
      Use& use = it->second;
      if (inserted) {
        faces.push_back(std::move(loop));
        owner.push_back(c);
        cells[static_cast<std::size_t>(c)].push_back(CellFace{use.face, false});
      } else {
        const std::string which = "face " + std::to_string(f) + " of cell " + std::to_string(c);
        if (use.count >= 2) src.fail(which + " is a wall already shared by two cells");
        const int orientation = cyclicOrientation(faces[use.face], loop);
        if (orientation == 0)
          src.fail(which + " has the vertices of a face of cell " + std::to_string(owner[use.face]) +
                   " in another cyclic order");
        if (orientation > 0)
          src.fail(which + " has the same orientation as in cell " + std::to_string(owner[use.face]) +
                   " (both cells claim the same side of the wall)");
        cells[static_cast<std::size_t>(c)].push_back(CellFace{use.face, true});
      }
      ++use.count;
    }
  }
}

// Every array listed as a property of the store, restored (Copy policy).
/// The division policy recorded for each listed property; Copy for files
/// written before policies were recorded. A custom policy's function cannot
/// be saved, so such a column divides by copying after a restart.
std::vector<DivisionPolicy> policiesOf(vtkFieldData* field, const char* list_name, std::size_t count,
                                       const char* kind, const Source& src) {
  std::vector<DivisionPolicy> policies(count, DivisionPolicy::Copy);
  if (!field->GetAbstractArray(list_name)) return policies;
  const std::vector<std::string> tags = stringList(field, list_name, src);
  if (tags.size() != count)
    src.fail(std::string(list_name) + " lists " + std::to_string(tags.size()) + " policies for " +
             std::to_string(count) + " " + kind + " properties");
  for (std::size_t i = 0; i < count; ++i) {
    if (tags[i] == "copy" || tags[i] == "custom") policies[i] = DivisionPolicy::Copy;
    else if (tags[i] == "split_by_measure") policies[i] = DivisionPolicy::SplitByMeasure;
    else if (tags[i] == "reset") policies[i] = DivisionPolicy::Reset;
    else
      src.fail(std::string(list_name) + "[" + std::to_string(i) + "] = '" + tags[i] +
               "' is not a division policy (copy, split_by_measure, reset, custom)");
  }
  return policies;
}

void restoreProperties(PropertyStore& store, vtkDataSetAttributes* data, vtkFieldData* field, const char* list_name,
                       const char* policies_name, const char* default_prefix, vtkIdType expected, const char* kind,
                       const Source& src) {
  const std::vector<std::string> names = stringList(field, list_name, src);
  const std::vector<DivisionPolicy> policies = policiesOf(field, policies_name, names.size(), kind, src);
  for (std::size_t i = 0; i < names.size(); ++i) {
    const std::string& name = names[i];
    if (name == Tissue::kLineageName || name == Tissue::kParentName || name == Tissue::kBirthTimeName) continue;
    vtkDataArray* array = data->GetArray(name.c_str());
    if (!array) src.fail(std::string(kind) + " property '" + name + "' is listed but its array is missing");
    if (array->GetNumberOfTuples() != expected)
      src.fail(std::string(kind) + " array '" + name + "' has " + std::to_string(array->GetNumberOfTuples()) +
               " values for " + std::to_string(expected) + " " + kind + "s");
    if (store.has(name)) src.fail(std::string(kind) + " property '" + name + "' is listed twice");
    vtkDataArray* default_value = field->GetArray((default_prefix + name).c_str());
    detail::addColumnFromArray(store, name, array, "'" + src.path + "'", policies[i], default_value);
  }
}

vtkDataArray* lineageArray(vtkCellData* data, const char* name, vtkIdType expected, const Source& src) {
  vtkDataArray* array = data->GetArray(name);
  if (!array) src.fail(std::string("cell array '") + name + "' is missing");
  if (array->GetNumberOfTuples() != expected || array->GetNumberOfComponents() != 1)
    src.fail(std::string("cell array '") + name + "' has " + std::to_string(array->GetNumberOfTuples()) + " x " +
             std::to_string(array->GetNumberOfComponents()) + " values for " + std::to_string(expected) + " cells");
  return array;
}

void restoreLineage(Tissue& tissue, vtkCellData* data, vtkIdType num_cells, const Source& src) {
  const auto lineage = detail::integerValues(lineageArray(data, Tissue::kLineageName, num_cells, src));
  const auto parent = detail::integerValues(lineageArray(data, Tissue::kParentName, num_cells, src));
  const auto birth = detail::doubleValues(lineageArray(data, Tissue::kBirthTimeName, num_cells, src));
  // Ids seen so far: one flag per id when the ids are at most a few times
  // the cells (as a run numbers them), else a hash set.
  const std::int64_t largest = lineage.empty() ? 0 : *std::max_element(lineage.begin(), lineage.end());
  const bool dense = largest < 4 * static_cast<std::int64_t>(lineage.size()) + 1024;
  std::vector<std::uint8_t> seen_flags(dense ? static_cast<std::size_t>(std::max<std::int64_t>(largest, 0)) + 1 : 0, 0);
  std::unordered_set<std::int64_t> seen;
  if (!dense) seen.reserve(lineage.size());
  for (std::size_t c = 0; c < lineage.size(); ++c) {
    if (lineage[c] < 0) src.fail("cell " + std::to_string(c) + " has the negative lineage id " + std::to_string(lineage[c]));
    const bool repeated = dense ? std::exchange(seen_flags[static_cast<std::size_t>(lineage[c])], std::uint8_t{1}) != 0
                                : !seen.insert(lineage[c]).second;
    if (repeated)
      src.fail("lineage id " + std::to_string(lineage[c]) + " is used by more than one cell (cell " + std::to_string(c) + ")");
    tissue.restoreLineage(CellId(static_cast<Index>(c)), lineage[c], parent[c], birth[c]);
  }
}

// The complex a snapshot's topology arrays describe, or nothing for a file
// without them (written before they existed).
std::optional<CellComplex> storedComplex(vtkFieldData* field, int dim, std::size_t num_vertices, const Source& src) {
  const std::string prefix = detail::kTopologyPrefix;
  if (!field->GetAbstractArray((prefix + "edge_vertices").c_str())) return std::nullopt;
  ComplexLayout layout;
  layout.dim = dim;
  layout.num_vertices = num_vertices;
  if (dim == 2) layout.volume_face_offsets = layout.face_volume_offsets = {0};  // as CellComplex::layout() has them
  detail::forEachLayoutList(layout, [&](const char* list, std::vector<Index>& items) {
    const std::string name = prefix + list;
    // VTK reads a UInt32 array back as its own unsigned int class.
    vtkDataArray* array = field->GetArray(name.c_str());
    if (!array || array->GetDataType() != VTK_UNSIGNED_INT || array->GetDataTypeSize() != 4 ||
        array->GetNumberOfComponents() != 1)
      src.fail("field data '" + name + "' is missing or not a one-component UInt32 array");
    const auto* values = static_cast<const std::uint32_t*>(array->GetVoidPointer(0));
    items.assign(values, values + array->GetNumberOfValues());
  });
  try {
    return CellComplex::fromLayout(layout);
  } catch (const TopologyError& e) {
    src.fail(std::string("the arrays ") + detail::kTopologyPrefix + "* do not form a tissue: " + e.what());
  }
}

// The polygons of a 2D file (checked by forEachPolygon) must be the stored
// complex's faces, vertex by vertex from where each loop starts (as the
// writer lists them).
void requireSamePolygons(vtkUnstructuredGrid* grid, const CellComplex& complex, const Source& src) {
  const auto num_cells = static_cast<std::size_t>(grid->GetNumberOfCells());
  if (complex.count(2) != num_cells)
    src.fail("the topology arrays list " + std::to_string(complex.count(2)) + " cells, the file has " +
             std::to_string(num_cells));
  vtkCellArray* cells = grid->GetCells();
  vtkIdType npts = 0;
  const vtkIdType* pts = nullptr;
  for (std::size_t c = 0; c < num_cells; ++c) {
    const auto loop = complex.faceVertices(FaceId(static_cast<Index>(c)));
    cells->GetCellAtId(static_cast<vtkIdType>(c), npts, pts);
    bool same = loop.size() == static_cast<std::size_t>(npts);
    for (std::size_t i = 0; same && i < loop.size(); ++i) same = static_cast<vtkIdType>(loop[i].index()) == pts[i];
    if (!same)
      src.fail("cell " + std::to_string(c) + " has another vertex loop than the topology arrays " +
               detail::kTopologyPrefix + "* give it");
  }
}

// The polyhedra of the file must be the stored complex's volumes, face by
// face and vertex by vertex (outward loops, as the writer lists them).
void requireSameCells(vtkUnstructuredGrid* grid, const CellComplex& complex, const Source& src) {
  const vtkIdType n = grid->GetNumberOfCells();
  if (complex.count(3) != static_cast<std::size_t>(n))
    src.fail("the topology arrays list " + std::to_string(complex.count(3)) + " cells, the file has " +
             std::to_string(n));
  vtkIdTypeArray* stream = grid->GetFaces();
  vtkIdTypeArray* locations = grid->GetFaceLocations();
  for (vtkIdType c = 0; c < n; ++c) {  // polyhedraOf checked the stream's bounds
    vtkIdType k = locations->GetValue(c);
    const auto faces = complex.volumeFaces(VolumeId(static_cast<Index>(c)));
    bool same = stream->GetValue(k++) == static_cast<vtkIdType>(faces.size());
    for (std::size_t f = 0; same && f < faces.size(); ++f) {
      const auto loop = complex.faceVertices(faces[f].handle());
      same = stream->GetValue(k++) == static_cast<vtkIdType>(loop.size());
      for (std::size_t i = 0; same && i < loop.size(); ++i) {
        const VertexId v = faces[f].reversed() ? loop[loop.size() - 1 - i] : loop[i];
        same = stream->GetValue(k++) == static_cast<vtkIdType>(v.index());
      }
    }
    if (!same)
      src.fail("cell " + std::to_string(c) + " has other faces than the topology arrays " +
               detail::kTopologyPrefix + "* give it");
  }
}

RunState runStateOf(vtkFieldData* field, const Source& src) {
  RunState state;
  if (!field->GetAbstractArray(detail::kRunStateArray)) return state;
  for (const std::string& entry : stringList(field, detail::kRunStateArray, src)) {
    const std::size_t eq = entry.find('=');
    if (eq == 0 || eq == std::string::npos)
      src.fail(std::string(detail::kRunStateArray) + " holds '" + entry.substr(0, 80) + "', not key=value");
    if (!state.emplace(entry.substr(0, eq), entry.substr(eq + 1)).second)
      src.fail(std::string(detail::kRunStateArray) + " lists '" + entry.substr(0, eq) + "' twice");
  }
  return state;
}

}  // namespace

Tissue readTissueVtu(const std::string& path) { return readSnapshot(path).tissue; }

Snapshot readSnapshot(const std::string& path) {
  const Source src{path};
  // In the worker that parses the file: the checksums first ("the file is
  // corrupted" says most), then what the walks below rely on.
  vtkSmartPointer<vtkUnstructuredGrid> grid = detail::readGridFile(path, [&](vtkUnstructuredGrid* parsed) {
    detail::verifyChecksums(parsed, path);
    detail::checkCellArrays(parsed, path);
  });
  vtkFieldData* field = grid->GetFieldData();

  const int version = static_cast<int>(requiredField(field, detail::kFormatVersionArray, src)->GetComponent(0, 0));
  if (version < 1 || version > detail::kSnapshotFormatVersion)
    src.fail("snapshot format version " + std::to_string(version) + " is not supported (this build reads up to " +
             std::to_string(detail::kSnapshotFormatVersion) + ")");
  const double dim_value = requiredField(field, detail::kDimArray, src)->GetComponent(0, 0);
  if (dim_value != 2 && dim_value != 3) src.fail("tessella_dim = " + std::to_string(dim_value) + " (expected 2 or 3)");
  const int dim = static_cast<int>(dim_value);
  const auto tags = stringList(field, detail::kEmbeddingArray, src);
  const auto embedding = tags.empty() ? std::nullopt : detail::embeddingFromTag(tags[0]);
  if (!embedding)
    src.fail("tessella_embedding = '" + (tags.empty() ? std::string() : tags[0]) +
             "' (expected planar, surface or volume)");
  if ((dim == 3) != (*embedding == Embedding::Volume))
    src.fail(std::string("tessella_embedding '") + tags[0] + "' does not fit tessella_dim = " + std::to_string(dim));
  const double time = requiredField(field, detail::kTimeArray, src)->GetComponent(0, 0);
  if (!std::isfinite(time)) src.fail("TimeValue is not a finite number");

  if (!grid->GetPoints() && grid->GetNumberOfCells() > 0) src.fail("the file has cells but no points");
  const std::vector<Vec3> positions = grid->GetPoints() ? positionsOf(grid) : std::vector<Vec3>{};
  detail::requireFinitePositions(positions, detail::RowSelection{.count = positions.size()}, path);
  Tissue tissue = [&] {
    try {
      if (dim == 2) {
        if (field->GetAbstractArray((std::string(detail::kTopologyPrefix) + "edge_vertices").c_str())) {
          forEachPolygon(grid, src, [](vtkIdType, vtkIdType, const vtkIdType*) {});
          std::optional<CellComplex> complex = storedComplex(field, 2, positions.size(), src);
          requireSamePolygons(grid, *complex, src);
          return Tissue(std::move(*complex), positions, *embedding);
        }
        return buildPolygonTissue(positions, polygonsOf(grid, src), *embedding);
      }
      std::vector<std::vector<Index>> faces;
      std::vector<std::vector<CellFace>> cells;
      polyhedraOf(grid, src, faces, cells);
      if (std::optional<CellComplex> complex = storedComplex(field, 3, positions.size(), src)) {
        requireSameCells(grid, *complex, src);
        return Tissue(std::move(*complex), positions, Embedding::Volume);
      }
      return buildPolyhedralTissue(positions, faces, cells);
    } catch (const InputError& e) {
      if (std::string(e.what()).rfind("'" + path + "'", 0) == 0) throw;
      src.fail(std::string("the cells do not form a tissue: ") + e.what());
    } catch (const Error& e) {
      src.fail(std::string("the cells do not form a tissue: ") + e.what());
    }
  }();
  if (static_cast<vtkIdType>(tissue.numCells()) != grid->GetNumberOfCells() ||
      static_cast<vtkIdType>(tissue.numVertices()) != grid->GetNumberOfPoints())
    src.fail("the tissue built from " + std::to_string(grid->GetNumberOfCells()) + " cells and " +
             std::to_string(grid->GetNumberOfPoints()) + " points has " + std::to_string(tissue.numCells()) +
             " cells and " + std::to_string(tissue.numVertices()) + " vertices (unused points?)");
  // Combinatorial invariants only: a run may legitimately have produced
  // cavities or degenerate cells, and the file should still read back.
  ValidateOptions checks;
  checks.check_euler = false;
  checks.check_measures = false;
  checks.check_shapes = false;
  if (const ValidationReport report = validate(tissue, checks); !report)
    src.fail("the cells do not form a valid tissue: " + report.message);
  tissue.setTime(time);

  restoreProperties(tissue.cellProperties(), grid->GetCellData(), field, detail::kCellPropertiesArray,
                    detail::kCellPoliciesArray, detail::kCellDefaultPrefix, grid->GetNumberOfCells(), "cell", src);
  restoreProperties(tissue.properties(0), grid->GetPointData(), field, detail::kVertexPropertiesArray,
                    detail::kVertexPoliciesArray, detail::kVertexDefaultPrefix, grid->GetNumberOfPoints(), "vertex", src);
  restoreLineage(tissue, grid->GetCellData(), grid->GetNumberOfCells(), src);
  detail::requireFiniteProperties(tissue, detail::RowSelection{.count = tissue.numVertices()},
                                  detail::RowSelection{.count = tissue.numCells()}, path);
  // Ids of cells that were removed before the save stay used: a restart must
  // not hand them out again. Optional, files of other writers may lack it.
  if (vtkDataArray* next = field->GetArray(detail::kNextLineageArray)) {
    const double value =
        next->GetNumberOfTuples() > 0 && next->GetNumberOfComponents() > 0 ? next->GetComponent(0, 0) : -1.0;
    if (!(value >= 0) || value != std::floor(value))
      src.fail(std::string(detail::kNextLineageArray) + " = " + formatNumber(value) +
               " is not a non-negative integer");
    tissue.reserveLineageIds(static_cast<std::int64_t>(value));
  }
  return Snapshot{std::move(tissue), runStateOf(field, src)};
}

}  // namespace tessella::io
