// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Generic labelled meshes (format labelled_mesh): a Tessella sheet written as
// labelled fan triangles, and a 3D Voronoi tissue written as triangles with
// the cells on either side, in PLY (ASCII, binary), OBJ and VTK PolyData,
// read back with the same cells, neighbours and measures; the real meristem
// converted to a labelled .vtp gives the MorphoGraphX import's tissue; and a
// clear error (file, element, label) for every bad input.

#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include <catch2/catch.hpp>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataWriter.h>

#include "io_test_support.hpp"
#include "tessella/generators/dome.hpp"
#include "tessella/generators/voronoi.hpp"
#include "tessella/io/import.hpp"
#include "tessella/io/ply.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/tissue/validate.hpp"

using namespace tessella;
using namespace tessella::io;
using tessella::io::testing::TempDir;
using Catch::Matchers::Contains;

namespace {

// Polygons with one label each (back empty) or two (the cells on either side).
struct LabelledFaces {
  std::vector<Vec3> points;
  std::vector<std::vector<int>> faces;
  std::vector<long long> front, back;
  std::vector<std::string> names = {"label"};  // PLY property / VTK array names (two for front, back)
  bool float_labels = false;                   // PLY: labels as double

  std::size_t addPoint(const Vec3& p) {
    points.push_back(p);
    return points.size() - 1;
  }

  void writePly(const std::string& path, bool binary) const {
    REQUIRE(std::endian::native == std::endian::little);
    std::ofstream out(path, std::ios::binary);
    out << "ply\nformat " << (binary ? "binary_little_endian" : "ascii") << " 1.0\n"
        << "element vertex " << points.size() << "\nproperty double x\nproperty double y\nproperty double z\n"
        << "element face " << faces.size() << "\nproperty list uchar int vertex_indices\n";
    for (const std::string& n : names) out << "property " << (float_labels ? "double " : "int ") << n << "\n";
    out << "end_header\n";
    auto put = [&](auto v) { out.write(reinterpret_cast<const char*>(&v), sizeof(v)); };
    out.precision(17);
    for (const Vec3& p : points) {
      if (binary) put(p.x()), put(p.y()), put(p.z());
      else out << p.x() << " " << p.y() << " " << p.z() << "\n";
    }
    for (std::size_t f = 0; f < faces.size(); ++f) {
      std::vector<long long> labels{front[f]};
      if (!back.empty()) labels.push_back(back[f]);
      if (binary) {
        put(static_cast<unsigned char>(faces[f].size()));
        for (int v : faces[f]) put(static_cast<std::int32_t>(v));
        for (long long l : labels) float_labels ? put(static_cast<double>(l)) : put(static_cast<std::int32_t>(l));
      } else {
        out << faces[f].size();
        for (int v : faces[f]) out << " " << v;
        for (long long l : labels) out << " " << l;
        out << "\n";
      }
    }
  }

  // Each run of faces with the same labels under one `g` statement.
  void writeObj(const std::string& path) const {
    std::ofstream out(path);
    out.precision(17);
    out << "# labelled_mesh test\n";
    for (const Vec3& p : points) out << "v " << p.x() << " " << p.y() << " " << p.z() << "\n";
    std::string group;
    for (std::size_t f = 0; f < faces.size(); ++f) {
      const std::string g = "g " + std::to_string(front[f]) + (back.empty() ? "" : " " + std::to_string(back[f]));
      if (g != group) out << (group = g) << "\n";
      out << "f";
      for (int v : faces[f]) out << " " << v + 1 << "//";  // v//n form, normals absent: still a vertex index
      out << "\n";
    }
  }

  // Two labels as one 2-component array when names has one entry.
  void writeVtp(const std::string& path) const {
    auto data = vtkSmartPointer<vtkPolyData>::New();
    auto pts = vtkSmartPointer<vtkPoints>::New();
    pts->SetDataTypeToDouble();
    for (const Vec3& p : points) pts->InsertNextPoint(p.x(), p.y(), p.z());
    data->SetPoints(pts);
    auto polys = vtkSmartPointer<vtkCellArray>::New();
    for (const auto& f : faces) {
      std::vector<vtkIdType> ids(f.begin(), f.end());
      polys->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
    }
    data->SetPolys(polys);
    const bool pair_in_one = !back.empty() && names.size() == 1;
    for (std::size_t a = 0; a < names.size(); ++a) {
      auto label = vtkSmartPointer<vtkIntArray>::New();
      label->SetName(names[a].c_str());
      label->SetNumberOfComponents(pair_in_one ? 2 : 1);
      for (std::size_t f = 0; f < faces.size(); ++f) {
        if (pair_in_one) {
          label->InsertNextValue(static_cast<int>(front[f]));
          label->InsertNextValue(static_cast<int>(back[f]));
        } else {
          label->InsertNextValue(static_cast<int>(a == 0 ? front[f] : back[f]));
        }
      }
      data->GetCellData()->AddArray(label);
    }
    auto writer = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
    writer->SetFileName(path.c_str());
    writer->SetInputData(data);
    REQUIRE(writer->Write() == 1);
  }
};

// A sheet's cells as fan triangles around each cell's vertex mean, labelled
// lineage id + 1; the tissue's vertices keep their indices.
LabelledFaces fanTriangles(const Tissue& t, std::map<long long, double>& triangle_area) {
  LabelledFaces m;
  for (const Vec3& p : t.positions()) m.points.push_back(p);
  for (CellId c : t.cells()) {
    const auto loop = t.topology().faceVertices(t.cellFace(c));
    Vec3 mean = Vec3::Zero();
    for (VertexId v : loop) mean += t.position(v);
    mean /= double(loop.size());
    const int centre = static_cast<int>(m.addPoint(mean));
    const long long label = t.lineageId(c) + 1;
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const VertexId a = loop[k], b = loop[(k + 1) % loop.size()];
      m.faces.push_back({centre, static_cast<int>(a.index()), static_cast<int>(b.index())});
      m.front.push_back(label);
      triangle_area[label] += 0.5 * (t.position(a) - mean).cross(t.position(b) - mean).norm();
    }
  }
  return m;
}

// A 3D tissue's walls as fan triangles from each wall's first vertex (the
// walls are planar and convex), labelled with the cells on either side
// (lineage id + 1; 0 outside).
LabelledFaces wallTriangles(const Tissue& t) {
  LabelledFaces m;
  for (const Vec3& p : t.positions()) m.points.push_back(p);
  for (WallId w : t.walls()) {
    const auto cells = t.wallCells(w);
    const long long a = t.lineageId(cells[0]) + 1, b = cells.size() > 1 ? t.lineageId(cells[1]) + 1 : 0;
    const auto loop = t.topology().faceVertices(FaceId(w.index()));
    for (std::size_t k = 1; k + 1 < loop.size(); ++k) {
      m.faces.push_back({static_cast<int>(loop[0].index()), static_cast<int>(loop[k].index()),
                         static_cast<int>(loop[k + 1].index())});
      m.front.push_back(a);
      m.back.push_back(b);
    }
  }
  return m;
}

using Pairs = std::set<std::pair<std::int64_t, std::int64_t>>;

template <typename Key>
void measuresAndPairs(const Tissue& t, Key key, std::map<long long, double>& measure, Pairs& pairs) {
  for (CellId c : t.cells()) {
    measure[key(c)] = cellMeasure(t, c);
    for (CellId d : t.cellNeighbors(c)) pairs.insert(std::minmax<std::int64_t>(key(c), key(d)));
  }
}

double worstRelative(const std::map<long long, double>& want, const std::map<long long, double>& got) {
  REQUIRE(got.size() == want.size());
  double worst = 0;
  for (const auto& [l, v] : want) worst = std::max(worst, std::abs(got.at(l) - v) / v);
  return worst;
}

enum class Kind { PlyAscii, PlyBinary, Obj, Vtp };

std::string write(const LabelledFaces& m, Kind kind, const TempDir& dir, const std::string& stem) {
  switch (kind) {
    case Kind::PlyAscii: m.writePly(dir.file(stem + "_ascii.ply"), false); return dir.file(stem + "_ascii.ply");
    case Kind::PlyBinary: m.writePly(dir.file(stem + "_binary.ply"), true); return dir.file(stem + "_binary.ply");
    case Kind::Obj: m.writeObj(dir.file(stem + ".obj")); return dir.file(stem + ".obj");
    case Kind::Vtp: m.writeVtp(dir.file(stem + ".vtp")); return dir.file(stem + ".vtp");
  }
  return {};
}

std::string importError(const std::string& path, const ImportOptions& options = {}) {
  try {
    importTissue(path, options);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

// Two unit squares side by side in z = 0, each two triangles: labels 5 and 2.
LabelledFaces twoSquares() {
  LabelledFaces m;
  m.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0), Vec3(2, 1, 0)};
  m.faces = {{0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}};
  m.front = {5, 5, 2, 2};
  return m;
}

}  // namespace

TEST_CASE("labelled mesh: a dome sheet as labelled fan triangles round-trips in every format",
          "[io][import][labelled_mesh]") {
  TempDir dir;
  Dome dome;
  dome.base_radius = 1.0;
  dome.height = 0.6;
  const Tissue original = domeTissue(randomSeeds(Disk{}, 60, 5), dome);
  std::map<long long, double> triangle_area, want, got;
  Pairs want_pairs, got_pairs;
  const LabelledFaces m = fanTriangles(original, triangle_area);
  measuresAndPairs(original, [&](CellId c) { return original.lineageId(c) + 1; }, want, want_pairs);
  for (Kind kind : {Kind::PlyAscii, Kind::PlyBinary, Kind::Obj, Kind::Vtp}) {
    const std::string path = write(m, kind, dir, "dome");
    INFO(path);
    const ImportResult r = importTissue(path);
    CHECK(r.report.format == "labelled_mesh");
    CHECK(r.report.file_faces == m.faces.size());
    CHECK_THAT(r.report.notes[0], Contains("open patches"));
    const Tissue& back = r.tissue;
    REQUIRE(back.dim() == 2);
    CHECK(back.embedding() == Embedding::Surface);
    CHECK(validate(back).ok);
    CHECK(back.numCells() == original.numCells());
    CHECK(back.numEdges() == original.numEdges());
    CHECK(back.numVertices() == original.numVertices());  // the centres are dropped
    const auto& label = back.cellProperties().get<std::int64_t>("label");
    got.clear(), got_pairs.clear();
    measuresAndPairs(back, [&](CellId c) { return label[c]; }, got, got_pairs);
    CHECK(got_pairs == want_pairs);
    CHECK(worstRelative(want, got) <= 1e-12);
    // The fan triangles span the same surface as the cell's own fan.
    CHECK(worstRelative(triangle_area, got) <= 1e-12);
    for (CellId c : back.cells()) CHECK(polygonMeasures(back, back.cellFace(c)).normal.z() > 0);
  }
}

TEST_CASE("labelled mesh: a label array of another name, given by label_array", "[io][import][labelled_mesh]") {
  TempDir dir;
  LabelledFaces m = twoSquares();
  m.names = {"segment"};
  for (Kind kind : {Kind::PlyAscii, Kind::Vtp}) {
    const std::string path = write(m, kind, dir, "squares");
    if (kind == Kind::Vtp)
      CHECK_THAT(importError(path), Contains(path) && Contains("(it has segment)") &&
                                        Contains("label, cell_label, cell_id"));
    else
      CHECK_THAT(importError(path), Contains(path) && Contains("face(vertex_indices segment)") &&
                                        Contains("none of the supported formats") && Contains("--label-array"));
    const ImportResult r = importTissue(path, ImportOptions{"auto", 2.0, 0.0, false, "segment"});
    const Tissue& t = r.tissue;
    REQUIRE(t.numCells() == 2);
    const auto& label = t.cellProperties().get<std::int64_t>("label");
    CHECK(label[CellId(0)] == 2);  // cells ordered by label
    CHECK(label[CellId(1)] == 5);
    CHECK(cellMeasure(t, CellId(0)) == Approx(4.0).epsilon(1e-14));  // scale 2
    CHECK(t.numVertices() == 6);
    CHECK(t.topology().faceVertices(t.cellFace(CellId(0))).size() == 4);  // the outline, no diagonal
    CHECK_THAT(r.report.notes.back(), Contains("segment"));
  }
  // The option is for labelled formats only.
  const std::string obj = write(twoSquares(), Kind::Obj, dir, "squares");
  CHECK(importTissue(obj, ImportOptions{"auto", 1.0, 0.0, false, "g"}).tissue.numCells() == 2);
  CHECK_THAT(importError(obj, ImportOptions{"auto", 1.0, 0.0, false, "vn"}), Contains("g, o or usemtl"));
  CHECK_THAT(importError(obj, ImportOptions{"morphographx", 1.0, 0.0, false, "label"}),
             Contains("applies to the labelled_mesh and labelled_vtu formats"));
}

TEST_CASE("labelled mesh: a 3D Voronoi tissue as triangles labelled with the cells on either side",
          "[io][import][labelled_mesh]") {
  TempDir dir;
  const Box box{Vec3(0, 0, 0), Vec3(2, 1, 1.5)};
  const Tissue original = voronoiTissue(randomSeeds(box, 40, 11), box);
  std::map<long long, double> want, got;
  Pairs want_pairs, got_pairs;
  measuresAndPairs(original, [&](CellId c) { return original.lineageId(c) + 1; }, want, want_pairs);
  LabelledFaces m = wallTriangles(original);
  for (int variant = 0; variant < 5; ++variant) {
    // PLY ascii and binary (label_front, label_back), OBJ (g A B), .vtp as
    // one 2-component array and as two arrays.
    m.names = variant == 3 ? std::vector<std::string>{"label"} : std::vector<std::string>{"label_front", "label_back"};
    const Kind kind = variant == 0 ? Kind::PlyAscii : variant == 1 ? Kind::PlyBinary : variant == 2 ? Kind::Obj
                                                                                                      : Kind::Vtp;
    const std::string path = write(m, kind, dir, "voronoi" + std::to_string(variant));
    INFO(path);
    const ImportResult r = importTissue(path);
    CHECK_THAT(r.report.notes[0], Contains("closed cells, a 3D tissue"));
    const Tissue& back = r.tissue;
    REQUIRE(back.dim() == 3);
    CHECK(validate(back).ok);
    CHECK(back.numCells() == original.numCells());
    CHECK(back.numFaces() == m.faces.size());  // each triangle a wall
    CHECK(back.numVertices() == original.numVertices());
    const auto& label = back.cellProperties().get<std::int64_t>("label");
    got.clear(), got_pairs.clear();
    measuresAndPairs(back, [&](CellId c) { return label[c]; }, got, got_pairs);
    CHECK(got_pairs == want_pairs);
    CHECK(worstRelative(want, got) <= 1e-12);
    CHECK(totalMeasure(back) == Approx(3.0).epsilon(1e-12));  // the box
  }
}

TEST_CASE("labelled mesh: the real meristem as a labelled .vtp gives the MorphoGraphX import's tissue",
          "[io][import][labelled_mesh][real]") {
  TempDir dir;
  std::vector<std::string> files = {std::string(TESSELLA_SOURCE_DIR) +
                                    "/tests/data/mgx_meristem_cropped/mesh_meristem_cropped_T0.ply"};
  const std::string shared = std::string(TESSELLA_SOURCE_DIR) + "/../shared/data/mgx_meristem_cropped";
  if (std::filesystem::exists(shared + "/mesh_meristem_cropped_T12h.ply")) {
    files.push_back(shared + "/mesh_meristem_cropped_T12h.ply");
    files.push_back(shared + "/mesh_meristem_cropped_T24h.ply");
  } else {
    WARN("SKIPPED T12h and T24h: the real-tissue data folder " << shared << " is absent (T0 from tests/data runs)");
  }
  for (const std::string& mgx : files) {
    INFO(mgx);
    REQUIRE(std::filesystem::exists(mgx));
    // MorphoGraphX's layout -> plain triangles with a cell-data label (its own reader, not the importer's).
    const PlyFile ply = PlyFile::read(mgx);
    LabelledFaces m;
    const auto &x = ply.scalar("vertex", "x").values, &y = ply.scalar("vertex", "y").values,
               &z = ply.scalar("vertex", "z").values;
    for (std::size_t i = 0; i < x.size(); ++i) m.points.emplace_back(x[i], y[i], z[i]);
    const PlyColumn& fv = ply.list("face", "vertex_index");
    const auto& fl = ply.scalar("face", "label").values;
    for (std::size_t f = 0; f + 1 < fv.offsets.size(); ++f) {
      m.faces.emplace_back();
      for (std::size_t k = fv.offsets[f]; k < fv.offsets[f + 1]; ++k) m.faces.back().push_back(int(fv.values[k]));
      m.front.push_back(static_cast<long long>(fl[f]));
    }
    const std::string vtp = dir.file("meristem.vtp");
    m.writeVtp(vtp);
    const Tissue want = importTissue(mgx, ImportOptions{"morphographx"}).tissue;
    const ImportResult r = importTissue(vtp);
    CHECK(r.report.format == "labelled_mesh");
    const Tissue& got = r.tissue;
    CHECK(validate(got).ok);
    REQUIRE(got.numCells() == want.numCells());
    CHECK(got.numVertices() == want.numVertices());
    CHECK(got.numEdges() == want.numEdges());
    std::map<long long, double> a, b;
    Pairs pa, pb;
    const auto& la = want.cellProperties().get<std::int64_t>("label");
    const auto& lb = got.cellProperties().get<std::int64_t>("label");
    measuresAndPairs(want, [&](CellId c) { return la[c]; }, a, pa);
    measuresAndPairs(got, [&](CellId c) { return lb[c]; }, b, pb);
    CHECK(pa == pb);
    CHECK(worstRelative(a, b) <= 1e-12);
  }
}

TEST_CASE("labelled mesh: bad files name the file, the element and the label", "[io][import][labelled_mesh][errors]") {
  TempDir dir;
  SECTION("no label array: the message lists what is there") {
    LabelledFaces m = twoSquares();
    m.names = {"quality"};
    const std::string ply = write(m, Kind::PlyBinary, dir, "bad");
    CHECK_THAT(importError(ply), Contains(ply) && Contains("none of the supported formats"));
    CHECK_THAT(importError(ply, ImportOptions{"labelled_mesh"}),
               Contains(ply) && Contains("no cell label property") && Contains("it has vertex_indices, quality"));
    const std::string vtp = write(m, Kind::Vtp, dir, "bad");
    CHECK_THAT(importError(vtp), Contains(vtp) && Contains("(it has quality)"));
    CHECK_THAT(importError(vtp, ImportOptions{"auto", 1.0, 0.0, false, "region"}),
               Contains("no cell-data array 'region'"));
  }
  SECTION("a PLY without faces, read as labelled_mesh") {
    const std::string path = dir.file("points.ply");
    std::ofstream(path) << "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                           "property float z\nend_header\n0 0 0\n";
    CHECK_THAT(importError(path, ImportOptions{"labelled_mesh"}), Contains(path) && Contains("face"));
  }
  SECTION("a label that is no integer") {
    LabelledFaces m = twoSquares();
    m.float_labels = true;
    const std::string ok = write(m, Kind::PlyAscii, dir, "float");  // integral doubles are labels
    CHECK(importTissue(ok).tissue.numCells() == 2);
    std::string text;
    {
      std::ifstream in(ok);
      text.assign(std::istreambuf_iterator<char>(in), {});
    }
    const auto at = text.rfind("3 1 5 4 2");
    REQUIRE(at != std::string::npos);
    text.replace(at, 9, "3 1 5 4 2.5");
    const std::string bad = dir.file("float_bad.ply");
    std::ofstream(bad) << text;
    CHECK_THAT(importError(bad), Contains(bad) && Contains("face 3") && Contains("label 2.5 is not an integer"));
  }
  SECTION("a vertex index out of range") {
    LabelledFaces m = twoSquares();
    m.faces[2][1] = 99;
    for (Kind kind : {Kind::PlyAscii, Kind::PlyBinary, Kind::Vtp}) {
      const std::string path = write(m, kind, dir, "range");
      CHECK_THAT(importError(path), Contains(path) && Contains(" 2 (cell label 2)") && Contains("99") &&
                                        Contains("out of range"));
    }
    const std::string obj = write(m, Kind::Obj, dir, "range");
    CHECK_THAT(importError(obj), Contains(obj) && Contains("line 12 (face 2, cell label 2)") &&
                                     Contains("vertex index 100 is out of range"));
  }
  SECTION("a truncated binary file") {
    const std::string path = write(twoSquares(), Kind::PlyBinary, dir, "cut");
    std::filesystem::resize_file(path, std::filesystem::file_size(path) - 7);
    CHECK_THAT(importError(path), Contains(path) && Contains("truncated") && Contains("element 'face' 3"));
  }
  SECTION("a label in two pieces") {
    LabelledFaces m = twoSquares();
    m.points.push_back(Vec3(3, 0, 0)), m.points.push_back(Vec3(3, 1, 0));
    m.faces.push_back({2, 6, 7});  // label 5 again, apart from its square
    m.front.push_back(5);
    for (Kind kind : {Kind::PlyAscii, Kind::Obj, Kind::Vtp}) {
      const std::string path = write(m, kind, dir, "pieces");
      CHECK_THAT(importError(path), Contains(path) && Contains("label 5") && Contains("2 disconnected pieces"));
    }
  }
  SECTION("OBJ: a group name that is no integer, a face before any group") {
    const std::string path = dir.file("groups.obj");
    std::ofstream(path) << "v 0 0 0\nv 1 0 0\nv 0 1 0\ng leaf\nf 1 2 3\n";
    CHECK_THAT(importError(path), Contains(path) && Contains("line 4") && Contains("'leaf' is not an integer"));
    std::ofstream(path) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    CHECK_THAT(importError(path), Contains("line 4 (face 0)") && Contains("before any 'g LABEL'"));
    std::ofstream(path) << "v 0 0 0\nv 1 0 0\nv 0 one 0\ng 1\nf 1 2 3\n";
    CHECK_THAT(importError(path), Contains("line 3 (vertex 2)") && Contains("'one' is not a finite number"));
  }
  SECTION("two labels: a face inside one cell, a face with no cell") {
    LabelledFaces m = twoSquares();
    m.names = {"label_front", "label_back"};
    m.back = {0, 5, 0, 0};
    CHECK_THAT(importError(write(m, Kind::PlyAscii, dir, "inside")),
               Contains("face 1 (cell labels 5 and 5)") && Contains("a face inside one cell"));
    m.front[1] = 0, m.back[1] = -1;
    CHECK_THAT(importError(write(m, Kind::Vtp, dir, "nocell")),
               Contains("polygon 1 (cell labels 0 and -1)") && Contains("no cell on either side"));
    // Open cells from two labels: not a 3D tissue.
    m.front = {5, 5, 2, 2}, m.back = {0, 0, 0, 0};
    CHECK_THAT(importError(write(m, Kind::Obj, dir, "open")), Contains("open.obj") && Contains("open patches"));
  }
}
