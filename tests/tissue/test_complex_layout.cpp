// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// CellComplex::layout / fromLayout: a complex written as flat lists and
// rebuilt is the same complex (numbering, edge directions, loop starts,
// list orders), and a damaged layout is a located TopologyError.

#include <catch2/catch.hpp>

#include <random>
#include <string>

#include "fixtures.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/tissue/validate.hpp"

using namespace tessella;

namespace {

// Divisions by tilted planes: edges split (new edges take their place in the
// vertices' lists, not at the end), faces split, walls added.
Tissue dividedBoxes() {
  Tissue t = boxGrid(2, 2, 2);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> tilt(-0.3, 0.3);
  for (int k = 0; k < 12; ++k) {
    const CellId c(static_cast<Index>(rng() % t.cellSlots()));
    const Vec3 normal(1 + tilt(rng), tilt(rng), 0.5 + tilt(rng));
    try {
      t.splitCell(c, Plane{cellCentroid(t, c), normal.normalized()});
    } catch (const GeometryError&) {
    }
  }
  return t;
}

// Where list `k` of a CSR pair starts.
std::size_t itemOf(const std::vector<Index>& offsets, std::size_t k) { return offsets[k]; }

}  // namespace

TEST_CASE("a 3D complex rebuilt from its layout is the same complex", "[tissue][layout]") {
  const Tissue t = dividedBoxes();
  REQUIRE(t.numCells() > 12);
  const ComplexLayout layout = t.topology().layout();
  // The divisions left the region lists out of numbering order: a rebuild by
  // first use (as the snapshot reader does without the layout) would differ.
  bool unordered = false;
  for (std::size_t v = 0; v < layout.num_vertices && !unordered; ++v)
    for (Index k = layout.vertex_edge_offsets[v] + 1; k < layout.vertex_edge_offsets[v + 1]; ++k)
      unordered = unordered || layout.vertex_edges[k] < layout.vertex_edges[k - 1];
  CHECK(unordered);

  const CellComplex rebuilt = CellComplex::fromLayout(layout);
  CHECK(rebuilt.layout() == layout);
  CHECK(rebuilt.count(3) == t.numCells());
  CHECK(rebuilt.count(1) == t.numEdges());
  // Independent of layout(): the borders read through the ordinary accessors.
  for (std::size_t e = 0; e < rebuilt.count(1); ++e) {
    const EdgeId edge(static_cast<Index>(e));
    CHECK(rebuilt.edgeFrom(edge).index() == layout.edge_vertices[2 * e]);
    CHECK(rebuilt.edgeTo(edge).index() == layout.edge_vertices[2 * e + 1]);
  }
}

TEST_CASE("a 2D complex with removed cells rebuilds from its layout, renumbered", "[tissue][layout]") {
  Tissue t = hexagonalGrid(4, 4);
  t.splitCell(CellId(5), Plane{cellCentroid(t, CellId(5)), Vec3(1, 0.3, 0)});
  t.removeCell(CellId(0));
  const ComplexLayout layout = t.topology().layout();
  CHECK(layout.num_vertices == t.numVertices());
  CHECK(layout.edge_vertices.size() == 2 * t.numEdges());
  const CellComplex rebuilt = CellComplex::fromLayout(layout);
  CHECK(rebuilt.layout() == layout);
  CHECK(rebuilt.count(2) == t.numCells());
  CHECK(rebuilt.slots(2) == t.numCells());  // no tombstones
}

TEST_CASE("a damaged layout is a located TopologyError", "[tissue][layout]") {
  const ComplexLayout good = boxGrid(2, 1, 1).topology().layout();
  REQUIRE_NOTHROW(CellComplex::fromLayout(good));

  auto failsWith = [](const ComplexLayout& layout, const std::string& part) {
    try {
      CellComplex::fromLayout(layout);
      FAIL("accepted");
    } catch (const TopologyError& e) {
      INFO(e.what());
      CHECK(std::string(e.what()).find(part) != std::string::npos);
    }
  };
  ComplexLayout odd = good;
  odd.edge_vertices.pop_back();
  failsWith(odd, "odd number");

  ComplexLayout twice = good;  // edge 1 becomes a second edge between edge 0's vertices
  twice.edge_vertices[2] = good.edge_vertices[0];
  twice.edge_vertices[3] = good.edge_vertices[1];
  failsWith(twice, "edge 1:");

  ComplexLayout open_loop = good;  // face 0's first edge turned round
  open_loop.face_edges[itemOf(good.face_edge_offsets, 0)] ^= 1u;
  failsWith(open_loop, "face 0:");

  ComplexLayout flipped = good;  // volume 0 sees its first face from the wrong side
  flipped.volume_faces[itemOf(good.volume_face_offsets, 0)] ^= 1u;
  failsWith(flipped, "volume 0:");

  ComplexLayout foreign = good;  // vertex 0 claims an edge that does not touch it
  Index far_edge = 0;
  for (std::size_t e = 0; e < good.edge_vertices.size() / 2; ++e)
    if (good.edge_vertices[2 * e] != 0 && good.edge_vertices[2 * e + 1] != 0) far_edge = static_cast<Index>(e);
  foreign.vertex_edges[itemOf(good.vertex_edge_offsets, 0)] = far_edge;
  failsWith(foreign, "vertex 0: its edge list");

  ComplexLayout short_offsets = good;
  short_offsets.edge_face_offsets.pop_back();
  failsWith(short_offsets, "edge_faces has");
}

TEST_CASE("a layout changed at random is refused or rebuilt as given, and valid", "[tissue][layout]") {
  // fromLayout checks a layout in bulk and copies it, or, at a defect, builds
  // it element by element to name the defect: whatever it accepts must be a
  // complex holding exactly the lists given, with every invariant of validate().
  Tissue hex = hexagonalGrid(4, 4);
  hex.splitCell(CellId(5), Plane{cellCentroid(hex, CellId(5)), Vec3(1, 0.3, 0)});
  const Tissue boxes = dividedBoxes();
  std::mt19937_64 rng(11);
  for (const Tissue* t : {static_cast<const Tissue*>(&hex), &boxes}) {
    const ComplexLayout good = t->topology().layout();
    std::vector<Vec3> positions;
    for (std::size_t v = 0; v < t->topology().slots(0); ++v)
      if (const VertexId vertex(static_cast<Index>(v)); t->topology().alive(vertex))
        positions.push_back(t->position(vertex));
    int accepted = 0, refused = 0;
    for (int trial = 0; trial < 3000; ++trial) {
      ComplexLayout bad = good;
      std::vector<std::vector<Index>*> arrays{&bad.edge_vertices, &bad.face_edges, &bad.vertex_edges,
                                              &bad.edge_faces};
      if (good.dim == 3) {
        arrays.push_back(&bad.volume_faces);
        arrays.push_back(&bad.face_volumes);
      }
      std::vector<Index>& a = *arrays[rng() % arrays.size()];
      std::size_t i = rng() % a.size(), j = rng() % a.size();
      if (trial % 4 == 0) {  // two items of one region list: the same complex, listed in another order
        const bool at_vertex = rng() % 2 == 0;
        const auto& offsets = at_vertex ? bad.vertex_edge_offsets : bad.edge_face_offsets;
        auto& items = at_vertex ? bad.vertex_edges : bad.edge_faces;
        const std::size_t k = rng() % (offsets.size() - 1);
        if (offsets[k + 1] - offsets[k] < 2) continue;
        std::swap(items[offsets[k]], items[offsets[k + 1] - 1]);
      } else switch (rng() % 3) {
        case 0: a[i] ^= 1u << (rng() % 3); break;  // a nearby number, or the other orientation
        case 1: a[i] = a[j]; break;                // an item of another list
        default: std::swap(a[i], a[j]); break;     // within one list only the order changes
      }
      try {
        const CellComplex rebuilt = CellComplex::fromLayout(bad);
        ++accepted;
        REQUIRE(rebuilt.layout() == bad);
        const Tissue again(rebuilt, positions, t->embedding());
        const ValidationReport report = validate(again);
        INFO(report.message);
        REQUIRE(report.ok);
      } catch (const TopologyError&) {
        ++refused;
      }
    }
    INFO("accepted " << accepted << ", refused " << refused);
    CHECK(accepted > 300);  // list orders swapped within a list (and changes to the same value)
    CHECK(refused > 1000);
  }
}
