// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Labelled VTK meshes (docs/import.md): a .vtu whose elements carry the
// label of the cell they lie in. Tetrahedra give a cell complex whose faces
// are the triangles between elements of different labels (and on the mesh
// boundary), each label a volume; triangles and polygons give one whose faces
// are the elements, each label a patch. Both then go through the cell-complex
// core (cell_complex_core.hpp), which classifies, orients and builds.

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <map>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>

#include "cell_complex_core.hpp"
#include "vtk_integer_types.hpp"
#include "tessella/io/import.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"
#include "vtu_file.hpp"

namespace tessella::io {

namespace {

using detail::ComplexFile;
using detail::Label;

constexpr const char* kLabelNames[] = {"label", "cell_label", "cell_id"};

// One side of a tetrahedron, as the loop that points out of it.
struct Side {
  std::array<Index, 3> key;  // sorted vertices
  std::array<Index, 3> loop;
  Index element;
};

}  // namespace

bool isLabelledVtu(const std::string& path) {
  // The XML header (everything before the appended data) names the arrays.
  std::ifstream in(path, std::ios::binary);
  std::string head(1 << 20, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  if (const auto end = head.find("<AppendedData"); end != std::string::npos) head.resize(end);
  if (head.find("tessella_format_version") != std::string::npos) return false;  // a snapshot
  const auto cell_data = head.find("<CellData");
  if (cell_data == std::string::npos) return false;
  for (const char* name : kLabelNames)
    if (head.find("Name=\"" + std::string(name) + "\"", cell_data) != std::string::npos) return true;
  return false;
}

ImportResult importLabelledVtu(const std::string& path, const ImportOptions& options) {
  detail::checkImportOptions(options);
  vtkSmartPointer<vtkUnstructuredGrid> grid =
      detail::readGridFile(path, [&](vtkUnstructuredGrid* parsed) { detail::checkCellArrays(parsed, path); });
  const std::string file = "'" + path + "'";
  vtkDataArray* labels = nullptr;
  std::string label_name;
  if (options.label_array.find(',') != std::string::npos)
    throw InputError(file + ": label_array '" + options.label_array +
                     "' names two arrays; a labelled .vtu carries one label per element");
  if (!options.label_array.empty()) {
    labels = grid->GetCellData()->GetArray(options.label_array.c_str());
    label_name = options.label_array;
  } else {
    for (const char* name : kLabelNames)
      if (!labels && (labels = grid->GetCellData()->GetArray(name))) label_name = name;
  }
  if (!labels) {
    std::string present;
    for (int i = 0; i < grid->GetCellData()->GetNumberOfArrays(); ++i) {
      const char* name = grid->GetCellData()->GetArrayName(i);
      present += (present.empty() ? "" : ", ") + std::string(name ? name : "(unnamed)");
    }
    throw InputError(file + " has no cell-data array " +
                     (options.label_array.empty() ? std::string("label, cell_label or cell_id")
                                                  : "'" + options.label_array + "'") +
                     " naming each element's cell (it has " + (present.empty() ? std::string("none") : present) +
                     ")");
  }
  if (labels->GetNumberOfComponents() != 1 || !detail::isVtkIntegerType(labels->GetDataType()))
    throw InputError(file + ": cell-data array '" + label_name + "' must be one integer per element (it has " +
                     std::to_string(labels->GetNumberOfComponents()) + " component(s) of type " +
                     labels->GetDataTypeAsString() + ")");

  ComplexFile m;
  m.path = path;
  m.volume_noun = "cell";
  const vtkIdType num_points = grid->GetPoints() ? grid->GetNumberOfPoints() : 0;
  m.positions.resize(static_cast<std::size_t>(num_points));
  for (vtkIdType i = 0; i < num_points; ++i) {
    double p[3];
    grid->GetPoint(i, p);
    m.positions[static_cast<std::size_t>(i)] = Vec3(p[0], p[1], p[2]);
    if (!m.positions[static_cast<std::size_t>(i)].allFinite())
      throw InputError(file + " point " + std::to_string(i) + ": position " +
                       detail::fmtPoint(m.positions[static_cast<std::size_t>(i)]) + " is not finite");
  }
  const vtkIdType n = grid->GetNumberOfCells();
  if (n == 0) throw InputError(file + " has no elements: no cell to import");
  const int first_type = grid->GetCellType(0);
  const bool tetrahedra = first_type == VTK_TETRA;
  auto surfaceType = [](int t) { return t == VTK_TRIANGLE || t == VTK_QUAD || t == VTK_POLYGON; };
  if (!tetrahedra && !surfaceType(first_type))
    throw InputError(file + " element 0 has VTK cell type " + std::to_string(first_type) +
                     ": a labelled mesh holds tetrahedra (a 3D tissue) or triangles and polygons (a sheet)");
  std::vector<Label> element_label(static_cast<std::size_t>(n));
  std::vector<std::vector<Index>> elements(static_cast<std::size_t>(n));
  vtkCellArray* cells = grid->GetCells();
  for (vtkIdType e = 0; e < n; ++e) {
    const double l = labels->GetComponent(e, 0);
    element_label[static_cast<std::size_t>(e)] = static_cast<Label>(l);
    const std::string where = file + " element " + std::to_string(e) + " (cell label " +
                              std::to_string(static_cast<long long>(l)) + ")";
    const int type = grid->GetCellType(e);
    if (tetrahedra ? type != VTK_TETRA : !surfaceType(type))
      throw InputError(where + ": VTK cell type " + std::to_string(type) + ", but element 0 is " +
                       (tetrahedra ? "a tetrahedron: a 3D mesh must be all tetrahedra"
                                   : "a surface element: a surface mesh must be all triangles and polygons"));
    vtkIdType npts = 0;
    const vtkIdType* pts = nullptr;
    cells->GetCellAtId(e, npts, pts);
    auto& loop = elements[static_cast<std::size_t>(e)];
    for (vtkIdType k = 0; k < npts; ++k) {
      if (pts[k] < 0 || pts[k] >= num_points)
        throw InputError(where + ": point index " + std::to_string(pts[k]) + " is out of range (the file has " +
                         std::to_string(num_points) + " points)");
      loop.push_back(static_cast<Index>(pts[k]));
    }
    std::vector<Index> sorted = loop;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end() || loop.size() < 3)
      throw InputError(where + ": a degenerate element (a repeated point, or fewer than 3)");
  }
  // Labels in increasing order are the volumes.
  std::vector<Label> distinct = element_label;
  std::sort(distinct.begin(), distinct.end());
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  auto volumeOf = [&](Label l) {
    return static_cast<std::size_t>(std::lower_bound(distinct.begin(), distinct.end(), l) - distinct.begin());
  };
  std::vector<std::vector<Index>> volume_faces(distinct.size());
  m.face_offsets = {0};
  auto addFace = [&](std::span<const Index> loop) {
    m.face_vertices.insert(m.face_vertices.end(), loop.begin(), loop.end());
    m.face_offsets.push_back(m.face_vertices.size());
    return static_cast<Index>(m.face_offsets.size() - 2);
  };
  std::size_t interfaces = 0;
  if (tetrahedra) {
    std::vector<Side> sides;
    sides.reserve(4 * static_cast<std::size_t>(n));
    for (std::size_t e = 0; e < elements.size(); ++e) {
      auto t = elements[e];
      const Vec3 &a = m.positions[t[0]], &b = m.positions[t[1]], &c = m.positions[t[2]], &d = m.positions[t[3]];
      const double six_volume = (b - a).dot((c - a).cross(d - a));
      if (!(six_volume != 0))
        throw InputError(file + " element " + std::to_string(e) + " (cell label " +
                         std::to_string(element_label[e]) + "): a flat tetrahedron (volume 0)");
      if (six_volume < 0) std::swap(t[2], t[3]);
      // Each side's loop runs counter-clockwise seen from outside the tetrahedron.
      const std::array<std::array<Index, 3>, 4> loops = {
          {{t[0], t[2], t[1]}, {t[0], t[1], t[3]}, {t[0], t[3], t[2]}, {t[1], t[2], t[3]}}};
      for (const auto& loop : loops) {
        Side s{loop, loop, static_cast<Index>(e)};
        std::sort(s.key.begin(), s.key.end());
        sides.push_back(s);
      }
    }
    std::sort(sides.begin(), sides.end(), [](const Side& x, const Side& y) {
      return x.key != y.key ? x.key < y.key : x.element < y.element;
    });
    for (std::size_t i = 0; i < sides.size();) {
      std::size_t j = i;
      while (j < sides.size() && sides[j].key == sides[i].key) ++j;
      if (j - i > 2)
        throw InputError(file + " elements " + std::to_string(sides[i].element) + ", " +
                         std::to_string(sides[i + 1].element) + " and " + std::to_string(sides[i + 2].element) +
                         " share one triangle: the tetrahedra do not form a conforming mesh");
      const Label la = element_label[sides[i].element];
      const bool inner = j - i == 2;
      if (!inner || element_label[sides[i + 1].element] != la) {
        const Index f = addFace(sides[i].loop);
        m.face_element.push_back(sides[i].element);
        volume_faces[volumeOf(la)].push_back(f);
        if (inner) volume_faces[volumeOf(element_label[sides[i + 1].element])].push_back(f), ++interfaces;
      }
      i = j;
    }
  } else {
    m.face_noun = "element";
    for (std::size_t e = 0; e < elements.size(); ++e) volume_faces[volumeOf(element_label[e])].push_back(addFace(elements[e]));
  }
  m.volume_offsets = {0};
  for (std::size_t v = 0; v < distinct.size(); ++v) {
    m.volume_faces.insert(m.volume_faces.end(), volume_faces[v].begin(), volume_faces[v].end());
    m.volume_offsets.push_back(m.volume_faces.size());
  }
  m.volume_label = distinct;

  ImportReport report;
  report.path = path;
  report.format = "labelled_vtu";
  report.file_vertices = m.positions.size();
  report.file_faces = elements.size();
  report.file_faces_noun = tetrahedra ? "tetrahedra" : "surface elements";
  ImportResult result = detail::importComplex(m, options, std::move(report));
  if (tetrahedra)
    result.report.notes.push_back(std::to_string(m.numFaces()) + " triangles bound the labels' regions: " +
                                  std::to_string(interfaces) + " between two labels, " +
                                  std::to_string(m.numFaces() - interfaces) + " on the mesh boundary");
  result.report.notes.push_back("cell properties: label (the elements' '" + label_name + "')");
  return result;
}

}  // namespace tessella::io
