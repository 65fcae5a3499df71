// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// MorphoGraphX cell meshes: what an import keeps, the options, and a clear
// error (file, element index, cell label) for every kind of bad cell.

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>

#include <catch2/catch.hpp>

#include "io_test_support.hpp"
#include "mgx_fixture.hpp"
#include "tessella/io/import.hpp"
#include "tessella/io/ply.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/tissue/validate.hpp"

using namespace tessella;
using namespace tessella::io;
using tessella::io::testing::MgxFixture;
using tessella::io::testing::TempDir;
using Catch::Matchers::Contains;

namespace {

std::map<std::int64_t, CellId> cellsByLabel(const Tissue& t) {
  std::map<std::int64_t, CellId> out;
  const auto& label = t.cellProperties().get<std::int64_t>("label");
  for (CellId c : t.cells()) out[label[c]] = c;
  return out;
}

std::string importError(const MgxFixture& m, const TempDir& dir, bool repair = false) {
  const std::string path = dir.file("bad.ply");
  m.write(path);
  try {
    importMorphoGraphX(path, ImportOptions{"auto", 1.0, 0.0, repair});
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST_CASE("mgx import: a grid of fan cells becomes a conforming curved sheet", "[io][import]") {
  TempDir dir;
  const MgxFixture m = MgxFixture::grid(3, 2, 3);
  for (auto format : {MgxFixture::Format::Ascii, MgxFixture::Format::BinaryLittleEndian,
                      MgxFixture::Format::BinaryBigEndian}) {
    const std::string path = dir.file("grid.ply");
    m.write(path, format);
    const ImportResult r = importTissue(path);
    const Tissue& t = r.tissue;
    CHECK(r.report.format == "morphographx");
    CHECK(r.report.repairs.empty());
    CHECK(t.dim() == 2);
    CHECK(t.embedding() == Embedding::Surface);
    REQUIRE(t.numCells() == 6);
    // Centres dropped, walls shared: the wall lattice's vertices only.
    CHECK(t.numVertices() == m.positions.size() - 6);
    CHECK(t.numEdges() == std::size_t(3 * 9 + 4 * 6));  // 3 horizontal and 4 vertical wall lines
    CHECK(validate(t).ok);
    const auto by_label = cellsByLabel(t);
    const auto& parent = t.cellProperties().get<std::int64_t>("parent");
    for (const auto& [label, c] : by_label) {
      CHECK(parent[c] == 1000 + label);
      CHECK(t.topology().faceVertices(FaceId(c.index())).size() == 12);
      // The outline's fan surface is close to the triangle mesh on a gently
      // curved sheet (exact for a flat one, see below).
      CHECK(cellMeasure(t, c) == Approx(m.triangleArea(static_cast<int>(label))).epsilon(1e-3));
    }
  }
}

TEST_CASE("mgx import: scale multiplies positions, flat cells keep their triangle area exactly", "[io][import]") {
  TempDir dir;
  const MgxFixture m = MgxFixture::grid(2, 2, 2, 0.0);
  const std::string path = dir.file("flat.ply");
  m.write(path);
  const ImportResult r = importTissue(path, ImportOptions{"morphographx", 2.5, 0.0, false});
  for (const auto& [label, c] : cellsByLabel(r.tissue))
    CHECK(cellMeasure(r.tissue, c) == Approx(m.triangleArea(static_cast<int>(label), 2.5)).epsilon(1e-12));
  CHECK_THROWS_WITH(importTissue(path, ImportOptions{"auto", -1.0, 0.0, false}), Contains("scale must be a positive"));
  CHECK_THROWS_WITH(importTissue(path, ImportOptions{"auto", 1.0, -0.1, false}), Contains("simplify tolerance"));
  CHECK_THROWS_WITH(importTissue(path, ImportOptions{"cellcomplex", 1.0, 0.0, false}),
                    Contains("unknown import format 'cellcomplex'") && Contains("morphographx (.ply)"));
}

TEST_CASE("mgx import: simplify straightens walls between junctions, both sides alike", "[io][import]") {
  TempDir dir;
  const MgxFixture m = MgxFixture::grid(3, 3, 4, 0.0);
  const std::string path = dir.file("grid.ply");
  m.write(path);
  const ImportResult full = importTissue(path);
  const ImportResult r = importTissue(path, ImportOptions{"auto", 1.0, 1e-6, false});
  // Straight walls: only the lattice corners stay; every cell is a quad.
  CHECK(r.tissue.numVertices() == 16);
  CHECK(r.report.simplified_vertices == full.tissue.numVertices() - 16);
  CHECK(validate(r.tissue).ok);
  for (CellId c : r.tissue.cells()) {
    CHECK(r.tissue.topology().faceVertices(FaceId(c.index())).size() == 4);
    CHECK(cellMeasure(r.tissue, c) == Approx(1.0).epsilon(1e-12));
  }
  // A bent wall keeps its bend beyond the tolerance.
  MgxFixture bent = m;
  bent.positions[bent.faces[bent.facesOf(10)[1]][1]].y() -= 0.2;  // a vertex inside the bottom wall of cell 10
  bent.write(path);
  const ImportResult b = importTissue(path, ImportOptions{"auto", 1.0, 0.1, false});
  CHECK(b.tissue.numVertices() > 16);
  CHECK(b.tissue.numVertices() < full.tissue.numVertices());
  bool bend_kept = false;
  for (VertexId v : b.tissue.vertices()) bend_kept = bend_kept || b.tissue.position(v).isApprox(Vec3(0.25, -0.2, 0));
  CHECK(bend_kept);
  CHECK(validate(b.tissue).ok);
}

TEST_CASE("mgx import: a wall with no junction keeps a polygon", "[io][import]") {
  // One cell alone: its whole outline is one closed wall.
  TempDir dir;
  const MgxFixture m = MgxFixture::grid(1, 1, 3, 0.0);
  const std::string path = dir.file("one.ply");
  m.write(path);
  const ImportResult r = importTissue(path, ImportOptions{"auto", 1.0, 1e-6, false});
  CHECK(r.tissue.numCells() == 1);
  CHECK(r.tissue.numVertices() >= 3);
  CHECK(validate(r.tissue).ok);
}

TEST_CASE("mgx import: bad cells are errors naming the file, the face and the label", "[io][import]") {
  TempDir dir;
  const MgxFixture grid = MgxFixture::grid(3, 3, 3, 0.0);

  SECTION("a face index out of range") {
    MgxFixture m = grid;
    m.faces[7][2] = 9999;
    CHECK_THAT(importError(m, dir), Contains("bad.ply' face 7 (cell label 10): vertex index 9999 is out of range"));
  }
  SECTION("duplicated vertices") {
    MgxFixture m = grid;
    // Cell 11 gets its own copy of a wall vertex it shares with cell 10.
    const int shared = m.faces[m.facesOf(10)[3]][2];
    const int copy = m.addVertex(0, 0, 0, -1, 0);
    m.positions[copy] = m.positions[shared];
    for (std::size_t f : m.facesOf(11))
      for (int& v : m.faces[f])
        if (v == shared) v = copy;
    CHECK_THAT(importError(m, dir), Contains("vertices " + std::to_string(shared) + " and " + std::to_string(copy) +
                                             " are duplicates") &&
                                        Contains("cell label 11") && Contains("not welded"));
  }
  SECTION("a cell in two pieces, and the one-triangle sliver repair") {
    MgxFixture m = grid;
    const std::size_t f = m.facesOf(10)[0];  // a triangle of the corner cell given to the far corner's label
    m.face_label[f] = 18;
    CHECK_THAT(importError(m, dir),
               Contains("(cell label 18): the cell is made of 2 disconnected pieces") && Contains("repair: true"));
    const std::string path = dir.file("sliver.ply");
    m.write(path);
    const ImportResult r = importTissue(path, ImportOptions{"auto", 1.0, 0.0, true});
    REQUIRE(r.report.repairs.size() == 1);
    CHECK_THAT(r.report.repairs[0], Contains("face " + std::to_string(f)) && Contains("sliver of cell label 18") &&
                                        Contains("moved to cell label 10"));
    CHECK(r.tissue.numCells() == 9);
    CHECK(validate(r.tissue).ok);
    for (const auto& [label, c] : cellsByLabel(r.tissue))
      CHECK(cellMeasure(r.tissue, c) == Approx(1.0).epsilon(1e-12));
  }
  SECTION("a label used by two separate cells") {
    MgxFixture m = grid;
    for (std::size_t f : m.facesOf(18)) m.face_label[f] = 10;
    for (int& l : m.vertex_label)
      if (l == 18) l = 10;
    CHECK_THAT(importError(m, dir), Contains("label 10 appears twice as separate cells"));
    CHECK_THAT(importError(m, dir, true), Contains("label 10 appears twice as separate cells"));
  }
  SECTION("a cell with the wrong orientation") {
    MgxFixture m = grid;
    for (std::size_t f : m.facesOf(14)) std::swap(m.faces[f][1], m.faces[f][2]);
    CHECK_THAT(importError(m, dir), Contains("cell label 14") && Contains("oriented opposite ways"));
  }
  SECTION("a non-positive face label") {
    MgxFixture m = grid;
    m.face_label[5] = -1;
    CHECK_THAT(importError(m, dir), Contains("face 5 (cell label -1): label -1 is no cell"));
  }
}

TEST_CASE("mgx import: a cell with a hole and a pinched cell are not disks", "[io][import]") {
  TempDir dir;
  const std::string path = dir.file("bad.ply");
  SECTION("hole") {
    // Cell 1: a square ring of 8 triangles around cell 2 (a square of 2).
    MgxFixture m;
    const double pts[8][2] = {{0, 0}, {3, 0}, {3, 3}, {0, 3}, {1, 1}, {2, 1}, {2, 2}, {1, 2}};
    for (const auto& p : pts) m.addVertex(p[0], p[1], 0, -1, 0);
    for (int k = 0; k < 4; ++k) {
      const int o0 = k, o1 = (k + 1) % 4, i0 = 4 + k, i1 = 4 + (k + 1) % 4;
      m.faces.push_back({o0, o1, i1}), m.face_label.push_back(1);
      m.faces.push_back({o0, i1, i0}), m.face_label.push_back(1);
    }
    m.faces.push_back({4, 5, 6}), m.face_label.push_back(2);
    m.faces.push_back({4, 6, 7}), m.face_label.push_back(2);
    m.write(path);
    CHECK_THROWS_WITH(importMorphoGraphX(path), Contains("face 0 (cell label 1): the cell has a hole") &&
                                                    Contains("2 loops"));
  }
  SECTION("pinched") {
    MgxFixture m;
    for (int i = 0; i < 6; ++i) m.addVertex(std::cos(i), std::sin(i), 0.1 * i, -1, 0);
    for (auto tri : std::vector<std::vector<int>>{{0, 1, 2}, {2, 1, 3}, {2, 3, 4}, {4, 3, 5}, {4, 5, 0}})
      m.faces.push_back(tri), m.face_label.push_back(7);
    m.write(path);
    CHECK_THROWS_WITH(importMorphoGraphX(path), Contains("(cell label 7)") && Contains("pinched, non-manifold vertex"));
  }
}

TEST_CASE("import: auto tells a MorphoGraphX mesh from other PLY layouts", "[io][import]") {
  TempDir dir;
  const std::string plain = dir.file("plain.ply");
  std::ofstream(plain) << "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                          "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                          "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  CHECK_THROWS_WITH(importTissue(plain), Contains("its layout (it holds vertex(x y z), face(vertex_indices)) is none "
                                                  "of the supported formats") &&
                                             Contains("morphographx (.ply)") && Contains("cell_complex (.ply)"));
  const std::string txt = dir.file("cells.stl");
  std::ofstream(txt) << "solid\n";
  CHECK_THROWS_WITH(importTissue(txt), Contains("no import format reads '.stl' files"));
  const MgxFixture m = MgxFixture::grid(1, 1, 1);
  const std::string upper = dir.file("GRID.PLY");
  m.write(upper);
  CHECK(detectImportFormat(upper).name == "morphographx");
  CHECK(importFormatNames() == std::vector<std::string>{"auto", "morphographx", "cell_complex", "labelled_mesh",
                                                        "labelled_vtu", "label_image"});
}

TEST_CASE("mgx cell graph: labels, areas and neighbour pairs by label", "[io][import]") {
  TempDir dir;
  const std::string path = dir.file("cellGraph.ply");
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty int label\nproperty float x\nproperty float y\n"
      "property float z\nproperty float Geometry/Area\nproperty list uchar float /Cell Axis curv10microns\nelement edge 5\n"
      "property uint source\nproperty uint target\nend_header\n"
      "5 0 0 0 1.5 2 0.1 0.2\n9 1 0 0 2.5 0\n12 0 1 0 3 1 7\n";
  std::ofstream(path) << header << "5 9\n9 5\n9 12\n12 9\n5 9\n";
  const MorphoGraphXCellGraph g = readMorphoGraphXCellGraph(path);
  CHECK(g.labels == std::vector<std::int64_t>{5, 9, 12});
  CHECK(g.areas == std::vector<double>{1.5, 2.5, 3});
  CHECK(g.edges.size() == 5);
  // MorphoGraphX names properties with spaces: the name is the rest of the line.
  CHECK(PlyFile::read(path).hasProperty("vertex", "/Cell Axis curv10microns"));
  CHECK(g.neighbourPairs() == std::vector<std::pair<std::int64_t, std::int64_t>>{{5, 9}, {9, 12}});
  std::ofstream(path) << header << "5 9\n9 5\n9 12\n12 9\n5 7\n";
  CHECK_THROWS_WITH(readMorphoGraphXCellGraph(path), Contains("edge 4: 7 is not the label of a listed cell"));
}
