// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Harmonic interpolation of vertex velocities (the paper's second growth
// mode): velocities are known on control vertices (by default the boundary
// vertices) and the others solve the discrete Laplace equation
//   sum_j w_ij (v_j - v_i) = 0   for every free vertex i
// over the complex's edge graph. Weights are uniform (w_ij = 1, the graph
// Laplacian): the matrix depends on topology only, so it is factorised
// (Eigen SimplicialLDLT, symmetric positive definite once the control rows
// are eliminated) once per topology version and reused while the topology is
// unchanged. With uniform weights a vertex's velocity is the mean of its
// neighbours'; affine fields are reproduced exactly where every free vertex
// is the mean of its neighbours (regular grids), and approximately elsewhere.

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "tessella/tissue/tissue.hpp"

namespace tessella::growth {

class HarmonicInterpolator {
 public:
  HarmonicInterpolator();
  ~HarmonicInterpolator();
  HarmonicInterpolator(HarmonicInterpolator&&) noexcept;
  HarmonicInterpolator& operator=(HarmonicInterpolator&&) noexcept;

  /// Use these vertices as control vertices instead of the boundary ones
  /// (empty: back to the boundary). Takes effect at the next interpolate().
  void setControlVertices(std::vector<VertexId> control);

  /// The control vertices for the tissue's current topology (rebuilds if
  /// the topology changed).
  const std::vector<VertexId>& controlVertices(const Tissue& t);
  /// Per vertex slot: 1 if the vertex is a control vertex.
  const std::vector<std::uint8_t>& isControl(const Tissue& t);

  /// Fills values for every vertex slot: control vertices keep `values`,
  /// free ones are interpolated. values.size() == t.slots(0). Throws
  /// GeometryError if a connected component has no control vertex (its
  /// interior velocity would be undetermined).
  void interpolate(const Tissue& t, std::span<Vec3> values);

  /// How many times the system was factorised (once per topology version).
  std::size_t factorisations() const;

 private:
  struct System;
  void rebuild(const Tissue& t);
  std::unique_ptr<System> system_;
  std::vector<VertexId> requested_control_;
};

/// Vertices on walls that bound a single cell (the tissue's outline or surface).
std::vector<VertexId> boundaryVertices(const Tissue& t);

}  // namespace tessella::growth
