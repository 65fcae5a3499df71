// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// The shared, versioned GeometryCache: require() computes a quantity only
// when it is missing or stale for the tissue's topology and geometry
// versions, and what it computes is bit-identical to a full recompute.

#include <catch2/catch.hpp>

#include <omp.h>

#include <cstring>
#include <vector>

#include "fixtures.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/generators/grids.hpp"

using namespace tessella;
using namespace tessella::fixtures;

namespace {

using Q = GeometryQuantity;

template <typename T>
bool sameBits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

// Every counter of the cache, in GeometryQuantity order.
std::vector<std::uint64_t> counts(const GeometryCache& g) {
  return {g.computations(Q::EdgeLengths), g.computations(Q::FaceMeasures), g.computations(Q::FaceSecondMoments),
          g.computations(Q::VolumeMeasures), g.computations(Q::VolumeSecondMoments)};
}

// Moves every vertex a little, differently, so nothing is symmetric.
void perturb(Tissue& t, std::uint64_t seed) {
  for (Vec3& p : t.mutablePositions()) {
    seed = seed * 6364136223846793005ull + 1442695040888963407ull;
    p += 1e-3 * Vec3(double(seed >> 40) / (1 << 24), double((seed >> 16) & 0xffffff) / (1 << 24),
                     t.dim() == 3 ? double(seed & 0xffff) / (1 << 16) : 0.0);
  }
}

}  // namespace

TEST_CASE("geometry cache: asking again without a change computes nothing", "[tissue][geometry][cache]") {
  Tissue t = hexagonalGrid(8, 6, 0.5);
  perturb(t, 7);
  GeometryCache g;
  CHECK_FALSE(g.fresh(t, kCellMeasures));
  g.require(t, kCellMeasures);
  CHECK(counts(g) == std::vector<std::uint64_t>{0, 1, 0, 0, 0});  // no volumes in 2D
  CHECK(g.fresh(t, kCellMeasures));
  g.require(t, kCellMeasures);
  g.require(t, Q::FaceMeasures);
  CHECK(counts(g) == std::vector<std::uint64_t>{0, 1, 0, 0, 0});
  for (CellId c : t.cells()) CHECK(g.cellMeasure(t, c) == cellMeasure(t, c));
}

TEST_CASE("geometry cache: fresh() is per quantity (a cache without second moments is not fresh for them)",
          "[tissue][geometry][cache]") {
  Tissue t = rectangularGrid(4, 3);
  GeometryCache g;
  recomputeGeometry(t, g, GeometryOptions{.edges = false, .second_moments = false});
  CHECK(g.fresh(t, kCellMeasures));
  CHECK_FALSE(g.fresh(t, Q::FaceSecondMoments));
  CHECK_FALSE(g.fresh(t, Q::EdgeLengths));
  CHECK_FALSE(g.fresh(t));  // not every quantity
  // Volume quantities of a 2D tissue are nothing to compute.
  CHECK(g.fresh(t, Q::VolumeMeasures | Q::VolumeSecondMoments));
  g.require(t, kAllGeometry);
  CHECK(g.fresh(t));
  CHECK(counts(g) == std::vector<std::uint64_t>{1, 1, 1, 0, 0});
}

TEST_CASE("geometry cache: a geometry change makes every quantity stale and recomputes it",
          "[tissue][geometry][cache]") {
  Tissue t = hexagonalGrid(6, 5, 0.5);
  GeometryCache g;
  g.require(t, kAllGeometry);
  t.setPosition(VertexId(3), t.position(VertexId(3)) + Vec3(0.01, 0.02, 0));
  for (Q q : {Q::EdgeLengths, Q::FaceMeasures, Q::FaceSecondMoments}) CHECK_FALSE(g.fresh(t, q));
  g.require(t, Q::FaceMeasures);
  CHECK(counts(g) == std::vector<std::uint64_t>{1, 2, 1, 0, 0});  // only what was asked
  CHECK(g.fresh(t, Q::FaceMeasures));
  CHECK_FALSE(g.fresh(t, Q::EdgeLengths));
  for (CellId c : t.cells()) {
    CHECK(g.cellMeasure(t, c) == cellMeasure(t, c));
    CHECK(g.cellCentroid(t, c) == cellCentroid(t, c));
  }
  g.require(t, Q::EdgeLengths);
  for (EdgeId e : t.edges()) CHECK(g.edge_length[e.index()] == edgeLength(t, e));
}

TEST_CASE("geometry cache: second moments after areas computes only them, bit-identical to one full pass",
          "[tissue][geometry][cache]") {
  for (int which = 0; which < 3; ++which) {
    Tissue t = which == 0 ? hexagonalGrid(12, 10, 0.5) : which == 1 ? curvedSheet(12, 10, 1.5, 2.0)
                                                                    : boxGrid(5, 4, 3, 1.0, 0.5, 2.0);
    perturb(t, 99 + which);
    GeometryCache full;
    recomputeGeometry(t, full);  // everything in one pass
    for (int threads : {1, 2}) {
      omp_set_num_threads(threads);
      GeometryCache g;
      g.require(t, kCellMeasures);
      const std::vector<double> areas = g.face_area;
      const std::vector<double> volumes = g.volume;
      const std::uint64_t measured_faces = g.computations(Q::FaceMeasures);
      const std::uint64_t measured_volumes = g.computations(Q::VolumeMeasures);
      g.require(t, Q::FaceSecondMoments | Q::VolumeSecondMoments);
      CHECK(g.computations(Q::FaceMeasures) == measured_faces);
      CHECK(g.computations(Q::VolumeMeasures) == measured_volumes);
      CHECK(g.computations(Q::FaceSecondMoments) == 1);
      CHECK(g.computations(Q::VolumeSecondMoments) == (t.dim() == 3 ? 1u : 0u));
      CHECK(sameBits(g.face_area, areas));  // untouched
      CHECK(sameBits(g.volume, volumes));
      CHECK(sameBits(g.face_second_moment, full.face_second_moment));
      CHECK(sameBits(g.volume_second_moment, full.volume_second_moment));
      CHECK(sameBits(g.face_area, full.face_area));
      CHECK(sameBits(g.face_centroid, full.face_centroid));
      CHECK(sameBits(g.face_normal, full.face_normal));
      CHECK(sameBits(g.volume, full.volume));
      CHECK(sameBits(g.volume_surface, full.volume_surface));
      CHECK(sameBits(g.volume_centroid, full.volume_centroid));
      CHECK(g.fresh(t, kCellMeasures | Q::FaceSecondMoments | Q::VolumeSecondMoments));
    }
    omp_set_num_threads(2);
  }
}

TEST_CASE("geometry cache: in 3D volume measures bring the face areas they read", "[tissue][geometry][cache]") {
  Tissue t = boxGrid(3, 3, 2);
  GeometryCache g;
  g.require(t, Q::VolumeMeasures);
  CHECK(g.fresh(t, Q::FaceMeasures));
  CHECK(counts(g) == std::vector<std::uint64_t>{0, 1, 0, 1, 0});
  g.require(t, Q::VolumeSecondMoments);
  CHECK(counts(g) == std::vector<std::uint64_t>{0, 1, 0, 1, 1});
  for (CellId c : t.cells()) {
    CHECK(g.cellMeasure(t, c) == cellMeasure(t, c));
    CHECK(Sym3::fromMatrix(cellSecondMoment(t, c)).v == g.volume_second_moment[c.index()].v);
  }
}

TEST_CASE("geometry cache: a topology change invalidates every quantity", "[tissue][geometry][cache]") {
  for (int dim : {2, 3}) {
    Tissue t = dim == 2 ? rectangularGrid(4, 4) : boxGrid(3, 3, 3);
    GeometryCache g;
    g.require(t, kAllGeometry);
    const std::vector<std::uint64_t> before = counts(g);
    const std::size_t cells = t.numCells();
    const Vec3 centre = cellCentroid(t, CellId(0));
    t.splitCell(CellId(0), Plane{centre, Vec3(1, 0.2, 0.1).normalized()});
    REQUIRE(t.numCells() == cells + 1);
    for (Q q : {Q::EdgeLengths, Q::FaceMeasures, Q::FaceSecondMoments}) CHECK_FALSE(g.fresh(t, q));
    if (dim == 3) CHECK_FALSE(g.fresh(t, Q::VolumeMeasures | Q::VolumeSecondMoments));
    g.require(t, kAllGeometry);
    const std::vector<std::uint64_t> after = counts(g);
    for (std::size_t i = 0; i < after.size(); ++i) CHECK(after[i] == before[i] + (before[i] > 0 ? 1 : 0));
    CHECK(g.face_area.size() == t.slots(2));
    CHECK(g.edge_length.size() == t.slots(1));
    for (CellId c : t.cells()) CHECK(g.cellMeasure(t, c) == cellMeasure(t, c));
  }
}

TEST_CASE("geometry cache: versions are unique, so a cache never takes another tissue for its own",
          "[tissue][geometry][cache]") {
  Tissue a = rectangularGrid(3, 3);
  Tissue b = rectangularGrid(3, 3);  // built the same way, its own versions
  GeometryCache g;
  g.require(a, kCellMeasures);
  CHECK_FALSE(g.fresh(b, kCellMeasures));
  Tissue copy = a;  // the same content until one of them changes
  CHECK(g.fresh(copy, kCellMeasures));
  copy.setPosition(VertexId(0), Vec3(-0.1, -0.1, 0));
  CHECK_FALSE(g.fresh(copy, kCellMeasures));
  CHECK(g.fresh(a, kCellMeasures));
  g.forget();
  CHECK_FALSE(g.fresh(a, kCellMeasures));
}
