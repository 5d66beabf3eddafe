// SPDX-License-Identifier: MIT
// The exact solver's step of a robot island: dWorldStep's row law (newton_solver.h) solved
// directly, with the unbounded rows eliminated through the bodies' matrix and only the bounded
// rows in a small dense LCP.
//
// Why: ODE's dWorldStep builds the dense matrix A = J M⁻¹ Jᵀ of every row and factors it
// (Dantzig): a humanoid has about 200 rows (five per hinge, its servos, its friction motors, its
// contacts), so a step costs about (200)³/6 multiply-adds and the pivots of its ~25 bounded rows
// as much again (hrp2_rough.xml: 95 % of the exact solver's time). Here the unbounded rows
// (λ = (c − J v)/cfm whatever v) join the bodies' matrix instead,
//   K = M + h Σ_U J_iᵀ J_i / cfm_i,
// factored in its block profile (profile_cholesky.h: a tree with every link before its parent
// stays narrow), and the velocity with only those rows is v₀ = K⁻¹ (M v_free + h Σ_U J_iᵀ
// c_i/cfm_i). With the bounded rows B, v' = v₀ + h K⁻¹ J_Bᵀ λ_B, and their law is the box LCP of
//   G = h J_B K⁻¹ J_Bᵀ + diag(cfm_B) = h Zᵀ Z + diag(cfm_B) (Z = L⁻¹ J_Bᵀ, K = L Lᵀ),
//   r = c_B − J_B v₀:
// λ minimizes ½ λᵀ G λ − rᵀ λ within lo <= λ <= hi (G is positive definite: one answer for fixed
// bounds). A column of Z only fills the blocks of its row's bodies and their ancestors (a
// contact on a foot: the leg and the trunk), so Z and G cost little. A primal active-set method
// finds λ exactly in a finite number of moves (each a Cholesky factorization of the free rows'
// part of G: 20 to 60 rows on a humanoid); friction bounds follow the normal forces in rounds as
// in the Newton solver (newton_solver.h: where friction saturates this is the consistent answer,
// where Dantzig fixes a bound from the normal force of the moment it pivots the row in; with
// friction the law may have more than one answer); after ten rounds each bound takes the secant
// step towards its fixed point (bound_secant.h), which settles rounds that swing back and forth
// (a wheel's friction and normal force feeding each other on rough ground). A solve that does not
// settle within its budget reports no convergence and the caller hands the island back to
// dWorldStep (object_islands.h).
//
// Units: those of newton_solver.h (m, kg, s, N; rows linear then angular, world axes).
#pragma once

#include <memory>
#include <vector>

#include "core/sim/bound_secant.h"
#include "core/sim/newton_solver.h"
#include "core/sim/profile_cholesky.h"

namespace lamina::core {

struct DirectOptions {
  int max_pivots = 400;           ///< active-set changes in all rounds together
  int max_rounds = 500;           ///< rounds of friction bounds
  double bound_tolerance = 1e-9;  ///< relative change of a friction bound that needs a round
};

/// The solver keeps its matrices between calls.
class DirectSolver {
 public:
  DirectSolver();
  ~DirectSolver();
  DirectSolver(const DirectSolver&) = delete;
  DirectSolver& operator=(const DirectSolver&) = delete;

  /// Solves the island's step of `step` seconds into `result` (velocity, force per row,
  /// iterations = active-set changes, rounds); returns result->converged.
  bool Solve(const std::vector<NewtonBody>& bodies, const std::vector<NewtonRow>& rows, double step,
             const DirectOptions& options, NewtonResult* result);
  /// The same over the generalized velocities u of `basis` (v = S u, reduced_system.h: K =
  /// Sᵀ M S + h Σ_U gᵢ gᵢᵀ / cfmᵢ, G = h g_Bᵀ K⁻¹ g_B + diag(cfm_B)); the caller leaves out the
  /// rows that only hold the basis' joints together (newton_solver.h, SolveReduced).
  bool SolveReduced(const std::vector<NewtonBody>& bodies, const std::vector<NewtonRow>& rows,
                    const ReducedBasis& basis, double step, const DirectOptions& options,
                    NewtonResult* result);

 private:
  struct Reduced;  ///< the reduced solve's system, factorization, u₀ and K⁻¹ g_B
  void Begin(double step, NewtonResult* result);
  bool Classify(const std::vector<NewtonRow>& rows);
  bool Rounds(const std::vector<NewtonRow>& rows, const DirectOptions& options,
              NewtonResult* result);
  bool FactorReduced(const std::vector<NewtonRow>& rows, const ReducedBasis& basis);
  void BoundedReduced(const std::vector<NewtonRow>& rows);
  bool FactorBodies(const std::vector<NewtonBody>& bodies, const std::vector<NewtonRow>& rows);
  void FreeVelocity(const std::vector<NewtonBody>& bodies, const std::vector<NewtonRow>& rows);
  void BoundedSystem(const std::vector<NewtonRow>& rows);
  void SetBounds(const std::vector<NewtonRow>& rows);
  void DampBounds(const Eigen::VectorXd& used_lo, const Eigen::VectorXd& used_hi);
  bool BoxSolve(int* budget);
  bool Optimal(const Eigen::VectorXd& gradient, int* released);
  bool SolveFree(Eigen::VectorXd* target);
  void FindFree();
  bool SolveFreeBlock(const Eigen::VectorXd& rhs, Eigen::VectorXd* solution);
  void Refine(const std::vector<NewtonBody>& bodies, const std::vector<NewtonRow>& rows,
              Eigen::VectorXd* velocity);

  double step_ = 0.0;
  ProfileCholesky cholesky_;
  std::vector<int> lowest_body_;
  std::vector<int> bounded_;        ///< indices of the bounded rows
  std::vector<int> position_;       ///< per row, its index in bounded_, or -1
  std::vector<int> normal_at_;      ///< per bounded row, its normal row's index in bounded_, or -1
  std::vector<Eigen::Index> free_;  ///< the bounded rows inside their bounds now
  Eigen::VectorXd v0_;
  Eigen::MatrixXd z_;                     ///< L⁻¹ J_iᵀ per bounded row (columns; K = L Lᵀ)
  std::vector<std::vector<int>> filled_;  ///< per column of z_, the blocks it fills
  Eigen::MatrixXd g_;
  Eigen::VectorXd r_, lambda_, lo_, hi_;
  std::vector<BoundSecant> secants_;  ///< per bounded row: DampBounds' last round
  std::vector<signed char> state_;    ///< per bounded row: -1 at lo, 0 free, 1 at hi
  Eigen::MatrixXd free_block_;        ///< G_FF, then its factor (SolveFreeBlock's storage)
  std::unique_ptr<Reduced> reduced_;
};

}  // namespace lamina::core
