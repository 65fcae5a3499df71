// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// 3D tissues, cell by cell: the walls are meshed first, once, to the size and
// angle bounds (wall_surface_mesh.hpp), and then every cell is filled by its
// own TetGen run on the closed surface of its wall triangles, with -Y so that
// TetGen keeps those triangles as they are. Two cells sharing a wall therefore
// share every node on it, and the cells can be meshed in parallel.
//
// Why not one TetGen run on all walls (volume_methods_whole_tissue.cpp): TetGen 1.5's
// facet repair walks its whole queue of subfaces for every refinement step
// that encroaches one, which grows quadratically with the number of walls
// (docs/meshing.md). Per cell, that queue holds one cell's walls.
//
// TetGen switches: p mesh a PLC, Y keep the input wall triangles, z number
// from 0, A region attributes (the cell's region is 1; 0 is a cavity such as
// a cell enclosed by this one, dropped), Q quiet, T<tol> coplanarity
// tolerance, then q<ratio>[/<dihedral>][a<volume>].
//
// The runs happen in worker processes (isolated_tasks.hpp): TetGen 1.5 calls
// abort() on a failed assertion and can flip forever on near-degenerate
// input, and it is not reentrant (tetgen_support.hpp). The wall points of a
// planar wall are coplanar only up to rounding, so neighbouring wall
// triangles meet at folds of ~1e-16 that the coplanarity tolerance decides
// about: a cell whose run fails is tried again with the next tolerance.
//
// Enclosing cube: every point TetGen is given lies on the cell's boundary,
// most of them on a few planes. Inserted one by one into a Delaunay
// tetrahedralization, each such point is coplanar with faces of the convex
// hull built so far, and TetGen's hull insertion decides those ties with
// exact arithmetic (Shewchuk's adaptive insphere falling through to its
// exact stages): on Voronoi cells that was 60 % of TetGen's time, the
// quality refinement included. So the first try adds the 8 corners of a
// cube around the cell, twice its size: the hull is then the cube, the wall
// points are inserted inside it, and the tetrahedra outside the walls are
// removed with the rest of the exterior (docs/meshing.md, figures). The
// corners are no vertices of the cell's mesh (checked). A cell whose runs
// with the cube fail is tried again without it, with the tolerances below.

#include "volume_methods.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include <omp.h>
#include <tetgen.h>

#include "isolated_tasks.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/format.hpp"
#include "tetgen_support.hpp"
#include "wall_surface_mesh.hpp"

namespace tessella::mesh::detail {
namespace {

/// One cell's tetrahedra. Corners >= 0 are wall-mesh nodes; < 0 are
/// -(k + 1) for the cell's own interior point k.
struct CellMesh {
  std::vector<Vec3> added;
  std::vector<std::array<int, 4>> tets;
};

/// Longest wall-triangle edge: max_edge_length if given, else the edge of
/// the regular tetrahedron of volume max_volume, else none.
double wallEdgeBound(const MeshOptions& o) {
  if (o.max_edge_length > 0.0) return o.max_edge_length;
  if (o.max_volume > 0.0) return std::cbrt(6.0 * std::sqrt(2.0) * o.max_volume);
  return 0.0;
}

/// One TetGen try for a cell: a coplanarity tolerance (TetGen -T), with or
/// without the enclosing cube (above).
struct Attempt {
  const char* tolerance;
  bool enclose;
  bool rotate = false;  ///< TetGen meshes the cell turned about its centre (turnMatrix), its points turned back
};
/// Tries, in order, for a cell whose TetGen run fails: with the cube, then
/// without it as before the cube: the default tolerance (1e-8) failed on some
/// Voronoi cells with short edges (never-ending flips, failed assertions)
/// where 1e-7 worked, and 1e-6 merges the ends of edges shorter than 1e-6 x
/// the cell's size.
/// Then, for a cell failing all of those, the cell turned (TetGen meshes it in turned coordinates, the
/// points it adds are turned back; the wall points stay the walls' own): on label images at simplify 1 and 0
/// TetGen failed an assertion of its insphere test (`oriB != 0.0`) or lost a voxel of the cell's volume with
/// every tolerance on cells whose points all lay on a few axis-parallel planes of the voxel grid, with clean
/// walls (no two triangles closer than 0.05 voxel, none crossing, no fold under 31 degrees): exactly coplanar
/// and cospherical points, which its symbolic perturbation does not resolve. Turned, they no longer are.
constexpr Attempt kAttempts[] = {{"T1e-7", true},  {"T1e-7", false},      {"", false},          {"T1e-9", false},
                                 {"T1e-6", false}, {"T1e-7", true, true}, {"T1e-7", false, true}};
/// Relative difference allowed between the volume of a cell's tetrahedra and
/// the volume its wall triangles enclose (docs/meshing.md: 1e-9 per cell).
constexpr double kVolumeTolerance = 1e-9;

std::string serialize(const CellMesh& cm) {
  const std::uint64_t sizes[2] = {cm.added.size(), cm.tets.size()};
  std::string out(sizeof sizes + cm.added.size() * sizeof(Vec3) + cm.tets.size() * sizeof(std::array<int, 4>), '\0');
  char* p = out.data();
  std::memcpy(p, sizes, sizeof sizes);
  p += sizeof sizes;
  if (!cm.added.empty()) std::memcpy(p, cm.added.data(), cm.added.size() * sizeof(Vec3));
  p += cm.added.size() * sizeof(Vec3);
  if (!cm.tets.empty()) std::memcpy(p, cm.tets.data(), cm.tets.size() * sizeof(std::array<int, 4>));
  return out;
}

CellMesh deserialize(const std::string& bytes) {
  std::uint64_t sizes[2];
  std::memcpy(sizes, bytes.data(), sizeof sizes);
  CellMesh cm;
  cm.added.resize(sizes[0]);
  cm.tets.resize(sizes[1]);
  const char* p = bytes.data() + sizeof sizes;
  if (sizes[0] > 0) std::memcpy(static_cast<void*>(cm.added.data()), p, sizes[0] * sizeof(Vec3));
  p += sizes[0] * sizeof(Vec3);
  if (sizes[1] > 0) std::memcpy(cm.tets.data(), p, sizes[1] * sizeof(std::array<int, 4>));
  return cm;
}

/// `local_of` is scratch: one -1 per wall-mesh node, left as found.
/// The turn of an Attempt's `rotate`: 1 radian about the axis (1, 2, 3), nothing special to a voxel grid.
Eigen::Matrix3d turnMatrix() {
  return Eigen::AngleAxisd(1.0, Vec3(1, 2, 3).normalized()).toRotationMatrix();
}

CellMesh meshCell(const Tissue& t, const WallSurfaceMesh& wm, CellId c, const Vec3& seed, const std::string& switches,
                  bool enclose, bool rotate, std::vector<int>& local_of) {
  const auto cellError = [&](const std::string& what) {
    return GeometryError("cell-by-cell mesher: cell " + std::to_string(c.index()) + ": " + what, ElementId{3, c.index()});
  };
  std::vector<int> global;  // local point -> wall-mesh node
  std::vector<std::array<int, 3>> triangles;
  double volume6 = 0;  // six times the cell's volume, from its outward wall triangles
  Vec3 origin = Vec3::Zero();
  for (OrientedFace of : t.topology().volumeFaces(handle_cast<VolumeId>(c))) {
    const std::size_t w = of.handle().index();
    for (std::size_t k = wm.wall_begin[w]; k < wm.wall_begin[w + 1]; ++k) {
      const auto& [a, b, d] = wm.triangles[k];
      if (triangles.empty()) origin = wm.nodes[static_cast<std::size_t>(a)];
      const auto at = [&](int n) { return Vec3(wm.nodes[static_cast<std::size_t>(n)] - origin); };
      const double v6 = at(a).dot(at(b).cross(at(d)));
      volume6 += of.reversed() ? -v6 : v6;
      std::array<int, 3> tri{};
      for (std::size_t j = 0; j < 3; ++j) {
        int& local = local_of[static_cast<std::size_t>(wm.triangles[k][j])];
        if (local < 0) {
          local = static_cast<int>(global.size());
          global.push_back(wm.triangles[k][j]);
        }
        tri[j] = local;
      }
      triangles.push_back(tri);
    }
  }
  for (int g : global) local_of[static_cast<std::size_t>(g)] = -1;

  // The cube's corners (when `enclose`) follow the wall points.
  const std::size_t corners = enclose ? 8 : 0;
  tetgenio in, out;
  in.firstnumber = 0;
  in.numberofpoints = static_cast<int>(global.size() + corners);
  in.pointlist = new REAL[(global.size() + corners) * 3];
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (std::size_t i = 0; i < global.size(); ++i) {
    const Vec3& x = wm.nodes[static_cast<std::size_t>(global[i])];
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  // Turned (rotate) about the centre of the cell's bounding box: TetGen gets turned(x), and turns back the points
  // it adds.
  const Eigen::Matrix3d turn = rotate ? turnMatrix() : Eigen::Matrix3d::Identity();
  const Vec3 pivot = 0.5 * (lo + hi);
  const auto turned = [&](const Vec3& x) { return rotate ? Vec3(pivot + turn * (x - pivot)) : x; };
  const auto turnedBack = [&](const Vec3& x) { return rotate ? Vec3(pivot + turn.transpose() * (x - pivot)) : x; };
  for (std::size_t i = 0; i < global.size(); ++i) {
    const Vec3 x = turned(wm.nodes[static_cast<std::size_t>(global[i])]);
    for (std::size_t k = 0; k < 3; ++k) in.pointlist[3 * i + k] = x(static_cast<Eigen::Index>(k));
  }
  if (rotate) {  // the turned cell's box
    lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for (std::size_t i = 0; i < global.size(); ++i) {
      const Vec3 x(in.pointlist[3 * i], in.pointlist[3 * i + 1], in.pointlist[3 * i + 2]);
      lo = lo.cwiseMin(x);
      hi = hi.cwiseMax(x);
    }
  }
  // Centred on the cell's bounding box, half-side twice its largest half-extent.
  const Vec3 centre = 0.5 * (lo + hi);
  const double half = (hi - lo).maxCoeff();
  std::array<Vec3, 8> corner;
  for (std::size_t j = 0; j < corners; ++j) {
    for (Eigen::Index k = 0; k < 3; ++k) corner[j](k) = centre(k) + ((j >> k) & 1U ? half : -half);
    for (std::size_t k = 0; k < 3; ++k)
      in.pointlist[3 * (global.size() + j) + k] = corner[j](static_cast<Eigen::Index>(k));
  }
  in.numberoffacets = static_cast<int>(triangles.size());
  in.facetlist = new tetgenio::facet[triangles.size()];
  for (std::size_t f = 0; f < triangles.size(); ++f)
    setPolygon(in.facetlist[f], {triangles[f][0], triangles[f][1], triangles[f][2]});
  in.numberofregions = 1;
  const Vec3 region_seed = turned(seed);
  in.regionlist = new REAL[5]{region_seed.x(), region_seed.y(), region_seed.z(), 1.0, 0.0};
  runTetgen(switches, in, out, "meshing cell " + std::to_string(c.index()));

  // -Y: the walls must come back exactly as given (TetGen may not split or
  // merge them, or the neighbour's copy of a wall would no longer match).
  // TetGen drops the cube's corners from its output once the tetrahedra
  // outside the walls are removed, so its points are the wall points, in
  // their order, then the points it added.
  const int inputs = static_cast<int>(global.size());
  const auto sorted = [](std::array<int, 3> tri) {
    std::sort(tri.begin(), tri.end());
    return tri;
  };
  std::vector<std::array<int, 3>> given, returned;
  for (const auto& tri : triangles) given.push_back(sorted(tri));
  for (int f = 0; f < out.numberoftrifaces; ++f)
    returned.push_back(sorted({out.trifacelist[3 * f], out.trifacelist[3 * f + 1], out.trifacelist[3 * f + 2]}));
  std::sort(given.begin(), given.end());
  std::sort(returned.begin(), returned.end());
  if (out.numberofpoints < inputs || given != returned)
    throw cellError("TetGen changed the cell's wall triangles (" + std::to_string(triangles.size()) + " given, " +
                    std::to_string(out.numberoftrifaces) + " returned, " +
                    std::to_string(std::max(0, out.numberofpoints - inputs)) + " points added)");
  if (!std::equal(in.pointlist, in.pointlist + 3 * inputs, out.pointlist))
    throw cellError("TetGen renumbered the cell's wall points");

  CellMesh cm;
  std::vector<int> added_of(static_cast<std::size_t>(out.numberofpoints - inputs), -1);
  const auto node = [&](int p) {
    if (p < inputs) return global[static_cast<std::size_t>(p)];
    int& a = added_of[static_cast<std::size_t>(p - inputs)];
    if (a < 0) {
      a = static_cast<int>(cm.added.size());
      const Vec3 x(out.pointlist[3 * p], out.pointlist[3 * p + 1], out.pointlist[3 * p + 2]);
      for (std::size_t j = 0; j < corners; ++j)
        if (x == corner[j]) throw cellError("a tetrahedron of the cell reaches a corner of the enclosing cube");
      cm.added.push_back(turnedBack(x));
    }
    return -a - 1;
  };
  const auto position = [&](int p) { return Vec3(out.pointlist[3 * p], out.pointlist[3 * p + 1], out.pointlist[3 * p + 2]); };
  double tets6 = 0;  // six times the tetrahedra's volume
  for (int e = 0; e < out.numberoftetrahedra; ++e) {
    if (std::lround(out.tetrahedronattributelist[e * out.numberoftetrahedronattributes]) != 1) continue;  // a cavity
    std::array<int, 4> p{};
    for (int k = 0; k < 4; ++k) p[static_cast<std::size_t>(k)] = out.tetrahedronlist[e * out.numberofcorners + k];
    const Vec3 a = position(p[0]);
    const double v6 = (position(p[1]) - a).dot((position(p[2]) - a).cross(position(p[3]) - a));
    if (v6 < 0) std::swap(p[2], p[3]);
    tets6 += std::abs(v6);
    cm.tets.push_back({node(p[0]), node(p[1]), node(p[2]), node(p[3])});
  }
  // The tetrahedra must fill the cell, neither more nor less (the walls of
  // an enclosed cavity are the cell's walls too, so its volume is not counted).
  if (!(std::abs(tets6 - volume6) <= kVolumeTolerance * std::abs(volume6)))
    throw cellError("TetGen's tetrahedra add up to a volume of " + std::to_string(tets6 / 6) +
                    ", the cell's walls enclose " + std::to_string(volume6 / 6));
  return cm;
}

}  // namespace

FeMesh meshCellByCell(const Tissue& t, const MeshOptions& options, const WallTriangulation& walls) {
  const WallSurfaceMesh wm = meshWallSurfaces(t, walls, wallEdgeBound(options), options.min_angle_degrees);
  const std::vector<CellId> cells(t.cells().begin(), t.cells().end());

  // Every cell in a worker process (isolated_tasks.hpp): a TetGen run that
  // aborts or never ends costs that cell's attempt, not the caller. A cell
  // that fails is tried again with the next coplanarity tolerance, within its
  // time limit (try k of n may run for cell_time_limit / 2^(k+1), the last as
  // long as the one before, so that they add up to the limit) and the mesh's
  // (MeshOptions::cell_time_limit, time_limit).
  const double inf = std::numeric_limits<double>::infinity();
  const double cell_limit = options.cell_time_limit > 0 ? options.cell_time_limit : inf;
  const double run_limit = options.time_limit > 0 ? options.time_limit : inf;
  const auto t_start = std::chrono::steady_clock::now();
  std::vector<CellMesh> meshed(cells.size());
  std::vector<std::size_t> todo(cells.size());
  for (std::size_t i = 0; i < cells.size(); ++i) todo[i] = i;
  std::vector<std::string> failures(cells.size());
  std::vector<int> local_of(wm.nodes.size(), -1);  // each worker's own copy
  const auto limitsText = [&] {
    return std::string(" (time limits: ") + (cell_limit < inf ? formatNumber(cell_limit) + " s" : "none") +
           " per cell, mesh.cell_time_limit; " + (run_limit < inf ? formatNumber(run_limit) + " s" : "none") +
           " per mesh, mesh.time_limit)";
  };
  bool limited = false;  // a try was cut short, or not made, by a time limit
  constexpr std::size_t n_attempts = std::size(kAttempts);
  for (std::size_t a = 0; a < n_attempts && !todo.empty(); ++a) {
    const Attempt& attempt = kAttempts[a];
    const std::string switches = tetgenSwitches(std::string("pYzAQ") + attempt.tolerance, options);
    const std::string tried =
        "switches " + switches + (attempt.enclose ? " in a cube" : "") + (attempt.rotate ? " turned" : "");
    const double run_left =
        run_limit - std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
    const double try_limit = cell_limit / std::ldexp(1.0, static_cast<int>(std::min(a + 1, n_attempts - 1)));
    std::vector<std::size_t> runnable, failed;
    for (const std::size_t i : todo) {
      if (run_left > 0) {
        runnable.push_back(i);
        continue;
      }
      limited = true;
      failures[i] += "; not tried: " + tried + " (the time limit of the mesh was spent)";
      failed.push_back(i);
    }
    const auto results = runIsolated(runnable, omp_get_max_threads(), std::vector<double>(runnable.size(), try_limit),
                                     std::max(run_left, 0.0), [&](std::size_t i) {
      return serialize(meshCell(t, wm, cells[i], cellSeed(t, walls, cells[i]), switches, attempt.enclose,
                                attempt.rotate, local_of));
    });
    for (std::size_t k = 0; k < runnable.size(); ++k) {
      const std::size_t i = runnable[k];
      if (results[k].ok) {
        meshed[i] = deserialize(results[k].bytes);
        continue;
      }
      limited = limited || !results[k].started || results[k].seconds >= try_limit;
      failures[i] += std::string(failures[i].empty() ? "" : "; ") + tried + ": " + results[k].failure;
      failed.push_back(i);
    }
    std::sort(failed.begin(), failed.end());
    todo = std::move(failed);
  }
  if (!todo.empty()) {
    const CellId c = cells[todo.front()];
    throw GeometryError("cell-by-cell mesher: TetGen could not mesh cell " + std::to_string(c.index()) + " (" +
                            std::to_string(todo.size()) + " cells failed) with any tolerance tried" +
                            (limited ? limitsText() : std::string()) + ": " + failures[todo.front()],
                        ElementId{3, c.index()});
  }

  // Nodes: the wall mesh's, then each cell's interior points, cell by cell.
  std::size_t nodes = wm.nodes.size(), elements = 0;
  std::vector<std::size_t> first_added(cells.size());
  for (std::size_t i = 0; i < cells.size(); ++i) {
    first_added[i] = nodes;
    nodes += meshed[i].added.size();
    elements += meshed[i].tets.size();
  }
  FeMesh mesh;
  mesh.dim = 3;
  mesh.nodes.resize(static_cast<Eigen::Index>(nodes), 3);
  mesh.node_vertex.setConstant(static_cast<Eigen::Index>(nodes), -1);
  for (std::size_t n = 0; n < wm.nodes.size(); ++n) {
    mesh.nodes.row(static_cast<Eigen::Index>(n)) = wm.nodes[n].transpose();
    mesh.node_vertex(static_cast<Eigen::Index>(n)) = wm.node_vertex[n];
  }
  mesh.elements.resize(static_cast<Eigen::Index>(elements), 4);
  mesh.element_cell.resize(static_cast<Eigen::Index>(elements));
  Eigen::Index row = 0;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const CellMesh& cm = meshed[i];
    for (std::size_t k = 0; k < cm.added.size(); ++k) mesh.nodes.row(static_cast<Eigen::Index>(first_added[i] + k)) = cm.added[k].transpose();
    for (const auto& tet : cm.tets) {
      for (Eigen::Index k = 0; k < 4; ++k) {
        const int n = tet[static_cast<std::size_t>(k)];
        mesh.elements(row, k) = n >= 0 ? n : static_cast<int>(first_added[i]) - n - 1;
      }
      mesh.element_cell(row++) = static_cast<int>(cells[i].index());
    }
  }

  const auto facets = static_cast<Eigen::Index>(wm.triangles.size());
  mesh.wall_facets.resize(facets, 3);
  mesh.facet_wall.resize(facets);
  mesh.facet_on_boundary.resize(facets);
  for (Eigen::Index f = 0; f < facets; ++f) {
    const auto& tri = wm.triangles[static_cast<std::size_t>(f)];
    mesh.wall_facets.row(f) << tri[0], tri[1], tri[2];
    mesh.facet_wall(f) = wm.triangle_wall[static_cast<std::size_t>(f)];
    mesh.facet_on_boundary(f) = t.isBoundaryWall(WallId(static_cast<Index>(mesh.facet_wall(f))));
  }
  return mesh;
}

}  // namespace tessella::mesh::detail
