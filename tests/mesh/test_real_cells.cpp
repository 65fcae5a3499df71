// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Meshing real cells: non-convex cells not star-shaped from their vertex mean
// (curved sheets, 3D walls), the family of pinched cells that crashed the
// planar mesher (issue 18), and a real MorphoGraphX meristem
// (../shared/data/mgx_meristem_cropped, skipped when absent).

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "mesh_test_support.hpp"
#include "../tissue/l_prisms.hpp"
#include "tessella/mesh/geometry_check.hpp"
#include "tessella/mesh/mesh_tissue.hpp"
#include "tessella/tissue/builders.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/generators/grids.hpp"
#include "tessella/tissue/validate.hpp"

using namespace tessella;
using namespace tessella::mesh;
using namespace tessella::test;

namespace {

// A MorphoGraphX cell mesh (ASCII PLY: vertices "x y z label ...", faces
// "3 i j k label"), read into each cell's outline and its own triangle-mesh
// area. A test fixture only, not an importer.
struct MgxCells {
  std::vector<Vec3> positions;               // the outline (wall) vertices used
  std::vector<std::vector<Index>> outlines;  // per cell, indices into positions
  std::vector<int> labels;
  std::vector<double> mgx_area;  // sum of the cell's triangle areas
};

MgxCells readMgxMesh(const std::string& path) {
  std::ifstream in(path);
  REQUIRE(in.good());
  std::string line;
  std::size_t nv = 0, nf = 0;
  std::vector<std::string> vprops;
  bool in_vertex = false;
  while (std::getline(in, line) && line != "end_header") {
    std::istringstream s(line);
    std::string a, b, c;
    s >> a >> b >> c;
    if (a == "element") {
      in_vertex = b == "vertex";
      (in_vertex ? nv : nf) = std::stoul(c);
    } else if (a == "property" && in_vertex) {
      vprops.push_back(c);
    }
  }
  const auto col = [&](const std::string& name) {
    const auto it = std::find(vprops.begin(), vprops.end(), name);
    REQUIRE(it != vprops.end());
    return static_cast<std::size_t>(it - vprops.begin());
  };
  const std::size_t cx = col("x"), cy = col("y"), cz = col("z"), cl = col("label");
  std::vector<Vec3> x(nv);
  std::vector<int> vlabel(nv);
  for (std::size_t i = 0; i < nv; ++i) {
    REQUIRE(std::getline(in, line));
    std::istringstream s(line);
    std::vector<double> v(vprops.size());
    for (double& d : v) s >> d;
    x[i] = Vec3(v[cx], v[cy], v[cz]);
    vlabel[i] = static_cast<int>(v[cl]);
  }
  std::map<int, std::vector<std::array<Index, 3>>> tris;
  for (std::size_t f = 0; f < nf; ++f) {
    REQUIRE(std::getline(in, line));
    std::istringstream s(line);
    int n = 0, label = 0;
    std::array<Index, 3> t{};
    s >> n >> t[0] >> t[1] >> t[2] >> label;
    REQUIRE(n == 3);
    tris[label].push_back(t);
  }
  MgxCells out;
  std::map<Index, Index> used;
  for (const auto& [label, ts] : tris) {
    double area = 0;
    std::map<std::pair<Index, Index>, int> directed;
    for (const auto& t : ts) {
      area += 0.5 * (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]).norm();
      for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
    }
    // The outline: edges not matched by their reverse, chained head to tail.
    std::map<Index, Index> next;
    for (const auto& [e, n] : directed)
      if (!directed.count({e.second, e.first})) {
        REQUIRE(vlabel[e.first] == -1);
        REQUIRE(!next.count(e.first));
        next[e.first] = e.second;
      }
    std::vector<Index> loop;
    Index v = next.begin()->first;
    do {
      const auto [it, fresh] = used.emplace(v, static_cast<Index>(out.positions.size()));
      if (fresh) out.positions.push_back(x[v]);
      loop.push_back(it->second);
      v = next.at(v);
    } while (v != next.begin()->first && loop.size() <= next.size());
    REQUIRE(loop.size() == next.size());  // one closed outline per cell
    out.outlines.push_back(loop);
    out.labels.push_back(label);
    out.mgx_area.push_back(area);
  }
  return out;
}

// The old measure: the signed fan from the vertex mean.
double fanArea(const std::vector<Vec3>& loop) {
  Vec3 c = Vec3::Zero(), va = Vec3::Zero();
  for (const Vec3& p : loop) c += p / static_cast<double>(loop.size());
  for (std::size_t i = 0; i < loop.size(); ++i) va += (loop[i] - c).cross(loop[(i + 1) % loop.size()] - c);
  double a = 0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Vec3 t = (loop[i] - c).cross(loop[(i + 1) % loop.size()] - c);
    a += 0.5 * (t.dot(va) < 0 ? -t.norm() : t.norm());
  }
  return a;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

TEST_CASE("a curved cell not star-shaped from its vertex mean is meshed on its outline's triangles",
          "[mesh][surface][real]") {
  // A non-planar dart (the vertex mean lies outside it) and a curved C.
  const std::vector<Vec3> dart = {{0, 0, 0}, {4, 0, 0.1}, {0.2, 0.2, 0}, {0, 4, 0.1}};
  std::vector<Vec3> c{{0, 0, 0}, {3, 0, 0}, {3, 1, 0}, {1, 1, 0}, {1, 2, 0}, {3, 2, 0}, {3, 3, 0}, {0, 3, 0}};
  for (Vec3& p : c) p.z() = 0.1 * p.x() * p.x() + 0.05 * p.y() * p.y();
  for (const auto& loop : {dart, c}) {
    REQUIRE(polygonTriangulation(loop).folded);
    std::vector<Index> ids;
    for (Index i = 0; i < loop.size(); ++i) ids.push_back(i);
    const Tissue t = buildPolygonTissue(loop, {ids}, Embedding::Surface);
    REQUIRE(validate(t).ok);
    MeshOptions o;
    o.max_edge_length = 0.3;
    const FeMesh mesh = meshTissue(t, o);
    requireGoodMesh(t, mesh);
  }
}

TEST_CASE("3D: a non-planar, non-convex wall is meshed on the surface the volumes are measured on",
          "[mesh][volume][real]") {
  const fixtures::StackedPrisms prisms = fixtures::stackedLPrisms(1.0, 0.3);
  const std::vector<Vec3>& q = prisms.positions;
  const Tissue t = prisms.build();
  REQUIRE(validate(t).ok);
  REQUIRE(polygonTriangulation(std::vector<Vec3>(q.begin() + 6, q.begin() + 12)).folded);
  for (VolumeMethod method : {VolumeMethod::WholeTissue, VolumeMethod::CellByCell}) {
    MeshOptions o;
    o.volume_method = method;
    const FeMesh mesh = meshTissue(t, o);
    requireGoodMesh(t, mesh);
  }
}

TEST_CASE("pinched planar cells: a clean GeometryError from the mesher, never a crash (issue 18)",
          "[mesh][planar][errors][real]") {
  // Vertices 109 and 130 are opposite corners of cell 50 of a 10 x 10 hexagonal grid.
  for (double offset : {0.0, 1e-16, 1e-15, 1e-13, 1e-12}) {
    Tissue t = hexagonalGrid(10, 10);
    t.setPosition(VertexId(130), t.position(VertexId(109)) + Vec3(offset, 0, 0));
    INFO("offset " << offset);
    const MeshabilityReport r = findGeometryDefects(t);
    INFO(r.message);
    CHECK_FALSE(r.ok);
    CHECK(r.element == ElementId{2, 50});
    try {
      meshTissue(t);
      FAIL("no error");
    } catch (const GeometryError& e) {
      CHECK_THAT(e.what(), Catch::Contains("cell 50") && Catch::Contains("109") && Catch::Contains("130"));
    }
    CHECK_FALSE(validate(t).ok);
  }
  // The same pinch on a curved sheet (the grid lifted onto a paraboloid).
  for (double offset : {0.0, 1e-16, 1e-13}) {
    const Tissue flat = hexagonalGrid(10, 10);
    std::vector<Vec3> p(flat.slots(0));
    for (VertexId v : flat.vertices()) p[v.index()] = flat.position(v);
    p[130] = p[109] + Vec3(offset, 0, 0);
    for (Vec3& x : p) x.z() = 0.01 * x.squaredNorm();
    std::vector<std::vector<Index>> polygons;
    for (CellId c : flat.cells()) {
      polygons.emplace_back();
      for (VertexId v : flat.topology().faceVertices(flat.cellFace(c))) polygons.back().push_back(v.index());
    }
    const Tissue t = buildPolygonTissue(p, polygons, Embedding::Surface);
    INFO("curved, offset " << offset);
    CHECK_THROWS_AS(meshTissue(t), GeometryError);
    CHECK_FALSE(validate(t).ok);
  }
}

TEST_CASE("the real MorphoGraphX meristem measures, validates, divides and meshes", "[mesh][surface][real][data]") {
  const std::filesystem::path dir =
      std::filesystem::path(TESSELLA_SOURCE_DIR) / ".." / "shared" / "data" / "mgx_meristem_cropped";
  const auto file = dir / "mesh_meristem_cropped_T0.ply";
  if (!std::filesystem::exists(file)) {
    WARN("skipped: " << file.string() << " is absent (the real meristem data set)");
    return;
  }
  const MgxCells cells = readMgxMesh(file.string());
  REQUIRE(cells.outlines.size() == 128);
  Tissue t = buildPolygonTissue(cells.positions, cells.outlines, Embedding::Surface);
  const ValidationReport report = validate(t);
  INFO(report.message);
  REQUIRE(report.ok);

  // Cell areas against MorphoGraphX's own (a fan from its cell centre on the
  // surface): ours is a surface through the outline only, under a domed
  // cell; the documented bound is 3 % (docs/ARCHITECTURE.md; measured: median
  // 8.9e-5, max 2.8 %, against max 5.7 % for the folding fan of before).
  std::vector<double> before, after;
  int folded = 0;
  for (std::size_t k = 0; k < cells.outlines.size(); ++k) {
    std::vector<Vec3> loop;
    for (Index v : cells.outlines[k]) loop.push_back(cells.positions[v]);
    folded += polygonTriangulation(loop).folded;
    before.push_back(std::abs(fanArea(loop) - cells.mgx_area[k]) / cells.mgx_area[k]);
    after.push_back(std::abs(cellMeasure(t, CellId(static_cast<Index>(k))) - cells.mgx_area[k]) / cells.mgx_area[k]);
  }
  std::printf("meristem: %zu cells, %d folded fans; |area - MGX area| / MGX area: fan from the vertex mean median %.3g "
              "max %.3g, now median %.3g max %.3g\n",
              cells.outlines.size(), folded, median(before), *std::max_element(before.begin(), before.end()),
              median(after), *std::max_element(after.begin(), after.end()));
  CHECK(folded > 0);
  CHECK(median(after) < 1e-3);
  CHECK(*std::max_element(after.begin(), after.end()) < 0.03);

  const FeMesh mesh = meshTissue(t);
  requireGoodMesh(t, mesh);

  // Every cell divided once across its main axis, through its centroid.
  const std::vector<CellId> mothers(t.cells().begin(), t.cells().end());
  for (CellId c : mothers) {
    const Vec3 g = cellCentroid(t, c);
    const Vec3 axis = cellPrincipalAxes(t, c).axes.col(0);
    INFO("cell " << c.index());
    REQUIRE_NOTHROW(t.splitCell(c, Plane{g, axis}));
  }
  REQUIRE(t.numCells() == 256);
  const ValidationReport divided = validate(t);
  INFO(divided.message);
  REQUIRE(divided.ok);
  const FeMesh mesh2 = meshTissue(t);
  requireGoodMesh(t, mesh2);
}

TEST_CASE("a non-finite vertex is named by the mesher's check, not an unrelated edge", "[mesh][check][finite]") {
  for (const double bad : {std::numeric_limits<double>::infinity(), std::nan("")}) {
    for (Tissue t : {hexagonalGrid(3, 3), boxGrid(2, 2, 1)}) {
      const VertexId v(5);
      Vec3 p = t.position(v);
      p.x() = bad;
      t.setPosition(v, p);
      try {
        meshTissue(t, MeshOptions{});
        FAIL("meshed");
      } catch (const GeometryError& e) {
        INFO(e.what());
        CHECK_THAT(e.what(), Catch::Contains("vertex 5 has the non-finite position"));
        CHECK(e.element().degree == 0);
        CHECK(e.element().index == 5);
      }
    }
  }
}
