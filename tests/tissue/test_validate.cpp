// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include <catch2/catch.hpp>

#include "fixtures.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/validate.hpp"

using namespace tessella;
using namespace tessella::fixtures;

TEST_CASE("validate reports a dangling vertex", "[tissue][validate]") {
  Tissue t = hexagon();
  const VertexId v = t.addVertex(Vec3(5, 5, 0));
  const ValidationReport r = validate(t);
  CHECK_FALSE(r.ok);
  CHECK(r.element == ElementId{0, v.index()});
  CHECK(r.message.find("dangling") != std::string::npos);
  CHECK_THROWS_AS(validateOrThrow(t), TopologyError);
}

TEST_CASE("validate reports inconsistent orientation of neighbouring 2D cells", "[tissue][validate]") {
  // Two squares sharing an edge, the second listed clockwise.
  std::vector<Vec3> p{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}};
  Tissue t = buildPolygonTissue(p, {{0, 1, 4, 3}, {1, 2, 5, 4}});
  CHECK(validate(t).ok);
  Tissue bad = buildPolygonTissue(p, {{0, 1, 4, 3}, {4, 5, 2, 1}}, Embedding::Surface);
  const ValidationReport r = validate(bad);
  CHECK_FALSE(r.ok);
  CHECK(r.element.degree == 1);
  CHECK(r.message.find("same direction") != std::string::npos);
}

TEST_CASE("validate reports inverted cells", "[tissue][validate]") {
  Tissue t = rectangularGrid(3, 1);
  // Drag a vertex of the middle cell across the cell: its loop turns the other way.
  t.setPosition(VertexId(6), Vec3(1.5, -2, 0));
  const ValidationReport r = validate(t);
  CHECK_FALSE(r.ok);
  CHECK(r.element.degree == 2);
  CHECK(r.message.find("inverted") != std::string::npos);

  Tissue b = box(1, 1, 1);
  for (VertexId v : b.vertices()) b.setPosition(v, Vec3(-b.position(v).x(), b.position(v).y(), b.position(v).z()));
  const ValidationReport rb = validate(b);
  CHECK_FALSE(rb.ok);
  CHECK(rb.message.find("non-positive volume") != std::string::npos);
}

TEST_CASE("validate checks the Euler characteristic", "[tissue][validate]") {
  // A sheet with a hole is fine (chi = 0 with two boundary loops) ...
  Tissue ring = rectangularGrid(3, 3);
  ring.removeCell(CellId(4));
  CHECK(validate(ring).ok);
  // ... a ring of boxes around a tunnel is not a solid ball.
  Tissue tunnel = boxGrid(3, 3, 1);
  tunnel.removeCell(CellId(4));
  const ValidationReport r = validate(tunnel);
  CHECK_FALSE(r.ok);
  CHECK(r.message.find("Euler characteristic") != std::string::npos);
  ValidateOptions lenient;
  lenient.check_euler = false;
  CHECK(validate(tunnel, lenient).ok);
}

TEST_CASE("building refuses bad input with the element named", "[tissue][builders]") {
  std::vector<Vec3> p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  CHECK_THROWS_WITH(buildPolygonTissue(p, {{0, 1}}), Catch::Contains("polygon 0"));
  CHECK_THROWS_WITH(buildPolygonTissue(p, {{0, 1, 7}}), Catch::Contains("vertex 7"));
  CHECK_THROWS_WITH(buildPolygonTissue(p, {{0, 1, 1}}), Catch::Contains("polygon 0"));
  p.push_back(Vec3(NAN, 0, 0));
  CHECK_THROWS_WITH(buildPolygonTissue(p, {{0, 1, 2}}), Catch::Contains("vertex 3"));
  // A third face on an edge of a 2D tissue.
  std::vector<Vec3> q{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {1, 1, 0}};
  CHECK_THROWS_WITH(buildPolygonTissue(q, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}), Catch::Contains("polygon 2"));
  // An open 3D cell (a cube missing its top).
  Tissue cube = box(1, 1, 1);
  std::vector<OrientedFace> open;
  for (OrientedFace of : cube.topology().volumeFaces(VolumeId(0))) open.push_back(of);
  cube.removeCell(CellId(0));
  CHECK(cube.numCells() == 0);
  CHECK_THROWS_AS(rectangularGrid(0, 3), InputError);
  CHECK_THROWS_AS(boxGrid(1, 1, 1, -1.0), InputError);
}

TEST_CASE("validate reports a face listed twice, naming the first", "[tissue][validate]") {
  // A hexagon, then a second face on the same six edges (each edge then bounds two faces, as an inner wall does).
  Tissue t = hexagon();
  REQUIRE(validate(t).ok);
  const auto edges = t.topology().faceEdges(FaceId(0));
  const std::vector<OrientedEdge> loop(edges.begin(), edges.end());
  const FaceId copy = t.addFace(loop);
  const ValidationReport r = validate(t);
  CHECK_FALSE(r.ok);
  CHECK(r.element == ElementId{2, copy.index()});
  CHECK(r.message.find("duplicates face 0") != std::string::npos);
}
