// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// The fast paths of the Voronoi generators: cells read off the Delaunay
// triangulation (interior) next to clipped cells (boundary), the bulk
// builders, lattice seeds (every Voronoi vertex shared by 4 / 8 Delaunay
// triangles / cells) and independence from the thread count.

#include <catch2/catch.hpp>

#include <omp.h>

#include <algorithm>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "tessella/tissue/builders.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/tissue/validate.hpp"
#include "tessella/generators/voronoi.hpp"
#include "../../generators/src/voronoi_cells.hpp"

using namespace tessella;

namespace {

// Same counts, positions (bit for bit), loops and regions.
bool identical(const Tissue& a, const Tissue& b) {
  if (a.dim() != b.dim()) return false;
  for (int d = 0; d <= a.dim(); ++d)
    if (a.slots(d) != b.slots(d)) return false;
  const CellComplex& x = a.topology();
  const CellComplex& y = b.topology();
  auto same = [](auto s, auto t) { return std::equal(s.begin(), s.end(), t.begin(), t.end()); };
  for (VertexId v : a.vertices())
    if (a.position(v) != b.position(v) || !same(x.vertexEdges(v), y.vertexEdges(v))) return false;
  for (EdgeId e : a.edges())
    if (x.edgeVertices(e) != y.edgeVertices(e) || !same(x.edgeFaces(e), y.edgeFaces(e))) return false;
  for (FaceId f : a.faces())
    if (!same(x.faceEdges(f), y.faceEdges(f)) || !same(x.faceVertices(f), y.faceVertices(f)) ||
        !same(x.faceVolumes(f), y.faceVolumes(f)))
      return false;
  for (VolumeId c : a.volumes())
    if (!same(x.volumeFaces(c), y.volumeFaces(c))) return false;
  for (CellId c : a.cells())
    if (a.lineageId(c) != b.lineageId(c) || a.parentId(c) != b.parentId(c)) return false;
  return true;
}

// The same complex up to the numbering of edges: every face has the same
// vertex loop, its edges join the same vertex pairs the same way round, every
// edge bounds the same faces and every vertex meets the same edges.
bool sameUpToEdgeIds(const Tissue& a, const Tissue& b) {
  if (a.dim() != 2 || b.dim() != 2) return false;
  for (int d = 0; d <= 2; ++d)
    if (a.slots(d) != b.slots(d)) return false;
  const CellComplex& x = a.topology();
  const CellComplex& y = b.topology();
  using Pair = std::pair<Index, Index>;
  auto key = [](const CellComplex& c, EdgeId e) {
    const auto ev = c.edgeVertices(e);
    return Pair(std::min(ev[0].index(), ev[1].index()), std::max(ev[0].index(), ev[1].index()));
  };
  auto faces = [](const CellComplex& c, EdgeId e) {
    std::vector<Index> f;
    for (FaceId g : c.edgeFaces(e)) f.push_back(g.index());
    return f;
  };
  std::map<Pair, EdgeId> in_y;
  for (EdgeId e : b.edges()) in_y[key(y, e)] = e;
  for (EdgeId e : a.edges()) {
    const auto it = in_y.find(key(x, e));
    if (it == in_y.end() || faces(x, e) != faces(y, it->second)) return false;
  }
  for (FaceId f : a.faces()) {
    const auto ex = x.faceEdges(f), ey = y.faceEdges(f);
    const auto vx = x.faceVertices(f), vy = y.faceVertices(f);
    if (!std::equal(vx.begin(), vx.end(), vy.begin(), vy.end()) || ex.size() != ey.size()) return false;
    for (std::size_t k = 0; k < ex.size(); ++k)
      if (key(x, ex[k].handle()) != key(y, ey[k].handle()) || x.tail(ex[k]) != y.tail(ey[k])) return false;
  }
  for (VertexId v : a.vertices()) {
    if (a.position(v) != b.position(v)) return false;
    std::vector<Pair> ex, ey;
    for (EdgeId e : x.vertexEdges(v)) ex.push_back(key(x, e));
    for (EdgeId e : y.vertexEdges(v)) ey.push_back(key(y, e));
    std::sort(ex.begin(), ex.end());
    std::sort(ey.begin(), ey.end());
    if (ex != ey) return false;
  }
  return true;
}

// The same tissue built one element at a time with the editing API.
Tissue rebuiltOneByOne(const Tissue& t) {
  Tissue r(t.dim(), t.embedding());
  for (VertexId v : t.vertices()) r.addVertex(t.position(v));
  for (FaceId f : t.faces()) {
    const auto loop = t.topology().faceVertices(f);
    r.addPolygon(std::vector<VertexId>(loop.begin(), loop.end()));
  }
  for (VolumeId c : t.volumes()) {
    const auto faces = t.topology().volumeFaces(c);
    r.addVolume(std::vector<OrientedFace>(faces.begin(), faces.end()));
  }
  return r;
}

template <typename Domain>
Tissue withThreads(int threads, const std::vector<Vec3>& seeds, const Domain& domain) {
  const int before = omp_get_max_threads();
  omp_set_num_threads(threads);
  Tissue t = voronoiTissue(seeds, domain);
  omp_set_num_threads(before);
  return t;
}

}  // namespace

TEST_CASE("bulk-built tissues equal the ones built polygon by polygon", "[voronoi][builders]") {
  SECTION("2D") {
    // The 2D generator creates edges visiting cells along a Hilbert curve,
    // so only edge ids may differ from the polygon-by-polygon build.
    const Tissue t = voronoiTissue(randomSeeds(Rectangle{}, 500, 3), Rectangle{});
    REQUIRE(validate(t).ok);
    const Tissue r = rebuiltOneByOne(t);
    CHECK(sameUpToEdgeIds(t, r));
    // Without a face order the bulk build is exactly the one-by-one build.
    std::vector<Index> offsets{0}, loops;
    for (FaceId f : t.faces()) {
      for (VertexId v : t.topology().faceVertices(f)) loops.push_back(v.index());
      offsets.push_back(static_cast<Index>(loops.size()));
    }
    std::vector<Vec3> positions;
    for (VertexId v : t.vertices()) positions.push_back(t.position(v));
    const Tissue plain = buildPolygonTissue(positions, offsets, loops);
    CHECK(identical(plain, r));
    // Loops listed in another order with their face ids: the same faces,
    // edges numbered by first use in list order; a bad id list is refused.
    std::vector<Index> reversed, listed_offsets{0}, listed_loops;
    for (Index f = static_cast<Index>(t.numCells()); f-- > 0;) {
      reversed.push_back(f);
      listed_loops.insert(listed_loops.end(), loops.begin() + offsets[f], loops.begin() + offsets[f + 1]);
      listed_offsets.push_back(static_cast<Index>(listed_loops.size()));
    }
    const Tissue by_order =
        buildPolygonTissue(positions, listed_offsets, listed_loops, Embedding::Planar, reversed);
    CHECK(validate(by_order).ok);
    CHECK(sameUpToEdgeIds(by_order, r));
    CHECK_FALSE(identical(by_order, r));
    Index next_new_edge = 0;
    bool numbered_by_first_use = true;
    for (Index f : reversed)
      for (OrientedEdge e : by_order.topology().faceEdges(FaceId(f)))
        if (e.handle().index() == next_new_edge) ++next_new_edge;
        else numbered_by_first_use &= e.handle().index() < next_new_edge;
    CHECK(numbered_by_first_use);
    CHECK(next_new_edge == by_order.numEdges());
    reversed[0] = reversed[1];
    CHECK_THROWS_WITH(buildPolygonTissue(positions, listed_offsets, listed_loops, Embedding::Planar, reversed),
                      Catch::Contains("not a permutation"));
  }
  SECTION("3D") {
    // The generator flags the cells it reads off the triangulation as closed
    // by construction, and addVolumes skips their surface check; addVolume,
    // one cell at a time, checks every surface.
    for (const Tissue& t : {voronoiTissue(randomSeeds(Box{}, 300, 3), Box{}),
                            voronoiTissue(randomSeeds(Box{}, 3000, 5), Box{}),
                            voronoiTissue(randomSeeds(Ball{}, 1500, 7), Ball{})}) {
      REQUIRE(validate(t).ok);
      CHECK(identical(t, rebuiltOneByOne(t)));
    }
  }
}

TEST_CASE("bulk builders reject bad loops and cells, naming them", "[builders][errors]") {
  const std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}};
  const std::vector<Index> offsets = {0, 3, 6};
  CHECK_THROWS_WITH(buildPolygonTissue(p, offsets, std::vector<Index>{0, 1, 2, 0, 2, 7}),
                    Catch::Contains("polygon 1") && Catch::Contains("vertex 7"));
  CHECK_THROWS_WITH(buildPolygonTissue(p, offsets, std::vector<Index>{0, 1, 2, 3, 2, 3}),
                    Catch::Contains("polygon 1") && Catch::Contains("twice"));
  // A tetrahedron, then with one face turned the wrong way round.
  const std::vector<Vec3> q = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 1}};
  const std::vector<Index> face_offsets = {0, 3, 6, 9, 12};
  const std::vector<Index> loops = {0, 2, 1, 0, 1, 3, 1, 2, 3, 2, 0, 3};
  const std::vector<Index> cell_offsets = {0, 4};
  const std::vector<CellFace> good = {{0, false}, {1, false}, {2, false}, {3, false}};
  CHECK(validate(buildPolyhedralTissue(q, face_offsets, loops, cell_offsets, good)).ok);
  const std::vector<CellFace> bad = {{0, true}, {1, false}, {2, false}, {3, false}};
  CHECK_THROWS_WITH(buildPolyhedralTissue(q, face_offsets, loops, cell_offsets, bad),
                    Catch::Contains("cell 0") && Catch::Contains("not closed"));
  const std::vector<CellFace> missing = {{0, false}, {1, false}, {2, false}, {9, false}};
  CHECK_THROWS_WITH(buildPolyhedralTissue(q, face_offsets, loops, cell_offsets, missing),
                    Catch::Contains("cell 0") && Catch::Contains("face 9"));
}

TEST_CASE("a square lattice of seeds gives square cells", "[voronoi][voronoi2d][lattice]") {
  const int nx = 24, ny = 12;
  const Rectangle domain{{0, 0, 0}, {2, 1, 0}};
  std::vector<Vec3> seeds;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) seeds.emplace_back(2 * (i + 0.5) / nx, (j + 0.5) / ny, 0);
  const Tissue t = voronoiTissue(seeds, domain);
  const auto report = validate(t);
  INFO(report.message);
  REQUIRE(report.ok);
  CHECK(t.numVertices() == static_cast<std::size_t>((nx + 1) * (ny + 1)));
  CHECK(t.numEdges() == static_cast<std::size_t>(nx * (ny + 1) + ny * (nx + 1)));
  const double h = 1.0 / ny;
  for (CellId c : t.cells()) {
    CHECK(t.cellVertices(c).size() == 4);
    CHECK(cellMeasure(t, c) == Approx(h * h).epsilon(1e-12));
    CHECK((cellCentroid(t, c) - seeds[c.index()]).norm() < 1e-12);
  }
  CHECK(totalMeasure(t) == Approx(2.0).epsilon(1e-12));
}

TEST_CASE("a cubic lattice of seeds gives cubic cells", "[voronoi][voronoi3d][lattice]") {
  // Cospherical seeds: 8 Delaunay cells share each inner circumcentre.
  const int n = GENERATE(3, 6);
  std::vector<Vec3> seeds;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) seeds.emplace_back((i + 0.5) / n, (j + 0.5) / n, (k + 0.5) / n);
  const Tissue t = voronoiTissue(seeds, Box{});
  const auto report = validate(t);
  INFO(report.message);
  REQUIRE(report.ok);
  // Every inner Voronoi vertex is the common circumcentre of several Delaunay
  // cells: one vertex each, no zero-area walls.
  CHECK(t.numVertices() == static_cast<std::size_t>((n + 1) * (n + 1) * (n + 1)));
  CHECK(t.numWalls() == static_cast<std::size_t>(3 * n * n * (n + 1)));
  CHECK(t.numEdges() == static_cast<std::size_t>(3 * n * (n + 1) * (n + 1)));
  for (CellId c : t.cells()) {
    CHECK(t.cellWalls(c).size() == 6);
    CHECK(t.cellVertices(c).size() == 8);
    CHECK(cellMeasure(t, c) == Approx(1.0 / (n * n * n)).epsilon(1e-12));
    CHECK((cellCentroid(t, c) - seeds[c.index()]).norm() < 1e-12);
  }
  CHECK(totalMeasure(t) == Approx(1.0).epsilon(1e-12));
}

TEST_CASE("Voronoi tissues do not depend on the thread count", "[voronoi][threads]") {
  SECTION("2D rectangle") {
    const auto seeds = randomSeeds(Rectangle{}, 20000, 11);
    CHECK(identical(withThreads(1, seeds, Rectangle{}), withThreads(3, seeds, Rectangle{})));
  }
  SECTION("2D rectangle, enough seeds for two half triangulations") {
    const auto seeds = randomSeeds(Rectangle{}, 110000, 14);
    CHECK(identical(withThreads(1, seeds, Rectangle{}), withThreads(2, seeds, Rectangle{})));
  }
  SECTION("2D disk") {
    const auto seeds = randomSeeds(Disk{}, 5000, 12);
    CHECK(identical(withThreads(1, seeds, Disk{}), withThreads(3, seeds, Disk{})));
  }
  SECTION("3D box and ball, 1 and 2 threads") {
    const auto seeds = randomSeeds(Box{}, 400, 15);
    CHECK(identical(withThreads(1, seeds, Box{}), withThreads(2, seeds, Box{})));
    const auto in_ball = randomSeeds(Ball{}, 400, 16);
    CHECK(identical(withThreads(1, in_ball, Ball{}), withThreads(2, in_ball, Ball{})));
  }
  SECTION("3D lattice (cospherical seeds everywhere), 1 and 2 threads") {
    // Degenerate: CGAL's symbolic perturbation picks one of the many
    // triangulations, the same whichever way it is built.
    for (int n : {6, 20}) {  // 20^3 seeds: two half triangulations, split on a lattice plane
      std::vector<Vec3> seeds;
      for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
          for (int i = 0; i < n; ++i) seeds.emplace_back((i + 0.5) / n, (j + 0.5) / n, (k + 0.5) / n);
      if (n == 20) REQUIRE(detail::triangulatesInHalves3(seeds));
      const Tissue one = withThreads(1, seeds, Box{});
      REQUIRE(validate(one).ok);
      CHECK(one.numVertices() == static_cast<std::size_t>((n + 1) * (n + 1) * (n + 1)));
      CHECK(identical(one, withThreads(2, seeds, Box{})));
    }
  }
  SECTION("3D box and ball, enough seeds for two half triangulations") {
    // With 2 threads the triangulation is built as two halves side by side,
    // with 1 thread as one: the same cells, numbered the same.
    auto seeds = randomSeeds(Box{}, 20000, 17);
    REQUIRE(detail::triangulatesInHalves3(seeds));  // (else both would build one triangulation)
    const Tissue one = withThreads(1, seeds, Box{});
    REQUIRE(validate(one).ok);
    CHECK(totalMeasure(one) == Approx(1.0).epsilon(1e-9));
    CHECK(identical(one, withThreads(2, seeds, Box{})));
    const auto in_ball = randomSeeds(Ball{}, 12000, 18);
    REQUIRE(detail::triangulatesInHalves3(in_ball));
    CHECK(identical(withThreads(1, in_ball, Ball{}), withThreads(2, in_ball, Ball{})));
    // A hole around the box's centre (where the split plane runs) with one
    // seed in it: its tetrahedra reach far past the halves' margin.
    std::erase_if(seeds, [](const Vec3& p) { return (p - Vec3(0.5, 0.5, 0.5)).norm() < 0.15; });
    seeds.emplace_back(0.5, 0.5, 0.5);
    const Tissue holed = withThreads(1, seeds, Box{});
    REQUIRE(validate(holed).ok);
    CHECK(identical(holed, withThreads(2, seeds, Box{})));
    // An exact duplicate: the same error whichever way it is triangulated.
    seeds[12345] = seeds[321];
    CHECK_FALSE(detail::triangulatesInHalves3(seeds));
    std::string message[2];
    const int before = omp_get_max_threads();
    for (int threads : {1, 2}) {
      omp_set_num_threads(threads);
      try {
        voronoiTissue(seeds, Box{});
      } catch (const InputError& e) {
        message[threads - 1] = e.what();
      }
    }
    omp_set_num_threads(before);
    CHECK_FALSE(message[0].empty());
    CHECK(message[0] == message[1]);
  }
  SECTION("3D box") {
    const auto seeds = randomSeeds(Box{}, 3000, 13);
    const Tissue one = withThreads(1, seeds, Box{});
    REQUIRE(validate(one).ok);
    CHECK(totalMeasure(one) == Approx(1.0).epsilon(1e-9));
    CHECK(identical(one, withThreads(3, seeds, Box{})));
  }
}
