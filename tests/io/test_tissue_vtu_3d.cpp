// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// 3D snapshots: polyhedra with their face streams. Checked against analytic
// box volumes, against the written tissue, and through VTK itself for what
// ParaView relies on (cell types, outward faces).

#include <catch2/catch.hpp>

#include <vtkCellType.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include "file_edits.hpp"
#include "io_test_support.hpp"
#include "tessella/io/vtu.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/generators/grids.hpp"
#include "tessella/tissue/validate.hpp"

using namespace tessella;
using namespace tessella::io;
using tessella::io::testing::requireSameColumn;
using tessella::io::testing::requireSameTissue;
using tessella::io::testing::TempDir;

namespace {

vtkSmartPointer<vtkUnstructuredGrid> readWithVtk(const std::string& path) {
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  return reader->GetOutput();
}

// For every face of every polyhedron in the file: the Newell normal of its
// loop must point away from the cell's vertex centroid (true for convex cells
// when faces are oriented outward, as VTK requires).
void requireOutwardFaces(vtkUnstructuredGrid* grid) {
  vtkIdTypeArray* faces = grid->GetFaces();
  vtkIdTypeArray* locations = grid->GetFaceLocations();
  REQUIRE(faces != nullptr);
  REQUIRE(locations != nullptr);
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
    REQUIRE(grid->GetCellType(c) == VTK_POLYHEDRON);
    vtkIdType k = locations->GetValue(c);
    const vtkIdType num_faces = faces->GetValue(k++);
    std::vector<std::vector<Vec3>> loops;
    Vec3 centre = Vec3::Zero();
    int count = 0;
    for (vtkIdType f = 0; f < num_faces; ++f) {
      const vtkIdType n = faces->GetValue(k++);
      std::vector<Vec3> loop;
      for (vtkIdType j = 0; j < n; ++j) {
        Vec3 p;
        grid->GetPoint(faces->GetValue(k++), p.data());
        loop.push_back(p);
        centre += p;
        ++count;
      }
      loops.push_back(loop);
    }
    centre /= count;
    for (const auto& loop : loops) {
      Vec3 normal = Vec3::Zero(), mid = Vec3::Zero();
      for (std::size_t j = 0; j < loop.size(); ++j) {
        normal += loop[j].cross(loop[(j + 1) % loop.size()]);
        mid += loop[j];
      }
      mid /= static_cast<double>(loop.size());
      REQUIRE(normal.dot(mid - centre) > 0);
    }
  }
}

}  // namespace

TEST_CASE("box grid round trip keeps counts, box volumes and properties", "[io][vtu][3d]") {
  TempDir dir;
  const std::size_t nx = 3, ny = 2, nz = 2;
  Tissue t = boxGrid(nx, ny, nz, 1.0, 2.0, 0.5);
  t.setTime(0.75);
  auto& auxin = t.cellProperties().add<double>("auxin", 0.0, DivisionPolicy::SplitByMeasure);
  auto& polarity = t.cellProperties().add<Vec3>("polarity", Vec3::Zero());
  auto& mark = t.properties(0).add<std::int32_t>("mark", 0);
  for (CellId c : t.cells()) {
    auxin[c] = 1.0 / (1 + c.index());
    polarity[c] = Vec3(c.index(), 0, 1);
  }
  for (VertexId v : t.vertices()) mark[v] = static_cast<std::int32_t>(v.index()) * 3 - 7;

  const std::string path = dir.file("boxes.vtu");
  writeTissueVtu(t, path);
  const Tissue r = readTissueVtu(path);

  REQUIRE(validate(r).ok);
  requireSameTissue(t, r);
  requireSameColumn<double>(t, r, 3, "auxin", t.cells());
  requireSameColumn<Vec3>(t, r, 3, "polarity", t.cells());
  requireSameColumn<std::int32_t>(t, r, 0, "mark", t.vertices());
  REQUIRE(r.numCells() == nx * ny * nz);
  REQUIRE(r.numVertices() == (nx + 1) * (ny + 1) * (nz + 1));
  REQUIRE(r.numWalls() == (nx + 1) * ny * nz + nx * (ny + 1) * nz + nx * ny * (nz + 1));
  for (CellId c : r.cells()) REQUIRE(cellMeasure(r, c) == Approx(1.0).epsilon(1e-14));

  requireOutwardFaces(readWithVtk(path));
}

TEST_CASE("divided polyhedra keep their volumes and lineage", "[io][vtu][3d]") {
  TempDir dir;
  Tissue t = boxGrid(2, 2, 2);
  t.setTime(3.0);
  t.splitCell(CellId(0), Plane{cellCentroid(t, CellId(0)), Vec3(1, 0.4, 0.2)});
  t.splitCell(CellId(7), Plane{cellCentroid(t, CellId(7)), Vec3(0, 0, 1)});
  REQUIRE(validate(t).ok);

  const std::string path = dir.file("divided.vtu");
  writeTissueVtu(t, path);
  const Tissue r = readTissueVtu(path);
  REQUIRE(validate(r).ok);
  requireSameTissue(t, r);
  REQUIRE(r.numCells() == 10);
  REQUIRE(totalMeasure(r) == Approx(8.0).epsilon(1e-13));
  REQUIRE(cellMeasure(r, CellId(7)) == Approx(0.5).epsilon(1e-13));
  requireOutwardFaces(readWithVtk(path));
}

namespace {

Tissue dividedGrid() {
  Tissue t = boxGrid(2, 2, 2);
  t.splitCell(CellId(0), Plane{cellCentroid(t, CellId(0)), Vec3(1, 0.4, 0.2)});
  t.splitCell(CellId(7), Plane{cellCentroid(t, CellId(7)), Vec3(0, 0, 1)});
  t.splitCell(CellId(8), Plane{cellCentroid(t, CellId(8)), Vec3(0.3, 1, 0.1)});
  t.splitCell(CellId(3), Plane{cellCentroid(t, CellId(3)), Vec3(0.2, -0.5, 1)});
  return t;
}

}  // namespace

TEST_CASE("a 3D snapshot keeps the numbering and direction of walls and edges", "[io][vtu][3d][restart]") {
  TempDir dir;
  const Tissue t = dividedGrid();
  const std::string path = dir.file("divided.vtu");
  writeTissueVtu(t, path);
  const Tissue r = readTissueVtu(path);
  requireSameTissue(t, r);
  CHECK(r.topology().layout() == t.topology().layout());

  // Without the arrays (a file written before they existed), the walls are
  // matched by vertex set and the edges numbered by first use: the same
  // cells, another numbering.
  const std::string old = dir.file("old.vtu");
  io::testing::withoutLayoutArrays(path, old);
  const Tissue from_old = readTissueVtu(old);
  requireSameTissue(t, from_old);
  CHECK_FALSE(from_old.topology().layout() == t.topology().layout());
}

TEST_CASE("damaged topology arrays of a 3D snapshot are refused, naming them", "[io][vtu][3d][restart]") {
  TempDir dir;
  const std::string path = dir.file("divided.vtu");
  writeTissueVtu(dividedGrid(), path);
  auto refused = [&](auto edit, const std::string& part) {
    const std::string bad = dir.file("bad.vtu");
    io::testing::tamper(path, bad, [&](vtkUnstructuredGrid* grid) {
      edit([&](const char* array) {
        vtkDataArray* values = grid->GetFieldData()->GetArray((std::string("tessella_topology:") + array).c_str());
        REQUIRE(values != nullptr);
        return values;
      });
    });
    try {
      readTissueVtu(bad);
      FAIL("accepted");
    } catch (const InputError& e) {
      INFO(e.what());
      CHECK(std::string(e.what()).find(part) != std::string::npos);
      CHECK(std::string(e.what()).find(bad) != std::string::npos);
    }
  };
  // The first face loop, started one edge later: a valid complex, but not
  // the polyhedra of the file.
  refused(
      [](auto array) {
        vtkDataArray* loops = array("face_edges");
        const auto size = static_cast<vtkIdType>(array("face_edge_offsets")->GetComponent(1, 0));
        const double first = loops->GetComponent(0, 0);
        for (vtkIdType k = 0; k + 1 < size; ++k) loops->SetComponent(k, 0, loops->GetComponent(k + 1, 0));
        loops->SetComponent(size - 1, 0, first);
      },
      "has other faces than the topology arrays");
  refused([](auto array) { array("edge_vertices")->SetComponent(0, 0, 1e6); },
          "tessella_topology:* do not form a tissue");
}
