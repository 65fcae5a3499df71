// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// Tissue::splitCells against the one-by-one sequence it stands for, written
// here with the public editing primitives (splitEdge, splitFace), and against
// itself with one and two threads.
#include <catch2/catch.hpp>

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <vector>

#include "tessella/generators/grids.hpp"
#include "tessella/generators/voronoi.hpp"
#include "tessella/tissue/cell_split_plan.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/tissue/validate.hpp"

using namespace tessella;

namespace {

// Columns with every policy but Custom, on edges and cells.
void addProperties(Tissue& t) {
  auto& amount = t.cellProperties().add<double>("amount", 0.0, DivisionPolicy::SplitByMeasure);
  auto& kind = t.cellProperties().add<std::int64_t>("kind", 0, DivisionPolicy::Copy);
  for (CellId c : t.cells()) {
    amount[c] = 1.0 + 0.001 * c.index();
    kind[c] = c.index() % 7;
  }
  auto& stock = t.wallProperties().add<double>("stock", 0.0, DivisionPolicy::SplitByMeasure);
  auto& tag = t.wallProperties().add<std::int64_t>("tag", 0, DivisionPolicy::Copy);
  for (WallId w : t.walls()) {
    stock[w] = 2.0 + 0.01 * w.index();
    tag[w] = w.index();
  }
}

// A plan per cell of `cells`, every one made on the tissue as it is.
std::vector<CellSplitPlan2D> plansFor(const Tissue& t, const std::vector<CellId>& cells,
                                      const std::vector<Vec3>& normals) {
  std::vector<CellSplitPlan2D> plans;
  for (std::size_t i = 0; i < cells.size(); ++i)
    plans.push_back(planCellSplit2D(t, cells[i], Plane{polygonMeasures(t, FaceId(cells[i].index())).centroid,
                                                        normals[i]}));
  return plans;
}

// The plans applied one after the other with splitEdge and splitFace: a new
// chord end reuses a vertex an earlier plan made on its edge when that vertex
// is within the plan's snap distance of its plane; otherwise it splits the
// piece of its edge holding its point.
void oneByOne(Tissue& t, const std::vector<CellSplitPlan2D>& plans) {
  std::map<Index, std::vector<VertexId>> made;  // original edge -> vertices made on it
  std::map<Index, std::pair<VertexId, VertexId>> ends;
  for (const CellSplitPlan2D& p : plans) {
    VertexId v[2];
    const CutNode* nodes[2] = {&p.a, &p.b};
    for (int k = 0; k < 2; ++k) {
      const CutNode& x = *nodes[k];
      if (!x.isNew()) {
        v[k] = x.vertex;
        continue;
      }
      const Index e = x.edge.index();
      if (!ends.count(e)) ends[e] = {t.topology().edgeFrom(x.edge), t.topology().edgeTo(x.edge)};
      for (VertexId w : made[e])
        if (std::abs(p.plane.normal.dot(t.position(w) - p.plane.point)) <= p.snap_distance) v[k] = w;
      if (v[k]) continue;
      // The chain of the edge, ordered along it; the piece between the two vertices around the point.
      const auto [a, b] = ends[e];
      const Vec3 ab = t.position(b) - t.position(a);
      auto along = [&](const Vec3& q) { return (q - t.position(a)).dot(ab); };
      std::vector<VertexId> chain{a, b};
      chain.insert(chain.end(), made[e].begin(), made[e].end());
      std::sort(chain.begin(), chain.end(),
                [&](VertexId u, VertexId w) { return along(t.position(u)) < along(t.position(w)); });
      std::size_t r = 0;
      while (along(t.position(chain[r + 1])) < along(x.point)) ++r;
      const VertexId lo = chain[r], hi = chain[r + 1];
      const EdgeId piece = t.topology().findEdge(lo, hi);
      REQUIRE(piece);
      v[k] = t.splitEdge(piece, x.point).vertex;
      made[e].push_back(v[k]);
    }
    if (p.daughter_from_a_to_b)
      t.splitFace(FaceId(p.cell.index()), v[1], v[0]);
    else
      t.splitFace(FaceId(p.cell.index()), v[0], v[1]);
  }
}

template <typename T>
const std::vector<T>& column(const PropertyStore& s, const char* name) {
  return s.get<T>(name).values();
}

// The same complex, numbered alike, with every list in the same order; the
// same positions, lineage and properties (bit for bit, but for cell amounts
// split by measure: the batch uses the plan's fraction, splitFace its own).
void requireSame(const Tissue& batch, const Tissue& ref) {
  REQUIRE(batch.topology().layout() == ref.topology().layout());
  REQUIRE(batch.numCells() == ref.numCells());
  CHECK(std::vector<Vec3>(batch.positions().begin(), batch.positions().end()) ==
        std::vector<Vec3>(ref.positions().begin(), ref.positions().end()));
  for (const char* name : {Tissue::kLineageName, Tissue::kParentName})
    CHECK(column<std::int64_t>(batch.cellProperties(), name) == column<std::int64_t>(ref.cellProperties(), name));
  CHECK(column<double>(batch.cellProperties(), Tissue::kBirthTimeName) ==
        column<double>(ref.cellProperties(), Tissue::kBirthTimeName));
  CHECK(batch.nextLineageId() == ref.nextLineageId());
  CHECK(column<std::int64_t>(batch.cellProperties(), "kind") == column<std::int64_t>(ref.cellProperties(), "kind"));
  CHECK(column<double>(batch.wallProperties(), "stock") == column<double>(ref.wallProperties(), "stock"));
  CHECK(column<std::int64_t>(batch.wallProperties(), "tag") == column<std::int64_t>(ref.wallProperties(), "tag"));
  const auto& a = column<double>(batch.cellProperties(), "amount");
  const auto& b = column<double>(ref.cellProperties(), "amount");
  for (std::size_t i = 0; i < a.size(); ++i) CHECK(a[i] == Approx(b[i]).epsilon(1e-12));
}

struct Case {
  Tissue tissue;
  std::vector<CellId> cells;
  std::vector<Vec3> normals;
};

// Elongated grid cells cut across their long axis: neighbours in a column
// cut their shared edge at the same point, so the second reuses the first's vertex.
Case gridCase() {
  Case k{rectangularGrid(48, 48, 1.0, 0.5), {}, {}};
  std::mt19937_64 rng(5);
  for (CellId c : k.tissue.cells())
    if (rng() % 4 != 0) {  // three cells in four, in a shuffled order
      k.cells.push_back(c);
      k.normals.push_back(Vec3(1, 0, 0));
    }
  std::shuffle(k.cells.begin(), k.cells.end(), rng);
  return k;
}

// Voronoi cells cut in random directions: shared edges cut twice at
// different points, in either order along them.
Case voronoiCase() {
  const Rectangle domain{Vec3(0, 0, 0), Vec3(60, 60, 0)};
  Case k{voronoiTissue(randomSeeds(domain, 3000, 7), domain), {}, {}};
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> angle(0, std::numbers::pi);
  for (CellId c : k.tissue.cells()) {
    k.cells.push_back(c);
    const double a = angle(rng);
    k.normals.push_back(Vec3(std::cos(a), std::sin(a), 0));
  }
  return k;
}

}  // namespace

TEST_CASE("splitCells equals the plans applied one by one with splitEdge and splitFace", "[tissue][split_cells]") {
  for (Case k : {gridCase(), voronoiCase()}) {
    addProperties(k.tissue);
    k.tissue.setTime(2.5);
    const std::vector<CellSplitPlan2D> plans = plansFor(k.tissue, k.cells, k.normals);
    // The cases to cover: edges cut by two plans, the later one's point before
    // and after the earlier one's along the edge, or within its snap distance.
    std::map<Index, std::vector<std::pair<const CellSplitPlan2D*, Vec3>>> cuts;
    for (const CellSplitPlan2D& p : plans)
      for (const CutNode* x : {&p.a, &p.b})
        if (x->isNew()) cuts[x->edge.index()].emplace_back(&p, x->point);
    int reused = 0, before = 0, after = 0;
    for (const auto& [e, list] : cuts) {
      if (list.size() < 2) continue;
      const CellSplitPlan2D& later = *list[1].first;
      const Vec3 from = k.tissue.position(k.tissue.topology().edgeFrom(EdgeId(e)));
      if (std::abs(later.plane.normal.dot(list[0].second - later.plane.point)) <= later.snap_distance)
        ++reused;
      else if ((list[1].second - from).norm() < (list[0].second - from).norm())
        ++before;
      else
        ++after;
    }
    INFO("edges cut twice: reused " << reused << ", before " << before << ", after " << after);
    CHECK(reused + before + after > 100);
    CHECK((reused > 100 || (before > 100 && after > 100)));
    Tissue batch = k.tissue, ref = k.tissue;
    const std::vector<CellSplit> splits = batch.splitCells(plans);
    oneByOne(ref, plans);
    requireSame(batch, ref);
    REQUIRE(validate(batch).ok);
    REQUIRE(splits.size() == plans.size());
    // Every cell divided once; mothers keep their handles, daughters are new cells.
    CHECK(batch.numCells() == k.tissue.numCells() + plans.size());
    for (std::size_t i = 0; i < plans.size(); ++i) {
      CHECK(batch.parentId(plans[i].cell) == k.tissue.lineageId(plans[i].cell));
      CHECK(batch.parentId(splits[i].daughter) == k.tissue.lineageId(plans[i].cell));
      CHECK(batch.birthTime(splits[i].daughter) == 2.5);
      const auto cells = batch.wallCells(splits[i].wall);
      CHECK(cells.size() == 2);
    }
    // The areas add up: the cells cover the tissue as before.
    CHECK(totalMeasure(batch) == Approx(totalMeasure(k.tissue)).epsilon(1e-12));
  }
}

TEST_CASE("splitCells reuses the vertex a neighbour makes on a shared edge", "[tissue][split_cells]") {
  // Two cells stacked in y, both cut by x = 0.5: one new vertex on their shared edge.
  Tissue t = rectangularGrid(1, 2, 1.0, 0.5);
  const std::vector<CellId> cells{CellId(0), CellId(1)};
  const std::vector<CellSplitPlan2D> plans = plansFor(t, cells, {Vec3(1, 0, 0), Vec3(1, 0, 0)});
  const std::size_t vertices = t.numVertices();
  t.splitCells(plans);
  CHECK(t.numVertices() == vertices + 3);  // bottom, shared and top edges cut once each
  CHECK(t.numCells() == 4);
  REQUIRE(validate(t).ok);
}

TEST_CASE("splitCells is the same with one and two threads", "[tissue][split_cells]") {
  for (Case k : {gridCase(), voronoiCase()}) {
    addProperties(k.tissue);
    const std::vector<CellSplitPlan2D> plans = plansFor(k.tissue, k.cells, k.normals);
    const int saved = omp_get_max_threads();
    Tissue one = k.tissue, two = k.tissue;
    omp_set_num_threads(1);
    one.splitCells(plans);
    omp_set_num_threads(2);
    two.splitCells(plans);
    omp_set_num_threads(saved);
    REQUIRE(one.topology().layout() == two.topology().layout());
    CHECK(std::vector<Vec3>(one.positions().begin(), one.positions().end()) ==
          std::vector<Vec3>(two.positions().begin(), two.positions().end()));
    for (const char* name : {"amount", Tissue::kBirthTimeName})
      CHECK(column<double>(one.cellProperties(), name) == column<double>(two.cellProperties(), name));
    CHECK(column<std::int64_t>(one.cellProperties(), Tissue::kLineageName) ==
          column<std::int64_t>(two.cellProperties(), Tissue::kLineageName));
    CHECK(column<double>(one.wallProperties(), "stock") == column<double>(two.wallProperties(), "stock"));
  }
}

TEST_CASE("splitCells refuses a cell given twice, a dead cell and a 3D tissue before changing anything",
          "[tissue][split_cells]") {
  Tissue t = rectangularGrid(2, 1);
  const std::vector<CellSplitPlan2D> plans = plansFor(t, {CellId(0), CellId(0)}, {Vec3(1, 0, 0), Vec3(1, 0, 0)});
  const ComplexLayout before = t.topology().layout();
  CHECK_THROWS_AS(t.splitCells(plans), InputError);
  CHECK_THROWS_WITH(t.splitCells(plans), Catch::Matchers::Contains("cell 0 has two plans"));
  CHECK(t.topology().layout() == before);
  Tissue box = boxGrid(1, 1, 1);
  CHECK_THROWS_AS(box.splitCells({}), InputError);
}

TEST_CASE("splitFaces names the first face given twice or dead, in chord order, before changing anything",
          "[tissue][split_cells]") {
  // 1600 chords (above the parallel threshold), each a diagonal of a grid cell.
  const Tissue t = rectangularGrid(40, 40);
  std::vector<FaceChord> chords;
  for (CellId c : t.cells()) {
    const auto loop = t.topology().faceVertices(FaceId(c.index()));
    FaceChord ch;
    ch.face = FaceId(c.index());
    ch.ends[0].vertex = loop[0];
    ch.ends[1].vertex = loop[2];
    chords.push_back(ch);
  }
  REQUIRE(chords.size() == 1600);
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    CellComplex twice = t.topology(), dead = t.topology(), fine = t.topology();
    std::vector<FaceChord> repeated = chords, with_dead = chords;
    repeated[1500].face = chords[700].face;  // face 700 again
    repeated[1510].face = chords[710].face;  // a later repeat: not the one named
    CHECK_THROWS_WITH(twice.splitFaces(repeated),
                      Catch::Matchers::Contains("face 700 is split by chords 700 and 1500"));
    CHECK(twice.layout() == t.topology().layout());
    with_dead[900].face = FaceId(99999);
    with_dead[1200].face = chords[100].face;  // a later defect
    CHECK_THROWS_WITH(dead.splitFaces(with_dead), Catch::Matchers::Contains("chord 900: face 99999 is not alive"));
    CHECK(dead.layout() == t.topology().layout());
    // The chords as given split every face once: 1600 new faces and edges, no new vertex.
    const auto out = fine.splitFaces(chords);
    CHECK(fine.slots(2) == 3200);
    CHECK(fine.slots(1) == t.topology().slots(1) + 1600);
    CHECK(fine.slots(0) == t.topology().slots(0));
    CHECK(out[1599].face == FaceId(3199));
    CHECK(out[1599].chord == EdgeId(static_cast<Index>(t.topology().slots(1) + 1599)));
  }
  omp_set_num_threads(omp_get_num_procs());
}
