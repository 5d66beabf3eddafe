// SPDX-License-Identifier: MIT
// The profile Cholesky factorization (core/sim/profile_cholesky.h) against Eigen's dense LLT.
#include "core/sim/profile_cholesky.h"

#include <random>

#include <Eigen/Cholesky>
#include <gtest/gtest.h>

namespace lamina::core {
namespace {

// an SPD matrix with the profile `first`: B Bᵀ of a lower-triangular B within the profile, plus
// a diagonal (B Bᵀ keeps B's profile)
ProfileCholesky::Matrix RandomSpd(const std::vector<int>& first, std::mt19937* random) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const int n = static_cast<int>(first.size());
  Eigen::MatrixXd b = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    for (int j = first[i]; j <= i; ++j) b(i, j) = unit(*random);
    b(i, i) = 1.0 + std::abs(b(i, i));
  }
  return b * b.transpose();
}

TEST(ProfileCholeskyTest, SolvesAsEigensDenseCholeskyOnChainsAndBlocks) {
  std::mt19937 random(3);
  for (int trial = 0; trial < 50; ++trial) {
    const int bodies = 1 + trial % 9;
    std::vector<int> first(6 * bodies);
    for (int i = 0; i < 6 * bodies; ++i) {
      const int body = i / 6;
      // a chain, with every third body also tied to the first
      first[i] = 6 * (body % 3 == 2 ? 0 : std::max(body - 1, 0));
    }
    ProfileCholesky::Matrix a = RandomSpd(first, &random);
    const Eigen::MatrixXd dense = a;
    Eigen::VectorXd x = Eigen::VectorXd::Random(a.rows());
    const Eigen::VectorXd expected = dense.llt().solve(x);
    ProfileCholesky cholesky;
    ASSERT_TRUE(cholesky.Factor(&a, first));
    cholesky.Solve(&x);
    EXPECT_LE((x - expected).norm(), 1e-10 * (1.0 + expected.norm())) << "trial " << trial;
  }
}

TEST(ProfileCholeskyTest, RefusesAMatrixThatIsNotPositiveDefinite) {
  ProfileCholesky::Matrix a(2, 2);
  a << 1.0, 2.0, 2.0, 1.0;  // eigenvalues 3 and -1
  ProfileCholesky cholesky;
  EXPECT_FALSE(cholesky.Factor(&a, {0, 0}));
  a << 1.0, 0.0, 0.0, std::nan("");
  EXPECT_FALSE(cholesky.Factor(&a, {0, 1}));
}

}  // namespace
}  // namespace lamina::core
