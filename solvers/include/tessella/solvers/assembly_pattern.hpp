// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Cached sparsity pattern of the P1 element matrices of one FeMesh, for fast
// re-assembly. Built once from the connectivity: the compressed matrix
// structure, for every element and local entry (a, b) the slot of that entry in
// the value array, and a greedy colouring of chunks of elements (chunks of
// one colour share no node). Re-assembly computes each element matrix and adds
// it straight into the value array, colour by colour, the chunks of a colour
// in parallel, the elements of a chunk in a fixed order. Every nonzero receives
// its contributions in that fixed order (at most one chunk per colour touches
// it), so the sums are the same for any thread count: bit-identical results. They agree with the triplet summation to round-off only (different
// order of the additions).
//
// Memory: (d+1)^2 int slots per element (64 bytes per tetrahedron) plus the
// matrix structure; about 0.4 GB for 10^6 tetrahedral nodes (5.8 M elements).

#include "tessella/mesh/fe_mesh.hpp"
#include "tessella/solvers/assembly.hpp"
#include "tessella/solvers/linear_solver.hpp"

#include <Eigen/Core>

#include <vector>

namespace tessella::solvers {

class AssemblyPattern {
 public:
  /// Builds the pattern of `mesh`'s elements (checks the mesh first).
  explicit AssemblyPattern(const mesh::FeMesh& mesh);

  /// K_ij = sum_e c_e * int_e grad phi_i . grad phi_j. Empty c means c = 1.
  /// `mesh` must have the connectivity the pattern was built from (node
  /// coordinates may differ); its sizes are checked.
  SparseMatrix stiffness(const mesh::FeMesh& mesh, const Eigen::VectorXd& element_coefficient = {}) const;
  /// M_ij = sum_e c_e * int_e phi_i phi_j (or its lumped diagonal; the
  /// off-diagonal entries are then stored zeros of the same pattern).
  SparseMatrix mass(const mesh::FeMesh& mesh, MassType type, const Eigen::VectorXd& element_coefficient = {}) const;

  /// Same, writing into `out`: when `out` already has this pattern's structure
  /// (e.g. from an earlier call) only its values are overwritten, no allocation.
  void stiffness(const mesh::FeMesh& mesh, const Eigen::VectorXd& element_coefficient, SparseMatrix& out) const;
  void mass(const mesh::FeMesh& mesh, MassType type, const Eigen::VectorXd& element_coefficient, SparseMatrix& out) const;

  int numNodes() const { return static_cast<int>(structure_.rows()); }
  int numElements() const { return num_elements_; }
  int numColours() const { return static_cast<int>(colour_ptr_.size()) - 1; }
  int numChunks() const { return static_cast<int>(chunk_ptr_.size()) - 1; }
  /// Elements per chunk (the last may be shorter): small enough for many
  /// chunks per colour, large enough that a chunk's writes stay in cache.
  static constexpr int kChunk = 64;
  long nonZeros() const { return static_cast<long>(structure_.nonZeros()); }

 private:
  enum class Kind { Stiffness, ConsistentMass, LumpedMass };
  void assemble(const mesh::FeMesh& mesh, Kind kind, const Eigen::VectorXd& c, SparseMatrix& out) const;
  void prepare(const mesh::FeMesh& mesh, const Eigen::VectorXd& c, const char* what, SparseMatrix& out) const;

  int dim_ = 0;
  int num_elements_ = 0;
  SparseMatrix structure_;         // all-zero values, compressed
  std::vector<int> colour_ptr_;    // chunks of colour k: colour_ptr_[k] .. colour_ptr_[k+1]
  std::vector<int> chunk_ptr_;     // elements of chunk q: order_[chunk_ptr_[q] .. chunk_ptr_[q+1])
  std::vector<int> order_;         // element indices, chunk by chunk, chunks grouped by colour
  std::vector<int> slots_;         // (d+1)^2 value slots per position in order_, row-major (a, b)
};

}  // namespace tessella::solvers
