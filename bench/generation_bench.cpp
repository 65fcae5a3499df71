// Prints how long the Voronoi generators take, next to CGAL's bare Delaunay
// triangulation of the same seeds timed in the same run (the ratio is what to
// compare between machines).
//
//   generation_bench            2D: 1e4 1e5 1e6 cells, 3D: 1e3 1e4 1e5 cells
//   generation_bench --quick    2D: 1e4 1e5,           3D: 1e3 1e4

#include <chrono>
#include <cstdio>
#include <cstring>
#include <utility>
#include <vector>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <omp.h>

#include "tessella/tissue/voronoi.hpp"

using namespace tessella;

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Delaunay2 = CGAL::Delaunay_triangulation_2<
    Kernel, CGAL::Triangulation_data_structure_2<
                CGAL::Triangulation_vertex_base_with_info_2<unsigned, Kernel>>>;
using Delaunay3 = CGAL::Delaunay_triangulation_3<
    Kernel, CGAL::Triangulation_data_structure_3<
                CGAL::Triangulation_vertex_base_with_info_3<unsigned, Kernel>,
                CGAL::Delaunay_triangulation_cell_base_3<Kernel>>>;

double seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

template <typename Triangulation, typename MakePoint>
double timeDelaunay(const std::vector<Vec3>& seeds, MakePoint make_point) {
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<std::pair<typename Triangulation::Point, unsigned>> points;
  points.reserve(seeds.size());
  for (unsigned i = 0; i < seeds.size(); ++i) points.emplace_back(make_point(seeds[i]), i);
  Triangulation dt;
  dt.insert(points.begin(), points.end());
  const double t = seconds(t0);
  if (dt.number_of_vertices() != seeds.size()) std::printf("  (duplicate seeds?)\n");
  return t;
}

template <typename Domain, typename Triangulation, typename MakePoint>
void run(const char* label, const Domain& domain, std::size_t n, MakePoint make_point) {
  const auto seeds = randomSeeds(domain, n, 2024);
  const double delaunay = timeDelaunay<Triangulation>(seeds, make_point);
  const auto t0 = std::chrono::steady_clock::now();
  const Tissue t = voronoiTissue(seeds, domain);
  const double voronoi = seconds(t0);
  std::printf("%-12s %9zu cells  %8zu vertices  %8zu walls  CGAL Delaunay %7.3f s  voronoiTissue %7.3f s  ratio %5.2f\n",
              label, t.numCells(), t.numVertices(), t.numWalls(), delaunay, voronoi, voronoi / delaunay);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  // CGAL's Delaunay runs on one thread; voronoiTissue uses OMP_NUM_THREADS.
  std::printf("Voronoi generation (random seeds, rng_seed 2024; CGAL Delaunay 1 thread, voronoiTissue %d threads)\n",
              omp_get_max_threads());
  const auto p2 = [](const Vec3& p) { return Kernel::Point_2(p.x(), p.y()); };
  const auto p3 = [](const Vec3& p) { return Kernel::Point_3(p.x(), p.y(), p.z()); };
  for (std::size_t n : {std::size_t{10000}, std::size_t{100000}, std::size_t{1000000}}) {
    if (quick && n > 100000) break;
    run<Rectangle, Delaunay2>("2D rectangle", Rectangle{}, n, p2);
  }
  run<Disk, Delaunay2>("2D disk", Disk{}, quick ? 10000 : 100000, p2);
  for (std::size_t n : {std::size_t{1000}, std::size_t{10000}, std::size_t{100000}}) {
    if (quick && n > 10000) break;
    run<Box, Delaunay3>("3D box", Box{}, n, p3);
  }
  run<Ball, Delaunay3>("3D ball", Ball{}, quick ? 1000 : 10000, p3);
  return 0;
}
