// mesh_bench: meshing time and elements per second for Voronoi tissues,
// 2D (10^3 .. 10^5 cells), curved domes and 3D (10^2 .. 10^4 cells), against
// CGAL / TetGen meshing the same walls alone (no checks, no cell tagging, no
// assembly) in the same run. The overhead ratio is tessella / mesher alone.
//
//   mesh_bench [max_cells_2d [max_cells_3d]]     defaults: 100000 10000
//   mesh_bench --quick                           the smallest sizes only (1000 2D, 100 3D)

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#define TETLIBRARY
#include <tetgen.h>

#include "bench_args.hpp"
#include "tessella/mesh/mesh_measures.hpp"
#include "tessella/mesh/mesh_tissue.hpp"
#include "tessella/tissue/dome.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tessella/tissue/voronoi.hpp"

using namespace tessella;

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
    const auto loop = t.topology().faceVertices(handle_cast<FaceId>(w));
    tetgenio::facet& fa = in.facetlist[f++];
    fa.numberofpolygons = 1;
    fa.polygonlist = new tetgenio::polygon[1];
    fa.numberofholes = 0;
    fa.holelist = nullptr;
    fa.polygonlist[0].numberofvertices = static_cast<int>(loop.size());
    fa.polygonlist[0].vertexlist = new int[loop.size()];
    for (std::size_t i = 0; i < loop.size(); ++i) fa.polygonlist[0].vertexlist[i] = id[loop[i].index()];
  }
  std::string sw = "pzQq";
  sw += std::to_string(o.radius_edge_ratio);
  if (o.max_volume > 0) {
    sw += 'a';
    sw += std::to_string(o.max_volume);
  }
  tetrahedralize(sw.data(), &in, &out);
  return static_cast<std::size_t>(out.numberoftetrahedra);
}

void row(const char* kind, std::size_t cells, std::size_t elements, double t_tessella, double t_alone,
         std::size_t alone_elements) {
  std::printf("%-8s %8zu cells %10zu elements  tessella %8.3f s (%9.0f el/s)", kind, cells, elements, t_tessella,
              static_cast<double>(elements) / t_tessella);
  if (t_alone > 0)
    std::printf("  alone %8.3f s (%9zu el)  overhead x%.2f", t_alone, alone_elements, t_tessella / t_alone);
  std::printf("\n");
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const char* usage = "mesh_bench [max_cells_2d [max_cells_3d]] | --quick   (defaults 100000 10000)";
  if (bench::helpRequested(argc, argv, usage)) return 0;
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  const std::size_t max2d = quick ? 1000 : bench::countArgument(argc, argv, 1, "max_cells_2d", 100000, 0, 10000000, usage);
  const std::size_t max3d = quick ? 100 : bench::countArgument(argc, argv, 2, "max_cells_3d", 10000, 0, 1000000, usage);
  std::printf("mesh_bench: Voronoi tissues with unit mean cell size; times are wall-clock, single run\n");

  for (std::size_t n = 1000; n <= max2d; n *= 10) {
    const double side = std::sqrt(static_cast<double>(n));
    const Rectangle rect{Vec3::Zero(), Vec3(side, side, 0)};
    const Tissue t = voronoiTissue(randomSeeds(rect, n, 1), rect);
    MeshOptions o;
    o.min_angle_degrees = 20;
    o.max_edge_length = 0.25;  // about 30 triangles per cell
    auto a = Clock::now();
    const FeMesh mesh = meshTissue(t, o);
    auto b = Clock::now();
    const std::size_t alone = cgalAlone(t, o);
    auto c = Clock::now();
    row("2D", t.numCells(), static_cast<std::size_t>(mesh.numElements()), seconds(a, b), seconds(b, c), alone);
  }
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
    const double side = std::cbrt(static_cast<double>(n));
    const Box box{Vec3::Zero(), Vec3::Constant(side)};
    const Tissue t = voronoiTissue(randomSeeds(box, n, 3), box);
    MeshOptions o;
    o.radius_edge_ratio = 1.5;
    o.max_volume = 0.02;  // about 50+ tetrahedra per cell
    auto a = Clock::now();
    FeMesh mesh;
    try {
      mesh = meshTissue(t, o);
    } catch (const GeometryError& e) {
      // Reported, not fatal: the rest of the table still means something.
      std::printf("3D       %8zu cells  not meshed: %s\n", t.numCells(), e.what());
      continue;
    }
    auto b = Clock::now();
    const std::size_t alone = tetgenAlone(t, o);
    auto c = Clock::now();
    row("3D", t.numCells(), static_cast<std::size_t>(mesh.numElements()), seconds(a, b), seconds(b, c), alone);
  }
  return 0;
}
