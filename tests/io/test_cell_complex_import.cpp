// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Cell-complex PLY ("property topomesh"): closed volumes -> a 3D tissue,
// open patches -> a curved sheet, round trips through writeCellComplexPly,
// and a clear error (file, element index, label) for every bad input.

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include <catch2/catch.hpp>
#include <omp.h>

#include "io_test_support.hpp"
#include "tessella/generators/dome.hpp"
#include "tessella/generators/voronoi.hpp"
#include "tessella/io/cell_complex_ply.hpp"
#include "tessella/io/import.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/tissue/validate.hpp"

using namespace tessella;
using namespace tessella::io;
using tessella::io::testing::TempDir;
using Catch::Matchers::Contains;

namespace {

// A cell complex written by hand (independent of writeCellComplexPly).
struct Complex {
  std::vector<Vec3> vertices;
  std::vector<std::vector<int>> faces;
  std::vector<std::vector<int>> volumes;  // face indices, written as given
  std::vector<long long> labels;          // empty: no label property
  bool faces_by_edges = false;            // write faces as edge lists (edge_index)
  bool edge_element = true;               // write the (optional) edge element

  int vertex(const Vec3& p) {
    for (std::size_t i = 0; i < vertices.size(); ++i)
      if (vertices[i] == p) return static_cast<int>(i);
    vertices.push_back(p);
    return static_cast<int>(vertices.size()) - 1;
  }
  // The face on these vertices, added once (a wall shared by two volumes).
  int face(const std::vector<int>& loop) {
    std::vector<int> key = loop;
    std::sort(key.begin(), key.end());
    for (std::size_t f = 0; f < faces.size(); ++f) {
      std::vector<int> other = faces[f];
      std::sort(other.begin(), other.end());
      if (other == key) return static_cast<int>(f);
    }
    faces.push_back(loop);
    return static_cast<int>(faces.size()) - 1;
  }
  // An axis-aligned box, each side a quad or two triangles (split along the
  // diagonal through its smallest vertex index, so that a shared side splits
  // the same way from both boxes), listed as a volume.
  void box(const Vec3& lo, const Vec3& hi, long long label, bool triangles) {
    auto at = [&](int i, int j, int k) {
      return vertex(Vec3(i ? hi.x() : lo.x(), j ? hi.y() : lo.y(), k ? hi.z() : lo.z()));
    };
    const int sides[6][4][3] = {{{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}}, {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}},
                                {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}}, {{0, 1, 0}, {0, 1, 1}, {1, 1, 1}, {1, 1, 0}},
                                {{0, 0, 0}, {0, 0, 1}, {0, 1, 1}, {0, 1, 0}}, {{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}}};
    std::vector<int> list;
    for (const auto& side : sides) {
      std::vector<int> q;
      for (const auto& c : side) q.push_back(at(c[0], c[1], c[2]));
      if (!triangles) {
        list.push_back(face(q));
        continue;
      }
      std::rotate(q.begin(), std::min_element(q.begin(), q.end()), q.end());
      list.push_back(face({q[0], q[1], q[2]}));
      list.push_back(face({q[0], q[2], q[3]}));
    }
    volumes.push_back(list);
    labels.push_back(label);
  }
  void reverseFace(int f) { std::reverse(faces[f].begin(), faces[f].end()); }

  std::string text() const {
    std::vector<std::pair<int, int>> edges;
    std::map<std::pair<int, int>, int> edge_of;
    for (const auto& f : faces)
      for (std::size_t k = 0; k < f.size(); ++k) {
        const auto key = std::minmax(f[k], f[(k + 1) % f.size()]);
        if (edge_of.emplace(key, static_cast<int>(edges.size())).second) edges.push_back(key);
      }
    std::ostringstream o;
    o.precision(17);
    o << "ply\nformat ascii 1.0\nelement vertex " << vertices.size()
      << "\nproperty float64 x\nproperty float64 y\nproperty float64 z\n";
    o << "element face " << faces.size() << "\nproperty list uchar int "
      << (faces_by_edges ? "edge_index" : "vertex_index") << "\n";
    if (edge_element) o << "element edge " << edges.size() << "\nproperty int source\nproperty int target\n";
    o << "element volume " << volumes.size() << "\nproperty list uchar int face_index\n";
    if (!labels.empty()) o << "property int label\n";
    o << "end_header\n";
    for (const Vec3& p : vertices) o << p.x() << " " << p.y() << " " << p.z() << "\n";
    for (const auto& f : faces) {
      o << f.size();
      for (std::size_t k = 0; k < f.size(); ++k)
        o << " " << (faces_by_edges ? edge_of.at(std::minmax(f[k], f[(k + 1) % f.size()])) : f[k]);
      o << "\n";
    }
    for (auto [a, b] : edges)
      if (edge_element) o << a << " " << b << "\n";
    for (std::size_t v = 0; v < volumes.size(); ++v) {
      o << volumes[v].size();
      for (int f : volumes[v]) o << " " << f;
      if (!labels.empty()) o << " " << labels[v];
      o << "\n";
    }
    return o.str();
  }
  void write(const std::string& path) const { std::ofstream(path) << text(); }
};

std::map<std::int64_t, CellId> cellsByLabel(const Tissue& t) {
  std::map<std::int64_t, CellId> out;
  const auto& label = t.cellProperties().get<std::int64_t>("label");
  for (CellId c : t.cells()) out[label[c]] = c;
  return out;
}

// Cell `key` -> measure, and the set of neighbouring key pairs.
template <typename Key>
void measuresAndPairs(const Tissue& t, Key key, std::map<std::int64_t, double>& measure,
                      std::set<std::pair<std::int64_t, std::int64_t>>& pairs) {
  for (CellId c : t.cells()) {
    measure[key(c)] = cellMeasure(t, c);
    for (CellId d : t.cellNeighbors(c)) pairs.insert(std::minmax(key(c), key(d)));
  }
}

// Two boxes sharing the side x = 1: [0,1]^3 (label 7) and [1,3]x[0,1]^2 (label 3).
Complex twoBoxes(bool triangles) {
  Complex m;
  m.box(Vec3(0, 0, 0), Vec3(1, 1, 1), 7, triangles);
  m.box(Vec3(1, 0, 0), Vec3(3, 1, 1), 3, triangles);
  return m;
}

// Two unit squares side by side in z = 0, each two triangles: labels 5 and 2.
Complex twoSquares() {
  Complex m;
  const int a = m.vertex(Vec3(0, 0, 0)), b = m.vertex(Vec3(1, 0, 0)), c = m.vertex(Vec3(2, 0, 0));
  const int d = m.vertex(Vec3(0, 1, 0)), e = m.vertex(Vec3(1, 1, 0)), f = m.vertex(Vec3(2, 1, 0));
  m.faces = {{a, b, e}, {a, e, d}, {b, c, f}, {b, f, e}};
  m.volumes = {{0, 1}, {2, 3}};
  m.labels = {5, 2};
  return m;
}

std::string importError(const Complex& m, const TempDir& dir) {
  const std::string path = dir.file("bad.ply");
  m.write(path);
  try {
    importTissue(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

std::string importErrorText(const std::string& text, const TempDir& dir) {
  const std::string path = dir.file("bad.ply");
  std::ofstream(path) << text;
  try {
    importTissue(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST_CASE("cell complex: closed volumes become a 3D tissue, oriented outwards", "[io][import][cell_complex]") {
  TempDir dir;
  for (bool triangles : {true, false}) {
    Complex m = twoBoxes(triangles);
    // Faces written inconsistently: the importer orients them per cell.
    for (std::size_t f = 0; f < m.faces.size(); f += 3) m.reverseFace(static_cast<int>(f));
    const std::string path = dir.file("boxes.ply");
    m.write(path);
    const ImportResult r = importTissue(path);
    CHECK(r.report.format == "cell_complex");
    CHECK_THAT(r.report.notes[0], Contains("closed volumes, a 3D tissue"));
    const Tissue& t = r.tissue;
    REQUIRE(t.dim() == 3);
    REQUIRE(t.numCells() == 2);
    CHECK(validate(t).ok);
    // Each face of the file is one wall: 6 sides (x2 triangles) per box, one side shared.
    CHECK(t.numWalls() == (triangles ? 22u : 11u));
    const auto cells = cellsByLabel(t);
    REQUIRE(cells.size() == 2);
    CHECK(cells.begin()->first == 3);  // ordered by label
    CHECK(cellMeasure(t, cells.at(7)) == Approx(1.0).epsilon(1e-14));
    CHECK(cellMeasure(t, cells.at(3)) == Approx(2.0).epsilon(1e-14));
    CHECK(cellCentroid(t, cells.at(3)).isApprox(Vec3(2, 0.5, 0.5), 1e-14));
    CHECK(t.cellNeighbors(cells.at(7)) == std::vector<CellId>{cells.at(3)});
  }
}

TEST_CASE("cell complex: a cell with triangulated walls divides like any cell", "[io][import][cell_complex]") {
  TempDir dir;
  const std::string path = dir.file("boxes.ply");
  twoBoxes(true).write(path);
  Tissue t = importTissue(path).tissue;
  const auto cells = cellsByLabel(t);
  // y = 0.3 crosses the cube's side triangles and both triangles of the wall it shares.
  const CellSplit split = t.splitCell(cells.at(7), Plane{Vec3(0.5, 0.3, 0.5), Vec3(0, 1, 0)});
  CHECK(validate(t).ok);
  CHECK(cellMeasure(t, cells.at(7)) == Approx(0.3).epsilon(1e-13));
  CHECK(cellMeasure(t, split.daughter) == Approx(0.7).epsilon(1e-13));
  CHECK(cellMeasure(t, cells.at(3)) == Approx(2.0).epsilon(1e-13));
  const auto& label = t.cellProperties().get<std::int64_t>("label");
  CHECK(label[split.daughter] == 7);  // daughters copy the label
}

TEST_CASE("cell complex: faces given by edges, volumes as signed 1-based, no label", "[io][import][cell_complex]") {
  TempDir dir;
  Complex m = twoBoxes(true);
  m.faces_by_edges = true;
  m.labels.clear();
  // OpenAlea's oriented writer: +-(face + 1).
  for (auto& v : m.volumes)
    for (std::size_t k = 0; k < v.size(); ++k) v[k] = (k % 2 ? -1 : 1) * (v[k] + 1);
  const std::string path = dir.file("edges.ply");
  m.write(path);
  const ImportResult r = importTissue(path);
  const Tissue& t = r.tissue;
  REQUIRE(t.numCells() == 2);
  CHECK(validate(t).ok);
  const auto cells = cellsByLabel(t);  // labels are the volume indices
  CHECK(cellMeasure(t, cells.at(0)) == Approx(1.0).epsilon(1e-14));
  CHECK(cellMeasure(t, cells.at(1)) == Approx(2.0).epsilon(1e-14));
  bool told = false;
  for (const auto& n : r.report.notes)
    told = told || (n.find("edge_index") != std::string::npos && n.find("signed 1-based") != std::string::npos);
  CHECK(told);
}

TEST_CASE("cell complex: open patches become a curved sheet of their outlines", "[io][import][cell_complex]") {
  TempDir dir;
  Complex m = twoSquares();
  m.reverseFace(3);  // one triangle written the other way round
  const std::string path = dir.file("sheet.ply");
  m.write(path);
  const ImportResult r = importTissue(path, ImportOptions{"cell_complex", 2.0, 0.0, false});
  CHECK_THAT(r.report.notes[0], Contains("open patches of one surface"));
  CHECK_THAT(r.report.notes[1], Contains("1 faces reversed"));
  const Tissue& t = r.tissue;
  REQUIRE(t.dim() == 2);
  CHECK(t.embedding() == Embedding::Surface);
  REQUIRE(t.numCells() == 2);
  CHECK(validate(t).ok);
  const auto cells = cellsByLabel(t);
  CHECK(cellMeasure(t, cells.at(5)) == Approx(4.0).epsilon(1e-14));  // scale 2
  CHECK(cellMeasure(t, cells.at(2)) == Approx(4.0).epsilon(1e-14));
  CHECK(t.topology().faceVertices(t.cellFace(cells.at(5))).size() == 4);  // the outline, no diagonal
  CHECK(t.numVertices() == 6);
}

TEST_CASE("cell complex: a 3D Voronoi tissue round-trips through writeCellComplexPly", "[io][import][cell_complex]") {
  TempDir dir;
  const Box box{Vec3(0, 0, 0), Vec3(2, 1, 1.5)};
  const Tissue original = voronoiTissue(randomSeeds(box, 40, 11), box);
  std::map<std::int64_t, double> want, got;
  std::set<std::pair<std::int64_t, std::int64_t>> want_pairs, got_pairs;
  measuresAndPairs(original, [&](CellId c) { return original.lineageId(c); }, want, want_pairs);
  for (bool binary : {false, true}) {
    const std::string path = dir.file(binary ? "voronoi_bin.ply" : "voronoi.ply");
    const CellComplexPlyInfo info = writeCellComplexPly(original, path, CellComplexPlyOptions{binary});
    CHECK(info.label_source == "lineage_id");
    CHECK(info.volumes == original.numCells());
    CHECK(info.faces == original.numFaces());
    const Tissue back = importTissue(path).tissue;
    REQUIRE(back.dim() == 3);
    CHECK(validate(back).ok);
    CHECK(back.numCells() == original.numCells());
    CHECK(back.numFaces() == original.numFaces());
    CHECK(back.numEdges() == original.numEdges());
    CHECK(back.numVertices() == original.numVertices());
    const auto& label = back.cellProperties().get<std::int64_t>("label");
    got.clear(), got_pairs.clear();
    measuresAndPairs(back, [&](CellId c) { return label[c]; }, got, got_pairs);
    CHECK(got_pairs == want_pairs);
    REQUIRE(got.size() == want.size());
    double worst = 0;
    for (const auto& [l, v] : want) worst = std::max(worst, std::abs(got.at(l) - v) / v);
    CHECK(worst <= 1e-12);
    CHECK(totalMeasure(back) == Approx(3.0).epsilon(1e-12));  // the box
  }
}

TEST_CASE("cell complex: a dome sheet round-trips as open patches", "[io][import][cell_complex]") {
  TempDir dir;
  Dome dome;
  dome.base_radius = 1.0;
  dome.height = 0.6;
  const Tissue original = domeTissue(randomSeeds(Disk{}, 60, 5), dome);
  REQUIRE(original.embedding() == Embedding::Surface);
  std::map<std::int64_t, double> want, got;
  std::set<std::pair<std::int64_t, std::int64_t>> want_pairs, got_pairs;
  measuresAndPairs(original, [&](CellId c) { return original.lineageId(c); }, want, want_pairs);
  const std::string path = dir.file("dome.ply");
  writeCellComplexPly(original, path);
  const ImportResult r = importTissue(path);
  CHECK_THAT(r.report.notes[0], Contains("open patches"));
  const Tissue& back = r.tissue;
  CHECK(back.embedding() == Embedding::Surface);
  CHECK(validate(back).ok);
  CHECK(back.numCells() == original.numCells());
  CHECK(back.numEdges() == original.numEdges());
  CHECK(back.numVertices() == original.numVertices());
  const auto& label = back.cellProperties().get<std::int64_t>("label");
  measuresAndPairs(back, [&](CellId c) { return label[c]; }, got, got_pairs);
  CHECK(got_pairs == want_pairs);
  REQUIRE(got.size() == want.size());
  double worst = 0;
  for (const auto& [l, a] : want) worst = std::max(worst, std::abs(got.at(l) - a) / a);
  CHECK(worst <= 1e-12);
  // Normals keep their side: the sheet's outward normal at the summit points up.
  for (CellId c : back.cells()) CHECK(polygonMeasures(back, back.cellFace(c)).normal.z() > 0);
}

TEST_CASE("cell complex export: the label property when unique, else lineage ids", "[io][cell_complex]") {
  TempDir dir;
  Tissue t = voronoiTissue(randomSeeds(Rectangle{}, 12, 3), Rectangle{});
  auto& label = t.cellProperties().add<std::int64_t>("label", 0);
  std::int64_t next = 100;
  for (CellId c : t.cells()) label[c] = next--;
  const std::string path = dir.file("labelled.ply");
  CHECK(writeCellComplexPly(t, path).label_source == "label");
  const Tissue back = importTissue(path).tissue;
  std::map<std::int64_t, double> want, got;
  std::set<std::pair<std::int64_t, std::int64_t>> want_pairs, got_pairs;
  measuresAndPairs(t, [&](CellId c) { return label[c]; }, want, want_pairs);
  const auto& back_label = back.cellProperties().get<std::int64_t>("label");
  measuresAndPairs(back, [&](CellId c) { return back_label[c]; }, got, got_pairs);
  CHECK(got_pairs == want_pairs);
  for (const auto& [l, a] : want) CHECK(got.at(l) == Approx(a).epsilon(1e-12));
  // Daughters copy their mother's label: no longer unique, so lineage ids.
  const std::vector<CellId> cells = tessella::io::testing::liveList(t.cells());
  label[cells[0]] = label[cells[1]];
  CHECK(writeCellComplexPly(t, path).label_source == "lineage_id");
  label[cells[0]] = std::int64_t(1) << 40;
  CHECK_THROWS_WITH(writeCellComplexPly(t, dir.file("big.ply")),
                    Contains("cell 0 has label 1099511627776, beyond the 32-bit int"));
  CHECK_FALSE(std::filesystem::exists(dir.file("big.ply")));
}

TEST_CASE("cell complex: malformed files name the file, element and index", "[io][import][cell_complex][errors]") {
  TempDir dir;
  const std::string good = twoBoxes(false).text();
  const std::string path = dir.file("bad.ply");
  SECTION("a count larger than the data: truncated") {
    std::string text = good;
    text.replace(text.find("element volume 2"), 16, "element volume 3");
    const std::string e = importErrorText(text, dir);
    CHECK_THAT(e, Contains(path) && Contains("truncated") && Contains("volume"));
  }
  SECTION("a count smaller than the data") {
    std::string text = good;
    text.replace(text.find("element vertex 12"), 17, "element vertex 11");
    CHECK_THAT(importErrorText(text, dir), Contains(path) && Contains("line"));
  }
  SECTION("a file cut short") {
    const std::string cut = good.substr(0, good.rfind('\n', good.size() - 2) + 1);  // without the last volume
    CHECK_THAT(importErrorText(cut, dir), Contains(path) && Contains("truncated") && Contains("1 of the 2 'volume'"));
  }
  SECTION("a face's vertex index out of range") {
    Complex m = twoBoxes(false);
    m.faces[4][2] = 99;
    m.edge_element = false;
    CHECK_THAT(importError(m, dir),
               Contains(path) && Contains("face 4: vertex index 99 is out of range (the file has 12 vertices"));
  }
  SECTION("an edge's vertex index out of range") {
    Complex m = twoBoxes(false);
    m.faces[4][2] = 99;  // the fixture derives its edges from the faces
    CHECK_THAT(importError(m, dir), Contains(path) && Contains("edge 12: vertex index 99 is out of range"));
  }
  SECTION("a volume's face index out of range") {
    Complex m = twoBoxes(false);
    m.volumes[1][3] = 40;
    CHECK_THAT(importError(m, dir),
               Contains(path) && Contains("volume 1 (label 3): face index 40 is out of range (the file has 11 faces"));
  }
  SECTION("a face listed twice in one volume") {
    Complex m = twoBoxes(false);
    m.volumes[0].push_back(m.volumes[0][2]);
    CHECK_THAT(importError(m, dir), Contains(path) && Contains("volume 0 (label 7): lists face 2 twice"));
  }
  SECTION("a label used twice") {
    Complex m = twoBoxes(false);
    m.labels[1] = 7;
    CHECK_THAT(importError(m, dir), Contains(path) && Contains("volumes 0 and 1: label 7 appears twice"));
  }
}

TEST_CASE("cell complex: bad cells name the volume and its label", "[io][import][cell_complex][errors]") {
  TempDir dir;
  const std::string path = dir.file("bad.ply");
  SECTION("an open cell among closed ones") {
    Complex m = twoBoxes(true);
    m.volumes[1].pop_back();
    CHECK_THAT(importError(m, dir), Contains(path) && Contains("volume 1 (label 3): an open patch, but volume 0 "
                                                               "(label 7) is a closed surface"));
  }
  SECTION("a volume that is neither closed nor a patch: a ring") {
    Complex m = twoBoxes(false);
    // Box 0 without its two sides in z: a tube, open at both ends (two boundary loops).
    m.volumes[0].erase(m.volumes[0].begin(), m.volumes[0].begin() + 2);
    CHECK_THAT(importError(m, dir), Contains(path) && Contains("volume 0 (label 7): neither a closed surface nor a "
                                                               "patch of one") && Contains("2 boundary loop(s)"));
  }
  SECTION("a non-manifold cell: a fin on an edge") {
    Complex m = twoBoxes(false);
    const int a = m.vertex(Vec3(0, 0, 0)), b = m.vertex(Vec3(0, 1, 0)), c = m.vertex(Vec3(-1, 0.5, -1));
    m.volumes[0].push_back(m.face({a, b, c}));
    CHECK_THAT(importError(m, dir), Contains(path) && Contains("volume 0 (label 7): edge") &&
                                        Contains("is in 3 of its faces") && Contains("not a manifold"));
  }
  SECTION("a closed cell with a handle: a ring of eight cubes") {
    Complex m;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        if (i != 1 || j != 1) m.box(Vec3(i, j, 0), Vec3(i + 1, j + 1, 1), 10 * i + j, false);
    std::map<int, int> uses;
    for (const auto& v : m.volumes)
      for (int f : v) ++uses[f];
    std::vector<int> outside;
    for (auto [f, n] : uses)
      if (n == 1) outside.push_back(f);
    m.volumes = {outside};
    m.labels = {4};
    CHECK_THAT(importError(m, dir), Contains(path) && Contains("volume 0 (label 4): its closed surface has Euler "
                                                               "characteristic V-E+F = 0, expected 2"));
  }
  SECTION("a cell in two disconnected pieces") {
    Complex m = twoBoxes(false);
    m.box(Vec3(5, 5, 5), Vec3(6, 6, 6), 9, false);
    const std::vector<int> far = m.volumes.back();
    m.volumes.pop_back(), m.labels.pop_back();
    m.volumes[0].insert(m.volumes[0].end(), far.begin(), far.end());
    CHECK_THAT(importError(m, dir), Contains(path) && Contains("volume 0 (label 7): its faces form 2 disconnected "
                                                               "pieces"));
  }
  SECTION("two cells on the same side of a wall: they overlap") {
    Complex m = twoBoxes(false);
    m.volumes[1] = m.volumes[0];
    CHECK_THAT(importError(m, dir), Contains(path) && Contains("volumes 0 and 1 (labels 7 and 3) lie on the same "
                                                               "side of it"));
  }
  SECTION("one wall written twice instead of shared") {
    Complex m = twoBoxes(false);
    std::vector<int> copy = m.faces[m.volumes[1][4]];
    m.faces.push_back(copy);
    m.volumes[1][4] = static_cast<int>(m.faces.size()) - 1;
    CHECK_THAT(importError(m, dir), Contains(path) && Contains("have the same vertices"));
  }
  SECTION("of several bad cells, the first in file order is named, on 1 and 2 threads") {
    // 300 boxes in a row (volumes are analysed in parallel chunks), with a
    // fin on volume 70 and on volume 250: volume 70 is reported.
    Complex m;
    for (int i = 0; i < 300; ++i) m.box(Vec3(i, 0, 0), Vec3(i + 1, 1, 1), 1000 + i, false);
    for (int bad : {250, 70}) {
      const int a = m.vertex(Vec3(bad, 0, 0)), b = m.vertex(Vec3(bad, 1, 0));
      const int c = m.vertex(Vec3(bad + 0.5, 0.5, -1));
      m.volumes[bad].push_back(m.face({a, b, c}));
    }
    const int threads = omp_get_max_threads();
    for (int n : {1, 2}) {
      omp_set_num_threads(n);
      CHECK_THAT(importError(m, dir), Contains(path) && Contains("volume 70 (label 1070): edge") &&
                                          Contains("not a manifold"));
    }
    omp_set_num_threads(threads);
  }
  SECTION("patches sharing a face") {
    Complex m = twoSquares();
    m.volumes[1].push_back(0);
    CHECK_THAT(importError(m, dir), Contains(path) && Contains("face 0: listed by volumes 0 and 1 (labels 5 and 2)"));
  }
}
