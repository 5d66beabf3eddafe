// SPDX-License-Identifier: MIT
// An island's bodies and rows over the generalized velocities u of a ReducedBasis (v = S u): the
// mass matrix Sᵀ M S, the free momentum Sᵀ M v_free, every row's gᵢ = Jᵢ S, and the
// factorization of Sᵀ M S plus rows. What the Newton solver's reduced step (newton_solver.h) and
// the direct solve's (direct_solver.h) share.
//
// Sparsity: each body's columns are its path to the root (reduced_basis.h), so Sᵀ M S only couples
// a column with those on its path, and so does a row whose bodies are on one path (a contact on a
// foot with the ground, a motor between a link and its parent). When every row is such a one the
// matrix keeps the tree's sparsity and ReducedCholesky factors it from the leaves as Lᵀ D L with
// no fill (Featherstone's LTDL: about Σ depth² operations instead of n³/3); otherwise (a contact
// between two branches, a free object touching the robot) densely.
//
// Units: those of newton_solver.h.
#pragma once

#include <vector>

#include "core/math_types.h"
#include "core/sim/newton_solver.h"
#include "core/sim/reduced_basis.h"

namespace lamina::core {

class ReducedSystem {
 public:
  /// The mass matrix (lower triangle), the free momentum and the rows of `bodies` and `rows`
  /// over `basis` (which outlives the system's use).
  void Build(const std::vector<NewtonBody>& bodies, const std::vector<NewtonRow>& rows,
             const ReducedBasis& basis);
  const ReducedBasis& basis() const { return *basis_; }
  Eigen::Index size() const { return basis_->size(); }
  /// Sᵀ M S, lower triangle (the upper is not set).
  const Eigen::MatrixXd& mass() const { return mass_; }
  /// Sᵀ M v_free.
  const VecX& free_momentum() const { return free_momentum_; }
  /// Every row has its columns on one path to the root (see above).
  bool on_paths() const { return on_paths_; }

  /// Row i's gᵢ: its entries [first(i), first(i + 1)) of index() and value(), columns ascending.
  size_t first(size_t i) const { return first_[i]; }
  const std::vector<int>& index() const { return index_; }
  const std::vector<double>& value() const { return value_; }
  /// Consecutive rows with the same columns (a contact's three, a pair's contacts) share a group.
  int group(size_t i) const { return group_[i]; }
  /// gᵢ u.
  double RowVelocity(size_t i, const VecX& u) const;
  /// out += scale gᵢ.
  void AddRow(size_t i, double scale, VecX* out) const;
  /// S_k u per body.
  Vec6 BodyVelocity(int k, const VecX& u) const { return basis_->Velocity(k, u); }

 private:
  void MassMatrix(const std::vector<NewtonBody>& bodies);
  void MapRow(const NewtonRow& row);
  void Accumulate(int body, const Vec6& j);
  bool OnOnePath(size_t first) const;
  bool SameColumns(size_t before, size_t first) const;

  const ReducedBasis* basis_ = nullptr;
  Eigen::MatrixXd mass_;
  std::vector<Eigen::Matrix<double, 6, 6>> composite_;  ///< per body, its subtree's inertia
  std::vector<Vec6> momentum_;                          ///< and its free momentum
  Eigen::Matrix<double, 6, Eigen::Dynamic> motion_;     ///< per column, its motion at the origin
  VecX free_momentum_, dense_row_;
  std::vector<size_t> first_;
  std::vector<int> index_, group_, touched_;
  std::vector<double> value_;
  bool on_paths_ = true;
};

/// A symmetric positive definite matrix over a ReducedBasis' columns (lower triangle), factored
/// in place from the leaves (LTDL, when it has the tree's sparsity) or densely (L Lᵀ).
class ReducedCholesky {
 public:
  /// Set the lower triangle, then Factor.
  Eigen::MatrixXd& matrix() { return matrix_; }
  /// False when the matrix is not positive definite (a pivot <= 0 or not finite).
  bool Factor(const ReducedBasis& basis, bool tree);
  /// Solves the factored matrix times x = b in place.
  void Solve(VecX* b) const;

 private:
  Eigen::MatrixXd matrix_;
  const ReducedBasis* basis_ = nullptr;
  bool tree_ = false;
};

}  // namespace lamina::core
