// SPDX-License-Identifier: MIT
#include "core/sim/profile_cholesky.h"

#include <algorithm>
#include <cmath>

namespace lamina::core {

namespace {

using Vec6 = Eigen::Matrix<double, 6, 1>;
using Block6 = ProfileCholesky::Block;

// The 6 × 6 kernels, written out: Eigen's LLT and triangular solves take their general paths
// (dynamic-size blocks, a blocked triangular solve) for a matrix this small, which cost the
// Newton solver about 5 % of a robot's step.

// The lower Cholesky factor of the symmetric `a` (its lower triangle read) in place, the upper
// triangle zeroed; false when a pivot is not positive and finite.
bool FactorDiagonalBlock(Block6* a) {
  Block6& m = *a;
  for (int j = 0; j < 6; ++j) {
    double pivot = m(j, j);
    for (int k = 0; k < j; ++k) pivot -= m(j, k) * m(j, k);
    if (!(pivot > 0.0) || !std::isfinite(pivot)) return false;
    const double root = std::sqrt(pivot);
    m(j, j) = root;
    for (int i = j + 1; i < 6; ++i) {
      double sum = m(i, j);
      for (int k = 0; k < j; ++k) sum -= m(i, k) * m(j, k);
      m(i, j) = sum / root;
      m(j, i) = 0.0;
    }
  }
  return true;
}

// x ← x L⁻ᵀ for the lower-triangular L: row by row, L y = x(r, :)ᵀ by forward substitution
void SolveTransposedOnTheRight(const Block6& l, Block6* x) {
  for (int r = 0; r < 6; ++r) {
    for (int j = 0; j < 6; ++j) {
      double sum = (*x)(r, j);
      for (int k = 0; k < j; ++k) sum -= l(j, k) * (*x)(r, k);
      (*x)(r, j) = sum / l(j, j);
    }
  }
}

// y ← L⁻¹ y
void SolveLower(const Block6& l, Vec6* y) {
  for (int j = 0; j < 6; ++j) {
    double sum = (*y)[j];
    for (int k = 0; k < j; ++k) sum -= l(j, k) * (*y)[k];
    (*y)[j] = sum / l(j, j);
  }
}

// y ← L⁻ᵀ y
void SolveLowerTransposed(const Block6& l, Vec6* y) {
  for (int j = 5; j >= 0; --j) {
    double sum = (*y)[j];
    for (int k = j + 1; k < 6; ++k) sum -= l(k, j) * (*y)[k];
    (*y)[j] = sum / l(j, j);
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
}

bool ProfileCholesky::Factor() {
  const int n = blocks();
  Block sum;
  for (int i = 0; i < n; ++i) {
    for (int j = first_[i]; j < i; ++j) {
      // L(i,j) = (A(i,j) − Σ L(i,k) L(j,k)ᵀ) L(j,j)⁻ᵀ over the block columns both rows have
      sum = block(i, j);
      for (int k = std::max(first_[i], first_[j]); k < j; ++k)
        sum.noalias() -= block(i, k) * block(j, k).transpose();
      SolveTransposedOnTheRight(block(j, j), &sum);
      block(i, j) = sum;
    }
    sum = block(i, i);
    for (int k = first_[i]; k < i; ++k) sum.noalias() -= block(i, k) * block(i, k).transpose();
    if (!FactorDiagonalBlock(&sum) || !sum.allFinite()) return false;
    block(i, i) = sum;
  }
  return true;
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
      if (!(*nonzero)[k]) continue;
      y.noalias() -= block(i, k) * x.segment<6>(6 * k);
      any = true;
    }
    if (!any) continue;
    SolveLower(block(i, i), &y);
    x.segment<6>(6 * i) = y;
    (*nonzero)[i] = 1;
  }
}

void ProfileCholesky::BackSolve(Eigen::VectorXd* b) const {
  Eigen::VectorXd& x = *b;
  for (int i = blocks() - 1; i >= 0; --i) {  // Lᵀ x = y, block column by block column of Lᵀ
    Vec6 y = x.segment<6>(6 * i);
    SolveLowerTransposed(block(i, i), &y);
    x.segment<6>(6 * i) = y;
    for (int k = first_[i]; k < i; ++k)
      x.segment<6>(6 * k).noalias() -= block(i, k).transpose() * y;
  }
}

void ProfileCholesky::Solve(Eigen::VectorXd* b) const {
  Eigen::VectorXd& x = *b;
  for (int i = 0; i < blocks(); ++i) {  // L y = b
    Vec6 y = x.segment<6>(6 * i);
    for (int k = first_[i]; k < i; ++k) y.noalias() -= block(i, k) * x.segment<6>(6 * k);
    SolveLower(block(i, i), &y);
    x.segment<6>(6 * i) = y;
  }
  BackSolve(b);
}

}  // namespace lamina::core
