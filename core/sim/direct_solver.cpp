// SPDX-License-Identifier: MIT
#include "core/sim/direct_solver.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Cholesky>

#include "core/sim/reduced_system.h"

namespace lamina::core {

namespace {

bool Unbounded(const NewtonRow& row) {
  return row.normal < 0 && row.lo == -kInf && row.hi == kInf;
}

// h λ J_iᵀ onto the rows' bodies in `momentum` (6 entries per body)
void AddImpulse(const NewtonRow& row, double impulse, Eigen::VectorXd* momentum) {
  if (row.a >= 0) momentum->segment<6>(6 * row.a) += impulse * row.ja;
  if (row.b >= 0) momentum->segment<6>(6 * row.b) += impulse * row.jb;
}

// w J_iᵀ J_i into the lower triangle of the blocks of bodies a and b (of a diagonal block only
// its lower triangle: the factor is the same to the last bit)
void AddRow(const NewtonRow& row, double w, ProfileCholesky* k) {
  const Vec6 wa = w * row.ja, wb = w * row.jb;
  if (row.a >= 0) ProfileCholesky::AddLowerOuter(wa, row.ja, &k->block(row.a, row.a));
  if (row.b >= 0) ProfileCholesky::AddLowerOuter(wb, row.jb, &k->block(row.b, row.b));
  if (row.a >= 0 && row.b >= 0) {
    if (row.b > row.a) {
      ProfileCholesky::AddOuter(wb, row.ja, &k->block(row.b, row.a));
    } else {
      ProfileCholesky::AddOuter(wa, row.jb, &k->block(row.a, row.b));
    }
  }
}

}  // namespace

// K = M + h Σ_U J_iᵀ J_i / cfm_i in the profile of the unbounded rows, factored
bool DirectSolver::FactorBodies(const std::vector<NewtonBody>& bodies,
                                const std::vector<NewtonRow>& rows) {
  lowest_body_.resize(bodies.size());
  for (size_t k = 0; k < bodies.size(); ++k) lowest_body_[k] = static_cast<int>(k);
  for (const NewtonRow& row : rows) {
    if (!Unbounded(row) || row.a < 0 || row.b < 0) continue;
    const int high = std::max(row.a, row.b), low = std::min(row.a, row.b);
    lowest_body_[high] = std::min(lowest_body_[high], low);
  }
  cholesky_.Reset(lowest_body_);
  for (size_t k = 0; k < bodies.size(); ++k) {
    ProfileCholesky::Block& diagonal = cholesky_.block(static_cast<int>(k), static_cast<int>(k));
    diagonal.topLeftCorner<3, 3>().diagonal().setConstant(bodies[k].mass);
    diagonal.bottomRightCorner<3, 3>() = bodies[k].inertia;
  }
  for (const NewtonRow& row : rows) {
    if (Unbounded(row)) AddRow(row, step_ / row.cfm, &cholesky_);
  }
  return cholesky_.Factor();
}

// v₀ = K⁻¹ (M v_free + h Σ_U J_iᵀ c_i / cfm_i)
void DirectSolver::FreeVelocity(const std::vector<NewtonBody>& bodies,
                                const std::vector<NewtonRow>& rows) {
  v0_.resize(6 * static_cast<Eigen::Index>(bodies.size()));
  for (size_t k = 0; k < bodies.size(); ++k) {
    v0_.segment<6>(6 * k) = MassTimes(bodies[k], bodies[k].free_velocity);
  }
  for (const NewtonRow& row : rows) {
    if (Unbounded(row)) AddImpulse(row, step_ * row.rhs / row.cfm, &v0_);
  }
  cholesky_.Solve(&v0_);
}

// Z = L⁻¹ J_Bᵀ (K = L Lᵀ; a column only fills the blocks of its bodies and their ancestors),
// G = h Zᵀ Z + diag(cfm_B) over the blocks both columns fill, r = c_B − J_B v₀
void DirectSolver::BoundedSystem(const std::vector<NewtonRow>& rows) {
  const Eigen::Index n = static_cast<Eigen::Index>(bounded_.size());
  z_.setZero(v0_.size(), n);
  filled_.resize(static_cast<size_t>(n));
  Eigen::VectorXd column = Eigen::VectorXd::Zero(v0_.size());
  std::vector<char> nonzero;
  for (Eigen::Index k = 0; k < n; ++k) {
    const NewtonRow& row = rows[bounded_[k]];
    if (row.a >= 0) column.segment<6>(6 * row.a) += row.ja;
    if (row.b >= 0) column.segment<6>(6 * row.b) += row.jb;
    const int start = row.a < 0 ? row.b : (row.b < 0 ? row.a : std::min(row.a, row.b));
    cholesky_.ForwardSolve(&column, start, &nonzero);
    filled_[k].clear();
    for (int block = 0; block < static_cast<int>(nonzero.size()); ++block) {
      if (nonzero[block]) filled_[k].push_back(block);
    }
    // only the filled blocks are copied and cleared for the next column (the rest stay zero:
    // a block left out holds the row's zero Jacobian block)
    for (int block : filled_[k]) z_.col(k).segment<6>(6 * block) = column.segment<6>(6 * block);
    for (int block : filled_[k]) column.segment<6>(6 * block).setZero();
    if (row.a >= 0) column.segment<6>(6 * row.a).setZero();
    if (row.b >= 0) column.segment<6>(6 * row.b).setZero();
  }
  g_.resize(n, n);
  r_.resize(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const NewtonRow& row = rows[bounded_[i]];
    for (Eigen::Index j = 0; j <= i; ++j) {
      double dot = 0.0;  // over the blocks both fill (sorted lists)
      auto p = filled_[i].begin(), q = filled_[j].begin();
      while (p != filled_[i].end() && q != filled_[j].end()) {
        if (*p < *q) {
          ++p;
        } else if (*q < *p) {
          ++q;
        } else {
          dot += z_.col(i).segment<6>(6 * *p).dot(z_.col(j).segment<6>(6 * *p));
          ++p;
          ++q;
        }
      }
      g_(i, j) = step_ * dot;
      g_(j, i) = g_(i, j);
    }
    g_(i, i) += row.cfm;
    r_(i) = row.rhs - RowVelocity(row, v0_);
  }
}

// the bounds of the bounded rows, friction rows from their normal row's current force
void DirectSolver::SetBounds(const std::vector<NewtonRow>& rows) {
  for (size_t k = 0; k < bounded_.size(); ++k) {
    const NewtonRow& row = rows[bounded_[k]];
    if (row.normal < 0) {
      lo_(k) = row.lo;
      hi_(k) = row.hi;
      continue;
    }
    // (a friction row's normal row is a contact's: bounded below by 0, so among bounded_)
    const double normal = std::abs(lambda_(normal_at_[k]));
    lo_(k) = FrictionBound(row.lo, normal);
    hi_(k) = FrictionBound(row.hi, normal);
  }
}

// the free rows (inside their bounds) into free_, and G_FF⁻¹ rhs into `solution`; false when G_FF
// does not factor or the solution is not finite
// (G_FF gathered column by column, as G is stored, and factored in place)
bool DirectSolver::SolveFreeBlock(const Eigen::VectorXd& rhs, Eigen::VectorXd* solution) {
  const Eigen::Index f = static_cast<Eigen::Index>(free_.size());
  free_block_.resize(f, f);
  for (Eigen::Index j = 0; j < f; ++j) {
    for (Eigen::Index i = j; i < f; ++i) free_block_(i, j) = g_(free_[i], free_[j]);
  }
  Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>> llt(free_block_);
  if (llt.info() != Eigen::Success) return false;
  *solution = llt.solve(rhs);
  return solution->allFinite();
}

void DirectSolver::FindFree() {
  free_.clear();
  for (size_t k = 0; k < state_.size(); ++k) {
    if (state_[k] == 0) free_.push_back(static_cast<Eigen::Index>(k));
  }
}

// target_F = G_FF⁻¹ (r_F − G_FW λ_W) for the free rows F (target_W = λ_W)
bool DirectSolver::SolveFree(Eigen::VectorXd* target) {
  FindFree();
  *target = lambda_;
  if (free_.empty()) return true;
  const Eigen::Index f = static_cast<Eigen::Index>(free_.size());
  Eigen::VectorXd rhs(f);
  for (Eigen::Index i = 0; i < f; ++i) {
    double sum = r_(free_[i]);
    for (size_t k = 0; k < state_.size(); ++k) {
      if (state_[k] != 0)
        sum -= g_(static_cast<Eigen::Index>(k), free_[i]) * lambda_(k);  // (G = Gᵀ)
    }
    rhs(i) = sum;
  }
  Eigen::VectorXd solution;
  if (!SolveFreeBlock(rhs, &solution)) return false;
  for (Eigen::Index i = 0; i < f; ++i) (*target)(free_[i]) = solution(i);
  return true;
}

// true when no row at a bound pulls inwards (its multiplier has the right sign); otherwise frees
// every row that does, counting them in `released`
bool DirectSolver::Optimal(const Eigen::VectorXd& gradient, int* released) {
  const double tolerance = 1e-11 * std::max(1.0, r_.cwiseAbs().maxCoeff());
  *released = 0;
  for (size_t k = 0; k < state_.size(); ++k) {
    if (state_[k] == 0 || lo_(k) == hi_(k)) continue;
    const bool inward = state_[k] < 0 ? gradient(k) < -tolerance : gradient(k) > tolerance;
    if (!inward) continue;
    state_[k] = 0;
    ++*released;
  }
  return *released == 0;
}

// the minimum of ½ λᵀ G λ − rᵀ λ within [lo, hi] from a feasible λ: move towards the minimum
// over the free rows until a row reaches a bound (it joins the bounds), and at that minimum
// free the bound rows whose multipliers pull inwards; f falls at every move (G > 0)
bool DirectSolver::BoxSolve(int* budget) {
  Eigen::VectorXd target;
  while (*budget > 0) {
    if (!SolveFree(&target)) return false;
    double alpha = 1.0;
    Eigen::Index blocking = -1;
    signed char side = 0;
    for (Eigen::Index k = 0; k < lambda_.size(); ++k) {
      if (state_[k] != 0) continue;
      const double d = target(k) - lambda_(k);
      if (target(k) < lo_(k) && d < 0.0 && (lo_(k) - lambda_(k)) / d < alpha) {
        alpha = std::max(0.0, (lo_(k) - lambda_(k)) / d);
        blocking = k;
        side = -1;
      } else if (target(k) > hi_(k) && d > 0.0 && (hi_(k) - lambda_(k)) / d < alpha) {
        alpha = std::max(0.0, (hi_(k) - lambda_(k)) / d);
        blocking = k;
        side = 1;
      }
    }
    for (Eigen::Index k = 0; k < lambda_.size(); ++k) {
      if (state_[k] == 0) lambda_(k) += alpha * (target(k) - lambda_(k));
    }
    if (blocking >= 0) {
      lambda_(blocking) = side < 0 ? lo_(blocking) : hi_(blocking);
      state_[blocking] = side;
      --*budget;
      continue;
    }
    int released = 0;
    if (Optimal(g_ * lambda_ - r_, &released)) return true;
    --*budget;
  }
  return false;
}

// One step of iterative refinement with the rows where they are: the momentum residual
// r_v = M (v_free − v') + h Σ_U J_iᵀ (c_i − J_i v')/cfm_i + h J_Bᵀ λ and the free bounded rows' law
// residual r_F = c_F − J_F v' − cfm_F λ_F, corrected through the same factors
// (δv = K⁻¹ (r_v + h J_Fᵀ δλ_F), G_FF δλ_F = r_F − J_F K⁻¹ r_v). K carries h/cfm of the hard
// rows (1e6 × the masses), so a single solve leaves 1e-9 m/s where dWorldStep's dual is exact to
// the last bits; one pass brings the two together.
void DirectSolver::Refine(const std::vector<NewtonBody>& bodies, const std::vector<NewtonRow>& rows,
                          Eigen::VectorXd* velocity) {
  Eigen::VectorXd& v = *velocity;
  Eigen::VectorXd residual(v.size());
  for (size_t k = 0; k < bodies.size(); ++k) {
    residual.segment<6>(6 * k) =
        MassTimes(bodies[k], bodies[k].free_velocity - v.segment<6>(6 * k));
  }
  for (const NewtonRow& row : rows) {
    if (Unbounded(row))
      AddImpulse(row, step_ * (row.rhs - RowVelocity(row, v)) / row.cfm, &residual);
  }
  for (size_t k = 0; k < bounded_.size(); ++k) {
    AddImpulse(rows[bounded_[k]], step_ * lambda_(static_cast<Eigen::Index>(k)), &residual);
  }
  cholesky_.Solve(&residual);  // δv₀ = K⁻¹ r_v
  v += residual;
  FindFree();
  if (free_.empty()) return;
  const Eigen::Index f = static_cast<Eigen::Index>(free_.size());
  Eigen::VectorXd rhs(f);
  for (Eigen::Index i = 0; i < f; ++i) {
    const NewtonRow& row = rows[bounded_[free_[i]]];
    rhs(i) = row.rhs - RowVelocity(row, v) - row.cfm * lambda_(free_[i]);  // (v: v' + δv₀)
  }
  Eigen::VectorXd correction;
  if (!SolveFreeBlock(rhs, &correction)) return;
  Eigen::VectorXd push = Eigen::VectorXd::Zero(v.size());
  for (Eigen::Index i = 0; i < f; ++i) {
    lambda_(free_[i]) += correction(i);
    push += step_ * correction(i) * z_.col(free_[i]);
  }
  cholesky_.BackSolve(&push);
  v += push;
}

// Rounds whose friction bounds follow the normal forces at once; later rounds take the secant step
// of bound_secant.h, which settles the back-and-forth of contacts whose normal force and friction
// feed each other (a wheel on rough ground) without moving the fixed point the rounds settle on.
constexpr int kUndampedRounds = 10;

// the bounded rows (bounded_, position_) and their normal rows' places (normal_at_); false for a
// friction row whose normal row is not bounded (not a row the law allows)
bool DirectSolver::Classify(const std::vector<NewtonRow>& rows) {
  bounded_.clear();
  position_.assign(rows.size(), -1);
  for (size_t i = 0; i < rows.size(); ++i) {
    if (Unbounded(rows[i])) continue;
    position_[i] = static_cast<int>(bounded_.size());
    bounded_.push_back(static_cast<int>(i));
  }
  normal_at_.assign(bounded_.size(), -1);
  for (size_t k = 0; k < bounded_.size(); ++k) {
    const int normal = rows[bounded_[k]].normal;
    if (normal < 0) continue;
    if (position_[normal] < 0) return false;
    normal_at_[k] = position_[normal];
  }
  return true;
}

// a friction row's bounds a fraction of the way from the last round's (`used_lo`, `used_hi`) to
// the ones its normal force gives now: the secant step of bound_secant.h, taken from the upper
// bound (the lower one is a fixed multiple of it, row.lo/row.hi, and moves with it)
void DirectSolver::DampBounds(const Eigen::VectorXd& used_lo, const Eigen::VectorXd& used_hi) {
  for (Eigen::Index k = 0; k < hi_.size(); ++k) {
    if (normal_at_[static_cast<size_t>(k)] < 0) continue;  // (a fixed bound; may be infinite)
    if (!std::isfinite(hi_(k)) || !std::isfinite(used_hi(k))) continue;  // (infinite friction)
    const double w = BoundStep(used_hi(k), hi_(k), &secants_[static_cast<size_t>(k)]);
    lo_(k) = used_lo(k) + w * (lo_(k) - used_lo(k));
    hi_(k) = used_hi(k) + w * (hi_(k) - used_hi(k));
  }
}

// the box LCP of G and r in rounds of friction bounds (into lambda_); true when they settled
bool DirectSolver::Rounds(const std::vector<NewtonRow>& rows, const DirectOptions& options,
                          NewtonResult* result) {
  const Eigen::Index n = static_cast<Eigen::Index>(bounded_.size());
  lambda_.setZero(n);
  lo_.resize(n);
  hi_.resize(n);
  state_.assign(static_cast<size_t>(n), 0);
  int budget = options.max_pivots;
  bool settled = n == 0;
  Eigen::VectorXd used_lo, used_hi;  // the bounds of the last round
  secants_.assign(static_cast<size_t>(n), {});
  while (!settled && result->rounds < options.max_rounds) {
    ++result->rounds;
    SetBounds(rows);
    if (result->rounds > kUndampedRounds) DampBounds(used_lo, used_hi);
    used_lo = lo_;
    used_hi = hi_;
    for (Eigen::Index k = 0; k < n; ++k) {  // λ into the bounds; the rows at a bound stay there
      lambda_(k) = std::clamp(lambda_(k), lo_(k), hi_(k));
      state_[k] = lambda_(k) <= lo_(k) ? -1 : (lambda_(k) >= hi_(k) ? 1 : 0);
    }
    if (!BoxSolve(&budget)) break;
    SetBounds(rows);
    settled = true;
    for (Eigen::Index k = 0; k < n && settled; ++k) {
      // (only a friction row's finite bounds move; a stop row's or an infinite friction row's
      // infinite one would make ∞ − ∞ here)
      if (normal_at_[static_cast<size_t>(k)] < 0 || !std::isfinite(hi_(k))) continue;
      const double change = std::max(std::abs(lo_(k) - used_lo(k)), std::abs(hi_(k) - used_hi(k)));
      settled = change <= options.bound_tolerance * std::max(hi_(k) - lo_(k), 1e-12);
    }
  }
  result->iterations = options.max_pivots - budget;
  return settled;
}

void DirectSolver::Begin(double step, NewtonResult* result) {
  step_ = step;
  result->converged = false;
  result->iterations = 0;
  result->rounds = 0;
}

bool DirectSolver::Solve(const std::vector<NewtonBody>& bodies, const std::vector<NewtonRow>& rows,
                         double step, const DirectOptions& options, NewtonResult* result) {
  Begin(step, result);
  if (!FactorBodies(bodies, rows)) return false;
  FreeVelocity(bodies, rows);
  if (!Classify(rows)) return false;
  BoundedSystem(rows);
  if (!Rounds(rows, options, result)) return false;
  const Eigen::Index n = static_cast<Eigen::Index>(bounded_.size());
  Eigen::VectorXd velocity = v0_;
  if (n > 0) {  // v₀ + h K⁻¹ J_Bᵀ λ = v₀ + h L⁻ᵀ Z λ
    Eigen::VectorXd push = step_ * (z_ * lambda_);
    cholesky_.BackSolve(&push);
    velocity += push;
  }
  Refine(bodies, rows, &velocity);
  result->velocity.resize(bodies.size());
  for (size_t k = 0; k < bodies.size(); ++k) result->velocity[k] = velocity.segment<6>(6 * k);
  result->force.resize(rows.size());
  for (size_t i = 0; i < rows.size(); ++i) {
    result->force[i] = (rows[i].rhs - RowVelocity(rows[i], velocity)) / rows[i].cfm;
  }
  for (Eigen::Index k = 0; k < n; ++k) result->force[bounded_[k]] = lambda_(k);
  result->converged = velocity.allFinite();
  return result->converged;
}

// ---- over a ReducedBasis' generalized velocities ----------------------------------------------

struct DirectSolver::Reduced {
  ReducedSystem system;
  ReducedCholesky cholesky;
  Eigen::VectorXd u0;
  Eigen::MatrixXd w;  ///< K⁻¹ gᵢ per bounded row (columns)
};

DirectSolver::DirectSolver() : reduced_(std::make_unique<Reduced>()) {}
DirectSolver::~DirectSolver() = default;

// K = Sᵀ M S + h Σ_U gᵢ gᵢᵀ / cfmᵢ, factored; u₀ = K⁻¹ (Sᵀ M v_free + h Σ_U gᵢ cᵢ / cfmᵢ)
bool DirectSolver::FactorReduced(const std::vector<NewtonRow>& rows, const ReducedBasis& basis) {
  Reduced& r = *reduced_;
  const ReducedSystem& system = r.system;
  Eigen::MatrixXd& k = r.cholesky.matrix();
  k = system.mass();
  r.u0 = system.free_momentum();
  for (size_t i = 0; i < rows.size(); ++i) {
    if (!Unbounded(rows[i])) continue;
    const double w = step_ / rows[i].cfm;
    for (size_t e = system.first(i); e < system.first(i + 1); ++e) {
      for (size_t f = system.first(i); f <= e; ++f) {  // (columns ascend: e's is the larger)
        k(system.index()[e], system.index()[f]) += w * system.value()[e] * system.value()[f];
      }
    }
    system.AddRow(i, w * rows[i].rhs, &r.u0);
  }
  if (!r.cholesky.Factor(basis, system.on_paths())) return false;
  r.cholesky.Solve(&r.u0);
  return r.u0.allFinite();
}

// G = h g_Bᵀ K⁻¹ g_B + diag(cfm_B), r = c_B − g_B u₀
void DirectSolver::BoundedReduced(const std::vector<NewtonRow>& rows) {
  Reduced& r = *reduced_;
  const ReducedSystem& system = r.system;
  const Eigen::Index n = static_cast<Eigen::Index>(bounded_.size());
  r.w.setZero(system.size(), n);
  for (Eigen::Index k = 0; k < n; ++k) {
    Eigen::VectorXd column = Eigen::VectorXd::Zero(system.size());
    system.AddRow(static_cast<size_t>(bounded_[k]), 1.0, &column);
    r.cholesky.Solve(&column);
    r.w.col(k) = column;
  }
  g_.resize(n, n);
  r_.resize(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const size_t row = static_cast<size_t>(bounded_[i]);
    for (Eigen::Index j = 0; j <= i; ++j) {
      g_(i, j) = step_ * system.RowVelocity(row, r.w.col(j));
      g_(j, i) = g_(i, j);
    }
    g_(i, i) += rows[row].cfm;
    r_(i) = rows[row].rhs - system.RowVelocity(row, r.u0);
  }
}

bool DirectSolver::SolveReduced(const std::vector<NewtonBody>& bodies,
                                const std::vector<NewtonRow>& rows, const ReducedBasis& basis,
                                double step, const DirectOptions& options, NewtonResult* result) {
  Begin(step, result);
  Reduced& r = *reduced_;
  r.system.Build(bodies, rows, basis);
  if (!FactorReduced(rows, basis) || !Classify(rows)) return false;
  BoundedReduced(rows);
  if (!Rounds(rows, options, result)) return false;
  Eigen::VectorXd u = r.u0;  // u₀ + h K⁻¹ g_B λ
  if (!bounded_.empty()) u += step_ * (r.w * lambda_);
  result->velocity.resize(bodies.size());
  for (size_t k = 0; k < bodies.size(); ++k) {
    result->velocity[k] = basis.Velocity(static_cast<int>(k), u);
  }
  result->force.resize(rows.size());
  for (size_t i = 0; i < rows.size(); ++i) {
    result->force[i] = (rows[i].rhs - r.system.RowVelocity(i, u)) / rows[i].cfm;
  }
  for (size_t k = 0; k < bounded_.size(); ++k) {
    result->force[bounded_[k]] = lambda_(static_cast<Eigen::Index>(k));
  }
  result->converged = u.allFinite();
  return result->converged;
}

}  // namespace lamina::core
