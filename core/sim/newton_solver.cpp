// SPDX-License-Identifier: MIT
#include "core/sim/newton_solver.h"

#include <algorithm>
#include <cmath>

namespace lamina::core {

double RowVelocity(const NewtonRow& row, const VecX& v) {
  double velocity = 0.0;
  if (row.a >= 0) velocity += row.ja.dot(v.segment<6>(6 * row.a));
  if (row.b >= 0) velocity += row.jb.dot(v.segment<6>(6 * row.b));
  return velocity;
}

Vec6 MassTimes(const NewtonBody& body, const Vec6& v) {
  Vec6 out;
  out.head<3>() = body.mass * v.head<3>();
  out.tail<3>() = body.inertia * v.tail<3>();
  return out;
}

namespace {

// Σ over bodies of uᵀ M w
double MassProduct(const std::vector<NewtonBody>& bodies, const VecX& u, const VecX& w) {
  double sum = 0.0;
  for (size_t k = 0; k < bodies.size(); ++k) {
    sum += u.segment<6>(6 * k).dot(MassTimes(bodies[k], w.segment<6>(6 * k)));
  }
  return sum;
}

using Mat6 = Eigen::Matrix<double, 6, 6>;

// the Hessian terms of consecutive rows between the same two bodies, summed in fixed-size
// blocks and added to the matrix once (a pair's contacts come together: 12 rows for 4 contacts)
struct PairBlocks {
  int a = -1, b = -1;
  Mat6 aa = Mat6::Zero(), bb = Mat6::Zero(), ba = Mat6::Zero();  ///< ba: row b, column a
  bool any = false;

  void Add(const NewtonRow& row, double w) {
    const Vec6 wa = w * row.ja, wb = w * row.jb;
    for (int c = 0; c < 6; ++c) {  // (column by column: Eigen's outer product is slower here)
      if (row.a >= 0) aa.col(c) += wa * row.ja(c);
      if (row.b >= 0) bb.col(c) += wb * row.jb(c);
      if (row.a >= 0 && row.b >= 0) ba.col(c) += wb * row.ja(c);
    }
    any = true;
  }
  // into the lower triangle of h
  void Flush(ProfileCholesky* h) {
    if (!any) return;
    if (a >= 0) h->block(a, a) += aa;
    if (b >= 0) h->block(b, b) += bb;
    if (a >= 0 && b >= 0) {
      if (b > a) {
        h->block(b, a) += ba;
      } else {
        h->block(a, b) += ba.transpose();
      }
    }
    aa.setZero();
    bb.setZero();
    ba.setZero();
    any = false;
  }
};

}  // namespace

// the direction's size: its largest mass-weighted speed on one body, √(dᵀ M d / m) (a light link
// of a heavy robot is held to the tolerance as well as the heavy base)
double NewtonSolver::StepSize(const std::vector<NewtonBody>& bodies) const {
  double largest = 0.0;
  for (size_t k = 0; k < bodies.size(); ++k) {
    const Vec6 d = direction_.segment<6>(6 * k);
    largest = std::max(largest, d.dot(MassTimes(bodies[k], d)) / bodies[k].mass);
  }
  return std::sqrt(largest);
}

// the first block column of each body's block row: the lowest body a row couples it with (the
// bodies' order is the caller's: a chain in order keeps the profile narrow)
void NewtonSolver::SetProfile(size_t bodies, const std::vector<NewtonRow>& rows) {
  std::vector<int>& lowest = lowest_body_;
  lowest.resize(bodies);
  for (size_t k = 0; k < bodies; ++k) lowest[k] = static_cast<int>(k);
  for (const NewtonRow& row : rows) {
    if (row.a < 0 || row.b < 0) continue;
    const int high = std::max(row.a, row.b), low = std::min(row.a, row.b);
    lowest[high] = std::min(lowest[high], low);
  }
}

double NewtonSolver::RowForce(size_t i, double x) const {
  return std::clamp(x / cfm_[i], lo_[i], hi_[i]);
}

// -1 below the lower bound, 0 inside the bounds (the quadratic part of Φ), 1 above the upper
signed char NewtonSolver::Regime(size_t i, double x) const {
  const double force = x / cfm_[i];
  return force < lo_[i] ? -1 : (force > hi_[i] ? 1 : 0);
}

// the bounds of every row, friction rows from their normal row's force at the current velocity
void NewtonSolver::SetBounds(const std::vector<NewtonRow>& rows) {
  for (size_t i = 0; i < rows.size(); ++i) {
    if (rows[i].normal >= 0) continue;
    lo_[i] = rows[i].lo;
    hi_[i] = rows[i].hi;
  }
  for (size_t i = 0; i < rows.size(); ++i) {
    const int n = rows[i].normal;
    if (n < 0) continue;
    const double normal = std::abs(RowForce(n, x_[n]));
    lo_[i] = rows[i].lo * normal;
    hi_[i] = rows[i].hi * normal;
  }
}

// x = c − J v for every row
void NewtonSolver::RowOffsets(const std::vector<NewtonRow>& rows, const VecX& v) {
  for (size_t i = 0; i < rows.size(); ++i) x_[i] = rows[i].rhs - RowVelocity(rows[i], v);
}

// the gradient M (v − v_free) − h Σ J_iᵀ λ_i, with x_ already that of v
void NewtonSolver::Gradient(const std::vector<NewtonBody>& bodies,
                            const std::vector<NewtonRow>& rows, const VecX& v) {
  for (size_t k = 0; k < bodies.size(); ++k) {
    gradient_.segment<6>(6 * k) =
        MassTimes(bodies[k], v.segment<6>(6 * k) - v_free_.segment<6>(6 * k));
  }
  for (size_t i = 0; i < rows.size(); ++i) {
    const NewtonRow& row = rows[i];
    const double impulse = step_ * RowForce(i, x_[i]);
    if (row.a >= 0) gradient_.segment<6>(6 * row.a) -= impulse * row.ja;
    if (row.b >= 0) gradient_.segment<6>(6 * row.b) -= impulse * row.jb;
  }
}

// M + h Σ J_iᵀ J_i / cfm_i over the rows inside their bounds, lower triangle (the profile
// factorization reads nothing else); remembers which rows those were
void NewtonSolver::Hessian(const std::vector<NewtonBody>& bodies,
                           const std::vector<NewtonRow>& rows) {
  cholesky_.Reset(lowest_body_);
  for (size_t k = 0; k < bodies.size(); ++k) {
    ProfileCholesky::Block& diagonal = cholesky_.block(static_cast<int>(k), static_cast<int>(k));
    diagonal.topLeftCorner<3, 3>().diagonal().setConstant(bodies[k].mass);
    diagonal.bottomRightCorner<3, 3>() = bodies[k].inertia;
  }
  PairBlocks blocks;
  for (size_t i = 0; i < rows.size(); ++i) {
    regime_[i] = Regime(i, x_[i]);
    if (regime_[i] != 0) continue;
    const NewtonRow& row = rows[i];
    if (row.a != blocks.a || row.b != blocks.b) {
      blocks.Flush(&cholesky_);
      blocks.a = row.a;
      blocks.b = row.b;
    }
    blocks.Add(row, step_ / cfm_[i]);
  }
  blocks.Flush(&cholesky_);
}

// f(v) (J·s) for x_ that of v
double NewtonSolver::Objective(const std::vector<NewtonBody>& bodies, const VecX& v) const {
  double value = 0.5 * MassProduct(bodies, v - v_free_, v - v_free_);
  for (size_t i = 0; i < x_.size(); ++i) {
    const double force = RowForce(i, x_[i]);
    // Φ(x) = ∫ λ: x²/(2 cfm) inside the bounds, bound · x − bound² cfm / 2 outside
    value += step_ * (force * x_[i] - 0.5 * force * force * cfm_[i]);
  }
  return value;
}

// f'(v + α d) along the direction, and its rate of change there
double NewtonSolver::Slope(double alpha, double* curvature) const {
  double slope = d_m_offset_ + alpha * d_m_d_;
  double bend = d_m_d_;
  for (size_t i = 0; i < x_.size(); ++i) {
    if (q_[i] == 0.0) continue;
    const double x = x_[i] - alpha * q_[i];
    slope -= step_ * q_[i] * RowForce(i, x);
    if (Regime(i, x) == 0) bend += step_ * q_[i] * q_[i] / cfm_[i];
  }
  if (curvature != nullptr) *curvature = bend;
  return slope;
}

// true when the full step lowers f enough (Armijo): it is taken even where the minimum along the
// direction lies nearer, since it moves every row to the side of its kink the linear model
// predicts at once (the exact minimum stops at the first stiff row that turns on, and a step per
// row is slow)
bool NewtonSolver::FullStepDescends(const std::vector<NewtonBody>& bodies, double slope) {
  const double before = Objective(bodies, v_);
  for (size_t i = 0; i < x_.size(); ++i) x_[i] -= q_[i];
  trial_ = v_ + direction_;
  const double after = Objective(bodies, trial_);
  for (size_t i = 0; i < x_.size(); ++i) x_[i] += q_[i];
  return after <= before + 1e-4 * slope;
}

// the exact minimum along the direction: the root of the nondecreasing, piecewise linear slope,
// by Newton's method kept inside a bracket (the full step first: it is the answer once the rows
// inside their bounds stop changing)
double NewtonSolver::LineSearch(const std::vector<NewtonBody>& bodies,
                                const std::vector<NewtonRow>& rows) {
  for (size_t i = 0; i < rows.size(); ++i) q_[i] = RowVelocity(rows[i], direction_);
  const double start = Slope(0.0, nullptr);
  if (start >= 0.0) return 0.0;
  if (FullStepDescends(bodies, start)) return 1.0;
  double low = 0.0, high = kInf, alpha = 1.0;
  for (int k = 0; k < 60; ++k) {
    double bend = 0.0;
    const double slope = Slope(alpha, &bend);
    if (std::abs(slope) <= 1e-13 * std::abs(start)) return alpha;
    (slope < 0.0 ? low : high) = alpha;
    if (std::isfinite(high) && high - low <= 1e-15 * high) return low;
    double next = alpha - slope / bend;
    if (!(next > low && next < high)) next = std::isinf(high) ? 2.0 * alpha : 0.5 * (low + high);
    alpha = next;
  }
  return low;
}

// Newton steps with the bounds as they are, until a step is below the tolerance or a full step
// keeps every row in the part of its law it started in (then it landed on the minimum)
bool NewtonSolver::NewtonSteps(const std::vector<NewtonBody>& bodies,
                               const std::vector<NewtonRow>& rows, const NewtonOptions& options,
                               int* budget) {
  while (*budget > 0) {
    RowOffsets(rows, v_);
    Gradient(bodies, rows, v_);
    Hessian(bodies, rows);
    if (!cholesky_.Factor()) return false;
    direction_ = -gradient_;
    cholesky_.Solve(&direction_);
    d_m_d_ = MassProduct(bodies, direction_, direction_);
    const double size = StepSize(bodies);
    if (size <= options.velocity_tolerance) return true;
    d_m_offset_ = MassProduct(bodies, direction_, v_ - v_free_);
    const double alpha = LineSearch(bodies, rows);
    --*budget;
    if (alpha == 0.0) return true;  // no descent left: the minimum within rounding
    v_ += alpha * direction_;
    // with every row where it was, f is one quadratic between here and the full step, and the
    // next Newton step would be (1 − α) d
    bool same = true;
    for (size_t i = 0; i < rows.size() && same; ++i) same = Regime(i, x_[i] - q_[i]) == regime_[i];
    if (same && std::abs(1.0 - alpha) * size <= options.velocity_tolerance) {
      return true;
    }
  }
  return false;
}

// true when the friction bounds of the normal forces now change no friction force
bool NewtonSolver::BoundsSettled(const std::vector<NewtonRow>& rows, double tolerance) {
  RowOffsets(rows, v_);
  for (size_t i = 0; i < rows.size(); ++i) q_[i] = RowForce(i, x_[i]);  // (q_ as scratch)
  SetBounds(rows);
  for (size_t i = 0; i < rows.size(); ++i) {
    if (rows[i].normal < 0) continue;
    const double change = std::abs(RowForce(i, x_[i]) - q_[i]);
    if (change > tolerance * std::max(hi_[i] - lo_[i], 1e-12)) return false;
  }
  return true;
}

bool NewtonSolver::Solve(const std::vector<NewtonBody>& bodies, const std::vector<NewtonRow>& rows,
                         double step, const NewtonOptions& options, NewtonResult* result) {
  const Eigen::Index n = 6 * static_cast<Eigen::Index>(bodies.size());
  step_ = step;
  v_.resize(n);
  v_free_.resize(n);
  gradient_.resize(n);
  SetProfile(bodies.size(), rows);
  for (size_t k = 0; k < bodies.size(); ++k) {
    v_.segment<6>(6 * k) = bodies[k].start;
    v_free_.segment<6>(6 * k) = bodies[k].free_velocity;
  }
  const size_t m = rows.size();
  lo_.assign(m, 0.0);
  hi_.assign(m, 0.0);
  x_.assign(m, 0.0);
  q_.assign(m, 0.0);
  cfm_.resize(m);
  regime_.assign(m, 0);
  for (size_t i = 0; i < m; ++i) cfm_[i] = rows[i].cfm;
  // the first round's friction bounds from the normal forces at the free velocity (with gravity
  // on every contact it loads), the start where the step began
  RowOffsets(rows, v_free_);
  SetBounds(rows);
  RowOffsets(rows, v_);
  int budget = options.max_iterations;
  result->converged = false;
  result->rounds = 0;
  while (result->rounds < options.max_rounds) {
    ++result->rounds;
    if (!NewtonSteps(bodies, rows, options, &budget)) break;
    if (BoundsSettled(rows, options.bound_tolerance)) {
      result->converged = true;
      break;
    }
  }
  result->iterations = options.max_iterations - budget;
  result->velocity.resize(bodies.size());
  for (size_t k = 0; k < bodies.size(); ++k) result->velocity[k] = v_.segment<6>(6 * k);
  result->force.resize(m);
  for (size_t i = 0; i < m; ++i) {
    result->force[i] = RowForce(i, rows[i].rhs - RowVelocity(rows[i], v_));
  }
  return result->converged;
}

}  // namespace lamina::core
