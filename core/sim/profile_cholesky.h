// SPDX-License-Identifier: MIT
// Cholesky factorization of a symmetric positive definite matrix of 6 × 6 blocks (one per rigid
// body: linear, angular) stored and factored only in its block profile (envelope): block row i's
// blocks from its first nonzero block column `first[i]` to the diagonal. The factor has no fill
// outside the profile, so a chain of bodies (a stack: each touches the next) costs about
// n · 2 · 6³ multiply-adds instead of (6n)³/3, and a robot's tree with every link before its
// parent stays as narrow (object_islands.h); the work is done in fixed-size 6 × 6 products.
// Blocks inside the profile that stay zero in the factor are skipped: a tree ordered children
// first has no fill at all, and its root's block row, whose profile reaches back to its first
// child's subtree, costs a product per child instead of one per body (ATHLETE: 6 legs of 6
// links).
// Used by the Newton and direct solvers (newton_solver.h, direct_solver.h).
#pragma once

#include <vector>

#include <Eigen/Core>
#include <Eigen/StdVector>

namespace lamina::core {

class ProfileCholesky {
 public:
  using Block = Eigen::Matrix<double, 6, 6>;
  using Column = Eigen::Matrix<double, 6, 1>;

  /// block += u vᵀ, column by column (as fast as Eigen's outer product of an expression is
  /// slow): a row's term w J_bᵀ J_a in an off-diagonal block
  static void AddOuter(const Column& u, const Column& v, Block* block) {
    for (int c = 0; c < 6; ++c) block->col(c) += u * v(c);
  }
  /// block += u vᵀ in its lower triangle: a row's term w JᵀJ in a diagonal block (u = w J,
  /// v = J), of which Factor reads no more (written out column by column in fixed-size
  /// segments)
  static void AddLowerOuter(const Column& u, const Column& v, Block* block) {
    block->col(0) += u * v(0);
    block->col(1).tail<5>() += u.tail<5>() * v(1);
    block->col(2).tail<4>() += u.tail<4>() * v(2);
    block->col(3).tail<3>() += u.tail<3>() * v(3);
    block->col(4).tail<2>() += u.tail<2>() * v(4);
    (*block)(5, 5) += u(5) * v(5);
  }

  /// Takes the block profile (first[i] <= i for every block row i) and sets the matrix to zero.
  /// Storage is kept from call to call (no allocation once it has grown).
  void Reset(const std::vector<int>& first);
  int blocks() const { return static_cast<int>(first_.size()); }
  /// Block (i, j) of the lower triangle, first[i] <= j <= i (the matrix, or after Factor L). A
  /// diagonal block's lower triangle is read, its upper one never (the Newton and direct
  /// solvers leave the rows' share of it out: AddLowerOuter).
  Block& block(int i, int j) { return values_[offset_[i] + j]; }
  const Block& block(int i, int j) const { return values_[offset_[i] + j]; }
  /// Factors the matrix as L Lᵀ in place. False when it is not positive definite (a pivot <= 0
  /// or not finite). The solves below then skip the blocks of L that are zero.
  bool Factor();
  /// After Factor: the number of blocks of L (diagonal included) that are not zero.
  int nonzero_blocks() const;
  /// Solves L Lᵀ x = b in place with the factor (b: 6 entries per block).
  void Solve(Eigen::VectorXd* b) const;
  /// The two halves of Solve: L y = b, then Lᵀ x = y, in place. ForwardSolve takes b's blocks
  /// before `start` as zero and skips every block row that only meets zero blocks, marking in
  /// `nonzero` (one flag per block) the blocks of y it computed (a column of a tree's matrix for a
  /// leaf's row only fills the leaf's ancestors).
  void ForwardSolve(Eigen::VectorXd* b, int start, std::vector<char>* nonzero) const;
  void BackSolve(Eigen::VectorXd* b) const;

 private:
  bool nonzero(int i, int j) const { return nonzero_[static_cast<size_t>(offset_[i] + j)] != 0; }
  bool FactorBlock(int i, int j, const std::vector<int>& row);

  std::vector<int> first_;
  std::vector<int> offset_;  ///< block (i, j) is values_[offset_[i] + j]
  std::vector<Block, Eigen::aligned_allocator<Block>> values_;
  std::vector<char> nonzero_;  ///< per block of values_: nonzero in the factor
  std::vector<int> row_;       ///< Factor's nonzero block columns of the row it is at
};

}  // namespace lamina::core
