// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Labelled VTK meshes: tetrahedra with a per-element cell label -> a 3D
// tissue walled by the triangles between labels; labelled triangles -> a
// curved sheet; a clear error for each bad input.

#include <array>
#include <map>

#include <catch2/catch.hpp>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include "io_test_support.hpp"
#include "tessella/io/import.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/tissue/validate.hpp"

using namespace tessella;
using namespace tessella::io;
using tessella::io::testing::TempDir;
using Catch::Matchers::Contains;

namespace {

struct LabelledMesh {
  std::vector<Vec3> points;
  std::vector<std::pair<int, std::vector<vtkIdType>>> elements;  // VTK type, point ids
  std::vector<int> labels;
  std::string label_name = "cell_id";

  void write(const std::string& path) const {
    auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
    auto pts = vtkSmartPointer<vtkPoints>::New();
    pts->SetDataTypeToDouble();
    for (const Vec3& p : points) pts->InsertNextPoint(p.x(), p.y(), p.z());
    grid->SetPoints(pts);
    for (const auto& [type, ids] : elements) grid->InsertNextCell(type, static_cast<vtkIdType>(ids.size()), ids.data());
    auto label = vtkSmartPointer<vtkIntArray>::New();
    label->SetName(label_name.c_str());
    for (int l : labels) label->InsertNextValue(l);
    grid->GetCellData()->AddArray(label);
    auto writer = vtkSmartPointer<vtkXMLUnstructuredGridWriter>::New();
    writer->SetFileName(path.c_str());
    writer->SetInputData(grid);
    REQUIRE(writer->Write() == 1);
  }
};

// An nx x ny x nz grid of unit cubes, each cut into the 6 tetrahedra around
// its main diagonal (the same way in every cube, so the mesh is conforming),
// every tetrahedron labelled label_of(i, j, k) of its cube.
template <typename LabelOf>
LabelledMesh cubeGrid(int nx, int ny, int nz, LabelOf label_of) {
  LabelledMesh m;
  auto id = [&](int i, int j, int k) { return static_cast<vtkIdType>((k * (ny + 1) + j) * (nx + 1) + i); };
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) m.points.emplace_back(i, j, k);
  const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        for (const auto& p : perms) {
          std::array<int, 3> c{0, 0, 0};
          std::vector<vtkIdType> tet{id(i, j, k)};
          for (int s = 0; s < 3; ++s) {
            c[p[s]] = 1;
            tet.push_back(id(i + c[0], j + c[1], k + c[2]));
          }
          m.elements.emplace_back(VTK_TETRA, tet);
          m.labels.push_back(label_of(i, j, k));
        }
  return m;
}

std::map<std::int64_t, CellId> cellsByLabel(const Tissue& t) {
  std::map<std::int64_t, CellId> out;
  const auto& label = t.cellProperties().get<std::int64_t>("label");
  for (CellId c : t.cells()) out[label[c]] = c;
  return out;
}

std::string importError(const LabelledMesh& m, const TempDir& dir) {
  const std::string path = dir.file("bad.vtu");
  m.write(path);
  try {
    importTissue(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST_CASE("labelled vtu: tetrahedra become cells walled by the triangles between labels", "[io][import][vtu_labels]") {
  TempDir dir;
  // Three slabs 1 x 2 x 2 along x, labels 10, 11, 12.
  const LabelledMesh m = cubeGrid(3, 2, 2, [](int i, int, int) { return 10 + i; });
  const std::string path = dir.file("slabs.vtu");
  m.write(path);
  const ImportResult r = importTissue(path);
  CHECK(r.report.format == "labelled_vtu");
  CHECK(r.report.file_faces == 72);
  CHECK_THAT(r.report.notes[0], Contains("closed cells, a 3D tissue"));
  const Tissue& t = r.tissue;
  REQUIRE(t.dim() == 3);
  REQUIRE(t.numCells() == 3);
  CHECK(validate(t).ok);
  const auto cells = cellsByLabel(t);
  for (const auto& [label, c] : cells) CHECK(cellMeasure(t, c) == Approx(4.0).epsilon(1e-14));
  CHECK(cellCentroid(t, cells.at(11)).isApprox(Vec3(1.5, 1, 1), 1e-14));
  CHECK(t.cellNeighbors(cells.at(11)).size() == 2);
  CHECK(t.cellNeighbors(cells.at(10)) == std::vector<CellId>{cells.at(11)});
  // Every unit square on a slab's surface is two triangles: 2 x (2x2 + 2x2 + 1x2 x 4 sides) per slab, minus shared.
  const std::size_t per_slab = 2 * (4 + 4 + 2 * 4);
  CHECK(t.numWalls() == 3 * per_slab - 2 * 8);
  // Vertices inside a slab bound no wall and are dropped: 36 grid points, none inside a slab.
  CHECK(t.numVertices() == 36);
}

TEST_CASE("labelled vtu: labelled triangles become a curved sheet", "[io][import][vtu_labels]") {
  TempDir dir;
  LabelledMesh m;
  m.label_name = "label";
  m.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0.5), Vec3(0, 1, 0), Vec3(1, 1, 0), Vec3(2, 1, 0.5)};
  m.elements = {{VTK_TRIANGLE, {0, 1, 4}}, {VTK_TRIANGLE, {0, 4, 3}}, {VTK_QUAD, {1, 2, 5, 4}}};
  m.labels = {4, 4, 9};
  const std::string path = dir.file("sheet.vtu");
  m.write(path);
  const ImportResult r = importTissue(path);
  CHECK_THAT(r.report.notes[0], Contains("open patches of one surface"));
  const Tissue& t = r.tissue;
  REQUIRE(t.numCells() == 2);
  CHECK(t.embedding() == Embedding::Surface);
  CHECK(validate(t).ok);
  const auto cells = cellsByLabel(t);
  CHECK(cellMeasure(t, cells.at(4)) == Approx(1.0).epsilon(1e-14));
  CHECK(cellMeasure(t, cells.at(9)) == Approx(std::sqrt(1.25)).epsilon(1e-14));
}

TEST_CASE("labelled vtu: bad meshes name the file, element and label", "[io][import][vtu_labels][errors]") {
  TempDir dir;
  const std::string path = dir.file("bad.vtu");
  SECTION("no label array") {
    LabelledMesh m = cubeGrid(1, 1, 1, [](int, int, int) { return 1; });
    m.label_name = "region";
    // Without a label array, auto does not recognise the file; the named format says why.
    m.write(path);
    CHECK_THROWS_WITH(importTissue(path), Contains("none of the supported formats"));
    CHECK_THROWS_WITH(importTissue(path, ImportOptions{"labelled_vtu"}),
                      Contains(path) && Contains("no cell-data array label, cell_label or cell_id") &&
                          Contains("(it has region)"));
  }
  SECTION("a cell in two disconnected pieces") {
    const LabelledMesh m = cubeGrid(3, 1, 1, [](int i, int, int) { return i == 1 ? 2 : 1; });
    CHECK_THAT(importError(m, dir), Contains(path) && Contains("cell 0 (label 1): its faces form 2 disconnected "
                                                               "pieces"));
  }
  SECTION("a non-manifold cell: two cubes touching along an edge") {
    const LabelledMesh m = cubeGrid(2, 2, 1, [](int i, int j, int) { return i == j ? 5 : 6; });
    CHECK_THAT(importError(m, dir), Contains(path) && Contains("cell 0 (label 5): edge") &&
                                        Contains("is in 4 of its faces") && Contains("side (vertices"));
  }
  SECTION("tetrahedra mixed with triangles") {
    LabelledMesh m = cubeGrid(1, 1, 1, [](int, int, int) { return 1; });
    m.elements.push_back({VTK_TRIANGLE, {0, 1, 2}});
    m.labels.push_back(1);
    CHECK_THAT(importError(m, dir), Contains(path) && Contains("element 6 (cell label 1): VTK cell type 5, but "
                                                               "element 0 is a tetrahedron"));
  }
  SECTION("a flat tetrahedron") {
    LabelledMesh m = cubeGrid(1, 1, 1, [](int, int, int) { return 3; });
    m.elements[2].second = {0, 1, 2, 3};  // four corners of the bottom square
    CHECK_THAT(importError(m, dir), Contains(path) && Contains("element 2 (cell label 3): a flat tetrahedron"));
  }
}
