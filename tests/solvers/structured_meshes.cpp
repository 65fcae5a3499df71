// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "structured_meshes.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>
#include <utility>

namespace tessella::test {

namespace {

// Collects the faces (dim nodes) of all elements lying on a plane
// coord[axis] == value; each face once, with the given wall id.
struct WallCollector {
  std::vector<std::vector<int>> facets;
  std::vector<int> wall;
  std::vector<bool> boundary;
  std::set<std::vector<int>> seen;
};

void collectPlane(const mesh::FeMesh& m, WallCollector& wc, int axis, double value, int wall_id, bool on_boundary) {
  const int d = m.dim;
  const double tol = 1e-9;
  for (int e = 0; e < m.numElements(); ++e)
    for (int opp = 0; opp <= d; ++opp) {
      std::vector<int> face;
      for (int a = 0; a <= d; ++a)
        if (a != opp) face.push_back(m.elements(e, a));
      bool on = true;
      for (int i : face) on = on && std::abs(m.nodes(i, axis) - value) < tol;
      if (!on) continue;
      std::vector<int> key = face;
      std::sort(key.begin(), key.end());
      if (!wc.seen.insert(key).second) continue;
      wc.facets.push_back(face);
      wc.wall.push_back(wall_id);
      wc.boundary.push_back(on_boundary);
    }
}

void storeWalls(mesh::FeMesh& m, const WallCollector& wc) {
  const int nf = static_cast<int>(wc.facets.size());
  m.wall_facets.resize(nf, m.dim);
  m.facet_wall.resize(nf);
  m.facet_on_boundary.resize(nf);
  for (int f = 0; f < nf; ++f) {
    for (int a = 0; a < m.dim; ++a) m.wall_facets(f, a) = wc.facets[static_cast<std::size_t>(f)][static_cast<std::size_t>(a)];
    m.facet_wall[f] = wc.wall[static_cast<std::size_t>(f)];
    m.facet_on_boundary[f] = wc.boundary[static_cast<std::size_t>(f)];
  }
}

void assignCells(mesh::FeMesh& m, double lx, bool two_cells) {
  m.element_cell = Eigen::VectorXi::Zero(m.numElements());
  if (!two_cells) return;
  for (int e = 0; e < m.numElements(); ++e) {
    double cx = 0.0;
    for (int a = 0; a <= m.dim; ++a) cx += m.nodes(m.elements(e, a), 0);
    m.element_cell[e] = cx / (m.dim + 1) < 0.5 * lx ? 0 : 1;
  }
}

}  // namespace

mesh::FeMesh rectangleMesh(int nx, int ny, double lx, double ly, bool two_cells) {
  if (two_cells && nx % 2) throw std::invalid_argument("rectangleMesh: two_cells needs an even nx");
  mesh::FeMesh m;
  m.dim = 2;
  m.nodes.resize((nx + 1) * (ny + 1), 3);
  auto id = [nx](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) m.nodes.row(id(i, j)) << lx * i / nx, ly * j / ny, 0.0;
  m.elements.resize(2 * nx * ny, 3);
  int e = 0;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      m.elements.row(e++) << id(i, j), id(i + 1, j), id(i + 1, j + 1);  // counter-clockwise
      m.elements.row(e++) << id(i, j), id(i + 1, j + 1), id(i, j + 1);
    }
  assignCells(m, lx, two_cells);
  WallCollector wc;
  collectPlane(m, wc, 0, 0.0, 0, true);
  collectPlane(m, wc, 0, lx, 1, true);
  collectPlane(m, wc, 1, 0.0, 2, true);
  collectPlane(m, wc, 1, ly, 3, true);
  if (two_cells) collectPlane(m, wc, 0, 0.5 * lx, 4, false);
  storeWalls(m, wc);
  m.node_vertex = Eigen::VectorXi::Constant(m.numNodes(), -1);
  return m;
}

mesh::FeMesh boxMesh(int nx, int ny, int nz, double lx, double ly, double lz, bool two_cells) {
  if (two_cells && nx % 2) throw std::invalid_argument("boxMesh: two_cells needs an even nx");
  mesh::FeMesh m;
  m.dim = 3;
  m.nodes.resize((nx + 1) * (ny + 1) * (nz + 1), 3);
  auto id = [nx, ny](int i, int j, int k) { return (k * (ny + 1) + j) * (nx + 1) + i; };
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) m.nodes.row(id(i, j, k)) << lx * i / nx, ly * j / ny, lz * k / nz;
  // Kuhn subdivision: one tetrahedron per path 000 -> 111 along the axes (6
  // permutations); the same in every cube, so the faces match across cubes.
  const std::array<std::array<int, 3>, 6> perms{{{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
  m.elements.resize(6 * nx * ny * nz, 4);
  int e = 0;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        for (const auto& p : perms) {
          std::array<int, 3> c{i, j, k};
          std::array<int, 4> t{};
          t[0] = id(c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s) {
            ++c[static_cast<std::size_t>(p[static_cast<std::size_t>(s)])];
            t[static_cast<std::size_t>(s + 1)] = id(c[0], c[1], c[2]);
          }
          Eigen::Matrix3d J;
          for (int a = 0; a < 3; ++a)
            J.col(a) = (m.nodes.row(t[static_cast<std::size_t>(a + 1)]) - m.nodes.row(t[0])).transpose();
          if (J.determinant() < 0) std::swap(t[2], t[3]);  // positive orientation
          m.elements.row(e++) << t[0], t[1], t[2], t[3];
        }
  assignCells(m, lx, two_cells);
  WallCollector wc;
  collectPlane(m, wc, 0, 0.0, 0, true);
  collectPlane(m, wc, 0, lx, 1, true);
  collectPlane(m, wc, 1, 0.0, 2, true);
  collectPlane(m, wc, 1, ly, 3, true);
  collectPlane(m, wc, 2, 0.0, 4, true);
  collectPlane(m, wc, 2, lz, 5, true);
  if (two_cells) collectPlane(m, wc, 0, 0.5 * lx, 6, false);
  storeWalls(m, wc);
  m.node_vertex = Eigen::VectorXi::Constant(m.numNodes(), -1);
  return m;
}

mesh::FeMesh cylinderStrip(int n_theta, int n_z, double radius, double angle, double height) {
  mesh::FeMesh m;
  m.dim = 2;
  m.nodes.resize((n_theta + 1) * (n_z + 1), 3);
  auto id = [n_theta](int i, int j) { return j * (n_theta + 1) + i; };
  for (int j = 0; j <= n_z; ++j)
    for (int i = 0; i <= n_theta; ++i) {
      const double th = angle * i / n_theta;
      m.nodes.row(id(i, j)) << radius * std::cos(th), radius * std::sin(th), height * j / n_z;
    }
  m.elements.resize(2 * n_theta * n_z, 3);
  int e = 0;
  for (int j = 0; j < n_z; ++j)
    for (int i = 0; i < n_theta; ++i) {
      // Counter-clockwise in (theta, z): normal d/dtheta x d/dz points outwards.
      m.elements.row(e++) << id(i, j), id(i + 1, j), id(i + 1, j + 1);
      m.elements.row(e++) << id(i, j), id(i + 1, j + 1), id(i, j + 1);
    }
  m.element_cell = Eigen::VectorXi::Zero(m.numElements());
  // Walls from the parameter grid: edges along theta = 0, angle and z = 0, height.
  std::vector<std::array<int, 3>> facets;  // (node, node, wall)
  for (int j = 0; j < n_z; ++j) {
    facets.push_back({id(0, j), id(0, j + 1), 0});
    facets.push_back({id(n_theta, j), id(n_theta, j + 1), 1});
  }
  for (int i = 0; i < n_theta; ++i) {
    facets.push_back({id(i, 0), id(i + 1, 0), 2});
    facets.push_back({id(i, n_z), id(i + 1, n_z), 3});
  }
  const int nf = static_cast<int>(facets.size());
  m.wall_facets.resize(nf, 2);
  m.facet_wall.resize(nf);
  m.facet_on_boundary = Eigen::Matrix<bool, Eigen::Dynamic, 1>::Constant(nf, true);
  for (int f = 0; f < nf; ++f) {
    const auto& fc = facets[static_cast<std::size_t>(f)];
    m.wall_facets.row(f) << fc[0], fc[1];
    m.facet_wall[f] = fc[2];
  }
  m.node_vertex = Eigen::VectorXi::Constant(m.numNodes(), -1);
  return m;
}

void perturbInterior(mesh::FeMesh& mesh, double h, double fraction, unsigned seed) {
  const Eigen::RowVector3d lo = mesh.nodes.colwise().minCoeff(), hi = mesh.nodes.colwise().maxCoeff();
  unsigned state = seed;
  auto uniform = [&state]() {  // small LCG: reproducible on every platform
    state = state * 1664525u + 1013904223u;
    return static_cast<double>(state >> 8) / static_cast<double>(1u << 24) * 2.0 - 1.0;
  };
  for (int i = 0; i < mesh.numNodes(); ++i) {
    bool interior = true;
    for (int c = 0; c < mesh.dim; ++c)
      interior = interior && mesh.nodes(i, c) > lo[c] + 1e-9 && mesh.nodes(i, c) < hi[c] - 1e-9;
    if (!interior) continue;
    for (int c = 0; c < mesh.dim; ++c) mesh.nodes(i, c) += fraction * h * uniform();
  }
}

std::vector<int> nodesOfWalls(const mesh::FeMesh& mesh, const std::vector<int>& walls) {
  std::set<int> nodes;
  for (int f = 0; f < mesh.numWallFacets(); ++f)
    if (std::find(walls.begin(), walls.end(), mesh.facet_wall[f]) != walls.end())
      for (int a = 0; a < mesh.dim; ++a) nodes.insert(mesh.wall_facets(f, a));
  return {nodes.begin(), nodes.end()};
}

Quadrature simplexQuadrature(int dim) {
  // 3-point Gauss-Legendre on [0, 1], collapsed (Duffy) onto the simplex.
  const double g[3] = {0.5 - 0.5 * std::sqrt(0.6), 0.5, 0.5 + 0.5 * std::sqrt(0.6)};
  const double w[3] = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};
  Quadrature q;
  if (dim == 2) {
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        const double u = g[a], v = g[b] * (1 - g[a]);
        q.points.emplace_back(u, v, 0.0);
        q.weights.push_back(2.0 * w[a] * w[b] * (1 - g[a]));  // reference area 1/2 -> normalised
      }
  } else {
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        for (int c = 0; c < 3; ++c) {
          const double u = g[a], v = g[b] * (1 - u), t = g[c] * (1 - u) * (1 - g[b]);
          q.points.emplace_back(u, v, t);
          q.weights.push_back(6.0 * w[a] * w[b] * w[c] * (1 - u) * (1 - u) * (1 - g[b]));
        }
  }
  return q;
}

}  // namespace tessella::test
