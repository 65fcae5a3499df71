// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Bad files and failed writes: always an InputError naming the path and the
// problem, never a crash, and never a damaged file left behind.

#include <filesystem>
#include <fstream>

#include <catch2/catch.hpp>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include "file_edits.hpp"
#include "io_test_support.hpp"
#include "tessella/io/mesh_vtu.hpp"
#include "tessella/io/vtu.hpp"
#include "tessella/generators/grids.hpp"

using namespace tessella;
using namespace tessella::io;
using tessella::io::testing::TempDir;
using tessella::io::testing::tamper;
using Catch::Contains;

namespace {

void writeText(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

}  // namespace

TEST_CASE("reading a missing or foreign file names the path and the problem", "[io][vtu][errors]") {
  TempDir dir;
  const std::string missing = dir.file("nope.vtu");
  REQUIRE_THROWS_AS(readTissueVtu(missing), InputError);
  REQUIRE_THROWS_WITH(readTissueVtu(missing), Contains(missing) && Contains("no such file"));

  REQUIRE_THROWS_WITH(readTissueVtu(dir.path().string()), Contains("not a regular file"));

  const std::string text = dir.file("text.vtu");
  writeText(text, "this is not XML at all\n");
  REQUIRE_THROWS_WITH(readTissueVtu(text), Contains(text) && Contains("not a VTK XML UnstructuredGrid"));

  const std::string other_xml = dir.file("poly.vtu");
  writeText(other_xml, "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\"><PolyData/></VTKFile>\n");
  REQUIRE_THROWS_WITH(readTissueVtu(other_xml), Contains(other_xml));
}

TEST_CASE("a truncated snapshot is refused, not half read", "[io][vtu][errors]") {
  TempDir dir;
  const std::string path = dir.file("full.vtu");
  VtuOptions options;
  options.compression = Compression::None;
  writeTissueVtu(rectangularGrid(30, 30), path, options);
  const auto size = std::filesystem::file_size(path);
  std::filesystem::resize_file(path, size / 2);
  REQUIRE_THROWS_AS(readTissueVtu(path), InputError);
  REQUIRE_THROWS_WITH(readTissueVtu(path), Contains(path));
}

TEST_CASE("a .vtu that is not a Tessella snapshot is refused by name", "[io][vtu][errors]") {
  TempDir dir;
  mesh::FeMesh mesh;
  mesh.nodes.resize(3, 3);
  mesh.nodes << 0, 0, 0, 1, 0, 0, 0, 1, 0;
  mesh.elements.resize(1, 3);
  mesh.elements << 0, 1, 2;
  mesh.element_cell = Eigen::VectorXi::Zero(1);
  const std::string path = dir.file("mesh.vtu");
  writeFeMeshVtu(mesh, path);
  REQUIRE_THROWS_WITH(readTissueVtu(path), Contains(path) && Contains("tessella_format_version"));
}

TEST_CASE("inconsistent arrays are named in the error", "[io][vtu][errors]") {
  TempDir dir;
  Tissue t = rectangularGrid(3, 3);
  auto& auxin = t.cellProperties().add<double>("auxin", 1.0);
  auxin[CellId(4)] = 2.0;
  const std::string good = dir.file("good.vtu");
  writeTissueVtu(t, good);
  const std::string bad = dir.file("bad.vtu");

  SECTION("a property array with too few values") {
    tamper(good, bad, [](vtkUnstructuredGrid* g) { g->GetCellData()->GetArray("auxin")->SetNumberOfTuples(5); });
    // VTK's reader already notices; either way the error names file and array.
    REQUIRE_THROWS_WITH(readTissueVtu(bad), Contains(bad) && Contains("auxin"));
  }
  SECTION("a listed property whose array is gone") {
    tamper(good, bad, [](vtkUnstructuredGrid* g) { g->GetCellData()->RemoveArray("auxin"); });
    REQUIRE_THROWS_WITH(readTissueVtu(bad), Contains("'auxin'") && Contains("missing"));
  }
  SECTION("lineage ids used twice") {
    tamper(good, bad, [](vtkUnstructuredGrid* g) {
      vtkDataArray* lineage = g->GetCellData()->GetArray(Tissue::kLineageName);
      lineage->SetComponent(1, 0, lineage->GetComponent(0, 0));
    });
    REQUIRE_THROWS_WITH(readTissueVtu(bad), Contains("lineage id") && Contains("more than one cell"));
  }
  SECTION("a missing lineage column") {
    tamper(good, bad, [](vtkUnstructuredGrid* g) { g->GetCellData()->RemoveArray(Tissue::kParentName); });
    REQUIRE_THROWS_WITH(readTissueVtu(bad), Contains("'parent_id'") && Contains("missing"));
  }
  SECTION("a cell pointing past the points") {
    tamper(good, bad, [](vtkUnstructuredGrid* g) {
      vtkNew<vtkIdList> ids;
      g->GetCellPoints(2, ids);
      ids->SetId(1, 999);
      g->ReplaceCell(2, static_cast<int>(ids->GetNumberOfIds()), ids->GetPointer(0));
    });
    REQUIRE_THROWS_WITH(readTissueVtu(bad), Contains(bad) && Contains("cell 2") && Contains("point 999"));
  }
  SECTION("an edit that keeps the checksum list is refused, naming the array") {
    const auto edit = [](vtkUnstructuredGrid* g) {
      vtkDataArray* auxin_array = g->GetCellData()->GetArray("auxin");
      auxin_array->SetComponent(4, 0, 2.5);
    };
    tamper(good, bad, edit, true);
    REQUIRE_THROWS_AS(readTissueVtu(bad), InputError);
    REQUIRE_THROWS_WITH(readTissueVtu(bad), Contains(bad) && Contains("array 'cell_data/auxin' does not match its checksum"));
    // Without the list, the same file reads, with the edited value.
    tamper(good, bad, edit);
    REQUIRE(readTissueVtu(bad).cellProperties().get<double>("auxin")[CellId(4)] == 2.5);
  }
  SECTION("polygons that do not form a tissue") {
    // Reverse one loop: it now runs against its neighbours. With the topology
    // arrays, it is not the loop they give that cell; in a file without them
    // (older ones), the polygons do not form a tissue.
    const auto reverse = [](vtkUnstructuredGrid* g) {
      vtkNew<vtkIdList> ids;
      g->GetCellPoints(4, ids);
      std::vector<vtkIdType> reversed(ids->GetPointer(0), ids->GetPointer(0) + ids->GetNumberOfIds());
      std::reverse(reversed.begin(), reversed.end());
      g->ReplaceCell(4, static_cast<int>(reversed.size()), reversed.data());
    };
    tamper(good, bad, reverse);
    REQUIRE_THROWS_WITH(readTissueVtu(bad),
                        Contains(bad) && Contains("cell 4 has another vertex loop than the topology arrays"));
    tamper(good, bad, [&](vtkUnstructuredGrid* g) {
      reverse(g);
      vtkFieldData* field = g->GetFieldData();
      for (int i = field->GetNumberOfArrays() - 1; i >= 0; --i)
        if (std::string(field->GetArrayName(i)).rfind("tessella_topology:", 0) == 0)
          field->RemoveArray(field->GetArrayName(i));
    });
    REQUIRE_THROWS_WITH(readTissueVtu(bad), Contains(bad) && Contains("do not form a"));
  }
}

TEST_CASE("failed writes throw, name the path and leave nothing behind", "[io][vtu][errors]") {
  TempDir dir;
  const Tissue t = rectangularGrid(2, 2);
  const std::string nowhere = dir.file("missing_dir/snap.vtu");
  REQUIRE_THROWS_AS(writeTissueVtu(t, nowhere), InputError);
  REQUIRE_THROWS_WITH(writeTissueVtu(t, nowhere), Contains(nowhere));
  REQUIRE(dir.entries().empty());

  VtuOptions options;
  options.compression_level = 0;
  REQUIRE_THROWS_WITH(writeTissueVtu(t, dir.file("x.vtu"), options), Contains("compression_level = 0"));
  REQUIRE(dir.entries().empty());
}

TEST_CASE("writing over a snapshot replaces it whole and leaves no temporaries", "[io][vtu]") {
  TempDir dir;
  const std::string path = dir.file("snap.vtu");
  writeTissueVtu(rectangularGrid(2, 2), path);
  writeTissueVtu(rectangularGrid(5, 3), path);
  REQUIRE(readTissueVtu(path).numCells() == 15);
  REQUIRE(dir.entries() == std::vector<std::string>{"snap.vtu"});

  // A failing write leaves the previous file untouched.
  VtuOptions options;
  options.durable = true;
  writeTissueVtu(rectangularGrid(4, 4), path, options);
  const auto before = std::filesystem::file_size(path);
  std::filesystem::create_directory(dir.file("snap.vtu.blocker"));
  REQUIRE_THROWS_AS(writeTissueVtu(rectangularGrid(1, 1), dir.file("snap.vtu.blocker"), options), InputError);
  REQUIRE(std::filesystem::file_size(path) == before);
  REQUIRE(readTissueVtu(path).numCells() == 16);
}
