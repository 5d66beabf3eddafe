// SPDX-License-Identifier: MIT
#include "core/sim/reduced_system.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Cholesky>

namespace lamina::core {

void ReducedSystem::Build(const std::vector<NewtonBody>& bodies, const std::vector<NewtonRow>& rows,
                          const ReducedBasis& basis) {
  basis_ = &basis;
  const Eigen::Index n = size();
  MassMatrix(bodies);
  first_.assign(1, 0);
  index_.clear();
  value_.clear();
  group_.clear();
  dense_row_.setZero(n);
  on_paths_ = true;
  for (size_t i = 0; i < rows.size(); ++i) {
    const size_t first = index_.size();
    MapRow(rows[i]);
    first_.push_back(index_.size());
    on_paths_ = on_paths_ && OnOnePath(first);
    const bool same = i > 0 && SameColumns(i - 1, first);
    group_.push_back(group_.empty() ? 0 : group_.back() + (same ? 0 : 1));
  }
}

namespace {

using Mat6 = Eigen::Matrix<double, 6, 6>;

Mat3 SkewOf(const Vec3& r) {
  Mat3 m;
  m << 0.0, -r.z(), r.y(), r.z(), 0.0, -r.x(), -r.y(), r.x(), 0.0;
  return m;
}

// a body's spatial inertia about the point `origin`, for motions (v_origin, ω)
Mat6 SpatialInertiaAbout(const NewtonBody& body, const Vec3& centre, const Vec3& origin) {
  const Mat3 r = SkewOf(centre - origin);
  Mat6 inertia;
  inertia.topLeftCorner<3, 3>() = body.mass * Mat3::Identity();
  inertia.topRightCorner<3, 3>() = -body.mass * r;
  inertia.bottomLeftCorner<3, 3>() = body.mass * r;
  inertia.bottomRightCorner<3, 3>() = body.inertia - body.mass * r * r;
  return inertia;
}

}  // namespace

// Sᵀ M S (lower triangle) and Sᵀ M v_free by composite bodies (the composite-rigid-body
// algorithm): column c, its body's own, moves that body's subtree, so for a column a on its path
// M(c, a) = s_aᵀ I_subtree s_c and (Sᵀ M v_free)_a = s_aᵀ (the subtree's momentum), with every
// motion s (v at a common point, ω) and inertia about that point: Σ depth² · 6 operations
// instead of Σ columns² · 12 (a 40-link chain: 60 times fewer)
void ReducedSystem::MassMatrix(const std::vector<NewtonBody>& bodies) {
  const ReducedBasis& basis = *basis_;
  const Eigen::Index n = size();
  mass_.setZero(n, n);
  free_momentum_.setZero(n);
  if (basis.bodies() == 0) return;
  const Vec3 origin = basis.centre(basis.order().front());
  composite_.resize(static_cast<size_t>(basis.bodies()));
  momentum_.resize(static_cast<size_t>(basis.bodies()));
  motion_.resize(6, n);
  for (int k : basis.order()) {
    const Vec3 arm = origin - basis.centre(k);
    composite_[k] = SpatialInertiaAbout(bodies[k], basis.centre(k), origin);
    Vec6 free;  // v_free at the origin point, ω
    free << bodies[k].free_velocity.head<3>() + bodies[k].free_velocity.tail<3>().cross(arm),
        bodies[k].free_velocity.tail<3>();
    momentum_[k] = composite_[k] * free;
    const std::vector<int>& columns = basis.columns(k);
    const int own = basis.own_columns(k);
    for (size_t c = columns.size() - own; c < columns.size(); ++c) {
      const Vec6 at_centre = basis.block(k).col(static_cast<Eigen::Index>(c));
      motion_.col(columns[c]) << at_centre.head<3>() + at_centre.tail<3>().cross(arm),
          at_centre.tail<3>();
    }
  }
  const std::vector<int>& order = basis.order();
  for (auto it = order.rbegin(); it != order.rend(); ++it) {  // leaves first
    const int k = *it;
    const int parent = basis.parent(k);
    const std::vector<int>& columns = basis.columns(k);
    for (size_t c = columns.size() - basis.own_columns(k); c < columns.size(); ++c) {
      const Vec6 force = composite_[k] * motion_.col(columns[c]);
      free_momentum_[columns[c]] = motion_.col(columns[c]).dot(momentum_[k]);
      for (size_t a = 0; a <= c; ++a) {
        mass_(columns[c], columns[a]) = motion_.col(columns[a]).dot(force);
      }
    }
    if (parent >= 0) {
      composite_[parent] += composite_[k];
      momentum_[parent] += momentum_[k];
    }
  }
}

// gᵢ = J_a S_a + J_b S_b over the union of the two bodies' columns, ascending, without exact
// zeros (a motor's row on a link and its parent is one entry: the two paths cancel)
void ReducedSystem::MapRow(const NewtonRow& row) {
  touched_.clear();
  Accumulate(row.a, row.ja);
  Accumulate(row.b, row.jb);
  std::sort(touched_.begin(), touched_.end());
  for (int c : touched_) {
    if (dense_row_[c] != 0.0) {
      index_.push_back(c);
      value_.push_back(dense_row_[c]);
    }
    dense_row_[c] = 0.0;
  }
}

void ReducedSystem::Accumulate(int body, const Vec6& j) {
  if (body < 0) return;
  const std::vector<int>& columns = basis_->columns(body);
  const ReducedBasis::Block& block = basis_->block(body);
  const bool second = !touched_.empty();
  for (size_t c = 0; c < columns.size(); ++c) {
    const int column = columns[c];
    if (!second || std::find(touched_.begin(), touched_.end(), column) == touched_.end()) {
      touched_.push_back(column);
    }
    dense_row_[column] += j.dot(block.col(static_cast<Eigen::Index>(c)));
  }
}

// whether the row starting at `first` only has columns on the path of its last one to the root
bool ReducedSystem::OnOnePath(size_t first) const {
  size_t next = index_.size();  // the entries from `next` on are on the path
  if (next == first) return true;
  for (int c = index_[next - 1]; c >= 0 && next > first; c = basis_->parent_column(c)) {
    if (index_[next - 1] == c) --next;
  }
  return next == first;
}

// whether the row before the one starting at `first` has the same columns
bool ReducedSystem::SameColumns(size_t before, size_t first) const {
  const size_t count = index_.size() - first;
  if (first_[before + 1] - first_[before] != count) return false;
  return std::equal(index_.begin() + static_cast<std::ptrdiff_t>(first_[before]),
                    index_.begin() + static_cast<std::ptrdiff_t>(first),
                    index_.begin() + static_cast<std::ptrdiff_t>(first));
}

double ReducedSystem::RowVelocity(size_t i, const VecX& u) const {
  double velocity = 0.0;
  for (size_t e = first_[i]; e < first_[i + 1]; ++e) velocity += value_[e] * u[index_[e]];
  return velocity;
}

void ReducedSystem::AddRow(size_t i, double scale, VecX* out) const {
  for (size_t e = first_[i]; e < first_[i + 1]; ++e) (*out)[index_[e]] += scale * value_[e];
}

bool ReducedCholesky::Factor(const ReducedBasis& basis, bool tree) {
  basis_ = &basis;
  tree_ = tree;
  Eigen::MatrixXd& h = matrix_;
  if (!tree) {  // (Eigen's unblocked factorization: no blocking overhead at a robot's sizes)
    const Eigen::Index failed = Eigen::internal::llt_inplace<double, Eigen::Lower>::unblocked(h);
    return failed < 0 && h.diagonal().allFinite();
  }
  for (int k = static_cast<int>(h.rows()) - 1; k >= 0; --k) {  // leaves first
    const double pivot = h(k, k);
    if (!(pivot > 0.0) || !std::isfinite(pivot)) return false;
    for (int i = basis.parent_column(k); i >= 0; i = basis.parent_column(i)) {
      const double a = h(k, i) / pivot;
      for (int j = i; j >= 0; j = basis.parent_column(j)) h(i, j) -= a * h(k, j);
      h(k, i) = a;
    }
  }
  return true;
}

void ReducedCholesky::Solve(VecX* b) const {
  const Eigen::MatrixXd& h = matrix_;
  if (!tree_) {
    h.triangularView<Eigen::Lower>().solveInPlace(*b);
    h.triangularView<Eigen::Lower>().adjoint().solveInPlace(*b);
    return;
  }
  VecX& x = *b;
  const int n = static_cast<int>(h.rows());
  for (int k = n - 1; k >= 0; --k) {  // Lᵀ y = b, leaves first
    for (int i = basis_->parent_column(k); i >= 0; i = basis_->parent_column(i)) {
      x[i] -= h(k, i) * x[k];
    }
  }
  for (int k = 0; k < n; ++k) x[k] /= h(k, k);  // D z = y
  for (int k = 0; k < n; ++k) {                 // L x = z, root first
    for (int i = basis_->parent_column(k); i >= 0; i = basis_->parent_column(i)) {
      x[k] -= h(k, i) * x[i];
    }
  }
}

}  // namespace lamina::core
