// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// A snapshot holds finite numbers only: a NaN or infinite coordinate or
// floating-point property value is refused when written (nothing is written)
// and when read, naming the element, the property and the value.

#include <cmath>
#include <limits>

#include <catch2/catch.hpp>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include "file_edits.hpp"
#include "io_test_support.hpp"
#include "tessella/io/vtu.hpp"
#include "tessella/generators/grids.hpp"

using namespace tessella;
using namespace tessella::io;
using tessella::io::testing::TempDir;
using tessella::io::testing::tamper;
using Catch::Contains;

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

}  // namespace

TEST_CASE("a non-finite property value or position is not written", "[io][vtu][errors][finite]") {
  TempDir dir;
  Tissue t = rectangularGrid(3, 2);
  auto& auxin = t.cellProperties().add<double>("auxin", 1.0);
  t.cellProperties().add<Vec3>("polarity", Vec3(1, 0, 0));
  t.properties(0).add<float>("stiffness", 2.0f);
  const std::string path = dir.file("snap.vtu");

  SECTION("a NaN double cell property") {
    auxin[CellId(4)] = kNaN;
    const std::string lineage = "(lineage id " + std::to_string(t.lineageId(CellId(4))) + ")";
    REQUIRE_THROWS_WITH(writeTissueVtu(t, path), Contains(path) && Contains("cell property 'auxin' of cell 4") &&
                                                     Contains(lineage) && Contains("is nan"));
  }
  SECTION("an infinite component of a vector property") {
    t.cellProperties().get<Vec3>("polarity")[CellId(2)] = Vec3(0, -kInf, 0);
    REQUIRE_THROWS_WITH(writeTissueVtu(t, path),
                        Contains("cell property 'polarity' of cell 2") && Contains("is (0, -inf, 0)"));
  }
  SECTION("a NaN float vertex property") {
    t.properties(0).get<float>("stiffness")[VertexId(5)] = std::numeric_limits<float>::quiet_NaN();
    REQUIRE_THROWS_WITH(writeTissueVtu(t, path), Contains("vertex property 'stiffness' of vertex 5 is nan"));
  }
  SECTION("a NaN birth time") {
    Tissue u = t;
    u.restoreLineage(CellId(1), u.lineageId(CellId(1)), u.parentId(CellId(1)), kNaN);
    REQUIRE_THROWS_WITH(writeTissueVtu(u, path), Contains("cell property 'birth_time' of cell 1"));
  }
  SECTION("a non-finite vertex position") {
    t.mutablePositions()[3] = Vec3(kInf, 0, 0);
    REQUIRE_THROWS_WITH(writeTissueVtu(t, path),
                        Contains(path) && Contains("vertex 3 has the non-finite position (inf, 0, 0)"));
  }
  SECTION("a removed cell's NaN is not written and not refused") {
    auxin[CellId(0)] = kNaN;
    t.removeCell(CellId(0));
    writeTissueVtu(t, path);
    REQUIRE(readTissueVtu(path).numCells() == 5);
    return;
  }
  REQUIRE(dir.entries().empty());
}

TEST_CASE("a snapshot with a non-finite value is refused when read", "[io][vtu][errors][finite]") {
  TempDir dir;
  Tissue t = rectangularGrid(3, 2);
  t.cellProperties().add<double>("auxin", 1.0);
  t.properties(0).add<Vec3>("velocity", Vec3::Zero());
  const std::string good = dir.file("good.vtu"), bad = dir.file("bad.vtu");
  writeTissueVtu(t, good);
  REQUIRE(readTissueVtu(good).numCells() == 6);

  SECTION("a NaN cell property") {
    tamper(good, bad,
                [](vtkUnstructuredGrid* g) { g->GetCellData()->GetArray("auxin")->SetComponent(3, 0, kNaN); });
    REQUIRE_THROWS_WITH(readTissueVtu(bad), Contains(bad) && Contains("cell property 'auxin' of cell 3") &&
                                                Contains("is nan"));
  }
  SECTION("an infinite vertex property component") {
    tamper(good, bad,
                [](vtkUnstructuredGrid* g) { g->GetPointData()->GetArray("velocity")->SetComponent(7, 2, kInf); });
    REQUIRE_THROWS_WITH(readTissueVtu(bad), Contains("vertex property 'velocity' of vertex 7 is (0, 0, inf)"));
  }
  SECTION("a NaN coordinate") {
    tamper(good, bad, [](vtkUnstructuredGrid* g) { g->GetPoints()->SetPoint(2, kNaN, 0, 0); });
    REQUIRE_THROWS_WITH(readTissueVtu(bad),
                        Contains(bad) && Contains("vertex 2 has the non-finite position (nan, 0, 0)"));
  }
}
