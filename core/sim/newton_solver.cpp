// SPDX-License-Identifier: MIT
#include "core/sim/newton_solver.h"

#include <algorithm>
#include <cmath>

#include "core/sim/reduced_system.h"

namespace lamina::core {

double RowVelocity(const NewtonRow& row, const VecX& v) {
  double velocity = 0.0;
  if (row.a >= 0) velocity += row.ja.dot(v.segment<6>(6 * row.a));
  if (row.b >= 0) velocity += row.jb.dot(v.segment<6>(6 * row.b));
  return velocity;
}

double FrictionBound(double coefficient, double normal_force) {
  return std::isinf(coefficient) ? coefficient : coefficient * normal_force;
}

Vec6 MassTimes(const NewtonBody& body, const Vec6& v) {
  Vec6 out;
  out.head<3>() = body.mass * v.head<3>();
  out.tail<3>() = body.inertia * v.tail<3>();
  return out;
}

namespace newton_detail {  // (named: NewtonSolver::BodySpace holds a PairBlocks)

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
// blocks and added to the matrix once (a pair's contacts come together: 12 rows for 4 contacts).
// The diagonal blocks aa and bb only in their lower triangle: ProfileCholesky::Factor reads no
// more of a diagonal block (the factor is the same to the last bit; on a 10-box stack Add takes
// 11 % fewer instructions, the step 1.2 %)
struct PairBlocks {
  int a = -1, b = -1;
  Mat6 aa = Mat6::Zero(), bb = Mat6::Zero(), ba = Mat6::Zero();  ///< ba: row b, column a
  bool any = false;

  void Add(const NewtonRow& row, double w) {
    const Vec6 wa = w * row.ja, wb = w * row.jb;
    if (row.a >= 0) ProfileCholesky::AddLowerOuter(wa, row.ja, &aa);
    if (row.b >= 0) ProfileCholesky::AddLowerOuter(wb, row.jb, &bb);
    if (row.a >= 0 && row.b >= 0) ProfileCholesky::AddOuter(wb, row.ja, &ba);
    any = true;
  }
  // into the lower triangle of h (aa's and bb's upper triangles are zero)
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

}  // namespace newton_detail

using newton_detail::MassProduct;
using newton_detail::PairBlocks;

// The two spaces the Newton solver works in: the unknowns, the mass term of f, the rows' velocity
// and the Hessian's factorization. The Newton method itself (below) is the same in both.

// every body's own velocity (6 unknowns per body); the Hessian in its block profile
class NewtonSolver::BodySpace {
 public:
  BodySpace(NewtonSolver* solver, const std::vector<NewtonBody>& bodies,
            const std::vector<NewtonRow>& rows)
      : s_(*solver), bodies_(bodies), rows_(rows) {}

  Eigen::Index size() const { return 6 * static_cast<Eigen::Index>(bodies_.size()); }
  void Start(VecX* v) {
    v->resize(size());
    s_.v_free_.resize(size());
    for (size_t k = 0; k < bodies_.size(); ++k) {
      v->segment<6>(6 * k) = bodies_[k].start;
      s_.v_free_.segment<6>(6 * k) = bodies_[k].free_velocity;
    }
  }
  double RowVelocity(size_t i, const VecX& v) const {
    return lamina::core::RowVelocity(rows_[i], v);
  }
  double FreeRowVelocity(size_t i) const { return RowVelocity(i, s_.v_free_); }
  void AddImpulse(size_t i, double impulse, VecX* gradient) const {
    const NewtonRow& row = rows_[i];
    if (row.a >= 0) gradient->segment<6>(6 * row.a) -= impulse * row.ja;
    if (row.b >= 0) gradient->segment<6>(6 * row.b) -= impulse * row.jb;
  }
  // M (v − v_free)
  void MassGradient(const VecX& v, VecX* gradient) const {
    for (size_t k = 0; k < bodies_.size(); ++k) {
      gradient->segment<6>(6 * k) =
          MassTimes(bodies_[k], v.segment<6>(6 * k) - s_.v_free_.segment<6>(6 * k));
    }
  }
  double MassProduct(const VecX& u, const VecX& w) const {
    return newton_detail::MassProduct(bodies_, u, w);
  }
  // dᵀ M (v − v_free)
  double MassOffset(const VecX& d, const VecX& v) const {
    return newton_detail::MassProduct(bodies_, d, v - s_.v_free_);
  }
  // ½ (v − v_free)ᵀ M (v − v_free)
  double MassObjective(const VecX& v) const {
    return 0.5 * newton_detail::MassProduct(bodies_, v - s_.v_free_, v - s_.v_free_);
  }
  void BeginHessian() {
    s_.SetProfile(bodies_.size(), rows_);  // (here: a kept factorization needs none)
    s_.cholesky_.Reset(s_.lowest_body_);
    for (size_t k = 0; k < bodies_.size(); ++k) {
      ProfileCholesky::Block& diagonal =
          s_.cholesky_.block(static_cast<int>(k), static_cast<int>(k));
      diagonal.topLeftCorner<3, 3>().diagonal().setConstant(bodies_[k].mass);
      diagonal.bottomRightCorner<3, 3>() = bodies_[k].inertia;
    }
  }
  void AddHessianRow(size_t i, double weight) {
    const NewtonRow& row = rows_[i];
    if (row.a != blocks_.a || row.b != blocks_.b) {
      blocks_.Flush(&s_.cholesky_);
      blocks_.a = row.a;
      blocks_.b = row.b;
    }
    blocks_.Add(row, weight);
  }
  void EndHessian() { blocks_.Flush(&s_.cholesky_); }
  bool Factor() { return s_.cholesky_.Factor(); }
  void Solve(VecX* b) const { s_.cholesky_.Solve(b); }
  // the direction's size: its largest mass-weighted speed on one body, √(dᵀ M d / m) (a light
  // link of a heavy robot is held to the tolerance as well as the heavy base)
  double StepSize(const VecX& d) const {
    double largest = 0.0;
    for (size_t k = 0; k < bodies_.size(); ++k) {
      const Vec6 dk = d.segment<6>(6 * k);
      largest = std::max(largest, dk.dot(MassTimes(bodies_[k], dk)) / bodies_[k].mass);
    }
    return std::sqrt(largest);
  }
  Vec6 BodyVelocity(size_t k, const VecX& v) const { return v.segment<6>(6 * k); }
  // the bodies, for a factorization kept from solve to solve
  const std::vector<NewtonBody>* KeptBodies() const { return &bodies_; }

 private:
  NewtonSolver& s_;
  const std::vector<NewtonBody>& bodies_;
  const std::vector<NewtonRow>& rows_;
  PairBlocks blocks_;
};

// the generalized velocities u of a ReducedBasis (v = S u, reduced_system.h): f's mass term
// ½ (S u − v_free)ᵀ M (S u − v_free) body by body, the Hessian Sᵀ M S + h Σ gᵢ gᵢᵀ / cfmᵢ
struct NewtonSolver::Reduced {
  ReducedSystem system;
  ReducedCholesky cholesky;
  Eigen::MatrixXd local;  ///< a group's block of the Hessian
};

class NewtonSolver::ReducedSpace {
 public:
  ReducedSpace(NewtonSolver* solver, const std::vector<NewtonBody>& bodies,
               const std::vector<NewtonRow>& rows, const ReducedBasis& basis)
      : s_(*solver), r_(*solver->reduced_), bodies_(bodies), rows_(rows), basis_(basis) {}

  Eigen::Index size() const { return basis_.size(); }
  // the system, the start's coordinates, and u_free (in v_free_): the free velocity mapped in the
  // mass metric ((Sᵀ M S)⁻¹ Sᵀ M v_free: the u whose S u is nearest to it in kinetic energy)
  void Start(VecX* u) {
    r_.system.Build(bodies_, rows_, basis_);
    r_.local.resize(size(), size());
    basis_.Coordinates([this](int k) { return bodies_[k].start; }, u);
    r_.cholesky.matrix() = r_.system.mass();
    s_.v_free_ = r_.system.free_momentum();
    // (the mass matrix alone always has the tree's sparsity)
    if (r_.cholesky.Factor(basis_, true)) r_.cholesky.Solve(&s_.v_free_);
  }
  double RowVelocity(size_t i, const VecX& u) const { return r_.system.RowVelocity(i, u); }
  // at u_free: where the first round's friction bounds come from (the robot falling as a whole,
  // not each body on its own)
  double FreeRowVelocity(size_t i) const { return RowVelocity(i, s_.v_free_); }
  void AddImpulse(size_t i, double impulse, VecX* gradient) const {
    r_.system.AddRow(i, -impulse, gradient);
  }
  // the mass term body by body, centred at each body's free velocity as the body space's is: the
  // differences Newton's method compares keep their digits
  void MassGradient(const VecX& u, VecX* gradient) const {
    gradient->setZero(size());
    for (int k = 0; k < basis_.bodies(); ++k) {
      const Vec6 r = MassTimes(bodies_[k], basis_.Velocity(k, u) - bodies_[k].free_velocity);
      const std::vector<int>& columns = basis_.columns(k);
      for (size_t c = 0; c < columns.size(); ++c) {
        (*gradient)[columns[c]] += basis_.block(k).col(static_cast<Eigen::Index>(c)).dot(r);
      }
    }
  }
  double MassProduct(const VecX& u, const VecX& w) const {
    double sum = 0.0;
    for (int k = 0; k < basis_.bodies(); ++k) {
      sum += basis_.Velocity(k, u).dot(MassTimes(bodies_[k], basis_.Velocity(k, w)));
    }
    return sum;
  }
  double MassOffset(const VecX& d, const VecX& u) const {
    double sum = 0.0;
    for (int k = 0; k < basis_.bodies(); ++k) {
      const Vec6 offset = basis_.Velocity(k, u) - bodies_[k].free_velocity;
      sum += basis_.Velocity(k, d).dot(MassTimes(bodies_[k], offset));
    }
    return sum;
  }
  double MassObjective(const VecX& u) const {
    double sum = 0.0;
    for (int k = 0; k < basis_.bodies(); ++k) {
      const Vec6 offset = basis_.Velocity(k, u) - bodies_[k].free_velocity;
      sum += offset.dot(MassTimes(bodies_[k], offset));
    }
    return 0.5 * sum;
  }
  void BeginHessian() {
    r_.cholesky.matrix() = r_.system.mass();
    group_ = -1;
  }
  // rows over the same columns (a pair's contacts) are summed in a small dense block first
  void AddHessianRow(size_t i, double weight) {
    const ReducedSystem& system = r_.system;
    const size_t first = system.first(i);
    const Eigen::Index k = static_cast<Eigen::Index>(system.first(i + 1) - first);
    if (system.group(static_cast<size_t>(i)) != group_) {
      Flush();
      group_ = system.group(i);
      group_row_ = i;
      r_.local.topLeftCorner(k, k).setZero();
    }
    const Eigen::Map<const VecX> g(system.value().data() + first, k);
    for (Eigen::Index c = 0; c < k; ++c) {
      r_.local.col(c).segment(c, k - c) += (weight * g[c]) * g.segment(c, k - c);
    }
  }
  void EndHessian() { Flush(); }
  bool Factor() { return r_.cholesky.Factor(basis_, r_.system.on_paths()); }
  void Solve(VecX* b) const { r_.cholesky.Solve(b); }
  double StepSize(const VecX& d) const {
    double largest = 0.0;
    for (int k = 0; k < basis_.bodies(); ++k) {
      const Vec6 dk = basis_.Velocity(k, d);
      largest = std::max(largest, dk.dot(MassTimes(bodies_[k], dk)) / bodies_[k].mass);
    }
    return std::sqrt(largest);
  }
  Vec6 BodyVelocity(size_t k, const VecX& u) const {
    return basis_.Velocity(static_cast<int>(k), u);
  }

  const std::vector<NewtonBody>* KeptBodies() const { return nullptr; }  // (not kept)

 private:
  // the group's block into the Hessian's lower triangle (its columns ascend)
  void Flush() {
    if (group_ < 0) return;
    const ReducedSystem& system = r_.system;
    const size_t first = system.first(group_row_);
    const Eigen::Index k = static_cast<Eigen::Index>(system.first(group_row_ + 1) - first);
    const int* index = system.index().data() + first;
    Eigen::MatrixXd& h = r_.cholesky.matrix();
    for (Eigen::Index c = 0; c < k; ++c) {
      for (Eigen::Index r = c; r < k; ++r) h(index[r], index[c]) += r_.local(r, c);
    }
    group_ = -1;
  }

  NewtonSolver& s_;
  Reduced& r_;
  const std::vector<NewtonBody>& bodies_;
  const std::vector<NewtonRow>& rows_;
  const ReducedBasis& basis_;
  int group_ = -1;        ///< the group being summed, -1: none
  size_t group_row_ = 0;  ///< its first row
};

// one island's kept factorization and what it was formed from
struct NewtonSolver::Kept {
  unsigned long long island = 0;  ///< 0: a free slot
  long long used = 0;             ///< the solve that last used it (the oldest goes first)
  double step = 0.0;
  std::vector<NewtonBody> bodies;
  std::vector<NewtonRow> rows;
  std::vector<signed char> regime;
  ProfileCholesky cholesky;
};

NewtonSolver::NewtonSolver() : reduced_(std::make_unique<Reduced>()) {}
NewtonSolver::~NewtonSolver() = default;

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

namespace {

bool NearBody(const NewtonBody& a, const NewtonBody& b, double tolerance) {
  return std::abs(a.mass - b.mass) <= tolerance * a.mass &&
         (a.inertia - b.inertia).cwiseAbs().maxCoeff() <= tolerance * a.inertia.trace();
}

// whether a solve may keep or use a kept factorization: the body space (`bodies`), a key, and
// two Newton steps or more (a chord step needs a second to find it is done)
bool Keyable(const std::vector<NewtonBody>* bodies, const NewtonOptions& options) {
  return bodies != nullptr && options.island != 0 && options.max_iterations >= 2;
}

bool NearRow(const NewtonRow& a, const NewtonRow& b, double tolerance) {
  return a.a == b.a && a.b == b.b && std::abs(a.cfm - b.cfm) <= tolerance * a.cfm &&
         (a.ja - b.ja).cwiseAbs().maxCoeff() <= tolerance &&
         (a.jb - b.jb).cwiseAbs().maxCoeff() <= tolerance;
}

}  // namespace

// whether `kept` is the factorization of these bodies and rows, at this step, to the tolerance
bool NewtonSolver::KeptFits(const Kept& kept, const std::vector<NewtonBody>& bodies,
                            const std::vector<NewtonRow>& rows,
                            const NewtonOptions& options) const {
  const double tolerance = options.kept_tolerance;
  if (kept.step != step_ || kept.bodies.size() != bodies.size() ||
      kept.rows.size() != rows.size()) {
    return false;
  }
  for (size_t k = 0; k < bodies.size(); ++k) {
    if (!NearBody(bodies[k], kept.bodies[k], tolerance)) return false;
  }
  for (size_t i = 0; i < rows.size(); ++i) {
    if (!NearRow(rows[i], kept.rows[i], tolerance)) return false;
  }
  return true;
}

// Before a solve: the slot of the island of `options` (-1: none, or not Keyable), and whether its
// factorization serves this solve: then it is swapped into cholesky_ with its regimes, and the
// slot is free until KeepFactor gives it back (a slot's description is always that of its
// factorization).
int NewtonSolver::TakeKept(const std::vector<NewtonBody>* bodies,
                           const std::vector<NewtonRow>& rows, const NewtonOptions& options) {
  stale_ = false;
  if (!Keyable(bodies, options)) return -1;
  ++solves_;
  int slot = -1;
  for (size_t k = 0; k < kept_.size(); ++k) {
    if (kept_[k].island == options.island) slot = static_cast<int>(k);
  }
  if (slot < 0 || !KeptFits(kept_[slot], *bodies, rows, options)) return slot;
  Kept& kept = kept_[slot];
  std::swap(cholesky_, kept.cholesky);
  kept.island = 0;
  regime_ = kept.regime;
  stale_ = true;
  return slot;
}

// After a solve (`slot`: TakeKept's): a kept factorization that served to the end goes back to
// its slot; one formed in the solve is kept there, or in a free or the oldest slot, with what it
// was formed from (the rows do not change within a solve); after a solve that did not converge
// nothing is kept (a slot TakeKept freed stays free).
void NewtonSolver::KeepFactor(int slot, const std::vector<NewtonBody>* bodies,
                              const std::vector<NewtonRow>& rows, const NewtonOptions& options,
                              bool converged) {
  if (!Keyable(bodies, options) || !converged || !factored_) return;
  if (slot < 0) slot = FreeSlot();
  Kept& kept = kept_[slot];
  std::swap(cholesky_, kept.cholesky);
  kept.used = solves_;
  kept.island = options.island;
  if (stale_) return;
  kept.step = step_;
  kept.bodies = *bodies;
  kept.rows = rows;
  kept.regime = regime_;
}

// a slot for another island: a free one, a new one up to kMostKeptIslands, or the oldest
int NewtonSolver::FreeSlot() {
  int oldest = -1;
  for (size_t k = 0; k < kept_.size(); ++k) {
    if (kept_[k].island == 0) return static_cast<int>(k);
    if (oldest < 0 || kept_[k].used < kept_[oldest].used) oldest = static_cast<int>(k);
  }
  if (kept_.size() < kMostKeptIslands) {
    kept_.emplace_back();
    return static_cast<int>(kept_.size()) - 1;
  }
  return oldest;
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
    lo_[i] = FrictionBound(rows[i].lo, normal);
    hi_[i] = FrictionBound(rows[i].hi, normal);
  }
}

// x = c − J v_ for every row, unless x_ already holds it (v_ unchanged since, x_ untouched): a
// new round of friction bounds and the step's end ask again for the x of the same v_
template <class Space>
void NewtonSolver::RowOffsets(const Space& space, const std::vector<NewtonRow>& rows) {
  if (offsets_current_) return;
  for (size_t i = 0; i < rows.size(); ++i) x_[i] = rows[i].rhs - space.RowVelocity(i, v_);
  offsets_current_ = true;
}

// the gradient M (v − v_free) − h Σ J_iᵀ λ_i, with x_ already that of v
template <class Space>
void NewtonSolver::Gradient(const Space& space, size_t rows, const VecX& v) {
  space.MassGradient(v, &gradient_);
  for (size_t i = 0; i < rows; ++i) space.AddImpulse(i, step_ * RowForce(i, x_[i]), &gradient_);
}

// M + h Σ J_iᵀ J_i / cfm_i over the rows inside their bounds, and its factorization; remembers
// which rows those were. The matrix depends on nothing else: when those rows are the ones of the
// factorization in hand (a new round of friction bounds where the same rows are saturated, a
// step that only moved inside the same parts of the law), that factorization is kept. False
// when the matrix is not positive definite.
template <class Space>
bool NewtonSolver::Factor(Space& space, size_t rows) {
  if (factored_) {
    bool same = true;
    for (size_t i = 0; i < rows && same; ++i) same = Regime(i, x_[i]) == regime_[i];
    if (same) return true;
  }
  stale_ = false;
  ++factorizations_;
  space.BeginHessian();
  for (size_t i = 0; i < rows; ++i) {
    regime_[i] = Regime(i, x_[i]);
    if (regime_[i] == 0) space.AddHessianRow(i, step_ / cfm_[i]);
  }
  space.EndHessian();
  factored_ = space.Factor();
  return factored_;
}

// f(v) (J·s) for x_ that of v
template <class Space>
double NewtonSolver::Objective(const Space& space, const VecX& v) const {
  double value = space.MassObjective(v);
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
template <class Space>
bool NewtonSolver::FullStepDescends(const Space& space, double slope) {
  const double before = Objective(space, v_);
  for (size_t i = 0; i < x_.size(); ++i) x_[i] -= q_[i];
  trial_ = v_ + direction_;
  const double after = Objective(space, trial_);
  for (size_t i = 0; i < x_.size(); ++i) x_[i] += q_[i];
  return after <= before + 1e-4 * slope;
}

// the exact minimum along the direction: the root of the nondecreasing, piecewise linear slope,
// by Newton's method kept inside a bracket (the full step first: it is the answer once the rows
// inside their bounds stop changing)
template <class Space>
double NewtonSolver::LineSearch(const Space& space, size_t rows) {
  offsets_current_ = false;  // FullStepDescends moves x_ and back, which may round it
  for (size_t i = 0; i < rows; ++i) q_[i] = space.RowVelocity(i, direction_);
  const double start = Slope(0.0, nullptr);
  if (start >= 0.0) return 0.0;
  if (FullStepDescends(space, start)) return 1.0;
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
template <class Space>
bool NewtonSolver::NewtonSteps(Space& space, const std::vector<NewtonRow>& rows,
                               const NewtonOptions& options, int* budget) {
  double chord_size = kInf;  // the last chord step's
  while (*budget > 0) {
    RowOffsets(space, rows);
    Gradient(space, rows.size(), v_);
    if (!Factor(space, rows.size())) return false;
    direction_ = -gradient_;
    space.Solve(&direction_);
    d_m_d_ = space.MassProduct(direction_, direction_);
    const double size = space.StepSize(direction_);
    if (size <= options.velocity_tolerance) return true;
    if (stale_ && size > kChordContraction * chord_size) {
      factored_ = false;  // the kept matrix is too far off: the Hessian, and this step again
      continue;
    }
    chord_size = size;
    d_m_offset_ = space.MassOffset(direction_, v_);
    const double alpha = LineSearch(space, rows.size());
    --*budget;
    if (alpha == 0.0) return true;  // no descent left: the minimum within rounding
    v_ += alpha * direction_;
    offsets_current_ = false;
    // with every row where it was, f is one quadratic between here and the full step, and the
    // next Newton step would be (1 − α) d
    bool same = true;
    for (size_t i = 0; i < rows.size() && same; ++i) same = Regime(i, x_[i] - q_[i]) == regime_[i];
    if (same && !stale_ && std::abs(1.0 - alpha) * size <= options.velocity_tolerance) {
      return true;
    }
  }
  return false;
}

// true when the friction bounds of the normal forces now change no friction force
template <class Space>
bool NewtonSolver::BoundsSettled(const Space& space, const std::vector<NewtonRow>& rows,
                                 double tolerance, bool damped) {
  RowOffsets(space, rows);
  for (size_t i = 0; i < rows.size(); ++i) q_[i] = RowForce(i, x_[i]);  // (q_ as scratch)
  if (damped) {
    used_lo_ = lo_;
    used_hi_ = hi_;
  }
  SetBounds(rows);
  for (size_t i = 0; i < rows.size() && damped; ++i) {
    lo_[i] = 0.5 * (lo_[i] + used_lo_[i]);
    hi_[i] = 0.5 * (hi_[i] + used_hi_[i]);
  }
  for (size_t i = 0; i < rows.size(); ++i) {
    if (rows[i].normal < 0) continue;
    const double change = std::abs(RowForce(i, x_[i]) - q_[i]);
    if (change > tolerance * std::max(hi_[i] - lo_[i], 1e-12)) return false;
  }
  return true;
}

bool NewtonSolver::Solve(const std::vector<NewtonBody>& bodies, const std::vector<NewtonRow>& rows,
                         double step, const NewtonOptions& options, NewtonResult* result) {
  BodySpace space(this, bodies, rows);
  return SolveIn(&space, bodies.size(), rows, step, options, result);
}

bool NewtonSolver::SolveReduced(const std::vector<NewtonBody>& bodies,
                                const std::vector<NewtonRow>& rows, const ReducedBasis& basis,
                                double step, const NewtonOptions& options, NewtonResult* result) {
  ReducedSpace space(this, bodies, rows, basis);
  return SolveIn(&space, bodies.size(), rows, step, options, result);
}

template <class Space>
bool NewtonSolver::SolveIn(Space* space, size_t bodies, const std::vector<NewtonRow>& rows,
                           double step, const NewtonOptions& options, NewtonResult* result) {
  step_ = step;
  space->Start(&v_);
  gradient_.resize(space->size());
  const size_t m = rows.size();
  lo_.assign(m, 0.0);
  hi_.assign(m, 0.0);
  x_.assign(m, 0.0);
  q_.assign(m, 0.0);
  cfm_.resize(m);
  regime_.assign(m, 0);
  for (size_t i = 0; i < m; ++i) cfm_[i] = rows[i].cfm;
  offsets_current_ = false;
  factorizations_ = 0;
  const std::vector<NewtonBody>* kept_bodies = space->KeptBodies();
  const int slot = TakeKept(kept_bodies, rows, options);
  factored_ = stale_;
  // the first round's friction bounds from the normal forces at the free velocity (with gravity
  // on every contact it loads), the start where the step began
  for (size_t i = 0; i < m; ++i) x_[i] = rows[i].rhs - space->FreeRowVelocity(i);
  SetBounds(rows);
  RowOffsets(*space, rows);
  int budget = options.max_iterations;
  result->converged = false;
  result->rounds = 0;
  while (result->rounds < options.max_rounds) {
    ++result->rounds;
    if (!NewtonSteps(*space, rows, options, &budget)) break;
    if (BoundsSettled(*space, rows, options.bound_tolerance,
                      result->rounds > options.undamped_rounds)) {
      result->converged = true;
      break;
    }
  }
  result->iterations = options.max_iterations - budget;
  result->factorizations = factorizations_;
  KeepFactor(slot, kept_bodies, rows, options, result->converged);
  result->velocity.resize(bodies);
  for (size_t k = 0; k < bodies; ++k) result->velocity[k] = space->BodyVelocity(k, v_);
  result->force.resize(m);
  RowOffsets(*space, rows);
  for (size_t i = 0; i < m; ++i) result->force[i] = RowForce(i, x_[i]);
  return result->converged;
}

}  // namespace lamina::core
