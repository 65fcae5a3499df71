// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Division plans on their own: what planCellSplit2D/3D decide (crossed edges
// and walls, new vertex positions, sides) for cells whose cut is known by
// hand, that planning never changes the tissue, and that splitCell does what
// the plan says.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "fixtures.hpp"
#include "tessella/tissue/cell_split_plan.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/tissue/validate.hpp"

using namespace tessella;
using namespace tessella::fixtures;

namespace {

// Everything planning could have changed.
struct Snapshot {
  std::uint64_t topology, geometry;
  std::vector<Vec3> positions;
  explicit Snapshot(const Tissue& t)
      : topology(t.topologyVersion()),
        geometry(t.geometryVersion()),
        positions(t.positions().begin(), t.positions().end()) {}
  bool operator==(const Snapshot&) const = default;
};

// The edge of `t` between the vertices at these positions.
EdgeId edgeBetween(const Tissue& t, const Vec3& p, const Vec3& q) {
  for (EdgeId e : t.edges()) {
    const Vec3 &a = t.position(t.topology().edgeFrom(e)), &b = t.position(t.topology().edgeTo(e));
    if (((a - p).norm() < 1e-12 && (b - q).norm() < 1e-12) || ((a - q).norm() < 1e-12 && (b - p).norm() < 1e-12))
      return e;
  }
  return {};
}

VertexId vertexAt(const Tissue& t, const Vec3& p) {
  for (VertexId v : t.vertices())
    if ((t.position(v) - p).norm() < 1e-12) return v;
  return {};
}

}  // namespace

TEST_CASE("a 2D plan: a square cut across two edges, and through two corners", "[tissue][editing][plan]") {
  Tissue t = singlePolygon({Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2, 1, 0), Vec3(0, 1, 0)});
  const CellId c(0);
  const Snapshot before(t);

  SECTION("a vertical plane at x = 0.5 crosses the bottom and top edges") {
    const CellSplitPlan2D plan = planCellSplit2D(t, c, Plane{Vec3(0.5, 0.3, 0), Vec3(1, 0, 0)});
    CHECK(Snapshot(t) == before);
    REQUIRE(plan.a.isNew());
    REQUIRE(plan.b.isNew());
    // In loop order: the bottom edge (0 -> 1) first, then the top edge (2 -> 3).
    CHECK(plan.a.edge == edgeBetween(t, Vec3(0, 0, 0), Vec3(2, 0, 0)));
    CHECK(plan.b.edge == edgeBetween(t, Vec3(2, 1, 0), Vec3(0, 1, 0)));
    CHECK((plan.a.point - Vec3(0.5, 0, 0)).norm() < 1e-15);
    CHECK((plan.b.point - Vec3(0.5, 1, 0)).norm() < 1e-15);
    // The loop part from a to b runs through (2, 0) and (2, 1): x > 0.5, the daughter's side.
    CHECK(plan.daughter_from_a_to_b);
    CHECK(plan.mother_fraction == Approx(0.25).epsilon(1e-14));

    // splitCell does what the plan says.
    const CellSplit s = t.splitCell(c, Plane{Vec3(0.5, 0.3, 0), Vec3(1, 0, 0)});
    REQUIRE(s.new_vertices.size() == 2);
    CHECK(t.position(s.new_vertices[0]) == plan.a.point);
    CHECK(t.position(s.new_vertices[1]) == plan.b.point);
    CHECK(cellMeasure(t, c) == Approx(0.5));
    CHECK(cellCentroid(t, s.daughter).x() > 0.5);
  }

  SECTION("the plane flipped: the same chord, the other part goes to the daughter") {
    const CellSplitPlan2D plan = planCellSplit2D(t, c, Plane{Vec3(0.5, 0.3, 0), Vec3(-1, 0, 0)});
    CHECK_FALSE(plan.daughter_from_a_to_b);
    CHECK(plan.mother_fraction == Approx(0.75).epsilon(1e-14));
  }

  SECTION("a diagonal through two corners reuses them") {
    const CellSplitPlan2D plan = planCellSplit2D(t, c, Plane{Vec3(1, 0.5, 0), Vec3(1, -2, 0)});
    CHECK_FALSE(plan.a.isNew());
    CHECK_FALSE(plan.b.isNew());
    CHECK(plan.a.vertex == vertexAt(t, Vec3(0, 0, 0)));
    CHECK(plan.b.vertex == vertexAt(t, Vec3(2, 1, 0)));
    CHECK(plan.mother_fraction == Approx(0.5).epsilon(1e-14));
    const CellSplit s = t.splitCell(c, Plane{Vec3(1, 0.5, 0), Vec3(1, -2, 0)});
    CHECK(s.new_vertices.empty());
  }

  SECTION("a refused plan throws and changes nothing") {
    CHECK_THROWS_AS(planCellSplit2D(t, c, Plane{Vec3(5, 0, 0), Vec3(1, 0, 0)}), GeometryError);       // misses
    CHECK_THROWS_AS(planCellSplit2D(t, c, Plane{Vec3(0, 0, 0), Vec3(0, 1, 0)}), GeometryError);       // along a wall
    CHECK_THROWS_AS(planCellSplit2D(t, c, Plane{Vec3(1e-7, 0, 0), Vec3(1, 0, 0)}), GeometryError);    // sliver
    CHECK_THROWS_AS(planCellSplit2D(t, c, Plane{Vec3(1, 0, 0), Vec3(1, 0, 0)}, {.snap_tolerance = 1}), InputError);
    CHECK_THROWS_AS(planCellSplit3D(t, c, Plane{Vec3(1, 0, 0), Vec3(1, 0, 0)}), InputError);  // a 2D tissue
    CHECK(Snapshot(t) == before);
  }
}

TEST_CASE("a 3D plan: a box cut across four edges, and through a diagonal", "[tissue][editing][plan]") {
  Tissue t = box(2, 1, 1);
  const CellId c(0);
  const Snapshot before(t);

  SECTION("a plane at x = 0.5 splits the four x edges and the four walls along x") {
    const Plane plane{Vec3(0.5, 0.5, 0.5), Vec3(1, 0, 0)};
    const CellSplitPlan3D plan = planCellSplit3D(t, c, plane);
    CHECK(Snapshot(t) == before);
    REQUIRE(plan.ring.size() == 4);
    Vec3 area = Vec3::Zero();
    for (std::size_t i = 0; i < 4; ++i) {
      const CutNode& n = plan.ring[i];
      REQUIRE(n.isNew());
      CHECK(n.point.x() == 0.5);
      // Each new vertex lies on an edge along x.
      const Vec3 &a = t.position(t.topology().edgeFrom(n.edge)), &b = t.position(t.topology().edgeTo(n.edge));
      CHECK(a.y() == b.y());
      CHECK(a.z() == b.z());
      CHECK(n.point.y() == a.y());
      CHECK(n.point.z() == a.z());
      area += n.point.cross(plan.ring[(i + 1) % 4].point);
    }
    CHECK(area.dot(plane.normal) > 0);  // counter-clockwise seen from the daughter's side
    REQUIRE(plan.wall_cuts.size() == 4);
    for (const auto& cut : plan.wall_cuts) {
      CHECK(cut.from < 4);
      CHECK(cut.to < 4);
      CHECK(cut.from != cut.to);
      // A 2 x 1 wall cut at x = 0.5: the parts hold a quarter and three quarters of it.
      CHECK(std::min(cut.kept_fraction, 1 - cut.kept_fraction) == Approx(0.25));
    }
    REQUIRE(plan.distances.size() == 8);
    for (const auto& [v, d] : plan.distances) CHECK(d == t.position(v).x() - 0.5);

    const CellSplit s = t.splitCell(c, plane);
    REQUIRE(s.new_vertices.size() == 4);
    for (std::size_t i = 0; i < 4; ++i) CHECK(t.position(s.new_vertices[i]) == plan.ring[i].point);
    CHECK(cellMeasure(t, c) == Approx(0.5));
    CHECK(cellMeasure(t, s.daughter) == Approx(1.5));
  }

  SECTION("a plane through four corners of a cube reuses them and splits two walls diagonally") {
    t = box(1, 1, 1);
    const Plane plane{Vec3(0.5, 0.5, 0.5), Vec3(1, -1, 0)};  // x = y: corners (0,0,*) and (1,1,*)
    const CellSplitPlan3D plan = planCellSplit3D(t, c, plane);
    REQUIRE(plan.ring.size() == 4);
    for (const CutNode& n : plan.ring) {
      CHECK_FALSE(n.isNew());
      CHECK(n.point == t.position(n.vertex));
      CHECK(n.point.x() == n.point.y());
    }
    CHECK(plan.wall_cuts.size() == 2);  // the walls z = 0 and z = 1
    const auto zeros = std::count_if(plan.distances.begin(), plan.distances.end(),
                                     [](const auto& vd) { return vd.second == 0; });
    CHECK(zeros == 4);
    const CellSplit s = t.splitCell(c, plane);
    CHECK(s.new_vertices.empty());
    CHECK(cellMeasure(t, c) == Approx(0.5));
    CHECK(cellMeasure(t, s.daughter) == Approx(0.5));
  }

  SECTION("a refused plan throws and changes nothing") {
    CHECK_THROWS_AS(planCellSplit3D(t, c, Plane{Vec3(3, 0, 0), Vec3(1, 0, 0)}), GeometryError);     // misses
    CHECK_THROWS_AS(planCellSplit3D(t, c, Plane{Vec3(0, 0, 0), Vec3(1, 0, 0)}), GeometryError);     // a wall's plane
    CHECK_THROWS_AS(planCellSplit3D(t, c, Plane{Vec3(1e-7, 0, 0), Vec3(1, 0, 0)}), GeometryError);  // sliver
    CHECK_THROWS_AS(planCellSplit3D(t, CellId(7), Plane{Vec3(1, 0, 0), Vec3(1, 0, 0)}), TopologyError);
    CHECK(Snapshot(t) == before);
  }
}

TEST_CASE("a refused 3D cut leaves the tissue as it was", "[tissue][editing][plan]") {
  // The plane 2x + y + z = 2 + 2 eps (snap tolerance 0) passes 2 eps / sqrt(6)
  // below the corners (1,0,0) and (0,1,1) of the unit cube: it crosses the edges
  // (0,1,0)-(1,1,0) and (0,0,1)-(1,0,1) near their middles and three edges
  // within about 2e-14 of their length of a corner, where splitEdge refuses a
  // vertex (parameter within 1e-12 of an end). Before the plan checked it, the
  // middle crossings were split first, then the cut threw half-way (9 vertices).
  Tissue t = box(1, 1, 1);
  const double eps = 1e-14;
  const Plane plane{Vec3(1 + eps, 0, 0), Vec3(2, 1, 1)};
  const SplitOptions options{.snap_tolerance = 0, .min_fraction = 0};
  const Snapshot before(t);
  const std::size_t vertices = t.numVertices(), edges = t.numEdges(), faces = t.numFaces();

  CHECK_THROWS_WITH(planCellSplit3D(t, CellId(0), plane, options),
                    Catch::Contains("is not strictly between its vertices") && Catch::Contains("cell 0"));
  CHECK_THROWS_AS(t.splitCell(CellId(0), plane, options), GeometryError);
  CHECK(Snapshot(t) == before);
  CHECK(t.numVertices() == vertices);
  CHECK(t.numEdges() == edges);
  CHECK(t.numFaces() == faces);
  CHECK(t.numCells() == 1);
  CHECK(validate(t).ok);

  // The same plane 0.1 further out crosses every edge away from its ends and divides.
  const Plane far{Vec3(1.1, 0, 0), Vec3(2, 1, 1)};
  const CellSplit s = t.splitCell(CellId(0), far, options);
  CHECK(s.new_vertices.size() == 5);
  CHECK(validate(t).ok);
  // The daughter is {2x + y + z > 2.2} in the cube: over x, the part of the unit square where
  // y + z > s = 2.2 - 2x has area (2 - s)^2 / 2 for s >= 1 (x in [0.1, 0.6]) and 1 - s^2 / 2 for
  // s <= 1 (x in [0.6, 1]), which integrate to 1/12 and 0.4 - 0.992/12.
  const double daughter = 1.0 / 12 + 0.4 - 0.992 / 12;
  CHECK(cellMeasure(t, s.daughter) == Approx(daughter).epsilon(1e-12));
  CHECK(cellMeasure(t, CellId(0)) == Approx(1 - daughter).epsilon(1e-12));
}

TEST_CASE("a plan applied later: the same division, refused once the tissue changed", "[tissue][editing][plan]") {
  SECTION("3D") {
    Tissue t = box(2, 1, 1);
    const Plane plane{Vec3(0.7, 0.5, 0.5), Vec3(1, 0.2, 0.1)};
    Tissue reference = t;
    const CellSplit expected = reference.splitCell(CellId(0), plane);
    const CellSplitPlan3D plan = planCellSplit3D(t, CellId(0), plane);
    CHECK(plan.cell == CellId(0));
    Tissue copy = t;  // same versions: the plan is its plan too
    const CellSplit got = t.splitCell(plan);
    CHECK(got.daughter == expected.daughter);
    CHECK(got.wall == expected.wall);
    CHECK(got.new_vertices == expected.new_vertices);
    CHECK(std::equal(t.positions().begin(), t.positions().end(), reference.positions().begin(),
                     reference.positions().end()));
    CHECK(cellMeasure(t, CellId(0)) == cellMeasure(reference, CellId(0)));
    CHECK(cellMeasure(t, got.daughter) == cellMeasure(reference, expected.daughter));
    CHECK(t.lineageId(got.daughter) == reference.lineageId(expected.daughter));
    CHECK(validate(t).ok);

    // The tissue has changed since: the plan is refused, and nothing changes.
    const Snapshot after(t);
    CHECK_THROWS_AS(t.splitCell(plan), std::logic_error);
    CHECK(Snapshot(t) == after);
    // The copy, unchanged, takes it; once a vertex moves, it refuses it.
    Tissue moved = copy;
    CHECK(copy.splitCell(plan).daughter == expected.daughter);
    moved.setPosition(VertexId(0), moved.position(VertexId(0)));
    CHECK_THROWS_WITH(moved.splitCell(plan), Catch::Contains("cell 0") && Catch::Contains("another state"));
  }
  SECTION("2D") {
    Tissue t = hexagon();
    const Plane plane{Vec3(0.1, 0, 0), Vec3(1, 0.3, 0)};
    Tissue reference = t;
    const CellSplit expected = reference.splitCell(CellId(0), plane);
    const CellSplitPlan2D plan = planCellSplit2D(t, CellId(0), plane);
    const CellSplit got = t.splitCell(plan);
    CHECK(got.daughter == expected.daughter);
    CHECK(got.new_vertices == expected.new_vertices);
    CHECK(std::equal(t.positions().begin(), t.positions().end(), reference.positions().begin(),
                     reference.positions().end()));
    CHECK(cellMeasure(t, got.daughter) == cellMeasure(reference, expected.daughter));
    CHECK_THROWS_AS(t.splitCell(plan), std::logic_error);
    CHECK_THROWS_AS(t.splitCell(planCellSplit3D(box(1, 1, 1), CellId(0), plane)), std::logic_error);  // a 3D plan
  }
}

TEST_CASE("a refused 2D cut leaves the tissue as it was", "[tissue][editing][plan]") {
  // Two unit squares side by side; cell 0 is [0,1]^2, its loop (0,0) (1,0) (1,1) (0,1).
  // With snap tolerance 0, the line through (0.5, 0) and (1 - eps, 1) leaves the corner
  // (1, 1) eps * 2 / sqrt(5) off it, on the side of (1, 0): it crosses the bottom edge at
  // its middle and the top edge (1,1)-(0,1) at parameter eps from (1, 1), where splitEdge
  // refuses a vertex (within 1e-12 of an end). The plan is made (the batch splitCells
  // takes such plans); the serial edit made its first cut, then threw (an extra vertex).
  const double eps = 1e-14;
  Tissue t = rectangularGrid(2, 1);
  const CellId c(0);
  const Vec3 p(0.5, 0, 0), q(1 - eps, 1, 0);
  const Vec3 normal = (q - p).cross(Vec3(0, 0, 1));
  const EdgeId bottom = edgeBetween(t, Vec3(0, 0, 0), Vec3(1, 0, 0)), top = edgeBetween(t, Vec3(1, 1, 0), Vec3(0, 1, 0));
  const SplitOptions options{.snap_tolerance = 0, .min_fraction = 0};
  const Snapshot before(t);
  const std::size_t vertices = t.numVertices(), edges = t.numEdges(), faces = t.numFaces();
  const auto unchanged = [&] {
    CHECK(Snapshot(t) == before);
    CHECK(t.numVertices() == vertices);
    CHECK(t.numEdges() == edges);
    CHECK(t.numFaces() == faces);
    CHECK(t.numCells() == 2);
    CHECK(t.topology().faceVertices(FaceId(0)).size() == 4);
    CHECK(t.topology().faceVertices(FaceId(1)).size() == 4);
    CHECK(validate(t).ok);
  };
  // The message of the GeometryError `divide` throws ("" if it throws none).
  const auto geometryError = [](auto&& divide) -> std::string {
    try {
      divide();
    } catch (const GeometryError& e) {
      return e.what();
    }
    return "";
  };
  const auto edgeName = [](EdgeId e) { return "edge " + std::to_string(e.index()) + " "; };

  SECTION("the corner crossing is the second cut") {
    const Plane plane{p, normal};
    const CellSplitPlan2D plan = planCellSplit2D(t, c, plane, options);
    REQUIRE(plan.a.isNew());
    REQUIRE(plan.b.isNew());
    REQUIRE(plan.a.edge == bottom);  // cut first, fine
    REQUIRE(plan.b.edge == top);     // cut second, refused
    CHECK_THROWS_AS(t.splitCell(c, plane, options), GeometryError);
    unchanged();
    const std::string what = geometryError([&] { t.splitCell(c, plane, options); });
    CHECK_THAT(what, Catch::Contains("cell 0 (lineage 0)") && Catch::Contains(edgeName(top)) &&
                         Catch::Contains("not strictly between its vertices (parameter "));
    // The value named is the new vertex's parameter on the top edge: about eps from one end.
    const std::size_t at = what.find("(parameter ");
    REQUIRE(at != std::string::npos);
    const double named = std::stod(what.substr(at + 11));
    CHECK(std::min(named, 1 - named) == Approx(eps).epsilon(0.01));
    unchanged();
    CHECK_THAT(geometryError([&] { t.splitCell(plan); }), Catch::Contains("cell 0") && Catch::Contains(edgeName(top)));
    unchanged();

    // The batch takes the plan as it did (a vertex eps from the corner).
    Tissue batch = t;
    const std::vector<CellSplitPlan2D> plans{plan};
    const std::vector<CellSplit> splits = batch.splitCells(plans);
    CHECK(splits.at(0).new_vertices.size() == 2);
    CHECK(batch.numCells() == 3);
  }
  SECTION("the corner crossing is the first cut") {
    // The same line mirrored in y = 0.5: through (0.5, 1) and (1 - eps, 0).
    const Plane plane{Vec3(0.5, 1, 0), Vec3(normal.x(), -normal.y(), 0)};
    const CellSplitPlan2D plan = planCellSplit2D(t, c, plane, options);
    REQUIRE(plan.a.edge == bottom);  // now the refused one, cut first
    REQUIRE(plan.b.edge == top);
    CHECK_THROWS_AS(t.splitCell(c, plane, options), GeometryError);
    CHECK_THAT(geometryError([&] { t.splitCell(c, plane, options); }),
               Catch::Contains("cell 0 (lineage 0)") && Catch::Contains(edgeName(bottom)) &&
                   Catch::Contains("not strictly between its vertices (parameter"));
    unchanged();
  }
  SECTION("a plan edited by hand is refused before any edit") {
    // splitCell(plan) takes any plan with the tissue's versions. Before the
    // check, the first three defects below made the first cut, then threw in
    // the complex's splitFace; the fourth threw there, naming no cell.
    const CellSplitPlan2D planned = planCellSplit2D(t, c, Plane{Vec3(0.5, 0.5, 0), Vec3(1, 0, 0)});
    REQUIRE(planned.a.edge == bottom);
    REQUIRE(planned.b.edge == top);
    const EdgeId right = edgeBetween(t, Vec3(1, 0, 0), Vec3(1, 1, 0)), far = edgeBetween(t, Vec3(2, 0, 0), Vec3(2, 1, 0));
    CellSplitPlan2D plan = planned;
    SECTION("an edge of another cell") {
      plan.b = {{}, far, Vec3(2, 0.5, 0)};
      CHECK_THROWS_WITH(t.splitCell(plan), Catch::Contains("cell 0") && Catch::Contains("edge " + std::to_string(far.index())));
    }
    SECTION("the same edge twice") {
      plan.b = {{}, bottom, Vec3(0.25, 0, 0)};
      CHECK_THROWS_WITH(t.splitCell(plan), Catch::Contains("cell 0") && Catch::Contains("twice"));
    }
    SECTION("an end of the edge it cuts") {
      plan.b = {vertexAt(t, Vec3(1, 0, 0)), {}, Vec3(1, 0, 0)};
      CHECK_THROWS_WITH(t.splitCell(plan), Catch::Contains("cell 0") && Catch::Contains("its own edge"));
    }
    SECTION("two adjacent corners") {
      plan.a = {vertexAt(t, Vec3(1, 0, 0)), {}, Vec3(1, 0, 0)};
      plan.b = {vertexAt(t, Vec3(1, 1, 0)), {}, Vec3(1, 1, 0)};
      REQUIRE(right);  // they are joined by the right edge
      CHECK_THROWS_WITH(t.splitCell(plan), Catch::Contains("cell 0") && Catch::Contains("adjacent"));
    }
    CHECK_THROWS_AS(t.splitCell(plan), TopologyError);
    unchanged();
    CHECK(t.splitCell(planned).new_vertices.size() == 2);  // the plan as made still divides
  }
  SECTION("the line a little further from the corner divides") {
    const Plane plane{p, (Vec3(1 - 1e-3, 1, 0) - p).cross(Vec3(0, 0, 1))};
    const CellSplit s = t.splitCell(c, plane, options);
    CHECK(s.new_vertices.size() == 2);
    CHECK(validate(t).ok);
    // The trapezoid (0,0) (0.5,0) (0.999,1) (0,1) stays: (0.5 + 0.999) / 2.
    CHECK(cellMeasure(t, c) == Approx(0.7495).epsilon(1e-12));
    CHECK(cellMeasure(t, s.daughter) == Approx(0.2505).epsilon(1e-12));
  }
}
