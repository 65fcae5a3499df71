// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
// 3D tissues: the walls become a piecewise-linear complex (one TetGen facet
// per planar wall, one facet per fan triangle of a non-planar wall, every
// facet marked with its wall id + 1) and TetGen fills the cells with quality
// tetrahedra. Each cell is a TetGen region seeded with a point verified to lie
// strictly inside it, so the region attribute of every tetrahedron is its
// cell id + 1 (0 marks an enclosed cavity that belongs to no cell).
//
// TetGen switches (see docs/meshing.md):
//   p  mesh a piecewise-linear complex      z  number everything from 0
//   q  radius-edge ratio bound [/ min dihedral angle]
//   a  maximum tetrahedron volume           A  region attributes
//   Q  quiet
//
// TetGen runs in a worker process (isolated_tasks.hpp), as in the cell-by-cell
// mesher: a failed assertion in TetGen 1.5 calls abort(), which must not take
// the caller's process with it.

#include "volume_methods.hpp"

#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include <Eigen/Geometry>
#include <tetgen.h>

#include "isolated_tasks.hpp"
#include "tessella/mesh/mesh_tissue.hpp"
#include "tessella/tissue/errors.hpp"
#include "tessella/tissue/geometry.hpp"
#include "tetgen_support.hpp"

namespace tessella::mesh::detail {
namespace {

/// The FeMesh of TetGen's output: region attribute - 1 is the cell (0, an
/// enclosed cavity, is dropped), marked faces are wall facets.
FeMesh meshFromTetgen(const Tissue& t, const tetgenio& out, const std::vector<int>& point_vertex,
                      const WallTriangulation& walls) {
  FeMesh mesh;
  mesh.dim = 3;
  mesh.nodes.resize(out.numberofpoints, 3);
  mesh.node_vertex.setConstant(out.numberofpoints, -1);
  for (int i = 0; i < out.numberofpoints; ++i) {
    mesh.nodes.row(i) << out.pointlist[3 * i], out.pointlist[3 * i + 1], out.pointlist[3 * i + 2];
    if (i < static_cast<int>(point_vertex.size())) mesh.node_vertex(i) = point_vertex[static_cast<std::size_t>(i)];
  }
  std::vector<int> kept;
  for (int e = 0; e < out.numberoftetrahedra; ++e) {
    const int cell = static_cast<int>(std::lround(out.tetrahedronattributelist[e * out.numberoftetrahedronattributes])) - 1;
    if (cell >= 0) kept.push_back(e);  // attribute 0: an enclosed cavity, no cell's
  }
  mesh.elements.resize(static_cast<Eigen::Index>(kept.size()), 4);
  mesh.element_cell.resize(static_cast<Eigen::Index>(kept.size()));
  const int corners = out.numberofcorners;
  for (std::size_t i = 0; i < kept.size(); ++i) {
    const int e = kept[i];
    int n[4];
    for (int k = 0; k < 4; ++k) n[k] = out.tetrahedronlist[e * corners + k];
    const Vec3 a = mesh.nodes.row(n[0]).transpose();
    const double det = (Vec3(mesh.nodes.row(n[1]).transpose()) - a)
                           .dot((Vec3(mesh.nodes.row(n[2]).transpose()) - a).cross(Vec3(mesh.nodes.row(n[3]).transpose()) - a));
    if (det < 0) std::swap(n[2], n[3]);
    const auto r = static_cast<Eigen::Index>(i);
    mesh.elements.row(r) << n[0], n[1], n[2], n[3];
    mesh.element_cell(r) = static_cast<int>(std::lround(out.tetrahedronattributelist[e * out.numberoftetrahedronattributes])) - 1;
  }

  // Wall facets: the output faces lying on marked input facets.
  std::vector<int> facet_rows;
  for (int f = 0; f < out.numberoftrifaces; ++f)
    if (out.trifacemarkerlist[f] > 0) facet_rows.push_back(f);
  mesh.wall_facets.resize(static_cast<Eigen::Index>(facet_rows.size()), 3);
  mesh.facet_wall.resize(static_cast<Eigen::Index>(facet_rows.size()));
  mesh.facet_on_boundary.resize(static_cast<Eigen::Index>(facet_rows.size()));
  for (std::size_t i = 0; i < facet_rows.size(); ++i) {
    const int f = facet_rows[i];
    int n[3] = {out.trifacelist[3 * f], out.trifacelist[3 * f + 1], out.trifacelist[3 * f + 2]};
    const WallId w(static_cast<Index>(out.trifacemarkerlist[f] - 1));
    // Orient every wall facet along its wall's normal (first cell's outward side).
    const Vec3 a = mesh.nodes.row(n[0]).transpose();
    const Vec3 normal = (Vec3(mesh.nodes.row(n[1]).transpose()) - a).cross(Vec3(mesh.nodes.row(n[2]).transpose()) - a);
    if (normal.dot(walls.wall_normal[w.index()]) < 0) std::swap(n[1], n[2]);
    const auto r = static_cast<Eigen::Index>(i);
    mesh.wall_facets.row(r) << n[0], n[1], n[2];
    mesh.facet_wall(r) = static_cast<int>(w.index());
    mesh.facet_on_boundary(r) = t.isBoundaryWall(w);
  }
  return mesh;
}

template <typename M>
void appendMatrix(std::string& bytes, const M& m) {
  const std::int64_t shape[2] = {m.rows(), m.cols()};
  bytes.append(reinterpret_cast<const char*>(shape), sizeof shape);
  bytes.append(reinterpret_cast<const char*>(m.data()), sizeof(typename M::Scalar) * static_cast<std::size_t>(m.size()));
}

template <typename M>
const char* readMatrix(const char* p, M& m) {
  std::int64_t shape[2];
  std::memcpy(shape, p, sizeof shape);
  m.resize(shape[0], shape[1]);
  std::memcpy(static_cast<void*>(m.data()), p + sizeof shape, sizeof(typename M::Scalar) * static_cast<std::size_t>(m.size()));
  return p + sizeof shape + sizeof(typename M::Scalar) * static_cast<std::size_t>(m.size());
}

/// An FeMesh as bytes, to come back from the worker process.
std::string toBytes(const FeMesh& m) {
  std::string bytes;
  appendMatrix(bytes, m.nodes);
  appendMatrix(bytes, m.elements);
  appendMatrix(bytes, m.element_cell);
  appendMatrix(bytes, m.wall_facets);
  appendMatrix(bytes, m.facet_wall);
  appendMatrix(bytes, m.facet_on_boundary);
  appendMatrix(bytes, m.node_vertex);
  return bytes;
}

FeMesh fromBytes(const std::string& bytes) {
  FeMesh m;
  m.dim = 3;
  const char* p = bytes.data();
  p = readMatrix(p, m.nodes);
  p = readMatrix(p, m.elements);
  p = readMatrix(p, m.element_cell);
  p = readMatrix(p, m.wall_facets);
  p = readMatrix(p, m.facet_wall);
  p = readMatrix(p, m.facet_on_boundary);
  readMatrix(p, m.node_vertex);
  return m;
}

}  // namespace

FeMesh meshWholeTissue(const Tissue& t, const MeshOptions& options, const WallTriangulation& walls) {
  const auto& topo = t.topology();

  // Input points: live vertices, then the fan centres of non-planar walls.
  std::vector<int> point_of(walls.points.size(), -1);
  std::vector<int> point_vertex;
  std::vector<Vec3> points;
  for (VertexId v : t.vertices()) {
    point_of[v.index()] = static_cast<int>(points.size());
    points.push_back(t.position(v));
    point_vertex.push_back(static_cast<int>(v.index()));
  }
  std::size_t facets = 0;
  for (WallId w : t.walls()) {
    if (walls.wall_planar[w.index()]) {
      ++facets;
    } else {
      point_of[walls.centerPoint(w)] = static_cast<int>(points.size());
      points.push_back(walls.points[walls.centerPoint(w)]);
      point_vertex.push_back(-1);
      facets += walls.wall_triangles[w.index()].size();
    }
  }

  tetgenio in;
  in.firstnumber = 0;
  in.numberofpoints = static_cast<int>(points.size());
  in.pointlist = new REAL[points.size() * 3];
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int k = 0; k < 3; ++k) in.pointlist[3 * i + static_cast<std::size_t>(k)] = points[i](k);
  in.numberoffacets = static_cast<int>(facets);
  in.facetlist = new tetgenio::facet[facets];
  in.facetmarkerlist = new int[facets];
  std::size_t next = 0;
  for (WallId w : t.walls()) {
    const int marker = static_cast<int>(w.index()) + 1;
    if (walls.wall_planar[w.index()]) {
      std::vector<int> corners;
      for (VertexId v : topo.faceVertices(handle_cast<FaceId>(w))) corners.push_back(point_of[v.index()]);
      setPolygon(in.facetlist[next], corners);
      in.facetmarkerlist[next++] = marker;
    } else {
      for (const auto& tri : walls.wall_triangles[w.index()]) {
        setPolygon(in.facetlist[next], {point_of[static_cast<std::size_t>(tri[0])], point_of[static_cast<std::size_t>(tri[1])],
                                        point_of[static_cast<std::size_t>(tri[2])]});
        in.facetmarkerlist[next++] = marker;
      }
    }
  }

  // One region per cell, seeded strictly inside it.
  in.numberofregions = static_cast<int>(t.numCells());
  in.regionlist = new REAL[t.numCells() * 5];
  next = 0;
  for (CellId c : t.cells()) {
    const Vec3 seed = cellSeed(t, walls, c);
    for (int k = 0; k < 3; ++k) in.regionlist[5 * next + static_cast<std::size_t>(k)] = seed(k);
    in.regionlist[5 * next + 3] = static_cast<double>(c.index()) + 1.0;
    in.regionlist[5 * next + 4] = 0.0;  // no per-region volume bound (the global -a applies)
    ++next;
  }

  // TetGen runs in a worker process (isolated_tasks.hpp): if it fails an
  // assertion (it calls abort()) or crashes, that is reported, and the
  // caller's process lives on. Its time limit is the mesh's (time_limit; large tissues take long).
  const std::string switches = tetgenSwitches("pzAQ", options);
  const double limit = options.time_limit > 0 ? options.time_limit : std::numeric_limits<double>::infinity();
  const auto result = runIsolated({0}, 1, limit, [&](std::size_t) {
    tetgenio out;
    runTetgen(switches, in, out, "meshing the walls");
    return toBytes(meshFromTetgen(t, out, point_vertex, walls));
  });
  if (!result[0].ok) {
    std::string why = result[0].failure;  // TetGen's own error, or how the worker ended
    if (why.rfind("did not finish", 0) == 0) why += " (the mesh's time limit, mesh.time_limit)";
    throw GeometryError("whole-tissue mesher: " +
                        (why.rfind("TetGen", 0) == 0 ? why : "TetGen (switches \"" + switches + "\") " + why));
  }
  return fromBytes(result[0].bytes);
}

}  // namespace tessella::mesh::detail
