// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// 2D snapshots: write, read back, compare with the written tissue and with
// analytic measures.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <set>

#include <catch2/catch.hpp>

#include "file_edits.hpp"
#include "io_test_support.hpp"
#include "tessella/io/vtu.hpp"
#include "tessella/tissue/builders.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/generators/grids.hpp"
#include "tessella/tissue/validate.hpp"

using namespace tessella;
using namespace tessella::io;
using tessella::io::testing::requireSameColumn;
using tessella::io::testing::requireSameTissue;
using tessella::io::testing::TempDir;

namespace {

// One column of every writable kind, with values that differ from cell to cell.
void addCellProperties(Tissue& t) {
  auto& auxin = t.cellProperties().add<double>("auxin", 0.0, DivisionPolicy::SplitByMeasure);
  auto& type = t.cellProperties().add<std::int32_t>("cell_type", 0);
  auto& flag = t.cellProperties().add<std::uint8_t>("is_l1", 0);
  auto& clone = t.cellProperties().add<std::int64_t>("clone", 0);
  auto& f = t.cellProperties().add<float>("stiffness", 0.0f);
  auto& polarity = t.cellProperties().add<Vec3>("polarity", Vec3::Zero());
  auto& v2 = t.cellProperties().add<Eigen::Vector2d>("growth_2d", Eigen::Vector2d::Zero());
  auto& stress = t.cellProperties().add<Sym3>("stress", Sym3{});
  auto& tensor = t.cellProperties().add<Mat3>("growth_tensor", Mat3::Zero());
  t.cellProperties().add<std::string>("label", "none");  // no VTK array type: skipped
  for (CellId c : t.cells()) {
    const double i = c.index();
    auxin[c] = 0.1 * i + 1.0 / 3.0;
    type[c] = static_cast<std::int32_t>(c.index() % 3) - 1;
    flag[c] = static_cast<std::uint8_t>(c.index() % 2);
    clone[c] = (std::int64_t{1} << 40) + c.index();  // beyond 2^32: must survive exactly
    f[c] = static_cast<float>(i) / 7.0f;
    polarity[c] = Vec3(i, -i, 0.5 * i);
    v2[c] = Eigen::Vector2d(i, 2 * i);
    stress[c] = Sym3{{1 + i, 2 + i, 3 + i, 4 + i, 5 + i, 6 + i}};
    Mat3 m;
    m << 1, 2, 3, 4, 5, 6, 7, 8, i;
    tensor[c] = m;
  }
}

void addVertexProperties(Tissue& t) {
  auto& height = t.properties(0).add<double>("height", 0.0);
  auto& velocity = t.properties(0).add<Vec3>("velocity", Vec3::Zero());
  for (VertexId v : t.vertices()) {
    height[v] = t.position(v).y() * 0.25;
    velocity[v] = Vec3(1.0, t.position(v).x(), -3.0);
  }
}

void requireSameProperties(const Tissue& a, const Tissue& b) {
  requireSameColumn<double>(a, b, 2, "auxin", a.cells());
  requireSameColumn<std::int32_t>(a, b, 2, "cell_type", a.cells());
  requireSameColumn<std::uint8_t>(a, b, 2, "is_l1", a.cells());
  requireSameColumn<std::int64_t>(a, b, 2, "clone", a.cells());
  requireSameColumn<float>(a, b, 2, "stiffness", a.cells());
  requireSameColumn<Vec3>(a, b, 2, "polarity", a.cells());
  requireSameColumn<Eigen::Vector2d>(a, b, 2, "growth_2d", a.cells());
  requireSameColumn<Mat3>(a, b, 2, "growth_tensor", a.cells());
  const auto& sa = a.cellProperties().get<Sym3>("stress");
  const auto& sb = b.cellProperties().get<Sym3>("stress");
  const auto live = tessella::io::testing::liveList(a.cells());
  for (std::size_t i = 0; i < live.size(); ++i) REQUIRE(sb[static_cast<Index>(i)].v == sa[live[i]].v);
  REQUIRE_FALSE(b.cellProperties().has("label"));
  requireSameColumn<double>(a, b, 0, "height", a.vertices());
  requireSameColumn<Vec3>(a, b, 0, "velocity", a.vertices());
}

}  // namespace

TEST_CASE("rectangular grid round trip keeps counts, unit areas and every property", "[io][vtu]") {
  TempDir dir;
  Tissue t = rectangularGrid(6, 4, 1.5, 0.5);
  t.setTime(2.25);
  addCellProperties(t);
  addVertexProperties(t);
  REQUIRE(unwritableProperties(t.cellProperties()) == std::vector<std::string>{"label"});

  const std::string path = dir.file("grid.vtu");
  writeTissueVtu(t, path);
  const Tissue r = readTissueVtu(path);

  REQUIRE(validate(r).ok);
  requireSameTissue(t, r);
  requireSameProperties(t, r);
  REQUIRE(r.numCells() == 24);
  REQUIRE(r.numVertices() == 35);
  REQUIRE(r.numEdges() == 6 * 5 + 7 * 4);
  for (CellId c : r.cells()) REQUIRE(cellMeasure(r, c) == Approx(1.5 * 0.5).epsilon(1e-14));
  REQUIRE(totalMeasure(r) == Approx(9.0 * 2.0).epsilon(1e-13));
}

TEST_CASE("hexagonal grid round trip keeps the regular hexagon area", "[io][vtu]") {
  TempDir dir;
  const double radius = 0.7;
  Tissue t = hexagonalGrid(5, 3, radius);
  const std::string path = dir.file("hex.vtu");
  writeTissueVtu(t, path);
  const Tissue r = readTissueVtu(path);
  REQUIRE(validate(r).ok);
  requireSameTissue(t, r);
  const double hexagon = 1.5 * std::sqrt(3.0) * radius * radius;
  for (CellId c : r.cells()) REQUIRE(cellMeasure(r, c) == Approx(hexagon).epsilon(1e-12));
}

TEST_CASE("divided and removed cells: lineage survives, tombstones are skipped", "[io][vtu]") {
  TempDir dir;
  Tissue t = rectangularGrid(4, 3);
  addCellProperties(t);
  addVertexProperties(t);
  t.setTime(1.0);
  // Divide three cells through their centres; then remove a corner cell so
  // that cell and vertex slots have tombstones.
  for (Index i : {5u, 6u, 9u}) {
    const CellId c(i);
    t.splitCell(c, Plane{cellCentroid(t, c), Vec3(1, 0.3, 0)});
  }
  t.setTime(2.0);
  t.splitCell(CellId(0), Plane{cellCentroid(t, CellId(0)), Vec3(0, 1, 0)});
  t.removeCell(CellId(11));
  REQUIRE(validate(t).ok);
  REQUIRE(t.numCells() < t.cellSlots());
  REQUIRE(t.numVertices() < t.slots(0));

  const std::string path = dir.file("divided.vtu");
  writeTissueVtu(t, path);
  const Tissue r = readTissueVtu(path);
  REQUIRE(validate(r).ok);
  requireSameTissue(t, r);
  requireSameProperties(t, r);
  REQUIRE(r.numCells() == 12 + 4 - 1);
  REQUIRE(totalMeasure(r) == Approx(11.0).epsilon(1e-13));

  // Daughters: parent is a retired id, birth time the time of the division.
  int daughters = 0;
  for (CellId c : r.cells())
    if (r.parentId(c) >= 0) {
      ++daughters;
      REQUIRE((r.birthTime(c) == 1.0 || r.birthTime(c) == 2.0));
    }
  REQUIRE(daughters == 8);
  // New cells of the read tissue get ids never used by a live cell.
  std::int64_t max_id = -1;
  for (CellId c : r.cells()) max_id = std::max(max_id, r.lineageId(c));
  REQUIRE(r.nextLineageId() > max_id);
}

TEST_CASE("a 2D snapshot keeps the numbering and direction of edges", "[io][vtu][restart]") {
  // Divisions append edges, and a removed cell leaves tombstones: the
  // numbering of a run's complex is not the polygons' order of first use.
  TempDir dir;
  Tissue t = rectangularGrid(4, 3);
  for (Index i : {5u, 6u, 9u}) t.splitCell(CellId(i), Plane{cellCentroid(t, CellId(i)), Vec3(1, 0.3, 0)});
  t.splitCell(CellId(0), Plane{cellCentroid(t, CellId(0)), Vec3(0, 1, 0)});
  t.removeCell(CellId(11));
  const std::string path = dir.file("divided.vtu");
  writeTissueVtu(t, path);
  const Tissue r = readTissueVtu(path);
  requireSameTissue(t, r);
  CHECK(r.topology().layout() == t.topology().layout());

  // Without the arrays (a file written before 2D layouts were stored): the
  // same cells, edges numbered by first use.
  const std::string old = dir.file("old.vtu");
  io::testing::withoutLayoutArrays(path, old);
  const Tissue from_old = readTissueVtu(old);
  requireSameTissue(t, from_old);
  CHECK_FALSE(from_old.topology().layout() == t.topology().layout());

  // A polygon that is not its face's loop from where the loop starts.
  const std::string shifted = dir.file("shifted.vtu");
  io::testing::tamper(path, shifted, [](vtkUnstructuredGrid* grid) {
    vtkIdType n = 0;
    const vtkIdType* pts = nullptr;
    grid->GetCells()->GetCellAtId(0, n, pts);
    std::vector<vtkIdType> loop(pts, pts + n);
    std::rotate(loop.begin(), loop.begin() + 1, loop.end());
    grid->GetCells()->ReplaceCellAtId(0, n, loop.data());
  });
  try {
    readTissueVtu(shifted);
    FAIL("a polygon started elsewhere was accepted");
  } catch (const InputError& e) {
    INFO(e.what());
    CHECK(std::string(e.what()).find("cell 0 has another vertex loop than the topology arrays") != std::string::npos);
    CHECK(std::string(e.what()).find(shifted) != std::string::npos);
  }
}

TEST_CASE("the ids of removed cells are not handed out again after reading back", "[io][vtu]") {
  TempDir dir;
  Tissue t = rectangularGrid(2, 1);
  t.splitCell(CellId(0), Plane{cellCentroid(t, CellId(0)), Vec3(1, 0, 0)});
  // Remove the cell that holds the newest id: the file's live cells alone
  // would then suggest a smaller next id than the tissue's.
  CellId newest;
  for (CellId c : t.cells())
    if (!newest.valid() || t.lineageId(c) > t.lineageId(newest)) newest = c;
  REQUIRE(t.lineageId(newest) == t.nextLineageId() - 1);
  t.removeCell(newest);

  const std::string path = dir.file("removed_newest.vtu");
  writeTissueVtu(t, path);
  Tissue r = readTissueVtu(path);
  REQUIRE(r.nextLineageId() == t.nextLineageId());
  // A division of the read tissue gets ids nobody ever had.
  std::set<std::int64_t> before;
  for (CellId d : r.cells()) before.insert(r.lineageId(d));
  const CellId c = *r.cells().begin();
  r.splitCell(c, Plane{cellCentroid(r, c), Vec3(0, 1, 0)});
  int new_cells = 0;
  for (CellId d : r.cells())
    if (!before.count(r.lineageId(d))) {
      ++new_cells;
      CHECK(r.lineageId(d) >= t.nextLineageId());
    }
  CHECK(new_cells == 2);
}

TEST_CASE("division policies are saved, so a restored tissue divides its properties as before", "[io][vtu]") {
  TempDir dir;
  Tissue t = rectangularGrid(2, 2);
  auto& amount = t.cellProperties().add<double>("amount", 0.0, DivisionPolicy::SplitByMeasure);
  auto& marker = t.cellProperties().add<std::int32_t>("marker", 0, DivisionPolicy::Reset);
  auto& type = t.cellProperties().add<std::int32_t>("type", 0, DivisionPolicy::Copy);
  for (CellId c : t.cells()) {
    amount[c] = 8.0;
    marker[c] = 5;
    type[c] = 3;
  }
  const std::string path = dir.file("policies.vtu");
  writeTissueVtu(t, path);
  Tissue r = readTissueVtu(path);
  CHECK(r.cellProperties().get<double>("amount").policy() == DivisionPolicy::SplitByMeasure);
  CHECK(r.cellProperties().get<std::int32_t>("marker").policy() == DivisionPolicy::Reset);
  CHECK(r.cellProperties().get<std::int32_t>("type").policy() == DivisionPolicy::Copy);

  // A quarter/three-quarter cut: the amount splits by area, the marker resets.
  const CellId c = *r.cells().begin();
  const Vec3 centroid = cellCentroid(r, c);
  r.splitCell(c, Plane{centroid + Vec3(0.25, 0, 0), Vec3(1, 0, 0)});
  double total = 0;
  int fresh = 0;
  for (CellId d : r.cells()) {
    const double a = r.cellProperties().get<double>("amount")[d];
    total += a;
    if (r.parentId(d) < 0) continue;
    ++fresh;
    CHECK(a == Approx(8.0 * cellMeasure(r, d)).epsilon(1e-12));
    CHECK(r.cellProperties().get<std::int32_t>("marker")[d] == 0);
    CHECK(r.cellProperties().get<std::int32_t>("type")[d] == 3);
  }
  CHECK(fresh == 2);
  CHECK(total == Approx(32.0).epsilon(1e-12));
}

TEST_CASE("surface tissue keeps its 3D points, embedding and fan areas", "[io][vtu]") {
  TempDir dir;
  // A sheet folded along y = 1: a flat unit square and a square tilted 45 degrees.
  const std::vector<Vec3> points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {1, 2, 1}, {0, 2, 1}};
  Tissue t = buildPolygonTissue(points, {{0, 1, 2, 3}, {3, 2, 4, 5}}, Embedding::Surface);
  const std::string path = dir.file("surface.vtu");
  writeTissueVtu(t, path);
  const Tissue r = readTissueVtu(path);
  REQUIRE(r.embedding() == Embedding::Surface);
  REQUIRE(validate(r).ok);
  requireSameTissue(t, r);
  REQUIRE(cellMeasure(r, CellId(0)) == Approx(1.0).epsilon(1e-14));
  REQUIRE(cellMeasure(r, CellId(1)) == Approx(std::sqrt(2.0)).epsilon(1e-14));
}

TEST_CASE("every compression round-trips and is named in the file", "[io][vtu]") {
  TempDir dir;
  Tissue t = hexagonalGrid(8, 8);
  addCellProperties(t);
  addVertexProperties(t);
  for (auto [compression, marker] : {std::pair{Compression::None, ""},
                                     std::pair{Compression::LZ4, "vtkLZ4DataCompressor"},
                                     std::pair{Compression::ZLib, "vtkZLibDataCompressor"}}) {
    INFO(compressionName(compression));
    VtuOptions options;
    options.compression = compression;
    const std::string path = dir.file(std::string(compressionName(compression)) + ".vtu");
    writeTissueVtu(t, path, options);
    std::ifstream in(path, std::ios::binary);
    std::string head(512, '\0');
    in.read(head.data(), static_cast<std::streamsize>(head.size()));
    if (*marker)
      REQUIRE(head.find(std::string("compressor=\"") + marker) != std::string::npos);
    else
      REQUIRE(head.find("compressor=") == std::string::npos);
    REQUIRE(head.find("format=\"appended\"") != std::string::npos);
    const Tissue r = readTissueVtu(path);
    requireSameTissue(t, r);
    requireSameProperties(t, r);
  }
}

TEST_CASE("compression names parse both ways", "[io][vtu]") {
  for (Compression c : {Compression::None, Compression::LZ4, Compression::ZLib})
    REQUIRE(parseCompression(compressionName(c)) == c);
  REQUIRE(parseCompression("LZ4") == Compression::LZ4);
  REQUIRE_THROWS_WITH(parseCompression("gzip"), Catch::Contains("'gzip'"));
}

TEST_CASE("a property named like the derived measure is written as the property", "[io][vtu]") {
  TempDir dir;
  Tissue t = rectangularGrid(2, 2);
  auto& area = t.cellProperties().add<double>("area", 0.0);
  for (CellId c : t.cells()) area[c] = 10.0 + c.index();  // deliberately not the real area
  const std::string path = dir.file("area.vtu");
  writeTissueVtu(t, path);
  const Tissue r = readTissueVtu(path);
  requireSameColumn<double>(t, r, 2, "area", t.cells());
}

TEST_CASE("a tissue with a single cell and one with many vertices per cell", "[io][vtu]") {
  TempDir dir;
  std::vector<Vec3> circle;
  const int n = 64;
  std::vector<Index> loop;
  for (int k = 0; k < n; ++k) {
    circle.emplace_back(std::cos(2 * M_PI * k / n), std::sin(2 * M_PI * k / n), 0.0);
    loop.push_back(static_cast<Index>(k));
  }
  Tissue t = buildPolygonTissue(circle, {loop});
  const std::string path = dir.file("disk.vtu");
  writeTissueVtu(t, path);
  const Tissue r = readTissueVtu(path);
  REQUIRE(r.numCells() == 1);
  // Regular n-gon of circumradius 1: n/2 sin(2 pi / n).
  REQUIRE(cellMeasure(r, CellId(0)) == Approx(0.5 * n * std::sin(2 * M_PI / n)).epsilon(1e-13));
}
