// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// mesh_bench: meshing time and elements per second for Voronoi tissues,
// 2D (10^3 .. 10^5 cells), curved domes and 3D (10^2 .. 10^4 cells), against
// CGAL / TetGen meshing the same input alone (no checks, no cell tagging, no
// assembly) in the same run. The overhead ratio is tessella / mesher alone.
//
// 3D rows, one per volume method:
//   cell_by_cell   "alone" is TetGen run on each cell's closed surface of wall
//                  triangles (taken from the mesh), one cell after another in
//                  this process, with the switches of the mesher's first try
//                  but without its enclosing cube (a run that crashes in the
//                  cube would end the bench; the mesher's worker processes
//                  survive it): TetGen as the mesher ran it before the cube.
//                  (The mesher runs the cells in worker processes side by side.)
//   whole_tissue   "alone" is TetGen on all walls as polygons, as before;
//                  only up to 1000 cells (it grows quadratically, see
//                  docs/meshing.md).
// Quality columns: the share of tetrahedra above the radius-edge bound and
// below a 10 degree dihedral angle, and the smallest dihedral angle.
//
//   mesh_bench [max_cells_2d [max_cells_3d]]     defaults: 100000 10000
//   mesh_bench --quick                           the smallest sizes only (1000 2D, 100 3D)
//   mesh_bench --cell-by-cell N [--no-alone]     the 3D cell-by-cell row alone, at N cells
//                                                (OMP_NUM_THREADS sets the mesher's worker processes)
//   mesh_bench --planar N [runs]                 the 2D row alone, at N cells, runs turns (default 5)
// 2D rows: Tessella and CGAL alone in turns in this process, 5 turns below
// 10^5 cells (1 from 10^5); the row gives the median of each, the median of
// the per-turn ratios and the medians of their CPU times.
// 3D rows also print the CPU time of the mesher (this process and its worker
// processes), which a busy shared machine disturbs less than wall-clock.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include <omp.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#define TETLIBRARY
#include <tetgen.h>

#include "../mesh/src/tetgen_support.hpp"  // the meshers' switch string and facet filling (internal)
#include "bench_args.hpp"
#include "bench_figure.hpp"
#include "process_usage.hpp"
#include "tessella/mesh/mesh_measures.hpp"
#include "tessella/mesh/mesh_tissue.hpp"
#include "tessella/generators/dome.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/generators/voronoi.hpp"

using namespace tessella;
using namespace tessella::mesh;

namespace {

using Clock = std::chrono::steady_clock;
double seconds(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Tds = CGAL::Triangulation_data_structure_2<CGAL::Delaunay_mesh_vertex_base_2<K>, CGAL::Delaunay_mesh_face_base_2<K>>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;

/// CGAL alone: the same vertices and wall constraints, the same criteria.
std::size_t cgalAlone(const Tissue& t, const MeshOptions& o) {
  Cdt cdt;
  std::vector<Cdt::Vertex_handle> h(t.slots(0));
  Cdt::Face_handle hint;
  for (VertexId v : t.vertices()) {
    h[v.index()] = cdt.insert(K::Point_2(t.position(v).x(), t.position(v).y()), hint);
    hint = h[v.index()]->face();
  }
  for (EdgeId e : t.edges()) cdt.insert_constraint(h[t.topology().edgeFrom(e).index()], h[t.topology().edgeTo(e).index()]);
  const double s = std::sin(o.min_angle_degrees * M_PI / 180.0);
  CGAL::refine_Delaunay_mesh_2(cdt, CGAL::Delaunay_mesh_size_criteria_2<Cdt>(s * s, o.max_edge_length));
  std::size_t n = 0;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) n += f->is_in_domain();
  return n;
}

/// TetGen alone: every wall as one polygon facet (Voronoi walls are planar).
std::size_t tetgenAlone(const Tissue& t, const MeshOptions& o) {
  tetgenio in, out;
  std::vector<int> id(t.slots(0), -1);
  in.numberofpoints = static_cast<int>(t.numVertices());
  in.pointlist = new REAL[3 * t.numVertices()];
  int n = 0;
  for (VertexId v : t.vertices()) {
    for (int k = 0; k < 3; ++k) in.pointlist[3 * n + k] = t.position(v)(k);
    id[v.index()] = n++;
  }
  in.numberoffacets = static_cast<int>(t.numWalls());
  in.facetlist = new tetgenio::facet[t.numWalls()];
  int f = 0;
  for (WallId w : t.walls()) {
    std::vector<int> corners;
    for (VertexId v : t.topology().faceVertices(handle_cast<FaceId>(w))) corners.push_back(id[v.index()]);
    mesh::detail::setPolygon(in.facetlist[f++], corners);
  }
  std::string sw = mesh::detail::tetgenSwitches("pzQ", o);
  tetrahedralize(sw.data(), &in, &out);
  return static_cast<std::size_t>(out.numberoftetrahedra);
}

/// TetGen alone on each cell's wall triangles as the cell-by-cell mesher
/// hands them over (-Y keeps them), cells one after another.
std::size_t tetgenPerCellAlone(const Tissue& t, const FeMesh& mesh, const MeshOptions& o) {
  std::vector<std::vector<int>> cell_facets(t.cellSlots());
  for (int f = 0; f < mesh.numWallFacets(); ++f)
    for (CellId c : t.wallCells(WallId(static_cast<Index>(mesh.facet_wall(f))))) cell_facets[c.index()].push_back(f);
  std::string sw = mesh::detail::tetgenSwitches("pYzQT1e-7", o);  // the mesher's first try, without the cube
  std::size_t tets = 0;
  std::vector<int> local(static_cast<std::size_t>(mesh.numNodes()), -1);
  for (CellId c : t.cells()) {
    std::vector<int> nodes;
    for (int f : cell_facets[c.index()])
      for (int k = 0; k < 3; ++k) {
        int& l = local[static_cast<std::size_t>(mesh.wall_facets(f, k))];
        if (l < 0) {
          l = static_cast<int>(nodes.size());
          nodes.push_back(mesh.wall_facets(f, k));
        }
      }
    tetgenio in, out;
    in.numberofpoints = static_cast<int>(nodes.size());
    in.pointlist = new REAL[3 * nodes.size()];
    for (std::size_t i = 0; i < nodes.size(); ++i)
      for (int k = 0; k < 3; ++k) in.pointlist[3 * i + static_cast<std::size_t>(k)] = mesh.nodes(nodes[i], k);
    in.numberoffacets = static_cast<int>(cell_facets[c.index()].size());
    in.facetlist = new tetgenio::facet[cell_facets[c.index()].size()];
    for (std::size_t i = 0; i < cell_facets[c.index()].size(); ++i) {
      const int f = cell_facets[c.index()][i];
      mesh::detail::setPolygon(in.facetlist[i], {local[static_cast<std::size_t>(mesh.wall_facets(f, 0))],
                                                local[static_cast<std::size_t>(mesh.wall_facets(f, 1))],
                                                local[static_cast<std::size_t>(mesh.wall_facets(f, 2))]});
    }
    for (int n : nodes) local[static_cast<std::size_t>(n)] = -1;
    tetrahedralize(sw.data(), &in, &out);
    tets += static_cast<std::size_t>(out.numberoftetrahedra);
  }
  return tets;
}

/// "bad %  sliver %  min dihedral" of a tetrahedral mesh.
std::string tetQuality(const FeMesh& mesh, double ratio_bound) {
  std::size_t bad = 0, slivers = 0;
  double smallest = 180;
  for (int e = 0; e < mesh.numElements(); ++e) {
    if (tetRadiusEdgeRatio(mesh, e) > ratio_bound * (1 + 1e-6)) ++bad;
    Vec3 p[4];
    for (int k = 0; k < 4; ++k) p[k] = mesh.nodes.row(mesh.elements(e, k)).transpose();
    double d = 180;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        int o[2], n = 0;
        for (int k = 0; k < 4; ++k)
          if (k != i && k != j) o[n++] = k;
        const Vec3 axis = (p[j] - p[i]).normalized();
        Vec3 a = p[o[0]] - p[i], b = p[o[1]] - p[i];
        a -= a.dot(axis) * axis;
        b -= b.dot(axis) * axis;
        d = std::min(d, std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)) * 180.0 / M_PI);
      }
    smallest = std::min(smallest, d);
    if (d < 10.0) ++slivers;
  }
  const double n = static_cast<double>(std::max<int>(1, mesh.numElements()));
  char text[128];
  std::snprintf(text, sizeof text, "  ratio>%.2g %.2f%%  dihedral<10 %.3f%%  min dihedral %.3f", ratio_bound,
                100.0 * static_cast<double>(bad) / n, 100.0 * static_cast<double>(slivers) / n, smallest);
  return text;
}

/// One row; `figure` names its FIGURE line (none when empty), with the
/// target of its overhead over the mesher alone.
void row(const char* kind, std::size_t cells, std::size_t elements, double t_tessella, double t_alone,
         std::size_t alone_elements, const std::string& figure = "", double target_overhead = bench::kNoTarget) {
  std::printf("%-8s %8zu cells %10zu elements  tessella %8.3f s (%9.0f el/s)", kind, cells, elements, t_tessella,
              static_cast<double>(elements) / t_tessella);
  if (t_alone > 0)
    std::printf("  alone %8.3f s (%9zu el)  overhead x%.2f", t_alone, alone_elements, t_tessella / t_alone);
  std::printf("\n");
  std::fflush(stdout);
  if (!figure.empty() && t_alone > 0)
    bench::printFigure(figure + "." + std::to_string(cells) + "cells", t_tessella, "s", t_alone, "mesher_alone",
                       target_overhead);
}


/// The median of `v` (the mean of the middle two for an even count).
double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

/// CPU seconds of this process and its waited-for children (the mesher's
/// worker processes) so far; without `children`, this process's only.
double cpuSeconds(bool children = true) {
  return bench::processCpuSeconds() + (children ? bench::childrenCpuSeconds() : 0.0);
}

/// The 2D row: a Voronoi rectangle of n cells meshed by Tessella and by CGAL
/// alone, `runs` times each in turns (Tessella first, then CGAL). The row
/// gives the median wall-clock of each and the median of the per-turn
/// ratios; CPU times (this process) are printed as medians too. On a shared
/// machine one run of each can differ by 1.5x from load alone, the median of
/// several turns much less.
void row2d(std::size_t n, int runs) {
  const double side = std::sqrt(static_cast<double>(n));
  const Rectangle rect{Vec3::Zero(), Vec3(side, side, 0)};
  const Tissue t = voronoiTissue(randomSeeds(rect, n, 1), rect);
  MeshOptions o;
  o.min_angle_degrees = 20;
  o.max_edge_length = 0.25;  // about 80 triangles per cell
  std::vector<double> mine, theirs, ratio, mine_cpu, theirs_cpu;
  FeMesh mesh;
  std::size_t alone = 0;
  for (int r = 0; r < runs; ++r) {
    const double c0 = cpuSeconds(false);
    auto a = Clock::now();
    mesh = meshTissue(t, o);
    auto b = Clock::now();
    const double c1 = cpuSeconds(false);
    alone = cgalAlone(t, o);
    auto c = Clock::now();
    const double c2 = cpuSeconds(false);
    mine.push_back(seconds(a, b));
    theirs.push_back(seconds(b, c));
    ratio.push_back(seconds(a, b) / seconds(b, c));
    mine_cpu.push_back(c1 - c0);
    theirs_cpu.push_back(c2 - c1);
  }
  // issue #19: within 1.3x of CGAL alone
  row("2D", t.numCells(), static_cast<std::size_t>(mesh.numElements()), median(mine), median(theirs), alone, "mesh.2d",
      1.3);
  std::printf("         %d runs in turns: median ratio x%.3f (min %.3f, max %.3f); cpu tessella %.3f s, alone %.3f s"
              " (medians, this process), cpu ratio x%.3f\n",
              runs, median(ratio), *std::min_element(ratio.begin(), ratio.end()),
              *std::max_element(ratio.begin(), ratio.end()), median(mine_cpu), median(theirs_cpu),
              median(mine_cpu) / median(theirs_cpu));
  std::fflush(stdout);
}

/// The 3D rows: a Voronoi box of n cells meshed by `method`, then (with
/// `alone`) the mesher alone on the same input, and the quality columns.
void row3d(std::size_t n, VolumeMethod method, bool alone) {
  const double side = std::cbrt(static_cast<double>(n));
  const Box box{Vec3::Zero(), Vec3::Constant(side)};
  const Tissue t = voronoiTissue(randomSeeds(box, n, 3), box);
  const bool by_cell = method == VolumeMethod::CellByCell;
  MeshOptions o;
  o.radius_edge_ratio = 1.5;
  o.max_volume = 0.02;  // at least 50 tetrahedra per cell
  o.volume_method = method;
  const double cpu0 = cpuSeconds();
  auto a = Clock::now();
  FeMesh mesh;
  try {
    mesh = meshTissue(t, o);
  } catch (const GeometryError& e) {
    // Reported, not fatal: the rest of the table still means something.
    std::printf("3D       %8zu cells  not meshed: %s\n", t.numCells(), e.what());
    return;
  }
  auto b = Clock::now();
  const double cpu = cpuSeconds() - cpu0;
  const std::size_t alone_elements = !alone ? 0 : by_cell ? tetgenPerCellAlone(t, mesh, o) : tetgenAlone(t, o);
  auto c = Clock::now();
  row(by_cell ? "3D cells" : "3D whole", t.numCells(), static_cast<std::size_t>(mesh.numElements()), seconds(a, b),
      alone ? seconds(b, c) : 0.0, alone_elements, by_cell ? "mesh.3d_cell_by_cell" : "mesh.3d_whole");
  // issue #19: 10^4 cells cell by cell within 60 s
  if (by_cell && n == 10000) bench::printFigure("mesh.3d_cell_by_cell.10000cells.time", seconds(a, b), "s", 60.0);
  std::printf("         cpu %.3f s (this process and its workers)  %s\n", cpu,
              tetQuality(mesh, o.radius_edge_ratio).c_str());
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const char* usage =
      "mesh_bench [max_cells_2d [max_cells_3d]] | --quick | --cell-by-cell N [--no-alone] | --planar N [runs]   "
      "(defaults 100000 10000)";
  if (bench::helpRequested(argc, argv, usage)) return 0;
  if (argc > 1 && std::strcmp(argv[1], "--cell-by-cell") == 0) {
    // The 3D cell-by-cell row alone, at N cells (with or without TetGen alone).
    const std::size_t n = bench::countArgument(argc, argv, 2, "N", 1000, 1, 1000000, usage);
    const bool no_alone = argc > 3 && std::strcmp(argv[3], "--no-alone") == 0;
    if (argc > 4 || (argc == 4 && !no_alone)) {
      std::fprintf(stderr, "%s: unexpected argument '%s'; usage: %s\n", argv[0], argv[argc - 1], usage);
      return 2;
    }
    std::printf("mesh_bench: 3D Voronoi box, unit mean cell size, cell by cell, %d worker processes; "
                "wall-clock, one run\n",
                omp_get_max_threads());
    row3d(n, VolumeMethod::CellByCell, !no_alone);
    return 0;
  }
  if (argc > 1 && std::strcmp(argv[1], "--planar") == 0) {
    // The 2D row alone, at N cells, `runs` turns of Tessella and CGAL alone.
    const std::size_t n = bench::countArgument(argc, argv, 2, "N", 1000, 1, 10000000, usage);
    const std::size_t runs = bench::countArgument(argc, argv, 3, "runs", 5, 1, 1000, usage);
    if (argc > 4) {
      std::fprintf(stderr, "%s: unexpected argument '%s'; usage: %s\n", argv[0], argv[4], usage);
      return 2;
    }
    std::printf("mesh_bench: 2D Voronoi rectangle, unit mean cell size; wall-clock, median of %zu runs in turns\n",
                runs);
    row2d(n, static_cast<int>(runs));
    return 0;
  }
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  const std::size_t max2d = quick ? 1000 : bench::countArgument(argc, argv, 1, "max_cells_2d", 100000, 0, 10000000, usage);
  const std::size_t max3d = quick ? 100 : bench::countArgument(argc, argv, 2, "max_cells_3d", 10000, 0, 1000000, usage);
  std::printf("mesh_bench: Voronoi tissues with unit mean cell size; times are wall-clock, 2D rows below 10^5 cells "
              "median of 5 in turns, others single runs\n");

  for (std::size_t n = 1000; n <= max2d; n *= 10) row2d(n, n < 100000 ? 5 : 1);
  for (std::size_t n = 1000; n <= std::min<std::size_t>(max2d, 10000); n *= 10) {
    const double radius = std::sqrt(static_cast<double>(n) / M_PI);
    const Disk disk{Vec3::Zero(), radius, 512};
    Dome dome;
    dome.base_radius = radius;
    dome.height = 0.5 * radius;
    const Tissue t = domeTissue(randomSeeds(disk, n, 2), dome);
    MeshOptions o;
    o.min_angle_degrees = 20;
    o.max_edge_length = 0.25;
    auto a = Clock::now();
    const FeMesh mesh = meshTissue(t, o);
    auto b = Clock::now();
    row("surface", t.numCells(), static_cast<std::size_t>(mesh.numElements()), seconds(a, b), 0, 0);
  }
  for (std::size_t n = 100; n <= max3d; n *= 10) {
    row3d(n, VolumeMethod::CellByCell, true);
    if (n > 1000)
      std::printf("3D whole %8zu cells  skipped: TetGen 1.5 on all walls grows quadratically (docs/meshing.md)\n", n);
    else
      row3d(n, VolumeMethod::WholeTissue, true);
  }
  return 0;
}
