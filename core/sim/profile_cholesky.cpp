// SPDX-License-Identifier: MIT
#include "core/sim/profile_cholesky.h"

#include <algorithm>

#include <Eigen/Cholesky>

namespace lamina::core {

namespace {

using Vec6 = Eigen::Matrix<double, 6, 1>;

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
      block(j, j).transpose().triangularView<Eigen::Upper>().solveInPlace<Eigen::OnTheRight>(sum);
      block(i, j) = sum;
    }
    sum = block(i, i);
    for (int k = first_[i]; k < i; ++k) sum.noalias() -= block(i, k) * block(i, k).transpose();
    Eigen::LLT<Block> llt(sum);
    if (llt.info() != Eigen::Success || !llt.matrixLLT().allFinite()) return false;
    block(i, i) = llt.matrixL();
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
    for (int k = first_[i]; k < i; ++k)
      x.segment<6>(6 * k).noalias() -= block(i, k).transpose() * y;
  }
}

void ProfileCholesky::Solve(Eigen::VectorXd* b) const {
  Eigen::VectorXd& x = *b;
  for (int i = 0; i < blocks(); ++i) {  // L y = b
    Vec6 y = x.segment<6>(6 * i);
    for (int k = first_[i]; k < i; ++k) y.noalias() -= block(i, k) * x.segment<6>(6 * k);
    block(i, i).triangularView<Eigen::Lower>().solveInPlace(y);
    x.segment<6>(6 * i) = y;
  }
  BackSolve(b);
}

}  // namespace lamina::core
