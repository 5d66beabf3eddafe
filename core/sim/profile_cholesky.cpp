// SPDX-License-Identifier: MIT
#include "core/sim/profile_cholesky.h"

#include <algorithm>
#include <cmath>

namespace lamina::core {

bool ProfileCholesky::Factor(Matrix* a, const std::vector<int>& first) {
  Matrix& l = *a;
  const int n = static_cast<int>(l.rows());
  for (int i = 0; i < n; ++i) {
    for (int j = first[i]; j <= i; ++j) {
      // L(i,k) L(j,k) over the columns both rows have
      const int k0 = std::max(first[i], first[j]);
      double s = l(i, j) - l.row(i).segment(k0, j - k0).dot(l.row(j).segment(k0, j - k0));
      if (j < i) {
        l(i, j) = s / l(j, j);
      } else {
        if (!(s > 0.0) || !std::isfinite(s)) return false;
        l(i, i) = std::sqrt(s);
      }
    }
  }
  factor_ = a;
  first_ = &first;
  return true;
}

void ProfileCholesky::Solve(Eigen::VectorXd* b) const {
  const Matrix& l = *factor_;
  const std::vector<int>& first = *first_;
  Eigen::VectorXd& x = *b;
  const int n = static_cast<int>(l.rows());
  for (int i = 0; i < n; ++i) {  // L y = b
    const int k0 = first[i];
    x(i) = (x(i) - l.row(i).segment(k0, i - k0).dot(x.segment(k0, i - k0))) / l(i, i);
  }
  for (int i = n - 1; i >= 0; --i) {  // Lᵀ x = y, column by column of Lᵀ (row i of L)
    x(i) /= l(i, i);
    const int k0 = first[i];
    x.segment(k0, i - k0) -= x(i) * l.row(i).segment(k0, i - k0).transpose();
  }
}

}  // namespace lamina::core
