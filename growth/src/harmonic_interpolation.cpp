// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tessella/growth/harmonic_interpolation.hpp"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <deque>

#include "tessella/tissue/errors.hpp"

namespace tessella::growth {

struct HarmonicInterpolator::System {
  std::uint64_t topology_version = ~0ull;
  std::vector<VertexId> control;
  std::vector<std::uint8_t> is_control;
  std::vector<Index> free_index;        // vertex slot -> row, kInvalidIndex for control/dead
  std::vector<VertexId> free_vertices;  // row -> vertex
  // Control-to-free coupling: for row i, the control neighbours contributing to its rhs.
  std::vector<std::pair<Index, VertexId>> coupling;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
  std::size_t factorisations = 0;
};

HarmonicInterpolator::HarmonicInterpolator() : system_(std::make_unique<System>()) {}
HarmonicInterpolator::~HarmonicInterpolator() = default;
HarmonicInterpolator::HarmonicInterpolator(HarmonicInterpolator&&) noexcept = default;
HarmonicInterpolator& HarmonicInterpolator::operator=(HarmonicInterpolator&&) noexcept = default;

void HarmonicInterpolator::setControlVertices(std::vector<VertexId> control) {
  requested_control_ = std::move(control);
  system_->topology_version = ~0ull;  // force a rebuild
}

std::size_t HarmonicInterpolator::factorisations() const { return system_->factorisations; }

std::vector<VertexId> boundaryVertices(const Tissue& t) {
  const CellComplex& k = t.topology();
  std::vector<std::uint8_t> mark(t.slots(0), 0);
  for (WallId w : t.walls()) {
    if (!t.isBoundaryWall(w)) continue;
    if (t.dim() == 2) {
      for (VertexId v : k.edgeVertices(EdgeId(w.index()))) mark[v.index()] = 1;
    } else {
      for (VertexId v : k.faceVertices(FaceId(w.index()))) mark[v.index()] = 1;
    }
  }
  std::vector<VertexId> out;
  for (VertexId v : t.vertices())
    if (mark[v.index()]) out.push_back(v);
  return out;
}

const std::vector<VertexId>& HarmonicInterpolator::controlVertices(const Tissue& t) {
  rebuild(t);
  return system_->control;
}

const std::vector<std::uint8_t>& HarmonicInterpolator::isControl(const Tissue& t) {
  rebuild(t);
  return system_->is_control;
}

void HarmonicInterpolator::rebuild(const Tissue& t) {
  System& s = *system_;
  if (s.topology_version == t.topologyVersion()) return;
  const CellComplex& k = t.topology();
  const std::size_t nv = t.slots(0);

  s.control = requested_control_.empty() ? boundaryVertices(t) : requested_control_;
  s.is_control.assign(nv, 0);
  for (VertexId v : s.control) {
    if (!t.alive(v))
      throw InputError("harmonic interpolation: control vertex " + std::to_string(v.index()) +
                       " is not a live vertex");
    s.is_control[v.index()] = 1;
  }
  s.free_index.assign(nv, kInvalidIndex);
  s.free_vertices.clear();
  for (VertexId v : t.vertices())
    if (!s.is_control[v.index()]) {
      s.free_index[v.index()] = static_cast<Index>(s.free_vertices.size());
      s.free_vertices.push_back(v);
    }

  // Every free vertex must reach a control vertex, or its value is undetermined.
  std::vector<std::uint8_t> reached(nv, 0);
  std::deque<VertexId> queue(s.control.begin(), s.control.end());
  for (VertexId v : s.control) reached[v.index()] = 1;
  while (!queue.empty()) {
    const VertexId v = queue.front();
    queue.pop_front();
    for (EdgeId e : k.vertexEdges(v)) {
      const auto ends = k.edgeVertices(e);
      const VertexId w = ends[0] == v ? ends[1] : ends[0];
      if (!reached[w.index()]) {
        reached[w.index()] = 1;
        queue.push_back(w);
      }
    }
  }
  for (VertexId v : s.free_vertices)
    if (!reached[v.index()])
      throw GeometryError("harmonic interpolation: vertex " + std::to_string(v.index()) +
                              " is in a part of the tissue without control vertices",
                          ElementId{0, v.index()});

  // Uniform-weight Laplacian restricted to the free vertices.
  const Index n = static_cast<Index>(s.free_vertices.size());
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(static_cast<std::size_t>(n) * 7);
  s.coupling.clear();
  for (Index i = 0; i < n; ++i) {
    const VertexId v = s.free_vertices[i];
    double degree = 0;
    for (EdgeId e : k.vertexEdges(v)) {
      const auto ends = k.edgeVertices(e);
      const VertexId w = ends[0] == v ? ends[1] : ends[0];
      degree += 1;
      if (s.is_control[w.index()]) {
        s.coupling.emplace_back(i, w);
      } else {
        triplets.emplace_back(i, s.free_index[w.index()], -1.0);
      }
    }
    triplets.emplace_back(i, i, degree);
  }
  if (n > 0) {
    Eigen::SparseMatrix<double> a(n, n);
    a.setFromTriplets(triplets.begin(), triplets.end());
    s.solver.compute(a);
    if (s.solver.info() != Eigen::Success)
      throw GeometryError("harmonic interpolation: the Laplacian could not be factorised");
    ++s.factorisations;
  }
  s.topology_version = t.topologyVersion();
}

void HarmonicInterpolator::interpolate(const Tissue& t, std::span<Vec3> values) {
  if (values.size() != t.slots(0))
    throw InputError("harmonic interpolation: " + std::to_string(values.size()) +
                     " values for " + std::to_string(t.slots(0)) + " vertex slots");
  rebuild(t);
  System& s = *system_;
  const Index n = static_cast<Index>(s.free_vertices.size());
  if (n == 0) return;
  Eigen::MatrixX3d rhs = Eigen::MatrixX3d::Zero(n, 3);
  for (const auto& [row, w] : s.coupling) rhs.row(row) += values[w.index()].transpose();
  const Eigen::MatrixX3d x = s.solver.solve(rhs);
  for (Index i = 0; i < n; ++i) values[s.free_vertices[i].index()] = x.row(i).transpose();
}

}  // namespace tessella::growth
