// SPDX-License-Identifier: MIT
// The velocity step of an island of free bodies and contact rows, solved by Newton's method on
// the convex function whose minimum is ODE's row law (Lamina's fast solver for object islands).
//
// The row law is dWorldStep's (ode/src/step.cpp), with the forces λ in newtons:
//   v' = v_free + h M⁻¹ Σ J_iᵀ λ_i                 (v_free: the velocity after the step with the
//                                                   applied forces, gravity and gyroscopic torque)
//   λ_i = clamp((c_i − J_i v') / cfm_i, lo_i, hi_i)  (a friction row's bounds are its lo/hi times
//                                                   |λ| of its normal row, ODE's findex)
// For fixed bounds v' is the unique minimum of the strictly convex, piecewise quadratic
//   f(v) = ½ (v − v_free)ᵀ M (v − v_free) + h Σ Φ_i(c_i − J_i v),   Φ_i' = the clamp above,
// so Newton's method reaches it in a few steps whatever the mass ratio: the cost of a step is one
// Cholesky factorization of M + h Σ J_iᵀ J_i / cfm_i over the rows inside their bounds (in its
// profile: profile_cholesky.h), not a number of sweeps that grows with the ratio (ODE's
// QuickStep, Bullet). The line search takes the full step when it lowers f enough (Armijo),
// otherwise the exact minimum along the direction.
//
// The friction bounds follow the normal forces in rounds (the fixed point of "solve with the
// bounds of the last normal forces"); ODE's Dantzig solver sets each friction bound once from the
// normal force of the moment it pivots the row in, so where friction saturates the two may differ
// and this one is the consistent answer. From a cold start (every body sliding, random
// velocities) about 7 % of islands need more than 100 Newton steps: the caller hands those back
// (object_islands.h).
//
// A Newton step whose rows inside their bounds are those of the factorization in hand (a new
// round of friction bounds, most often) keeps it: the matrix is the same.
//
// Kept from step to step (NewtonOptions::island): an island solved again at the same step with
// the same bodies and rows, none of whose Jacobians, CFMs, masses or inertias moved by more than
// kKeptFactorTolerance since its Hessian was factored (a resting stack, a pile at rest), starts
// from that factorization instead of forming and factoring the Hessian again (the last
// kMostKeptIslands islands keep theirs). Its steps are then
// chord steps (the direction from a matrix a little off the Hessian): still descent directions,
// and the line search is the same, but a full step no longer lands on the minimum, so the solve
// goes on until a step is below the tolerance, as far as each chord step shrinks to at most
// kChordContraction of the one before; when one does not, the Hessian is formed and factored
// as without. The answer is the same minimum to the tolerance; only the way there differs.
//
// Warm start: Newton starts from `start` (the bodies' velocity before the step): a resting or
// steadily moving island keeps the rows it had, and the first step lands on the answer. The
// first round's friction bounds come from the normal forces at the free velocity, where gravity
// loads every contact: from the start they would be those of the step before, 0 on a contact
// that is only now pressed (ATHLETE on a plane: 6.6 Newton steps a time step from the start's
// bounds, 1.6 from these; HRP-2 on rough ground 23 and 20).
//
// Units: m, kg, s, N; Jacobian rows are linear then angular (world axes, about each body's centre
// of mass), as ODE's getInfo2 writes them; a row's velocity is J_a v_a + J_b v_b.
#pragma once

#include <memory>
#include <vector>

#include "core/math_types.h"
#include "core/sim/profile_cholesky.h"
#include "core/sim/reduced_basis.h"

namespace lamina::core {

/// One free body of the island.
struct NewtonBody {
  double mass = 1.0;                  ///< kg (> 0)
  Mat3 inertia = Mat3::Identity();    ///< about the centre of mass, world axes (kg·m², SPD)
  Vec6 free_velocity = Vec6::Zero();  ///< after the step without the rows (m/s, rad/s)
  Vec6 start = Vec6::Zero();          ///< where Newton starts (the velocity before the step)
};

/// One constraint row between bodies a and b of the island (-1: the fixed world).
struct NewtonRow {
  int a = -1;
  int b = -1;
  Vec6 ja = Vec6::Zero();  ///< the row's Jacobian on body a (linear, angular)
  Vec6 jb = Vec6::Zero();  ///< on body b
  double rhs = 0.0;        ///< c: the velocity asked of the row (m/s or rad/s)
  double cfm = 1e-9;       ///< constraint force mixing ((m/s)/N, > 0)
  double lo = 0.0;         ///< force bounds (N; lo <= 0 <= hi), or, with `normal` >= 0,
  double hi = kInf;        ///< coefficients of |λ| of row `normal`
  int normal = -1;         ///< the normal row of a friction row (ODE's findex), or -1
};

/// How far a Jacobian entry (1 or m), and relatively a CFM, mass or inertia, may move from those
/// of the kept factorization (above).
inline constexpr double kKeptFactorTolerance = 1e-10;
/// A chord step at most this fraction of the one before, or the Hessian is factored again.
inline constexpr double kChordContraction = 0.25;
/// Islands whose factorizations are kept at once (the one used longest ago makes room).
inline constexpr size_t kMostKeptIslands = 8;

struct NewtonOptions {
  int max_iterations = 100;  ///< Newton steps in all rounds together
  /// the caller's key of the island (0: none): a solve with the key of an earlier converged solve
  /// may start from its factorization (above); only for the body space (Solve), and with
  /// max_iterations of 2 or more (a chord step needs a second to find it is done)
  unsigned long long island = 0;
  double kept_tolerance = kKeptFactorTolerance;  ///< (for tests)
  int max_rounds = 100;  ///< rounds of friction bounds (each takes a Newton step or more)
  double velocity_tolerance = 1e-12;  ///< a Newton step smaller than this on every body (m/s,
                                      ///< √(dᵀ M d / m) per body) ends
  double bound_tolerance = 1e-9;      ///< relative change of a friction force that needs a round
  /// rounds whose friction bounds follow the normal forces at once; later rounds move them
  /// halfway from the last round's, which damps the back-and-forth of contacts whose normal force
  /// and friction feed each other without moving the fixed point (direct_solver.h takes the
  /// secant steps of bound_secant.h instead, which also settle steeper swings)
  int undamped_rounds = 1 << 30;
};

struct NewtonResult {
  std::vector<Vec6> velocity;  ///< v' per body
  std::vector<double> force;   ///< λ per row (N or N·m)
  int iterations = 0;          ///< Newton steps taken
  int factorizations = 0;      ///< Hessians formed and factored (0: the kept one served)
  int rounds = 0;              ///< rounds of friction bounds
  bool converged = false;      ///< false: the last iterate, not the answer (the caller falls back)
};

/// A row's velocity J_a v_a + J_b v_b (v: 6 entries per body of the island).
double RowVelocity(const NewtonRow& row, const VecX& v);
/// The body's mass matrix times a velocity (linear, angular): its momentum.
Vec6 MassTimes(const NewtonBody& body, const Vec6& v);
/// A friction row's bound: its coefficient (row.lo or row.hi) times its normal row's |λ| (N). An
/// infinite coefficient (kFriction inf: no sliding) gives an infinite bound, also at no normal
/// force, where the product would be NaN (and every solve of such an island went back to
/// dWorldStep).
double FrictionBound(double coefficient, double normal_force);

/// The solver keeps its matrices between calls (no allocation once they have grown).
class NewtonSolver {
 public:
  NewtonSolver();
  ~NewtonSolver();
  NewtonSolver(const NewtonSolver&) = delete;
  NewtonSolver& operator=(const NewtonSolver&) = delete;

  /// Solves the island's step of `step` seconds into `result`; returns result->converged.
  bool Solve(const std::vector<NewtonBody>& bodies, const std::vector<NewtonRow>& rows, double step,
             const NewtonOptions& options, NewtonResult* result);
  /// The same row law over the generalized velocities u of `basis` (v = S u, reduced_basis.h):
  /// the bodies' velocities stay where S puts them, so rows that only hold the basis' joints
  /// together are left out by the caller. result->velocity is S u per body, result->force per
  /// row of `rows`. The Hessian is over basis.size() unknowns (reduced_system.h: factored from
  /// the tree's leaves, or densely).
  bool SolveReduced(const std::vector<NewtonBody>& bodies, const std::vector<NewtonRow>& rows,
                    const ReducedBasis& basis, double step, const NewtonOptions& options,
                    NewtonResult* result);

 private:
  class BodySpace;     ///< every body's velocity, the Hessian in its block profile
  class ReducedSpace;  ///< a ReducedBasis' u (reduced_system.h)
  struct Reduced;      ///< the reduced space's system and factorization
  struct Kept;         ///< what the kept factorization was formed from

  template <class Space>
  bool SolveIn(Space* space, size_t bodies, const std::vector<NewtonRow>& rows, double step,
               const NewtonOptions& options, NewtonResult* result);
  void SetProfile(size_t bodies, const std::vector<NewtonRow>& rows);
  double RowForce(size_t i, double x) const;
  signed char Regime(size_t i, double x) const;
  void SetBounds(const std::vector<NewtonRow>& rows);
  template <class Space>
  void RowOffsets(const Space& space, const std::vector<NewtonRow>& rows);
  template <class Space>
  void Gradient(const Space& space, size_t rows, const VecX& v);
  template <class Space>
  bool Factor(Space& space, size_t rows);
  template <class Space>
  double Objective(const Space& space, const VecX& v) const;
  template <class Space>
  bool FullStepDescends(const Space& space, double slope);
  template <class Space>
  double LineSearch(const Space& space, size_t rows);
  double Slope(double alpha, double* curvature) const;
  template <class Space>
  bool NewtonSteps(Space& space, const std::vector<NewtonRow>& rows, const NewtonOptions& options,
                   int* budget);
  bool KeptFits(const Kept& kept, const std::vector<NewtonBody>& bodies,
                const std::vector<NewtonRow>& rows, const NewtonOptions& options) const;
  int TakeKept(const std::vector<NewtonBody>* bodies, const std::vector<NewtonRow>& rows,
               const NewtonOptions& options);
  void KeepFactor(int slot, const std::vector<NewtonBody>* bodies,
                  const std::vector<NewtonRow>& rows, const NewtonOptions& options, bool converged);
  int FreeSlot();
  template <class Space>
  bool BoundsSettled(const Space& space, const std::vector<NewtonRow>& rows, double tolerance,
                     bool damped);

  double step_ = 0.0;
  VecX v_, v_free_, gradient_, direction_, trial_;
  ProfileCholesky cholesky_;      ///< the Hessian's lower triangle in its profile, then its factor
  std::vector<int> lowest_body_;  ///< the Hessian's block profile: per body, the lowest body a
                                  ///< row couples it with
  std::vector<double> lo_, hi_, cfm_, x_, q_;  ///< per row: bounds now, CFM, c − J v, J d
  std::vector<double> used_lo_, used_hi_;      ///< per row: the last round's bounds
  std::vector<signed char> regime_;            ///< per row: the part of its law in the Hessian
  double d_m_d_ = 0.0, d_m_offset_ = 0.0;
  bool factored_ = false;             ///< the factorization in hand is that of regime_
  bool offsets_current_ = false;      ///< x_ is c − J v_ as RowOffsets computes it
  bool stale_ = false;                ///< the factorization in hand is a kept one (chord steps)
  int factorizations_ = 0;            ///< in this solve
  std::unique_ptr<Reduced> reduced_;  ///< the reduced space's
  std::vector<Kept> kept_;            ///< per island (at most kMostKeptIslands)
  long long solves_ = 0;              ///< keyed solves so far
};

}  // namespace lamina::core
