// SPDX-License-Identifier: MIT
// The Newton solver of object islands (core/sim/newton_solver.h): analytic answers (a resting
// box, a sliding point, a 1000:1 stack) and ODE's row law checked row by row on random islands.
#include "core/sim/newton_solver.h"

#include <random>

#include <gtest/gtest.h>

#include "tests/common/island_rows.h"

namespace lamina::core {
namespace {

using test::AddContact;
using test::AddFace;
using test::kIslandGravity;
using test::NormalSum;

using test::IslandBody;

TEST(NewtonSolverTest, ABoxOnTheGroundCarriesItsWeightAndStops) {
  NewtonSolver solver;
  EXPECT_LE(test::ExpectABoxOnTheGroundCarriesItsWeight(&solver).iterations, 3);
}

TEST(NewtonSolverTest, APointSlidingOnTheGroundLosesMuGTimesTheStep) {
  const double h = 0.01, mu = 0.5;
  Vec6 start = Vec6::Zero();
  start(0) = 1.0;
  std::vector<NewtonBody> bodies = {IslandBody(1.0, start, h)};
  std::vector<NewtonRow> rows;
  AddContact(&rows, 0, -1, Vec3::Zero(), Vec3::Zero(), mu);  // at the centre: no torque
  NewtonSolver solver;
  NewtonResult result;
  ASSERT_TRUE(solver.Solve(bodies, rows, h, {}, &result));
  const double normal = kIslandGravity * h / (h + 1e-9);  // m g h / (h + m cfm), m = 1
  EXPECT_NEAR(result.force[0], normal, 1e-12 * normal);
  EXPECT_NEAR(result.velocity[0](0), 1.0 - mu * normal * h, 1e-12);
  EXPECT_NEAR(result.force[1], -mu * result.force[0], 1e-9);
  EXPECT_GE(result.rounds, 2);  // the first round has no normal force to bound friction with
}

TEST(NewtonSolverTest, AThousandToOneStackHoldsInOneStepFromRest) {
  NewtonSolver solver;
  EXPECT_LE(test::ExpectAThousandToOneStackHolds(&solver).iterations, 2);
}

TEST(NewtonSolverTest, ASlidingBoxStopsOnInfiniteFriction) {
  NewtonSolver solver;
  EXPECT_TRUE(test::ExpectASlidingBoxStopsOnInfiniteFriction(&solver).converged);
}

// every row obeys ODE's law at the answer, and the velocities are what the forces make them
TEST(NewtonSolverTest, RandomIslandsObeyTheRowLawRowByRow) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double h = 0.005;
  int failed = 0, iterations = 0;
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<NewtonBody> bodies;
    const int n = 1 + trial % 5;
    for (int k = 0; k < n; ++k) {
      Vec6 start;
      for (int j = 0; j < 6; ++j) start(j) = 0.05 * unit(random);
      bodies.push_back(IslandBody(std::pow(10.0, unit(random)), start, h));
    }
    std::vector<NewtonRow> rows;
    for (int k = 0; k < n; ++k) {
      const Vec3 offset(0.03 * unit(random), 0.03 * unit(random), 0.0);
      AddFace(&rows, k, k - 1, 0.6 + 0.4 * unit(random));
      for (size_t i = rows.size() - 12; i < rows.size(); ++i) {
        rows[i].rhs = rows[i].normal < 0 ? 0.01 * unit(random) : 0.002 * unit(random);
        rows[i].ja.tail<3>() += offset.cross(rows[i].ja.head<3>());
      }
    }
    NewtonSolver solver;
    NewtonResult result;
    if (!solver.Solve(bodies, rows, h, {}, &result)) {
      ++failed;
      continue;
    }
    iterations += result.iterations;
    std::vector<Vec6> impulse(n, Vec6::Zero());
    for (size_t i = 0; i < rows.size(); ++i) {
      const NewtonRow& row = rows[i];
      double jv = row.ja.dot(result.velocity[row.a]);
      if (row.b >= 0) jv += row.jb.dot(result.velocity[row.b]);
      const double scale = row.normal < 0 ? 1.0 : std::abs(result.force[row.normal]);
      const double law = std::clamp((row.rhs - jv) / row.cfm, row.lo * scale, row.hi * scale);
      EXPECT_NEAR(result.force[i], law, 1e-6 * (1.0 + std::abs(law))) << trial << " row " << i;
      impulse[row.a] += h * result.force[i] * row.ja;
      if (row.b >= 0) impulse[row.b] += h * result.force[i] * row.jb;
    }
    // M (v' − v_free) = h Σ Jᵀ λ, in velocity: the forces reported move the bodies as the answer
    // does to 1e-6 m/s (6e-7 measured: λ of a hard row moves by 1e-3 N per 1e-12 m/s of v', so
    // the simulator applies M (v' − v_free) / h, object_islands.h, and reports λ)
    for (int k = 0; k < n; ++k) {
      const NewtonBody& body = bodies[k];
      Vec6 predicted = body.free_velocity;
      predicted.head<3>() += impulse[k].head<3>() / body.mass;
      predicted.tail<3>() += body.inertia.inverse() * impulse[k].tail<3>();
      EXPECT_LE((result.velocity[k] - predicted).norm(), 1e-6) << trial << " body " << k;
    }
  }
  // cold starts (Newton starts from the velocity before the step, here a random one, and every
  // body slides): 184 to 188 of 200 converge, in 34 Newton steps on average; the simulator
  // hands the rest to dWorldStep. From the simulator's warm starts it takes 0-3
  // (newton_islands_test: under one per step on a resting stack).
  std::printf("%d of 200 did not converge; %d Newton steps in all\n", failed, iterations);
  EXPECT_LE(failed, 20);  // 12 to 16 measured as the summation order changed
}

TEST(NewtonSolverTest, AnIslandWithoutRowsKeepsItsFreeVelocity) {
  const double h = 0.01;
  Vec6 start;
  start << 1, 2, 3, 0.1, 0.2, 0.3;
  std::vector<NewtonBody> bodies = {IslandBody(3.0, start, h)};
  NewtonSolver solver;
  NewtonResult result;
  ASSERT_TRUE(solver.Solve(bodies, {}, h, {}, &result));
  EXPECT_LE((result.velocity[0] - bodies[0].free_velocity).norm(), 1e-14);
}

// ---- the factorization kept from solve to solve (newton_solver.h) ---------------------------

// a stack of three boxes of 1, 3 and 10 kg on the ground, 10 ms steps; `push` along x on the top
// box's start gives the next step a correction to make (1e-5 m/s: every friction row stays
// inside its bound from the start, λ = push / cfm = 10 N < μ N, so the rows inside their bounds
// are those of the kept factorization; a larger push saturates them at the start, and the
// solver factors the Hessian of the rows then inside, as for any island)
struct KeptStack {
  static constexpr double kStep = 0.01;
  std::vector<NewtonBody> bodies;
  std::vector<NewtonRow> rows;

  KeptStack() {
    const double masses[3] = {1.0, 3.0, 10.0};
    for (int k = 0; k < 3; ++k) {
      bodies.push_back(IslandBody(masses[k], Vec6::Zero(), kStep));
      AddFace(&rows, k, k - 1, 0.5);
    }
  }
  // the next step's island: the answer as the start, the top box pushed, every Jacobian entry
  // moved by `shift` and every mass and inertia scaled by `scale`
  void Next(const NewtonResult& answer, double push, double shift, double scale = 1.0) {
    for (size_t k = 0; k < bodies.size(); ++k) {
      NewtonBody& body = bodies[k];
      body.mass *= scale;
      body.inertia *= scale;
      body.start = answer.velocity[k];
      body.free_velocity = body.start;
      body.free_velocity(2) -= test::kIslandGravity * kStep;
    }
    bodies.back().start(0) += push;
    bodies.back().free_velocity(0) += push;
    for (NewtonRow& row : rows) {
      row.ja.array() += shift;
      row.jb.array() -= shift;
    }
  }
};

NewtonOptions KeyedOptions(unsigned long long island) {
  NewtonOptions options;
  options.island = island;
  return options;
}

// The same island a step later, its rows moved within the tolerance: no factorization, and the
// answer of a solver that factors (velocities to 1e-12 m/s; the forces then agree to
// cfm⁻¹ · 1e-12 = 1e-3 N on each hard row, so the four normal rows under the bottom box, about
// 34 N each, to 4e-3 N in sum: checked at 1e-2 N)
TEST(NewtonSolverTest, AKeptFactorizationServesTheSameIslandAStepLaterWithTheSameAnswer) {
  KeptStack stack;
  NewtonSolver kept, fresh;
  NewtonResult first, again, check;
  ASSERT_TRUE(kept.Solve(stack.bodies, stack.rows, KeptStack::kStep, KeyedOptions(7), &first));
  EXPECT_GE(first.factorizations, 1);
  stack.Next(first, 1e-5, 3e-11);
  ASSERT_TRUE(kept.Solve(stack.bodies, stack.rows, KeptStack::kStep, KeyedOptions(7), &again));
  ASSERT_TRUE(fresh.Solve(stack.bodies, stack.rows, KeptStack::kStep, {}, &check));
  EXPECT_EQ(again.factorizations, 0);
  EXPECT_GE(check.factorizations, 1);
  EXPECT_GE(again.iterations, 1);  // the push is corrected by chord steps
  for (size_t k = 0; k < stack.bodies.size(); ++k) {
    EXPECT_LE((again.velocity[k] - check.velocity[k]).cwiseAbs().maxCoeff(), 1e-12) << k;
  }
  EXPECT_NEAR(NormalSum(stack.rows, again, 0, -1), NormalSum(stack.rows, check, 0, -1), 1e-2);
  // friction held the push, to its rows' give (cfm 1e-6 (m/s)/N times at most 10 N)
  EXPECT_NEAR(again.velocity[2](0), 0.0, 1e-5);
}

// Anything else factors: another island's key, no key, rows or masses moved beyond the
// tolerance, a changed CFM, another step (a solve after one that did not converge: below)
TEST(NewtonSolverTest, AFactorizationIsKeptOnlyForTheSameIslandWithinTheTolerance) {
  auto factorizations_after = [](auto change, unsigned long long key = 7,
                                 double step = KeptStack::kStep) {
    KeptStack stack;
    NewtonSolver solver;
    NewtonResult first, second;
    EXPECT_TRUE(solver.Solve(stack.bodies, stack.rows, KeptStack::kStep, KeyedOptions(7), &first));
    NewtonOptions options = KeyedOptions(key);
    change(&stack, &solver, &first, &options);
    EXPECT_TRUE(solver.Solve(stack.bodies, stack.rows, step, options, &second));
    return second.factorizations;
  };
  auto nothing = [](KeptStack* stack, NewtonSolver*, NewtonResult* first, NewtonOptions*) {
    stack->Next(*first, 0.0, 0.0);
  };
  EXPECT_EQ(factorizations_after(nothing), 0);  // (the control)
  EXPECT_GE(factorizations_after(nothing, 8), 1);
  EXPECT_GE(factorizations_after(nothing, 0), 1);
  EXPECT_GE(factorizations_after([](KeptStack* stack, NewtonSolver*, NewtonResult* first,
                                    NewtonOptions*) { stack->Next(*first, 0.0, 3e-10); }),
            1);
  EXPECT_GE(factorizations_after([](KeptStack* stack, NewtonSolver*, NewtonResult* first,
                                    NewtonOptions*) { stack->Next(*first, 0.0, 0.0, 1.0 + 1e-9); }),
            1);
  EXPECT_GE(factorizations_after(
                [](KeptStack* stack, NewtonSolver*, NewtonResult* first, NewtonOptions*) {
                  stack->Next(*first, 0.0, 0.0);
                  stack->rows[0].cfm *= 2.0;
                }),
            1);
  EXPECT_GE(factorizations_after([](KeptStack* stack, NewtonSolver*, NewtonResult* first,
                                    NewtonOptions*) { stack->Next(*first, 0.0, 0.0); },
                                 7, 0.5 * KeptStack::kStep),
            1);
}

// A solve that did not converge (a push that saturates the friction rows, two Newton steps)
// after one that kept its factorization: the island keeps nothing, and the next step, which the
// kept matrix would have served (as the control of the test above shows), factors and takes the
// Newton steps of a solver that keeps nothing, to the same answer (a kept slot whose description
// were not that of its factorization would take a chord step of a wrong matrix first)
TEST(NewtonSolverTest, AfterASolveThatDidNotConvergeTheIslandKeepsNothing) {
  KeptStack stack;
  NewtonSolver solver, fresh;
  NewtonResult first, unconverged, again, check;
  ASSERT_TRUE(solver.Solve(stack.bodies, stack.rows, KeptStack::kStep, KeyedOptions(7), &first));
  KeptStack pushed = stack;
  pushed.Next(first, 0.02, 0.0);
  NewtonOptions two = KeyedOptions(7);
  two.max_iterations = 2;
  EXPECT_FALSE(solver.Solve(pushed.bodies, pushed.rows, KeptStack::kStep, two, &unconverged));
  stack.Next(first, 1e-5, 0.0);
  ASSERT_TRUE(solver.Solve(stack.bodies, stack.rows, KeptStack::kStep, KeyedOptions(7), &again));
  ASSERT_TRUE(fresh.Solve(stack.bodies, stack.rows, KeptStack::kStep, {}, &check));
  EXPECT_EQ(again.factorizations, 1);
  EXPECT_EQ(again.iterations, check.iterations);
  for (size_t k = 0; k < stack.bodies.size(); ++k) {
    EXPECT_LE((again.velocity[k] - check.velocity[k]).cwiseAbs().maxCoeff(), 1e-12) << k;
  }
}

// Under a budget of one Newton step nothing is kept (a chord step needs a second to find it is
// done): every solve factors and converges
TEST(NewtonSolverTest, ASolveOfOneNewtonStepKeepsNoFactorization) {
  KeptStack stack;
  NewtonSolver solver;
  NewtonOptions options = KeyedOptions(7);
  options.max_iterations = 1;
  NewtonResult result;
  for (int step = 0; step < 4; ++step) {
    ASSERT_TRUE(solver.Solve(stack.bodies, stack.rows, KeptStack::kStep, options, &result)) << step;
    EXPECT_EQ(result.factorizations, 1) << step;
    stack.Next(result, 1e-5, 0.0);
  }
}

// Two islands solved in turn by one solver (as ObjectIslands does) each keep their own
TEST(NewtonSolverTest, IslandsSolvedInTurnEachKeepTheirOwnFactorization) {
  KeptStack first, second;
  second.bodies.pop_back();
  second.rows.resize(second.rows.size() - 12);
  NewtonSolver solver;
  NewtonResult a, b;
  for (int step = 0; step < 3; ++step) {
    ASSERT_TRUE(solver.Solve(first.bodies, first.rows, KeptStack::kStep, KeyedOptions(7), &a));
    ASSERT_TRUE(solver.Solve(second.bodies, second.rows, KeptStack::kStep, KeyedOptions(8), &b));
    EXPECT_EQ(a.factorizations, step == 0 ? 1 : 0) << step;
    EXPECT_EQ(b.factorizations, step == 0 ? 1 : 0) << step;
    // (1e-6 m/s: the two-box stack's top box is 3 kg, and its friction bounds are 1.8 N a
    // contact)
    first.Next(a, 1e-6, 0.0);
    second.Next(b, 1e-6, 0.0);
  }
}

// One island more than kMostKeptIslands: the one solved longest ago makes room, and the others
// keep theirs (each island here is the same resting stack under its own key, which its kept
// factorization serves unchanged)
TEST(NewtonSolverTest, TheIslandSolvedLongestAgoMakesRoomForAnother) {
  const KeptStack stack;
  NewtonSolver solver;
  auto factorizations = [&](unsigned long long key) {
    NewtonResult result;
    EXPECT_TRUE(
        solver.Solve(stack.bodies, stack.rows, KeptStack::kStep, KeyedOptions(key), &result));
    return result.factorizations;
  };
  const unsigned long long last = kMostKeptIslands + 1;
  for (unsigned long long key = 1; key <= last; ++key) EXPECT_EQ(factorizations(key), 1) << key;
  EXPECT_EQ(factorizations(last), 0);  // the newest keeps its own
  EXPECT_EQ(factorizations(2), 0);     // the second oldest too
  EXPECT_EQ(factorizations(1), 1);     // the oldest made room for the last
}

// With a kept matrix far off the Hessian (the ground contacts' CFM four times what it was,
// allowed by a loose tolerance) a chord step shrinks the next to about a third: the Hessian is
// factored again, and the answer is the factoring solver's. 0.1 % off, the chord steps shrink
// fast and need no factorization.
TEST(NewtonSolverTest, ChordStepsThatDoNotShrinkEnoughFactorTheHessianAgain) {
  for (double scale : {4.0, 1.001}) {
    KeptStack stack;
    NewtonSolver kept, fresh;
    NewtonOptions options = KeyedOptions(7);
    options.kept_tolerance = 10.0;
    NewtonResult first, again, check;
    ASSERT_TRUE(kept.Solve(stack.bodies, stack.rows, KeptStack::kStep, options, &first));
    stack.Next(first, 1e-5, 0.0);
    for (NewtonRow& row : stack.rows) row.cfm *= row.b < 0 ? scale : 1.0;
    ASSERT_TRUE(kept.Solve(stack.bodies, stack.rows, KeptStack::kStep, options, &again));
    ASSERT_TRUE(fresh.Solve(stack.bodies, stack.rows, KeptStack::kStep, {}, &check));
    EXPECT_EQ(again.factorizations, scale > 2.0 ? 1 : 0) << scale;
    for (size_t k = 0; k < stack.bodies.size(); ++k) {
      EXPECT_LE((again.velocity[k] - check.velocity[k]).cwiseAbs().maxCoeff(), 1e-12) << scale;
    }
  }
}

}  // namespace
}  // namespace lamina::core
