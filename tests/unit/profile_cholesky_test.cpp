// SPDX-License-Identifier: MIT
// The profile Cholesky factorization (core/sim/profile_cholesky.h) against Eigen's dense LLT.
#include "core/sim/profile_cholesky.h"

#include <cmath>
#include <random>

#include <Eigen/Cholesky>
#include <gtest/gtest.h>

namespace lamina::core {
namespace {

// an SPD matrix with the block profile `first` (6 × 6 blocks): B Bᵀ of a lower-triangular B
// within the profile, plus a diagonal (B Bᵀ keeps B's profile)
Eigen::MatrixXd RandomSpd(const std::vector<int>& first, std::mt19937* random) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const int n = 6 * static_cast<int>(first.size());
  Eigen::MatrixXd b = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    for (int j = 6 * first[i / 6]; j <= i; ++j) b(i, j) = unit(*random);
    b(i, i) = 1.0 + std::abs(b(i, i));
  }
  return b * b.transpose();
}

// `dense` within the block profile
void Load(const Eigen::MatrixXd& dense, const std::vector<int>& first, ProfileCholesky* a) {
  a->Reset(first);
  for (int i = 0; i < a->blocks(); ++i) {
    for (int j = first[i]; j <= i; ++j) a->block(i, j) = dense.block<6, 6>(6 * i, 6 * j);
  }
}

TEST(ProfileCholeskyTest, SolvesAsEigensDenseCholeskyOnChainsBlocksAndTrees) {
  std::mt19937 random(3);
  for (int trial = 0; trial < 60; ++trial) {
    const int bodies = 1 + trial % 9;
    std::vector<int> first(bodies);
    for (int body = 0; body < bodies; ++body) {
      if (trial % 2 == 0) {
        // a chain, with every third body also tied to the first
        first[body] = body % 3 == 2 ? 0 : std::max(body - 1, 0);
      } else {
        // a robot's tree, every link before its parent: chains of two, the last body the root
        first[body] = body + 1 == bodies ? 0 : body - body % 2;
      }
    }
    const Eigen::MatrixXd dense = RandomSpd(first, &random);
    ProfileCholesky a;
    Load(dense, first, &a);
    Eigen::VectorXd x = Eigen::VectorXd::Random(dense.rows());
    const Eigen::VectorXd expected = dense.llt().solve(x);
    ASSERT_TRUE(a.Factor());
    a.Solve(&x);
    EXPECT_LE((x - expected).norm(), 1e-10 * (1.0 + expected.norm())) << "trial " << trial;
    // the factor itself: L Lᵀ = A, L as Eigen's within the profile
    const Eigen::MatrixXd l = dense.llt().matrixL();
    for (int i = 0; i < bodies; ++i) {
      for (int j = first[i]; j < i; ++j) {
        EXPECT_LE((a.block(i, j) - l.block<6, 6>(6 * i, 6 * j)).norm(), 1e-10) << i << ", " << j;
      }
      const ProfileCholesky::Block diagonal = a.block(i, i).triangularView<Eigen::Lower>();
      EXPECT_LE((diagonal - l.block<6, 6>(6 * i, 6 * i)).norm(), 1e-10) << i;
    }
  }
}

// A robot's tree ordered children first (three legs of three links, leaf first, then the root)
// has blocks inside its profile that stay zero: the root's row reaches back to the first leg's
// top link, but it only touches the three top links. The factor has no fill (one nonzero block
// per body and per edge), those blocks stay exactly zero, and it still equals Eigen's.
TEST(ProfileCholeskyTest, LeavesATreesBlocksZeroWithoutFill) {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const int bodies = 10, root = 9;
  std::vector<int> parent(bodies, root), first(bodies);
  for (int body = 0; body < root; ++body) {
    if (body % 3 != 2) parent[body] = body + 1;  // 0 → 1 → 2 → root, 3 → 4 → 5 → root, ...
  }
  Eigen::MatrixXd dense = Eigen::MatrixXd::Identity(6 * bodies, 6 * bodies);
  for (int body = 0; body < root; ++body) {  // an edge: E Eᵀ on the two bodies' rows
    Eigen::MatrixXd e = Eigen::MatrixXd::Zero(6 * bodies, 6);
    for (int i = 0; i < 6; ++i) {
      for (int j = 0; j < 6; ++j) {
        e(6 * body + i, j) = unit(random);
        e(6 * parent[body] + i, j) = unit(random);
      }
    }
    dense += e * e.transpose();
  }
  for (int body = 0; body < bodies; ++body) first[body] = body;
  for (int body = 0; body < root; ++body) first[parent[body]] = std::min(first[parent[body]], body);
  ASSERT_EQ(first[root], 2);  // the profile reaches back over legs two and three's lower links
  ProfileCholesky a;
  Load(dense, first, &a);
  ASSERT_TRUE(a.Factor());
  EXPECT_EQ(a.nonzero_blocks(), bodies + root);  // the diagonal and the nine edges
  const Eigen::MatrixXd l = dense.llt().matrixL();
  for (int i = 0; i < bodies; ++i) {
    for (int j = first[i]; j < i; ++j) {
      if (parent[j] == i) {
        EXPECT_LE((a.block(i, j) - l.block<6, 6>(6 * i, 6 * j)).norm(), 1e-10) << i << ", " << j;
      } else {
        EXPECT_TRUE(a.block(i, j).isZero(0.0)) << i << ", " << j;
        EXPECT_LE((l.block<6, 6>(6 * i, 6 * j)).norm(), 1e-12) << i << ", " << j;
      }
    }
  }
  Eigen::VectorXd x = Eigen::VectorXd::Random(dense.rows());
  const Eigen::VectorXd expected = dense.llt().solve(x);
  a.Solve(&x);
  EXPECT_LE((x - expected).norm(), 1e-10 * (1.0 + expected.norm()));
}

TEST(ProfileCholeskyTest, RefusesAMatrixThatIsNotPositiveDefinite) {
  ProfileCholesky a;
  Eigen::MatrixXd dense = Eigen::MatrixXd::Identity(12, 12);
  dense(7, 6) = dense(6, 7) = 2.0;  // eigenvalues 3 and -1 in the second block
  Load(dense, {0, 0}, &a);
  EXPECT_FALSE(a.Factor());
  dense = Eigen::MatrixXd::Identity(12, 12);
  dense(11, 11) = std::nan("");
  Load(dense, {0, 1}, &a);
  EXPECT_FALSE(a.Factor());
}

// The solvers fill a diagonal block's lower triangle only (AddLowerOuter): the factor must not
// read the upper one. NaN there gives the same factor to the last bit as the symmetric block.
TEST(ProfileCholeskyTest, NeverReadsTheUpperTriangleOfADiagonalBlock) {
  std::mt19937 random(5);
  const std::vector<int> first = {0, 0, 1, 0};
  const Eigen::MatrixXd dense = RandomSpd(first, &random);
  ProfileCholesky full, lower;
  Load(dense, first, &full);
  Load(dense, first, &lower);
  for (int i = 0; i < lower.blocks(); ++i) {
    ProfileCholesky::Block& block = lower.block(i, i);
    for (int c = 1; c < 6; ++c) block.col(c).head(c).setConstant(std::nan(""));
  }
  ASSERT_TRUE(full.Factor());
  ASSERT_TRUE(lower.Factor());
  for (int i = 0; i < full.blocks(); ++i) {
    for (int j = first[i]; j <= i; ++j) {
      EXPECT_TRUE(lower.block(i, j) == full.block(i, j)) << i << ", " << j;
    }
  }
}

// u vᵀ into the lower triangle, each entry the product itself; the upper triangle untouched
TEST(ProfileCholeskyTest, AddLowerOuterFillsTheLowerTriangleOnly) {
  ProfileCholesky::Column u, v;
  u << 1.5, -2.0, 0.25, 3.0, -0.5, 7.0;
  v << 0.1, 2.0, -3.0, 0.5, 4.0, -1.25;
  ProfileCholesky::Block block = ProfileCholesky::Block::Constant(2.0);
  ProfileCholesky::AddLowerOuter(u, v, &block);
  for (int c = 0; c < 6; ++c) {
    for (int r = 0; r < 6; ++r) {
      EXPECT_EQ(block(r, c), r >= c ? 2.0 + u(r) * v(c) : 2.0) << r << ", " << c;
    }
  }
}

}  // namespace
}  // namespace lamina::core
