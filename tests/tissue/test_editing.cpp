// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>

#include "fixtures.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/tissue/validate.hpp"

using namespace tessella;
using namespace tessella::fixtures;

namespace {

struct Counts {
  std::size_t v, e, f, c;
  bool operator==(const Counts&) const = default;
};
Counts counts(const Tissue& t) { return {count(t, 0), count(t, 1), count(t, 2), count(t, 3)}; }

void requireValid(const Tissue& t) {
  const ValidationReport r = validate(t);
  INFO(r.message);
  REQUIRE(r.ok);
}

// An edit that throws must leave the tissue exactly as it was.
template <typename Edit>
void requireRefusedUnchanged(Tissue& t, Edit edit) {
  const Counts before = counts(t);
  const auto version = t.topologyVersion();
  const double total = totalMeasure(t);
  CHECK_THROWS_AS(edit(), Error);
  CHECK(counts(t) == before);
  CHECK(t.topologyVersion() == version);
  CHECK(totalMeasure(t) == total);
  requireValid(t);
}

}  // namespace

TEST_CASE("fixtures are valid", "[tissue][validate]") {
  requireValid(hexagon());
  requireValid(threeCells());
  requireValid(boxGrid(2, 2, 2));
  requireValid(box(1, 2, 3));
  requireValid(tetrahedron(Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ()));
  requireValid(prism(5, 1, 1));
  requireValid(curvedSheet(4, 4, 1.0, 1.0));
  requireValid(hexagonalGrid(6, 5));
  requireValid(rectangularGrid(6, 5));
}

TEST_CASE("splitEdge inserts a vertex into every face through the edge", "[tissue][editing]") {
  Tissue t = threeCells();
  const EdgeId e = t.topology().findEdge(VertexId(0), VertexId(3));  // shared by cells 0 and 1
  REQUIRE(e.valid());
  const Counts before = counts(t);
  const double total = totalMeasure(t);
  const Vec3 point = 0.4 * t.position(VertexId(3));
  const Vec3 from = t.position(t.topology().edgeFrom(e)), to = t.position(t.topology().edgeTo(e));
  const EdgeSplit s = t.splitEdge(e, point);
  CHECK(counts(t) == Counts{before.v + 1, before.e + 1, before.f, 0});
  CHECK(t.topology().faceVertices(FaceId(0)).size() == 5);
  CHECK(t.topology().faceVertices(FaceId(1)).size() == 5);
  CHECK(t.topology().edgeTo(e) == s.vertex);
  CHECK(t.topology().edgeFrom(s.edge) == s.vertex);
  CHECK(edgeLength(t, e) == Approx((point - from).norm()));
  CHECK(edgeLength(t, s.edge) == Approx((to - point).norm()));
  CHECK(edgeLength(t, e) + edgeLength(t, s.edge) == Approx(1.0));
  CHECK(totalMeasure(t) == Approx(total).epsilon(1e-14));
  requireValid(t);
  requireRefusedUnchanged(t, [&] { t.splitEdge(e, t.position(VertexId(0))); });
  requireRefusedUnchanged(t, [&] { t.splitEdge(e, Vec3(NAN, 0, 0)); });
}

TEST_CASE("splitFace divides a polygon between two loop vertices", "[tissue][editing]") {
  Tissue t = hexagon();
  const auto loop = t.topology().faceVertices(FaceId(0));
  const VertexId a = loop[0], b = loop[3];
  const FaceSplit s = t.splitFace(FaceId(0), a, b);
  CHECK(counts(t) == Counts{6, 7, 2, 0});
  CHECK(polygonMeasures(t, FaceId(0)).area == Approx(polygonMeasures(t, s.face).area));
  CHECK(totalMeasure(t) == Approx(1.5 * std::sqrt(3.0)).epsilon(1e-14));
  requireValid(t);
  // Adjacent vertices, or vertices already joined, are refused.
  requireRefusedUnchanged(t, [&] { t.splitFace(FaceId(0), loop[0], loop[1]); });
  requireRefusedUnchanged(t, [&] { t.splitFace(FaceId(0), a, b); });
}

TEST_CASE("splitFace by a segment between two edges; refuses a chord outside a non-convex face",
          "[tissue][editing]") {
  Tissue t = rectangularGrid(2, 1);
  const FaceId f(0);
  const auto edges = t.topology().faceEdges(f);
  // Bottom edge (0->1) and top edge (1,1)->(0,1) of the left square.
  const FaceSplit s = t.splitFace(f, edges[0].handle(), Vec3(0.3, 0, 0), edges[2].handle(), Vec3(0.3, 1, 0));
  CHECK(counts(t) == Counts{8, 10, 3, 0});
  CHECK(cellMeasure(t, CellId(f.index())) + cellMeasure(t, CellId(s.face.index())) == Approx(1.0));
  CHECK(t.topology().faceVertices(FaceId(1)).size() == 4);  // the cut edges were not shared with it
  requireValid(t);

  // An L-shaped cell: the chord between the two arm tips runs outside it.
  Tissue l = singlePolygon({{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}});
  requireRefusedUnchanged(l, [&] { l.splitFace(FaceId(0), VertexId(2), VertexId(4)); });
}

TEST_CASE("splitCell in 2D: a rectangle across its long side, neighbours stay conforming", "[tissue][editing]") {
  Tissue t = rectangularGrid(3, 1, 2.0, 1.0);  // three 2x1 cells in a row
  const CellId mid(1);
  const Counts before = counts(t);
  const Vec3 centre = cellCentroid(t, mid);
  const CellSplit s = t.splitCell(mid, Plane{centre, Vec3(1, 0, 0)});
  CHECK(counts(t) == Counts{before.v + 2, before.e + 3, before.f + 1, 0});
  CHECK(s.new_vertices.size() == 2);
  CHECK(cellMeasure(t, mid) == Approx(1.0).epsilon(1e-14));
  CHECK(cellMeasure(t, s.daughter) == Approx(1.0).epsilon(1e-14));
  CHECK(cellCentroid(t, s.daughter).x() > cellCentroid(t, mid).x());  // daughter on the +normal side
  CHECK(wallMeasure(t, s.wall) == Approx(1.0));
  CHECK(totalMeasure(t) == Approx(6.0).epsilon(1e-14));
  // The mother's neighbours are unchanged (the cut does not reach them).
  CHECK(t.cellNeighbors(s.daughter).size() == 2);
  requireValid(t);
  // A second cut crossing the new wall makes a four-way-free T junction on the neighbour.
  const CellSplit s2 = t.splitCell(CellId(0), Plane{Vec3(1, 0.5, 0), Vec3(0, 1, 0)});
  CHECK(t.topology().faceVertices(FaceId(mid.index())).size() == 5);  // the mother got a vertex on its left wall
  CHECK(cellMeasure(t, s2.daughter) == Approx(1.0));
  requireValid(t);
}

TEST_CASE("splitCell in 2D: degenerate planes snap or are refused", "[tissue][editing]") {
  SECTION("through two opposite vertices: reuses them") {
    Tissue t = rectangularGrid(1, 1);
    const CellSplit s = t.splitCell(CellId(0), Plane{Vec3(0.5, 0.5, 0), Vec3(1, -1, 0)});
    CHECK(s.new_vertices.empty());
    CHECK(counts(t) == Counts{4, 5, 2, 0});
    CHECK(cellMeasure(t, CellId(0)) == Approx(0.5));
    requireValid(t);
  }
  SECTION("within the snap tolerance of a vertex: no sliver edge") {
    Tissue t = rectangularGrid(1, 1);
    const CellSplit s = t.splitCell(CellId(0), Plane{Vec3(0.5, 0.5, 0), Vec3(1, -1 + 1e-13, 0)});
    CHECK(s.new_vertices.empty());
    requireValid(t);
  }
  SECTION("along an existing wall, missing the cell, parallel, sliver: refused, unchanged") {
    Tissue t = rectangularGrid(2, 1);
    requireRefusedUnchanged(t, [&] { t.splitCell(CellId(0), Plane{Vec3(1, 0, 0), Vec3(1, 0, 0)}); });
    requireRefusedUnchanged(t, [&] { t.splitCell(CellId(0), Plane{Vec3(5, 0, 0), Vec3(1, 0, 0)}); });
    requireRefusedUnchanged(t, [&] { t.splitCell(CellId(0), Plane{Vec3(0.5, 0.5, 0), Vec3(0, 0, 1)}); });
    requireRefusedUnchanged(t, [&] { t.splitCell(CellId(0), Plane{Vec3(1e-8, 0.5, 0), Vec3(1, 0, 0)}); });
    requireRefusedUnchanged(t, [&] { t.splitCell(CellId(0), Plane{Vec3(0.5, 0.5, 0), Vec3(0, 0, 0)}); });
  }
  SECTION("a non-convex cell crossed four times: the chord through the plane point") {
    // A U shape: the horizontal line y = 1.5 crosses both arms.
    Tissue t = singlePolygon({{0, 0, 0}, {3, 0, 0}, {3, 2, 0}, {2, 2, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}});
    const double total = totalMeasure(t);
    const CellSplit s = t.splitCell(CellId(0), Plane{Vec3(2.5, 1.5, 0), Vec3(0, 1, 0)});
    CHECK(cellMeasure(t, s.daughter) == Approx(0.5));  // the tip of the right arm
    CHECK(totalMeasure(t) == Approx(total).epsilon(1e-14));
    requireValid(t);
  }
}

TEST_CASE("a division plane on a wall says so in 2D and 3D alike; a sliver prints significant digits",
          "[tissue][editing]") {
  // Cell 0 of each grid is the unit square / cube at the origin; x = 1 is its
  // wall with cell 1, x = 0 its outer wall, x = 5 misses it.
  for (Tissue t : {rectangularGrid(2, 1), boxGrid(2, 1, 1)}) {
    INFO(t.dim() << "D");
    const int wall_degree = t.dim() - 1;
    for (const double x : {1.0, 0.0}) {
      try {
        t.splitCell(CellId(0), Plane{Vec3(x, 0.5, 0.5), Vec3(1, 0, 0)});
        FAIL("accepted");
      } catch (const GeometryError& e) {
        INFO(e.what());
        CHECK_THAT(e.what(), Catch::StartsWith("division plane runs along wall ") &&
                                 Catch::EndsWith(" of cell 0 (lineage 0)"));
        CHECK(e.element().degree == wall_degree);
        // The wall named lies in the plane.
        for (VertexId v : t.dim() == 2 ? std::vector<VertexId>{t.topology().edgeFrom(EdgeId(e.element().index)),
                                                               t.topology().edgeTo(EdgeId(e.element().index))}
                                       : std::vector<VertexId>(t.topology().faceVertices(FaceId(e.element().index)).begin(),
                                                               t.topology().faceVertices(FaceId(e.element().index)).end()))
          CHECK(t.position(v).x() == x);
      }
    }
    CHECK_THROWS_WITH(t.splitCell(CellId(0), Plane{Vec3(5, 0.5, 0.5), Vec3(1, 0, 0)}),
                      Catch::Contains("misses cell 0"));
    // A cut 2.5e-7 from the wall: the sliver's fraction and the minimum as numbers, not "0.000000".
    try {
      t.splitCell(CellId(0), Plane{Vec3(1 - 2.5e-7, 0.5, 0.5), Vec3(1, 0, 0)});
      FAIL("accepted");
    } catch (const GeometryError& e) {
      INFO(e.what());
      CHECK_THAT(e.what(), Catch::Contains("would leave a sliver of 2.5e-07 of its") &&
                               Catch::Contains("(minimum 1e-06)"));
    }
  }
}

TEST_CASE("splitCell refuses options out of range, naming the option and value", "[tissue][editing]") {
  const auto refused = [](SplitOptions options, const std::string& text) {
    for (Tissue t : {rectangularGrid(2, 1), box(2, 1, 1)}) {
      const Plane plane{cellCentroid(t, CellId(0)), Vec3(1, 0, 0)};
      requireRefusedUnchanged(t, [&] { t.splitCell(CellId(0), plane, options); });
      CHECK_THROWS_AS(t.splitCell(CellId(0), plane, options), InputError);
      CHECK_THROWS_WITH(t.splitCell(CellId(0), plane, options), Catch::Contains(text));
    }
  };
  refused({.snap_tolerance = -1}, "snap_tolerance = -1 is out of range");
  refused({.snap_tolerance = std::nan("")}, "snap_tolerance = nan is out of range");
  refused({.snap_tolerance = 0.5}, "snap_tolerance = 0.5 is out of range");
  refused({.min_fraction = -1}, "min_fraction = -1 is out of range");
  refused({.min_fraction = std::numeric_limits<double>::infinity()}, "min_fraction = inf is out of range");
  refused({.min_fraction = 0.5}, "min_fraction = 0.5 is out of range");
  // The bounds themselves are fine.
  Tissue t = rectangularGrid(2, 1);
  t.splitCell(CellId(0), Plane{Vec3(0.5, 0.5, 0), Vec3(1, 0, 0)}, {.snap_tolerance = 0, .min_fraction = 0});
  t.splitCell(CellId(1), Plane{Vec3(1.5, 0.5, 0), Vec3(1, 0, 0)},
              {.snap_tolerance = kMaxSnapTolerance, .min_fraction = 0.4});
  requireValid(t);
}

TEST_CASE("splitCell on a curved sheet cuts along the plane's trace", "[tissue][editing]") {
  Tissue t = curvedSheet(4, 4, 1.0, 1.0);
  const CellId c(5);
  const Vec3 g = cellCentroid(t, c);
  const CellSplit s = t.splitCell(c, Plane{g, Vec3(1, 0, 0)});
  for (VertexId v : s.new_vertices) CHECK(std::abs(t.position(v).x() - g.x()) < 1e-14);
  requireValid(t);
}

TEST_CASE("splitCell in 3D: a 2:1:1 box across its long axis, a cube grid stays conforming", "[tissue][editing]") {
  SECTION("single box") {
    Tissue t = box(2, 1, 1);
    const CellSplit s = t.splitCell(CellId(0), Plane{Vec3(1, 0.5, 0.5), Vec3(1, 0, 0)});
    CHECK(counts(t) == Counts{12, 20, 11, 2});
    CHECK(s.new_vertices.size() == 4);
    CHECK(cellMeasure(t, CellId(0)) == Approx(1.0).epsilon(1e-14));
    CHECK(cellMeasure(t, s.daughter) == Approx(1.0).epsilon(1e-14));
    CHECK(wallMeasure(t, s.wall) == Approx(1.0).epsilon(1e-14));
    CHECK(cellCentroid(t, s.daughter).x() == Approx(1.5));
    requireValid(t);
  }
  SECTION("a diagonal plane through vertices and edges of a cube") {
    Tissue t = box(1, 1, 1);
    const CellSplit s = t.splitCell(CellId(0), Plane{Vec3(0.5, 0.5, 0.5), Vec3(1, -1, 0)});
    CHECK(s.new_vertices.empty());
    CHECK(cellMeasure(t, CellId(0)) == Approx(0.5).epsilon(1e-14));
    CHECK(wallMeasure(t, s.wall) == Approx(std::sqrt(2.0)).epsilon(1e-14));
    requireValid(t);
  }
  SECTION("an oblique plane cutting a corner-heavy hexagon section") {
    Tissue t = box(1, 1, 1);
    const CellSplit s = t.splitCell(CellId(0), Plane{Vec3(0.5, 0.5, 0.5), Vec3(1, 1, 1)});
    CHECK(s.new_vertices.size() == 6);
    CHECK(cellMeasure(t, CellId(0)) == Approx(0.5).epsilon(1e-13));
    CHECK(wallMeasure(t, s.wall) == Approx(0.75 * std::sqrt(3.0)).epsilon(1e-13));  // regular hexagon, side sqrt(2)/2
    requireValid(t);
  }
  SECTION("in a 2x2x2 grid the neighbours share the new vertices and walls") {
    Tissue t = boxGrid(2, 2, 2);
    const CellSplit s = t.splitCell(CellId(0), Plane{Vec3(0.3, 0.5, 0.5), Vec3(1, 0, 0)});
    CHECK(t.numCells() == 9);
    CHECK(totalMeasure(t) == Approx(8.0).epsilon(1e-14));
    requireValid(t);
    // Cell 2 (above in y) and cell 4 (above in z) now have the cut's vertices on their shared walls.
    CHECK(t.cellVertices(CellId(2)).size() == 10);
    CHECK(t.cellVertices(CellId(4)).size() == 10);
    CHECK(t.cellNeighbors(s.daughter).size() == 4);  // mother, +x cell, +y cell, +z cell
  }
  SECTION("degenerate planes are refused and change nothing") {
    Tissue t = boxGrid(2, 1, 1);
    requireRefusedUnchanged(t, [&] { t.splitCell(CellId(0), Plane{Vec3(1, 0, 0), Vec3(1, 0, 0)}); });
    requireRefusedUnchanged(t, [&] { t.splitCell(CellId(0), Plane{Vec3(3, 0, 0), Vec3(1, 0, 0)}); });
    requireRefusedUnchanged(t, [&] { t.splitCell(CellId(0), Plane{Vec3(1e-9, 0, 0), Vec3(1, 0, 0)}); });
    requireRefusedUnchanged(t, [&] { t.splitCell(CellId(0), Plane{Vec3(0, 0, 0), Vec3(1, 1, 0)}); });  // only touches an edge
  }
}

TEST_CASE("removeCell drops orphaned borders; compact renumbers everything", "[tissue][editing]") {
  Tissue t = rectangularGrid(4, 4);
  auto& tag = t.cellProperties().add<int>("tag", 0);
  for (CellId c : t.cells()) tag[c] = static_cast<int>(c.index()) * 10;
  const std::int64_t lineage8 = t.lineageId(CellId(8));
  t.removeCell(CellId(5));  // an interior cell: a hole, nothing orphaned
  CHECK(counts(t) == Counts{25, 40, 15, 0});
  t.removeCell(CellId(15));  // a corner: its two outer edges and corner vertex go
  CHECK(counts(t) == Counts{24, 38, 14, 0});
  requireValid(t);  // an annulus: V - E + F = 0 with two boundary loops
  const auto version = t.topologyVersion();
  const Renumbering r = t.compact();
  CHECK(t.topologyVersion() != version);
  CHECK(t.cellSlots() == 14);
  CHECK(r(2, Index(8)) == 7);
  CHECK(r(2, Index(5)) == kInvalidIndex);
  CHECK(t.cellProperties().get<int>("tag")[CellId(7)] == 80);
  CHECK(t.lineageId(CellId(7)) == lineage8);
  requireValid(t);
  // Lineage ids are never reused after compaction.
  const CellSplit s = t.splitCell(CellId(7), Plane{cellCentroid(t, CellId(7)), Vec3(1, 0, 0)});
  CHECK(t.lineageId(CellId(7)) == 16);
  CHECK(t.lineageId(s.daughter) == 17);
  CHECK(t.parentId(s.daughter) == lineage8);
}

TEST_CASE("copies are independent and keep their built-in columns", "[tissue]") {
  Tissue a = hexagon();
  Tissue b = a;
  b.splitCell(CellId(0), Plane{Vec3::Zero(), Vec3(1, 0, 0)});
  CHECK(a.numCells() == 1);
  CHECK(b.numCells() == 2);
  CHECK(b.lineageId(CellId(1)) == 2);
  Tissue c = std::move(b);
  CHECK(c.lineageId(CellId(1)) == 2);
  c.splitCell(CellId(1), Plane{cellCentroid(c, CellId(1)), Vec3(0, 1, 0)});
  CHECK(c.numCells() == 3);
  requireValid(c);
}
