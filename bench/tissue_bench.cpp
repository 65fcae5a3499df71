// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// tissue_bench: geometry recompute, division throughput, memory of the cell
// complex and building a planar tissue from polygon loops, printed next to the
// targets of the tissue issue and next to baselines run side by side (a flat
// loop over a CSR vertex list, no complex; copying the loops a build reads).
//
//   tissue_bench [--quick]     (--quick: skip the 10^6-cell and 10^5-cell 3D sizes)

#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <vector>

#include "tessella/tissue/builders.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/generators/grids.hpp"
#include "tessella/tissue/tissue.hpp"
#include "bench_args.hpp"
#include "bench_figure.hpp"
#include "process_usage.hpp"

using namespace tessella;
using Clock = std::chrono::steady_clock;

namespace {

template <typename F>
double bestSeconds(int repeats, F f) {
  double best = 1e300;
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = Clock::now();
    f();
    best = std::min(best, std::chrono::duration<double>(Clock::now() - t0).count());
  }
  return best;
}

// The baseline: the same area/centroid/second-moment formulas over a flat
// CSR copy of the cell vertex lists (what any hand-written loop would do).
struct FlatPolygons {
  std::vector<std::uint32_t> offsets, verts;
  std::vector<double> x, y;
};
FlatPolygons flatten(const Tissue& t) {
  FlatPolygons f;
  for (const Vec3& p : t.positions()) {
    f.x.push_back(p.x());
    f.y.push_back(p.y());
  }
  f.offsets.push_back(0);
  for (FaceId c : t.faces()) {
    for (VertexId v : t.topology().faceVertices(c)) f.verts.push_back(v.index());
    f.offsets.push_back(static_cast<std::uint32_t>(f.verts.size()));
  }
  return f;
}
void flatRecompute(const FlatPolygons& f, std::vector<double>& out) {
  const std::int64_t n = static_cast<std::int64_t>(f.offsets.size()) - 1;
  out.resize(6 * n);
#pragma omp parallel for schedule(static)
  for (std::int64_t c = 0; c < n; ++c) {
    const std::uint32_t b = f.offsets[c], e = f.offsets[c + 1];
    double a = 0, cx = 0, cy = 0, ixx = 0, iyy = 0, ixy = 0;
    std::uint32_t p = f.verts[e - 1];
    for (std::uint32_t k = b; k < e; ++k) {
      const std::uint32_t q = f.verts[k];
      const double x0 = f.x[p], y0 = f.y[p], x1 = f.x[q], y1 = f.y[q];
      const double cr = x0 * y1 - x1 * y0;
      a += cr;
      cx += (x0 + x1) * cr;
      cy += (y0 + y1) * cr;
      ixx += (x0 * x0 + x0 * x1 + x1 * x1) * cr;
      iyy += (y0 * y0 + y0 * y1 + y1 * y1) * cr;
      ixy += (x0 * y1 + 2 * x0 * y0 + 2 * x1 * y1 + x1 * y0) * cr;
      p = q;
    }
    double* o = &out[6 * c];
    o[0] = a / 2;
    o[1] = cx / (3 * a);
    o[2] = cy / (3 * a);
    o[3] = ixx / 12;
    o[4] = iyy / 12;
    o[5] = ixy / 24;
  }
}

void recompute2D(std::size_t side, double limit1, double limit2) {
  Tissue t = hexagonalGrid(side, side, 1.0);
  const std::size_t n = t.numCells();
  GeometryCache cache;
  GeometryOptions opts;
  opts.edges = false;  // area, centroid (+ normal), second moments
  FlatPolygons flat = flatten(t);
  std::vector<double> flat_out;
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    recomputeGeometry(t, cache, opts);  // warm up (allocations)
    const double s = bestSeconds(5, [&] { recomputeGeometry(t, cache, opts); });
    flatRecompute(flat, flat_out);
    const double b = bestSeconds(5, [&] { flatRecompute(flat, flat_out); });
    const double limit = threads == 1 ? limit1 : limit2;
    std::printf("  2D recompute %8zu cells, %d thread(s): %8.2f ms  %6.1f ns/cell | flat baseline %7.2f ms (ratio %.2f)",
                n, threads, s * 1e3, s * 1e9 / n, b * 1e3, s / b);
    if (limit > 0) std::printf(" | target < %.0f ms: %s", limit, s * 1e3 < limit ? "met" : "NOT met");
    std::printf("\n");
    // issue #19: within 1.3x of the flat loop
    bench::printFigure("tissue.recompute2d." + std::to_string(n) + "cells." + std::to_string(threads) + "threads", s,
                       "s", b, "flat_loop", 1.3);
  }
  if (side >= 1000) {
    std::printf("  2D memory: %.0f bytes/cell (target < 1024)\n", double(t.bytes()) / n);
    bench::printFigure("tissue.memory2d", double(t.bytes()) / n, "bytes/cell", 1024);
  }
}

void recompute3D(std::size_t side) {
  Tissue t = boxGrid(side, side, side);
  const std::size_t n = t.numCells();
  GeometryCache cache;
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    recomputeGeometry(t, cache);
    const double s = bestSeconds(3, [&] { recomputeGeometry(t, cache); });
    std::printf("  3D recompute %8zu cells, %d thread(s): %8.2f ms  %6.1f ns/cell\n", n, threads, s * 1e3,
                s * 1e9 / n);
  }
  std::printf("  3D memory: %.0f bytes/cell (target < 4096)\n", double(t.bytes()) / n);
  bench::printFigure("tissue.memory3d", double(t.bytes()) / n, "bytes/cell", 4096);
}

// Planar polygon loops like a 2D label image's cell outlines: a hexagonal
// grid's cells with every wall cut into `pieces` edges (new vertices shared by
// both sides), vertices numbered grid first, then wall by wall.
struct PolygonLoops {
  std::vector<Vec3> positions;
  std::vector<Index> offsets{0}, loops;
};
PolygonLoops outlineLoops(std::size_t side, int pieces) {
  const Tissue t = hexagonalGrid(side, side, 1.0);
  const CellComplex& c = t.topology();
  PolygonLoops p;
  p.positions.assign(t.positions().begin(), t.positions().end());
  std::vector<Index> inner_at(c.slots(1));  // the first of each edge's inner vertices, from its first vertex on
  for (EdgeId e : t.edges()) {
    inner_at[e.index()] = static_cast<Index>(p.positions.size());
    const Vec3 a = t.position(c.edgeFrom(e)), b = t.position(c.edgeTo(e));
    for (int k = 1; k < pieces; ++k) p.positions.push_back(a + (b - a) * (double(k) / pieces));
  }
  for (FaceId f : t.faces()) {
    for (OrientedEdge oe : c.faceEdges(f)) {
      p.loops.push_back(c.tail(oe).index());
      const Index first = inner_at[oe.handle().index()];
      for (int k = 1; k < pieces; ++k) p.loops.push_back(oe.reversed() ? first + (pieces - 1 - k) : first + (k - 1));
    }
    p.offsets.push_back(static_cast<Index>(p.loops.size()));
  }
  return p;
}

// buildPolygonTissue of ~10^5 cells, next to copying what it reads (positions,
// offsets, loops, into arrays already written: the memory traffic any build
// that owns its lists has at least), in turns.
void build2D(std::size_t side, int pieces) {
  const PolygonLoops p = outlineLoops(side, pieces);
  const std::size_t cells = p.offsets.size() - 1;
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    double best = 1e300, best_cpu = 1e300, copy = 1e300;
    long faults = 0;
    std::size_t edges = 0;
    PolygonLoops copied = p;  // the baseline copies into memory already touched: no allocator state in it
    for (int r = 0; r < 5; ++r) {
      const double c0 = bench::processCpuSeconds();
      const long f0 = bench::minorPageFaults();
      const auto t0 = Clock::now();
      const Tissue t = buildPolygonTissue(p.positions, p.offsets, p.loops);
      const double s = std::chrono::duration<double>(Clock::now() - t0).count();
      const double c1 = bench::processCpuSeconds();
      const long f1 = bench::minorPageFaults();
      if (s < best) best = s, best_cpu = c1 - c0, faults = f1 - f0;
      edges = t.numWalls();
      const auto t1 = Clock::now();
      std::copy(p.positions.begin(), p.positions.end(), copied.positions.begin());
      std::copy(p.offsets.begin(), p.offsets.end(), copied.offsets.begin());
      std::copy(p.loops.begin(), p.loops.end(), copied.loops.begin());
      copy = std::min(copy, std::chrono::duration<double>(Clock::now() - t1).count());
    }
    if (copied.loops != p.loops) std::abort();
    std::printf("  2D build from loops %zu cells, %zu edges, %zu vertices, %d thread(s): %7.2f ms (CPU %7.2f ms, %ld "
                "page faults) | copying the loops %6.2f ms (ratio %.2f)\n",
                cells, edges, p.positions.size(), threads, best * 1e3, best_cpu * 1e3, faults, copy * 1e3, best / copy);
    bench::printFigure("tissue.build2d." + std::to_string(cells) + "cells." + std::to_string(threads) + "threads", best,
                       "s", copy, "copy_loops", bench::kNoTarget);
  }
}

void divisions(int dim) {
  Tissue t = dim == 2 ? hexagonalGrid(100, 100, 1.0) : boxGrid(22, 22, 22);
  std::mt19937_64 rng(1);
  std::normal_distribution<double> g;
  const std::size_t n = t.numCells();
  std::vector<Plane> planes(n);
  for (std::size_t c = 0; c < n; ++c)
    planes[c] = Plane{cellCentroid(t, CellId(static_cast<Index>(c))), Vec3(g(rng), g(rng), dim == 3 ? g(rng) : 0.0)};
  std::size_t done = 0;
  const auto t0 = Clock::now();
  for (std::size_t c = 0; c < n; ++c) {
    try {
      t.splitCell(CellId(static_cast<Index>(c)), planes[c]);
      ++done;
    } catch (const GeometryError&) {
    }
  }
  const double s = std::chrono::duration<double>(Clock::now() - t0).count();
  const double rate = done / s;
  const double target = dim == 2 ? 1e5 : 1e4;
  std::printf("  %dD divisions: %zu in %.3f s = %.0f /s (%.2f us each) | target >= %.0f /s: %s\n", dim, done, s, rate,
              1e6 / rate, target, rate >= target ? "met" : "NOT met");
  bench::printFigure("tissue.divisions" + std::to_string(dim) + "d", rate, "/s", target, bench::Better::Higher);
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = tessella::bench::flagArgument(argc, argv, {"--quick"},
                                                   "tissue_bench [--quick]   (--quick: skip the 10^6-cell rows)") ==
                     "--quick";
  std::printf("tissue_bench (%d OpenMP threads available; best of repeated runs)\n", omp_get_max_threads());
  std::printf("geometry recompute (2D: area, centroid, normal, second moments):\n");
  recompute2D(100, 0, 0);
  recompute2D(316, 0, 0);
  if (!quick) recompute2D(1000, 50, 30);
  std::printf("geometry recompute (3D: face and cell measures, second moments):\n");
  recompute3D(22);
  if (!quick) recompute3D(47);
  std::printf("building a planar tissue from polygon loops (buildPolygonTissue; walls cut in 4, as pixel "
              "outlines; best of 5, CPU and page faults of that run):\n");
  build2D(316, 4);
  omp_set_num_threads(1);
  std::printf("divisions (random plane through each cell's centroid, once per cell):\n");
  divisions(2);
  divisions(3);
  return 0;
}
