// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// CellComplex::fromLoops against the element-by-element construction it
// documents (addVertex, addEdge at an edge's first use in list order, addFace
// in face id order): every list of the complex equal, on 1 and 2 threads, for
// grids, Voronoi tissues, random planar subdivisions, 3D face sets, shuffled
// loops and face id permutations; and its refusals, before anything is built.

#include <omp.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <map>
#include <numeric>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "tessella/generators/grids.hpp"
#include "tessella/generators/voronoi.hpp"
#include "tessella/tissue/builders.hpp"
#include "tessella/tissue/cell_complex.hpp"
#include "tessella/tissue/errors.hpp"

using namespace tessella;

namespace {

struct Loops {
  std::size_t num_vertices = 0;
  std::vector<Index> offsets{0}, vertices;
  std::vector<Index> face_ids;  // empty: loop q is face q

  void add(const std::vector<Index>& loop) {
    vertices.insert(vertices.end(), loop.begin(), loop.end());
    offsets.push_back(static_cast<Index>(vertices.size()));
  }
  std::size_t size() const { return offsets.size() - 1; }
  std::vector<Index> loop(std::size_t q) const {
    return {vertices.begin() + offsets[q], vertices.begin() + offsets[q + 1]};
  }
};

// The reference: the element-by-element construction, written out here.
CellComplex referenceComplex(int dim, const Loops& l) {
  CellComplex c(dim);
  for (std::size_t v = 0; v < l.num_vertices; ++v) c.addVertex();
  const std::size_t nf = l.size();
  std::vector<std::vector<OrientedEdge>> oriented(nf);
  std::map<std::pair<Index, Index>, EdgeId> edges;  // (lower, higher) end -> edge
  for (std::size_t q = 0; q < nf; ++q) {  // edges at their first use, in list order
    const std::vector<Index> loop = l.loop(q);
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const Index a = loop[i], h = loop[(i + 1) % loop.size()];
      auto [it, fresh] = edges.try_emplace({std::min(a, h), std::max(a, h)});
      if (fresh) it->second = c.addEdge(VertexId(a), VertexId(h));
      oriented[q].emplace_back(it->second, c.edgeFrom(it->second) != VertexId(a));
    }
  }
  std::vector<std::size_t> loop_of_face(nf);
  for (std::size_t q = 0; q < nf; ++q) loop_of_face[l.face_ids.empty() ? q : l.face_ids[q]] = q;
  for (std::size_t f = 0; f < nf; ++f) c.addFace(oriented[loop_of_face[f]]);
  return c;
}

CellComplex bulkComplex(int dim, const Loops& l) {
  return CellComplex::fromLoops(dim, l.num_vertices, l.offsets, l.vertices, l.face_ids);
}

// fromLoops on 1 and 2 threads gives the reference complex, list for list.
void checkSameComplex(int dim, const Loops& l) {
  const ComplexLayout expected = referenceComplex(dim, l).layout();
  const int threads = omp_get_max_threads();
  for (int t : {1, 2}) {
    omp_set_num_threads(t);
    const ComplexLayout got = bulkComplex(dim, l).layout();
    omp_set_num_threads(threads);
    INFO(dim << "D, " << l.size() << " loops, " << l.num_vertices << " vertices, " << t << " thread(s)");
    CHECK(got.num_vertices == expected.num_vertices);
    CHECK(got.edge_vertices == expected.edge_vertices);
    CHECK(got.vertex_edge_offsets == expected.vertex_edge_offsets);
    CHECK(got.vertex_edges == expected.vertex_edges);
    CHECK(got.face_edge_offsets == expected.face_edge_offsets);
    CHECK(got.face_edges == expected.face_edges);
    CHECK(got.edge_face_offsets == expected.edge_face_offsets);
    CHECK(got.edge_faces == expected.edge_faces);
    CHECK(got.face_volume_offsets == expected.face_volume_offsets);
    CHECK(got == expected);
  }
}

// The face loops of a tissue's complex (2D: its cells; 3D: its walls).
Loops loopsOf(const Tissue& t) {
  Loops l;
  l.num_vertices = t.topology().slots(0);
  for (FaceId f : t.faces()) {
    std::vector<Index> loop;
    for (VertexId v : t.topology().faceVertices(f)) loop.push_back(v.index());
    l.add(loop);
  }
  return l;
}

// The same loops with vertices renumbered, loops listed in another order
// (with the face ids that keep each face's id, when `keep_ids`), each loop
// started elsewhere and some reversed.
Loops shuffled(const Loops& in, std::mt19937_64& rng, bool keep_ids) {
  std::vector<Index> name(in.num_vertices);
  std::iota(name.begin(), name.end(), 0);
  std::shuffle(name.begin(), name.end(), rng);
  std::vector<std::size_t> order(in.size());
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), rng);
  Loops out;
  out.num_vertices = in.num_vertices;
  for (std::size_t q : order) {
    std::vector<Index> loop = in.loop(q);
    for (Index& v : loop) v = name[v];
    std::rotate(loop.begin(), loop.begin() + static_cast<std::ptrdiff_t>(rng() % loop.size()), loop.end());
    if (rng() % 4 == 0) std::reverse(loop.begin(), loop.end());
    out.add(loop);
    if (keep_ids) out.face_ids.push_back(static_cast<Index>(q));
  }
  return out;
}

// A random planar subdivision: a jittered-free n x n vertex grid whose squares
// are kept, cut into two triangles by either diagonal, or merged with their
// right neighbour into a hexagon-like 6-gon; then random grid edges split by
// extra vertices (shared by both sides), as pixel outlines have them.
Loops randomSubdivision(std::size_t n, std::mt19937_64& rng) {
  auto at = [n](std::size_t i, std::size_t j) { return static_cast<Index>(i + (n + 1) * j); };
  std::vector<std::vector<Index>> polys;
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t i = 0; i < n; ++i) {
      const Index a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      switch (rng() % 4) {
        case 0: polys.push_back({a, b, c, d}); break;
        case 1: polys.push_back({a, b, c}), polys.push_back({a, c, d}); break;
        case 2: polys.push_back({a, b, d}), polys.push_back({b, c, d}); break;
        default:
          if (i + 1 < n) {  // this square and the next as one 6-gon
            polys.push_back({a, b, at(i + 2, j), at(i + 2, j + 1), c, d});
            ++i;
          } else {
            polys.push_back({a, b, c, d});
          }
      }
    }
  // Split edges: a new vertex (or two) inserted between both sides' ends.
  Index next = at(n, n) + 1;
  std::map<std::pair<Index, Index>, std::vector<Index>> inserted;  // (from, to) -> the vertices between, in order
  for (const auto& p : polys)
    for (std::size_t k = 0; k < p.size(); ++k) {
      const Index u = p[k], w = p[(k + 1) % p.size()];
      if (inserted.count({u, w}) || inserted.count({w, u}) || rng() % 3) continue;
      std::vector<Index>& between = inserted[{u, w}];
      for (std::size_t m = 1 + rng() % 2; m > 0; --m) between.push_back(next++);
    }
  Loops l;
  l.num_vertices = next;
  for (const auto& p : polys) {
    std::vector<Index> loop;
    for (std::size_t k = 0; k < p.size(); ++k) {
      const Index u = p[k], w = p[(k + 1) % p.size()];
      loop.push_back(u);
      if (auto it = inserted.find({u, w}); it != inserted.end()) loop.insert(loop.end(), it->second.begin(), it->second.end());
      if (auto it = inserted.find({w, u}); it != inserted.end()) loop.insert(loop.end(), it->second.rbegin(), it->second.rend());
    }
    l.add(loop);
  }
  return l;
}

// Random triangles and quads over a few vertices, no vertex twice in a loop:
// in 3D any number of faces may share an edge.
Loops randomFaces3D(std::size_t num_vertices, std::size_t faces, std::mt19937_64& rng) {
  Loops l;
  l.num_vertices = num_vertices;
  std::vector<Index> all(num_vertices);
  std::iota(all.begin(), all.end(), 0);
  for (std::size_t f = 0; f < faces; ++f) {
    std::shuffle(all.begin(), all.end(), rng);
    l.add(std::vector<Index>(all.begin(), all.begin() + 3 + static_cast<std::ptrdiff_t>(rng() % 2)));
  }
  return l;
}

std::string refusal(int dim, const Loops& l) {
  const int threads = omp_get_max_threads();
  for (int t : {1, 2}) {
    omp_set_num_threads(t);
    CHECK_THROWS_AS(bulkComplex(dim, l), TopologyError);
  }
  omp_set_num_threads(threads);
  try {
    bulkComplex(dim, l);
  } catch (const TopologyError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST_CASE("fromLoops builds the complex addFace builds, for grids and Voronoi tissues", "[tissue][from_loops]") {
  std::mt19937_64 rng(15);
  std::vector<Loops> inputs{loopsOf(rectangularGrid(7, 5)), loopsOf(hexagonalGrid(6, 4)),
                            loopsOf(rectangularGrid(150, 120))};
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    const Rectangle domain{Vec3(0, 0, 0), Vec3(3, 2, 0)};
    inputs.push_back(loopsOf(voronoiTissue(randomSeeds(domain, 40 + 300 * seed, seed), domain)));
  }
  inputs.push_back(loopsOf(voronoiTissue(randomSeeds(Disk{}, 5000, 9), Disk{})));
  for (const Loops& l : inputs) {
    checkSameComplex(2, l);
    checkSameComplex(2, shuffled(l, rng, false));
    checkSameComplex(2, shuffled(l, rng, true));
  }
}

TEST_CASE("fromLoops builds the complex addFace builds, for random planar subdivisions", "[tissue][from_loops]") {
  std::mt19937_64 rng(33);
  for (std::size_t n : {1, 2, 3, 8, 40, 200}) {
    const Loops l = randomSubdivision(n, rng);
    checkSameComplex(2, l);
    checkSameComplex(2, shuffled(l, rng, true));
  }
  // Single polygons, and faces that meet at one vertex only.
  Loops one;
  one.num_vertices = 5000;
  std::vector<Index> big(5000);
  std::iota(big.begin(), big.end(), 0);
  one.add(big);
  checkSameComplex(2, one);
  Loops bowties;
  bowties.num_vertices = 7;
  bowties.add({0, 1, 2});
  bowties.add({0, 3, 4});
  bowties.add({4, 5, 6, 0});
  checkSameComplex(2, bowties);
  checkSameComplex(2, shuffled(bowties, rng, true));
}

TEST_CASE("fromLoops builds the complex addFace builds, for 3D face sets", "[tissue][from_loops]") {
  std::mt19937_64 rng(7);
  const Loops box = loopsOf(boxGrid(6, 5, 4));
  checkSameComplex(3, box);
  checkSameComplex(3, shuffled(box, rng, true));
  const Box domain{};
  const Loops voronoi = loopsOf(voronoiTissue(randomSeeds(domain, 300, 4), domain));
  checkSameComplex(3, voronoi);
  checkSameComplex(3, shuffled(voronoi, rng, true));
  for (std::size_t nv : {4, 6, 30}) {
    const Loops l = randomFaces3D(nv, 200, rng);
    checkSameComplex(3, l);
    checkSameComplex(3, shuffled(l, rng, true));
  }
}

TEST_CASE("fromLoops refuses bad loops with the first defect in list order", "[tissue][from_loops]") {
  Loops l;
  l.num_vertices = 6;
  l.add({0, 1, 2});
  l.add({1, 0, 3});
  SECTION("an edge in a third face (2D), named by its number in order of first use") {
    l.add({2, 4, 5});
    l.add({3, 4, 2, 1, 0});
    CHECK(refusal(2, l) == "face 3: edge 0 (vertices 1, 0) already bounds two faces");
    l.face_ids = {3, 1, 0, 2};
    CHECK(refusal(2, l) == "face 2: edge 0 (vertices 1, 0) already bounds two faces");
    l.face_ids.clear();
    checkSameComplex(3, l);  // in 3D an edge may bound any number of faces
  }
  SECTION("checks of every loop come before the edges: a repeat after an edge in a third face") {
    l.add({0, 1, 4});
    l.add({2, 5, 3, 5});
    CHECK(refusal(2, l) == "face 3 passes twice through vertex 5");
    CHECK(refusal(3, l) == "face 3 passes twice through vertex 5");
  }
  SECTION("a vertex out of range, the first in list order") {
    l.add({4, 5, 9});
    l.add({4, 7, 0});
    CHECK(refusal(2, l) == "face 2 uses vertex 9 but there are only 6 vertices");
    l.face_ids = {1, 3, 0, 2};
    CHECK(refusal(3, l) == "face 0 uses vertex 9 but there are only 6 vertices");
  }
  SECTION("a vertex out of range before a repeat in the same loop, and the last vertex's side") {
    l.add({4, 4, 8});
    CHECK(refusal(2, l) == "face 2 passes twice through vertex 4");
    Loops m;
    m.num_vertices = 3;
    m.add({0, 1, 2, 3});
    CHECK(refusal(2, m) == "face 0 uses vertex 3 but there are only 3 vertices");
  }
  SECTION("too short a loop, offsets, face ids") {
    l.add({4, 5});
    CHECK(refusal(2, l) == "face 2 has 2 vertices (at least 3 needed)");
    Loops m = l;
    m.offsets.back() = 99;
    CHECK(refusal(2, m) == "fromLoops: offsets do not cover the vertex list");
    l.face_ids = {0, 0, 1};
    CHECK(refusal(2, l) == "fromLoops: the face ids are not a permutation (face 0)");
  }
  // The builder names the polygon.
  const std::vector<Vec3> p(6, Vec3::Zero());
  CHECK_THROWS_WITH(buildPolygonTissue(p, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}),
                    "polygon 2: face 2: edge 0 (vertices 0, 1) already bounds two faces");
}
