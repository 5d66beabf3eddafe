// SPDX-License-Identifier: MIT
// Projected Gauss–Seidel over an island's rows (core/sim/row_relaxation.h): analytic answers (a
// point resting, a point sliding), and on random stacks every force inside its bounds and the
// velocities exactly those the forces make, converging to the Newton solver's answer.
#include "core/sim/row_relaxation.h"

#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "tests/common/island_rows.h"

namespace lamina::core {
namespace {

using test::AddContact;
using test::AddFace;
using test::IslandBody;
using test::kIslandGravity;

// one contact at the centre, no torque: the normal row alone is the 1-D law, which one sweep
// solves exactly: m (v' − v_free) = h λ and v' = −cfm λ, so λ = m g h / (h + m cfm)
TEST(RelaxRowsTest, APointRestingIsSolvedInOneSweep) {
  const double h = 0.01, cfm = 1e-9;
  const std::vector<NewtonBody> bodies = {IslandBody(1.0, Vec6::Zero(), h)};
  std::vector<NewtonRow> rows;
  AddContact(&rows, 0, -1, Vec3::Zero(), Vec3::Zero(), 0.5, cfm);
  NewtonResult result;
  RelaxRows(bodies, rows, h, 1, &result);
  const double normal = kIslandGravity * h / (h + cfm);
  EXPECT_NEAR(result.force[0], normal, 1e-12 * normal);
  EXPECT_NEAR(result.velocity[0](2), -cfm * normal, 1e-15);
  EXPECT_EQ(result.force[1], 0.0);  // no sliding: no friction
  EXPECT_FALSE(result.converged);
  EXPECT_EQ(result.iterations, 1);
}

// sliding at 1 m/s along x: friction saturates at μ λ_n and takes μ λ_n h / m off the speed
TEST(RelaxRowsTest, APointSlidingLosesMuTimesItsNormalForce) {
  const double h = 0.01, mu = 0.5;
  Vec6 start = Vec6::Zero();
  start(0) = 1.0;
  const std::vector<NewtonBody> bodies = {IslandBody(1.0, start, h)};
  std::vector<NewtonRow> rows;
  AddContact(&rows, 0, -1, Vec3::Zero(), Vec3::Zero(), mu);
  NewtonResult result;
  RelaxRows(bodies, rows, h, 3, &result);
  const double normal = kIslandGravity * h / (h + 1e-9);
  EXPECT_NEAR(result.force[0], normal, 1e-12 * normal);
  EXPECT_NEAR(result.force[1], -mu * result.force[0], 1e-12);
  EXPECT_NEAR(result.velocity[0](0), 1.0 - mu * normal * h, 1e-12);
}

// no sweep: no force, the free velocity (whatever result held before)
TEST(RelaxRowsTest, NoSweepLeavesNoForceAndTheFreeVelocity) {
  const double h = 0.01;
  const std::vector<NewtonBody> bodies = {IslandBody(1.0, Vec6::Zero(), h)};
  std::vector<NewtonRow> rows;
  AddContact(&rows, 0, -1, Vec3::Zero(), Vec3::Zero(), 0.5);
  NewtonResult result;
  result.force = {-5.0, 100.0, std::nan("")};
  RelaxRows(bodies, rows, h, 0, &result);
  EXPECT_EQ(result.force, std::vector<double>(3, 0.0));
  EXPECT_EQ(result.velocity[0], bodies[0].free_velocity);
}

// A box resting on a face of four contacts (redundant rows: its forces are not unique, its
// velocity is) converges to the Newton solver's answer, slowly, as Gauss–Seidel does on such rows:
// measured gaps 1.4e-4 m/s after 10 sweeps, 7.9e-6 after 100, 9.3e-9 after 1e5.
TEST(RelaxRowsTest, ABoxOnAFaceConvergesToTheNewtonAnswer) {
  const double h = 0.005;
  const std::vector<NewtonBody> bodies = {IslandBody(1.0, Vec6::Zero(), h)};
  std::vector<NewtonRow> rows;
  AddFace(&rows, 0, -1, 0.5);
  NewtonSolver solver;
  NewtonResult newton;
  ASSERT_TRUE(solver.Solve(bodies, rows, h, {}, &newton));
  const auto gap = [&](int sweeps) {
    NewtonResult result;
    RelaxRows(bodies, rows, h, sweeps, &result);
    return (result.velocity[0] - newton.velocity[0]).norm();
  };
  EXPECT_LE(gap(10), 3e-4);
  EXPECT_LE(gap(100), 2e-5);
  EXPECT_LE(gap(100000), 1e-7);
}

// stacks of 2 to 6 boxes with random masses (1:10 either way), offsets and starting speeds: at
// every sweep count the forces are inside their bounds and v = v_free + h M⁻¹ Σ Jᵀ λ exactly
TEST(RelaxRowsTest, RandomStacksKeepEveryForceInItsBoundsAndTheVelocitiesItsForcesMake) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double h = 0.005;
  for (int trial = 0; trial < 40; ++trial) {
    std::vector<NewtonBody> bodies;
    const int n = 2 + trial % 5;
    for (int k = 0; k < n; ++k) {
      Vec6 start;
      for (int j = 0; j < 6; ++j) start(j) = 0.02 * unit(random);
      bodies.push_back(IslandBody(std::pow(10.0, unit(random)), start, h));
    }
    std::vector<NewtonRow> rows;
    for (int k = 0; k < n; ++k) AddFace(&rows, k, k - 1, 0.6 + 0.3 * unit(random));
    for (int sweeps : {1, 4, 50}) {
      NewtonResult result;
      RelaxRows(bodies, rows, h, sweeps, &result);
      VecX v(6 * n);
      for (int k = 0; k < n; ++k) v.segment<6>(6 * k) = bodies[k].free_velocity;
      for (size_t i = 0; i < rows.size(); ++i) {
        const NewtonRow& row = rows[i];
        const double lambda = result.force[i];
        if (row.normal < 0) {
          EXPECT_GE(lambda, 0.0) << "trial " << trial << " row " << i;
        } else {
          EXPECT_LE(std::abs(lambda), row.hi * result.force[row.normal] * (1 + 1e-12))
              << "trial " << trial << " row " << i;
        }
        for (int side = 0; side < 2; ++side) {
          const int body = side == 0 ? row.a : row.b;
          if (body < 0) continue;
          Vec6 impulse = h * lambda * (side == 0 ? row.ja : row.jb);
          impulse.head<3>() /= bodies[body].mass;
          impulse.tail<3>() = bodies[body].inertia.inverse() * impulse.tail<3>();
          v.segment<6>(6 * body) += impulse;
        }
      }
      for (int k = 0; k < n; ++k) {
        // (the sums in another order: rounding of forces up to about 1e3 N times h / m)
        EXPECT_LE((result.velocity[k] - v.segment<6>(6 * k)).norm(), 1e-11)
            << "trial " << trial << " sweeps " << sweeps;
      }
    }
  }
}

}  // namespace
}  // namespace lamina::core
