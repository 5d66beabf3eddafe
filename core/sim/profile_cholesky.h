// SPDX-License-Identifier: MIT
// Cholesky factorization of a symmetric positive definite matrix that only touches its profile
// (envelope): row i's entries from its first nonzero column `first[i]` to the diagonal. The
// factor has no fill outside the profile, so a chain of bodies (a stack: each touches the next)
// costs Σ width² instead of n³/3: 60 unknowns of a 10-box stack, rows 6 to 12 wide, take about
// 7 000 multiply-adds instead of 72 000. Used by the Newton solver (newton_solver.h).
#pragma once

#include <vector>

#include <Eigen/Core>

namespace lamina::core {

class ProfileCholesky {
 public:
  using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

  /// Factors the lower triangle of `a` within the profile `first` (first[i] <= i, and entries
  /// left of first[i] are zero) as L Lᵀ, in place of `a`. False when `a` is not positive
  /// definite (a pivot <= 0 or not finite).
  bool Factor(Matrix* a, const std::vector<int>& first);
  /// Solves L Lᵀ x = b in place with the factor of the last Factor call.
  void Solve(Eigen::VectorXd* b) const;

 private:
  const Matrix* factor_ = nullptr;
  const std::vector<int>* first_ = nullptr;
};

}  // namespace lamina::core
