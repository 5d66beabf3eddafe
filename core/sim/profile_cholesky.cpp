// SPDX-License-Identifier: MIT
#include "core/sim/profile_cholesky.h"

#include <algorithm>

#include <Eigen/Cholesky>

namespace lamina::core {

namespace {

using Vec6 = Eigen::Matrix<double, 6, 1>;

// X Lᵀ = S for X in place of S (L lower triangular), column by column. Columns 4 and 5 first take
// the sum of the products of columns 0–3, then the rest: the order of Eigen 3.4's blocked solve
// (solveInPlace<OnTheRight>, panels of four columns) that this replaces at a quarter of its
// instructions, kept so that the factor stays the same to the last bit.
void SolveRightTransposed(const ProfileCholesky::Block& l, ProfileCholesky::Block* s) {
  constexpr int kPanel = 4;
  for (int c = 0; c < 6; ++c) {
    Vec6 column = s->col(c);
    const int panel = c < kPanel ? 0 : kPanel;
    if (panel > 0) {
      Vec6 sum = Vec6::Zero();
      for (int m = 0; m < panel; ++m) sum += s->col(m) * l(c, m);
      column += -1.0 * sum;
    }
    for (int m = panel; m < c; ++m) column -= s->col(m) * l(c, m);
    s->col(c) = column * (1.0 / l(c, c));
  }
}

}  // namespace

void ProfileCholesky::Reset(const std::vector<int>& first) {
  first_ = first;
  offset_.resize(first.size());
  int next = 0;
  for (size_t i = 0; i < first.size(); ++i) {
    offset_[i] = next - first[i];
    next += static_cast<int>(i) - first[i] + 1;
  }
  values_.resize(static_cast<size_t>(next));
  for (Block& b : values_) b.setZero();
  nonzero_.assign(values_.size(), 0);
}

// L(i,j) = (A(i,j) − Σ L(i,k) L(j,k)ᵀ) L(j,j)⁻ᵀ over the block columns k < j where both rows of L
// are nonzero (`row`: row i's so far, ascending); false, leaving the block zero, when A(i,j) is
// zero and no such k exists
bool ProfileCholesky::FactorBlock(int i, int j, const std::vector<int>& row) {
  Block& target = block(i, j);
  bool any = !target.isZero(0.0);
  Block sum = target;
  for (int k : row) {
    if (k < first_[j] || !nonzero(j, k)) continue;
    sum.noalias() -= block(i, k) * block(j, k).transpose();
    any = true;
  }
  if (!any) return false;
  SolveRightTransposed(block(j, j), &sum);
  target = sum;
  nonzero_[static_cast<size_t>(offset_[i] + j)] = 1;
  return true;
}

bool ProfileCholesky::Factor() {
  const int n = blocks();
  nonzero_.assign(values_.size(), 0);
  std::vector<int>& row = row_;
  for (int i = 0; i < n; ++i) {
    row.clear();
    for (int j = first_[i]; j < i; ++j) {
      if (FactorBlock(i, j, row)) row.push_back(j);
    }
    Block sum = block(i, i);
    for (int k : row) sum.noalias() -= block(i, k) * block(i, k).transpose();
    Eigen::LLT<Block> llt(sum);  // (reads the lower triangle only)
    if (llt.info() != Eigen::Success) return false;
    block(i, i) = llt.matrixL();
    if (!block(i, i).allFinite()) return false;  // (L alone: the upper triangle may hold anything)
    nonzero_[static_cast<size_t>(offset_[i] + i)] = 1;
  }
  return true;
}

int ProfileCholesky::nonzero_blocks() const {
  return static_cast<int>(std::count(nonzero_.begin(), nonzero_.end(), 1));
}

void ProfileCholesky::ForwardSolve(Eigen::VectorXd* b, int start,
                                   std::vector<char>* nonzero) const {
  Eigen::VectorXd& x = *b;
  const int n = blocks();
  nonzero->assign(static_cast<size_t>(n), 0);
  for (int i = start; i < n; ++i) {
    Vec6 y = x.segment<6>(6 * i);
    bool any = !y.isZero(0.0);
    for (int k = std::max(first_[i], start); k < i; ++k) {
      if (!(*nonzero)[k] || !this->nonzero(i, k)) continue;
      y.noalias() -= block(i, k) * x.segment<6>(6 * k);
      any = true;
    }
    if (!any) continue;
    block(i, i).triangularView<Eigen::Lower>().solveInPlace(y);
    x.segment<6>(6 * i) = y;
    (*nonzero)[i] = 1;
  }
}

void ProfileCholesky::BackSolve(Eigen::VectorXd* b) const {
  Eigen::VectorXd& x = *b;
  for (int i = blocks() - 1; i >= 0; --i) {  // Lᵀ x = y, block column by block column of Lᵀ
    Vec6 y = x.segment<6>(6 * i);
    block(i, i).transpose().triangularView<Eigen::Upper>().solveInPlace(y);
    x.segment<6>(6 * i) = y;
    for (int k = first_[i]; k < i; ++k) {
      if (nonzero(i, k)) x.segment<6>(6 * k).noalias() -= block(i, k).transpose() * y;
    }
  }
}

void ProfileCholesky::Solve(Eigen::VectorXd* b) const {
  Eigen::VectorXd& x = *b;
  for (int i = 0; i < blocks(); ++i) {  // L y = b
    Vec6 y = x.segment<6>(6 * i);
    for (int k = first_[i]; k < i; ++k) {
      if (nonzero(i, k)) y.noalias() -= block(i, k) * x.segment<6>(6 * k);
    }
    block(i, i).triangularView<Eigen::Lower>().solveInPlace(y);
    x.segment<6>(6 * i) = y;
  }
  BackSolve(b);
}

}  // namespace lamina::core
