// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// FeMesh output on tiny hand-made meshes, read back with VTK itself.

#include <filesystem>

#include <catch2/catch.hpp>

#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include "io_test_support.hpp"
#include "tessella/io/mesh_vtu.hpp"
#include "tessella/io/pvd.hpp"

using namespace tessella;
using namespace tessella::io;
using tessella::io::testing::TempDir;
using Catch::Contains;

namespace {

vtkSmartPointer<vtkUnstructuredGrid> readWithVtk(const std::string& path) {
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  return reader->GetOutput();
}

// The unit square as two cells (triangles below and above the diagonal 0-2):
// walls 0..3 are the sides, wall 4 the diagonal.
mesh::FeMesh twoTriangles() {
  mesh::FeMesh m;
  m.dim = 2;
  m.nodes.resize(4, 3);
  m.nodes << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
  m.elements.resize(2, 3);
  m.elements << 0, 1, 2, 0, 2, 3;
  m.element_cell.resize(2);
  m.element_cell << 7, 9;
  m.wall_facets.resize(5, 2);
  m.wall_facets << 0, 1, 1, 2, 2, 3, 3, 0, 0, 2;
  m.facet_wall.resize(5);
  m.facet_wall << 0, 1, 2, 3, 4;
  m.facet_on_boundary.resize(5);
  m.facet_on_boundary << true, true, true, true, false;
  m.node_vertex.resize(4);
  m.node_vertex << 0, 1, 2, -1;
  return m;
}

void requireCells(vtkUnstructuredGrid* g, const mesh::RowMatrix<int>& rows, int type) {
  REQUIRE(g->GetNumberOfCells() == rows.rows());
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < g->GetNumberOfCells(); ++c) {
    REQUIRE(g->GetCellType(c) == type);
    g->GetCellPoints(c, ids);
    REQUIRE(ids->GetNumberOfIds() == rows.cols());
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) REQUIRE(ids->GetId(k) == rows(c, k));
  }
}

}  // namespace

TEST_CASE("a triangle mesh and its wall facets, with fields", "[io][mesh]") {
  TempDir dir;
  const mesh::FeMesh m = twoTriangles();
  MeshFields fields;
  fields.point["u"] = Eigen::VectorXd(4);
  fields.point["u"] << 0.0, 1.0, 2.0, 1.0;  // u = x + y at the nodes
  fields.element["source"] = Eigen::Vector2d(0.25, -4.0);
  fields.facet["flux"] = Eigen::VectorXd::LinSpaced(5, 0.0, 1.0);

  const std::string path = dir.file("mesh.vtu");
  const std::string walls = dir.file("walls.vtu");
  writeFeMeshVtu(m, path, fields);
  writeWallFacetsVtu(m, walls, fields);

  auto g = readWithVtk(path);
  REQUIRE(g->GetNumberOfPoints() == 4);
  for (vtkIdType p = 0; p < 4; ++p) {
    double x[3];
    g->GetPoint(p, x);
    REQUIRE(Vec3(x[0], x[1], x[2]) == m.nodes.row(p).transpose());
    REQUIRE(g->GetPointData()->GetArray("u")->GetComponent(p, 0) == x[0] + x[1]);
    REQUIRE(g->GetPointData()->GetArray("vertex_id")->GetComponent(p, 0) == m.node_vertex[p]);
  }
  requireCells(g, m.elements, VTK_TRIANGLE);
  REQUIRE(g->GetCellData()->GetArray("cell_id")->GetComponent(0, 0) == 7);
  REQUIRE(g->GetCellData()->GetArray("cell_id")->GetComponent(1, 0) == 9);
  REQUIRE(g->GetCellData()->GetArray("source")->GetComponent(1, 0) == -4.0);

  auto w = readWithVtk(walls);
  requireCells(w, m.wall_facets, VTK_LINE);
  for (vtkIdType f = 0; f < 5; ++f) {
    REQUIRE(w->GetCellData()->GetArray("wall_id")->GetComponent(f, 0) == m.facet_wall[f]);
    REQUIRE(w->GetCellData()->GetArray("on_boundary")->GetComponent(f, 0) == (f < 4 ? 1 : 0));
    REQUIRE(w->GetCellData()->GetArray("flux")->GetComponent(f, 0) == fields.facet["flux"][f]);
  }
  REQUIRE(w->GetPointData()->GetArray("u") != nullptr);
}

TEST_CASE("a tetrahedral mesh writes tetrahedra and triangle facets", "[io][mesh]") {
  TempDir dir;
  mesh::FeMesh m;
  m.dim = 3;
  m.nodes.resize(5, 3);
  m.nodes << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1;
  m.elements.resize(2, 4);
  m.elements << 0, 1, 2, 3, 1, 2, 3, 4;
  m.element_cell = Eigen::VectorXi::Zero(2);
  m.wall_facets.resize(1, 3);
  m.wall_facets << 1, 2, 3;
  m.facet_wall = Eigen::VectorXi::Constant(1, 5);
  writeFeMeshVtu(m, dir.file("tets.vtu"));
  writeWallFacetsVtu(m, dir.file("tet_walls.vtu"));
  requireCells(readWithVtk(dir.file("tets.vtu")), m.elements, VTK_TETRA);
  auto w = readWithVtk(dir.file("tet_walls.vtu"));
  requireCells(w, m.wall_facets, VTK_TRIANGLE);
  REQUIRE(w->GetCellData()->GetArray("wall_id")->GetComponent(0, 0) == 5);
  REQUIRE(w->GetCellData()->GetArray("on_boundary") == nullptr);  // not given, not invented
}

TEST_CASE("mesh errors name the array or field", "[io][mesh][errors]") {
  TempDir dir;
  mesh::FeMesh m = twoTriangles();
  MeshFields fields;
  fields.point["u"] = Eigen::VectorXd::Zero(3);
  REQUIRE_THROWS_WITH(writeFeMeshVtu(m, dir.file("a.vtu"), fields),
                      Contains("point field 'u'") && Contains("has 3 entries, expected 4"));
  m.elements(1, 2) = 11;
  REQUIRE_THROWS_WITH(writeFeMeshVtu(m, dir.file("a.vtu")), Contains("elements row 1") && Contains("node 11"));
  m = twoTriangles();
  m.facet_wall.resize(2);
  REQUIRE_THROWS_WITH(writeWallFacetsVtu(m, dir.file("a.vtu")), Contains("facet_wall"));
  m = twoTriangles();
  m.dim = 4;
  REQUIRE_THROWS_WITH(checkFeMesh(m), Contains("dim = 4"));
  REQUIRE(dir.entries().empty());
}

TEST_CASE("a mesh series keeps elements and walls side by side", "[io][mesh][series]") {
  TempDir dir;
  MeshSeriesWriter series(dir.path().string(), "fem");
  mesh::FeMesh m = twoTriangles();
  series.write(m, 0.0);
  m.nodes *= 2.0;
  const std::string second = series.write(m, 0.5);
  REQUIRE(second == dir.file("fem_000001.vtu"));
  REQUIRE(series.steps() == 2);
  const auto entries = readPvdFile(series.pvdPath());
  const auto wall_entries = readPvdFile(series.wallsPvdPath());
  REQUIRE(entries.size() == 2);
  REQUIRE(wall_entries.size() == 2);
  REQUIRE(entries[1].time == 0.5);
  REQUIRE(wall_entries[1].file == "fem_walls_000001.vtu");
  for (const auto& e : entries) REQUIRE(std::filesystem::exists(dir.file(e.file)));
  for (const auto& e : wall_entries) REQUIRE(std::filesystem::exists(dir.file(e.file)));
  double x[3];
  readWithVtk(second)->GetPoint(2, x);
  REQUIRE(x[0] == 2.0);
  REQUIRE_THROWS_WITH(series.write(m, 0.25), Contains("not after"));
}
