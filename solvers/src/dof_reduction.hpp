// SPDX-FileCopyrightText: 2026 The Tessella developers
// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Private helper: Dirichlet conditions by elimination. The unknowns split into
// free (F) and fixed (C) ones; A_FF u_F = b_F - A_FC u_C keeps the reduced
// matrix symmetric positive definite, which the solvers rely on.

#include "tessella/solvers/linear_solver.hpp"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <vector>

namespace tessella::solvers::detail {

class DofReduction {
 public:
  DofReduction() = default;
  /// fixed[i] != 0 marks unknown i as prescribed.
  explicit DofReduction(const std::vector<char>& fixed) : slot_(fixed.size()) {
    for (std::size_t i = 0; i < fixed.size(); ++i) {
      if (fixed[i]) {
        slot_[i] = static_cast<int>(fixed_.size());
        fixed_.push_back(static_cast<int>(i));
      } else {
        slot_[i] = static_cast<int>(free_.size());
        free_.push_back(static_cast<int>(i));
      }
    }
    is_fixed_ = fixed;
  }

  int numFree() const { return static_cast<int>(free_.size()); }
  int numFixed() const { return static_cast<int>(fixed_.size()); }
  const std::vector<int>& fixedDofs() const { return fixed_; }

  /// A_FF and A_FC of a full square matrix.
  void split(const SparseMatrix& A, SparseMatrix& Aff, SparseMatrix& Afc) const {
    std::vector<Eigen::Triplet<double>> ff, fc;
    ff.reserve(static_cast<std::size_t>(A.nonZeros()));
    for (int c = 0; c < A.outerSize(); ++c)
      for (SparseMatrix::InnerIterator it(A, c); it; ++it) {
        const auto r = static_cast<std::size_t>(it.row());
        if (is_fixed_[r]) continue;
        const auto cc = static_cast<std::size_t>(c);
        (is_fixed_[cc] ? fc : ff).emplace_back(slot_[r], slot_[cc], it.value());
      }
    Aff.resize(numFree(), numFree());
    Aff.setFromTriplets(ff.begin(), ff.end());
    Afc.resize(numFree(), numFixed());
    Afc.setFromTriplets(fc.begin(), fc.end());
  }

  Eigen::VectorXd freePart(const Eigen::VectorXd& full) const { return gather(full, free_); }
  Eigen::VectorXd fixedPart(const Eigen::VectorXd& full) const { return gather(full, fixed_); }

  /// Writes reduced free values back into a full vector.
  void scatterFree(const Eigen::VectorXd& values, Eigen::VectorXd& full) const {
    for (std::size_t k = 0; k < free_.size(); ++k) full[free_[k]] = values[static_cast<Eigen::Index>(k)];
  }

 private:
  static Eigen::VectorXd gather(const Eigen::VectorXd& full, const std::vector<int>& idx) {
    Eigen::VectorXd out(static_cast<Eigen::Index>(idx.size()));
    for (std::size_t k = 0; k < idx.size(); ++k) out[static_cast<Eigen::Index>(k)] = full[idx[k]];
    return out;
  }

  std::vector<int> slot_;  // full index -> position in free_ or fixed_
  std::vector<int> free_, fixed_;
  std::vector<char> is_fixed_;
};

}  // namespace tessella::solvers::detail
