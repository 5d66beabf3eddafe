// SPDX-License-Identifier: MIT
// Parabolic ramps: 1-D minimum times against closed forms (triangular, trapezoidal, nonzero
// boundary velocities, overshoot, infinite bounds), fixed-duration minimum acceleration, gaps
// in the feasible durations, position limits, and seeded random property tests of the 1-D,
// synchronized N-D and straight-line ramps (end points, bounds sampled densely, continuity,
// optimality against the fixed-duration solver).
#include "core/control/parabolic_ramp.h"

#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

namespace lamina::core {
namespace {

constexpr double kRelative = 1e-9;  // tolerance of closed-form times and end points

// Samples `ramp` densely and checks the end points, |v| <= V, |a| <= A (from velocity
// differences, which also proves the velocity continuous), position continuity and bounds.
void ExpectValidRamp(const Ramp1D& ramp, const RampEnds& e, const RampBounds& b,
                     bool check_end_velocities = true) {
  const double T = ramp.duration;
  EXPECT_NEAR(ramp.Position(0), e.x0, kRelative * (1 + std::abs(e.x0)));
  EXPECT_NEAR(ramp.Position(T), e.x1, kRelative * (1 + std::abs(e.x1)));
  if (check_end_velocities && T > 0) {
    EXPECT_NEAR(ramp.Velocity(0), e.v0, kRelative * (1 + std::abs(e.v0)));
    EXPECT_NEAR(ramp.Velocity(T), e.v1, kRelative * (1 + std::abs(e.v1)));
  }
  constexpr int kSamples = 2000;
  const double h = T / kSamples;
  double x_previous = ramp.Position(0);
  double v_previous = ramp.Velocity(0);
  for (int k = 1; k <= kSamples; ++k) {
    const double t = k * h;
    const double x = ramp.Position(t);
    const double v = ramp.Velocity(t);
    ASSERT_LE(std::abs(v), b.velocity_max * (1 + kRelative)) << "t " << t;
    ASSERT_LE(std::abs(ramp.Acceleration(t)), b.acceleration_max * (1 + kRelative));
    ASSERT_LE(std::abs(v - v_previous), b.acceleration_max * h * (1 + kRelative) + 1e-12)
        << "velocity jump or |a| > A at t " << t;
    ASSERT_LE(std::abs(x - x_previous), b.velocity_max * h * (1 + kRelative) + 1e-12)
        << "position jump or |v| > V at t " << t;
    ASSERT_GE(x, b.position_min - 1e-9);
    ASSERT_LE(x, b.position_max + 1e-9);
    x_previous = x;
    v_previous = v;
  }
}

// [section] 1-D closed forms

TEST(ParabolicRampTest, RestToRestTriangularMatchesTwoRootDOverA) {
  const double d = 0.5, A = 2, V = 10;  // sqrt(dA) = 1 <= V: no cruise
  const auto ramp = MinTimeRamp({0, 0, d, 0}, {A, V});
  ASSERT_TRUE(ramp);
  const double expected = 2 * std::sqrt(d / A);  // = 1 s
  EXPECT_NEAR(ramp->duration, expected, 1e-9 * expected);
  EXPECT_NEAR(ramp->Velocity(expected / 2), std::sqrt(d * A), 1e-12);  // peak at half time
  EXPECT_DOUBLE_EQ(ramp->t1, ramp->t2);
  ExpectValidRamp(*ramp, {0, 0, d, 0}, {A, V});
}

TEST(ParabolicRampTest, RestToRestTrapezoidalMatchesDOverVPlusVOverA) {
  const double d = 10, A = 2, V = 1;  // sqrt(dA) = 4.47 > V: cruise at V
  const auto ramp = MinTimeRamp({0, 0, d, 0}, {A, V});
  ASSERT_TRUE(ramp);
  const double expected = d / V + V / A;  // 10.5 s
  EXPECT_NEAR(ramp->duration, expected, 1e-9 * expected);
  EXPECT_NEAR(ramp->t1, V / A, 1e-12);
  EXPECT_NEAR(ramp->t2, expected - V / A, 1e-9);
  EXPECT_DOUBLE_EQ(ramp->cruise_velocity, V);
  ExpectValidRamp(*ramp, {0, 0, d, 0}, {A, V});
}

TEST(ParabolicRampTest, NegativeDirectionMirrorsPositive) {
  const auto ramp = MinTimeRamp({1, 0, 0.5, 0}, {2, 10});
  ASSERT_TRUE(ramp);
  EXPECT_NEAR(ramp->duration, 1.0, 1e-12);        // 2 sqrt(0.5 / 2)
  EXPECT_NEAR(ramp->Velocity(0.5), -1.0, 1e-12);  // -sqrt(dA)
  EXPECT_DOUBLE_EQ(ramp->a1, -2.0);
}

TEST(ParabolicRampTest, NonzeroBoundaryVelocitiesBangBang) {
  // (0, 1) -> (3, 2), A = 1: vp^2 = A D + (v0^2 + v1^2)/2 = 5.5, T = 2 vp - v0 - v1
  const RampEnds e{0, 1, 3, 2};
  const auto ramp = MinTimeRamp(e, {1, kInf});
  ASSERT_TRUE(ramp);
  const double vp = std::sqrt(5.5);
  EXPECT_NEAR(ramp->duration, 2 * vp - 3, 1e-12);
  EXPECT_NEAR(ramp->cruise_velocity, vp, 1e-12);
  EXPECT_NEAR(ramp->t1, vp - 1, 1e-12);
  ExpectValidRamp(*ramp, e, {1, kInf});
}

TEST(ParabolicRampTest, NonzeroBoundaryVelocitiesWithCruise) {
  // V = 2.2 < vp: t1 = 1.2, t3 = 0.2, d1 = 1.92, d3 = 0.42, cruise (3 - 2.34)/2.2 = 0.3 s
  const RampEnds e{0, 1, 3, 2};
  const auto ramp = MinTimeRamp(e, {1, 2.2});
  ASSERT_TRUE(ramp);
  EXPECT_NEAR(ramp->duration, 1.7, 1e-12);
  EXPECT_NEAR(ramp->t1, 1.2, 1e-12);
  EXPECT_NEAR(ramp->t2, 1.5, 1e-12);
  ExpectValidRamp(*ramp, e, {1, 2.2});
}

TEST(ParabolicRampTest, TooFastTowardTargetOvershootsAndReturns) {
  // v0 = 2 toward x1 = 0.5, A = 1: braking takes 2 s and 2 m, then rest-to-rest back 1.5 m
  const RampEnds e{0, 2, 0.5, 0};
  const auto ramp = MinTimeRamp(e, {1, kInf});
  ASSERT_TRUE(ramp);
  EXPECT_NEAR(ramp->duration, 2 + 2 * std::sqrt(1.5), 1e-12);
  EXPECT_NEAR(ramp->MaxPosition(), 2.0, 1e-12);
  ExpectValidRamp(*ramp, e, {1, kInf});
}

TEST(ParabolicRampTest, InfiniteBounds) {
  // A = inf, V = inf: a jump
  const auto jump = MinTimeRamp({0, 0, 3, 0}, {kInf, kInf});
  ASSERT_TRUE(jump);
  EXPECT_EQ(jump->duration, 0);
  EXPECT_EQ(jump->Position(0), 3);
  // A = inf, V = 2: a straight line at -V, boundary velocities replaced by -V
  const auto line = MinTimeRamp({1, 0.5, -3, 0}, {kInf, 2});
  ASSERT_TRUE(line);
  EXPECT_NEAR(line->duration, 2.0, 1e-15);
  EXPECT_EQ(line->Velocity(0.7), -2);
  EXPECT_EQ(line->v0, -2);
  EXPECT_EQ(line->v1, -2);
  EXPECT_NEAR(line->Position(0.5), 0.0, 1e-15);
  // A finite, V = inf: the triangular profile
  const auto triangle = MinTimeRamp({0, 0, 8, 0}, {2, kInf});
  ASSERT_TRUE(triangle);
  EXPECT_NEAR(triangle->duration, 4.0, 1e-12);
  // nothing to do: zero duration
  const auto still = MinTimeRamp({1, 0, 1, 0}, {1, 1});
  ASSERT_TRUE(still);
  EXPECT_EQ(still->duration, 0);
  EXPECT_EQ(still->Position(0), 1);
}

TEST(ParabolicRampTest, BoundaryFasterThanSpeedLimitIsRejected) {
  EXPECT_FALSE(MinTimeRamp({0, 2, 1, 0}, {1, 1}));
  EXPECT_FALSE(MinAccelerationRamp({0, 0, 1, -3}, {1, 1}, 5));
}

TEST(ParabolicRampTest, ZeroLimitsFreezeTheJoint) {
  EXPECT_FALSE(MinTimeRamp({0, 0, 1, 0}, {0, 1}));
  EXPECT_FALSE(MinTimeRamp({0, 0, 1, 0}, {1, 0}));
  const auto still = MinAccelerationRamp({2, 0, 2, 0}, {0, 0}, 3);
  ASSERT_TRUE(still);
  EXPECT_EQ(still->Position(1.5), 2);
}

// [section] fixed duration and lower bounds

TEST(ParabolicRampTest, MinAccelerationRestToRestIsFourDOverTSquared) {
  const auto ramp = MinAccelerationRamp({0, 0, 1, 0}, {10, 10}, 4);
  ASSERT_TRUE(ramp);
  EXPECT_EQ(ramp->duration, 4);
  EXPECT_NEAR(ramp->a1, 4 * 1.0 / 16, 1e-15);
  EXPECT_NEAR(ramp->t1, 2, 1e-15);
  ExpectValidRamp(*ramp, {0, 0, 1, 0}, {10, 10});
}

TEST(ParabolicRampTest, MinAccelerationWithActiveSpeedLimitCruises) {
  // D = 3 in T = 4 with V = 1: cruise at 1, a = 2 V^2 / (2 (V T - D)) = 1
  const auto ramp = MinAccelerationRamp({0, 0, 3, 0}, {10, 1}, 4);
  ASSERT_TRUE(ramp);
  EXPECT_NEAR(ramp->a1, 1.0, 1e-15);
  EXPECT_NEAR(ramp->t2 - ramp->t1, 2.0, 1e-14);
  ExpectValidRamp(*ramp, {0, 0, 3, 0}, {10, 1});
  EXPECT_FALSE(MinAccelerationRamp({0, 0, 3, 0}, {0.9, 1}, 4));   // needs a = 1
  EXPECT_FALSE(MinAccelerationRamp({0, 0, 3, 0}, {10, 0.7}, 4));  // needs V >= 0.75
}

TEST(ParabolicRampTest, FeasibleDurationsCanHaveAGap) {
  // (0, 1) -> (0.1, 1), A = V = 1: bang-bang |a| = (4T - 0.4)/T^2 <= 1 only for
  // T <= 2 - sqrt(3.6) or T >= 2 + sqrt(3.6) (backing up through negative speeds)
  const RampEnds e{0, 1, 0.1, 1};
  const RampBounds b{1, 1};
  const auto fastest = MinTimeRamp(e, b);
  ASSERT_TRUE(fastest);
  EXPECT_NEAR(fastest->duration, 0.1, 1e-12);  // cruise at V
  EXPECT_TRUE(MinAccelerationRamp(e, b, 0.102));
  EXPECT_FALSE(MinAccelerationRamp(e, b, 1.0));
  const auto later = MinTimeRampAtLeast(e, b, 0.5);
  ASSERT_TRUE(later);
  EXPECT_NEAR(later->duration, 2 + std::sqrt(3.6), 1e-9);
  ExpectValidRamp(*later, e, b);
  const auto at_least = MinTimeRampAtLeast(e, b, 0.101);
  ASSERT_TRUE(at_least);
  EXPECT_DOUBLE_EQ(at_least->duration, 0.101);
}

// [section] position limits

TEST(ParabolicRampTest, RestToRestNeverOvershoots) {
  const RampBounds b{3, 2, -1, 1};
  for (double T : {0.0, 2.0, 5.0, 50.0}) {
    const auto ramp = MinTimeRampAtLeast({-1, 0, 1, 0}, b, T);
    ASSERT_TRUE(ramp);
    EXPECT_GE(ramp->MinPosition(), -1.0);
    EXPECT_LE(ramp->MaxPosition(), 1.0);
  }
}

TEST(ParabolicRampTest, UnavoidableOvershootIsReported) {
  // braking from v0 = 2 at A = 1 needs 2 m: reaching x = 2 > q_max = 1 cannot be avoided
  EXPECT_FALSE(MinTimeRamp({0, 2, 0.5, 0}, {1, kInf, -1, 1}));
  const auto ramp = MinTimeRamp({0, 2, 0.5, 0}, {1, kInf, -1, 2.5});
  ASSERT_TRUE(ramp);
  EXPECT_NEAR(ramp->duration, 2 + 2 * std::sqrt(1.5), 1e-12);  // limits not active
}

TEST(ParabolicRampTest, LongDurationWithinLimitsBrakesHard) {
  // moving away from the target at v0 = -1: the gentle minimum-acceleration profile for 10 s
  // would back up to x = -2.04; within q_min = -0.6 it must brake at A (to x = -0.5)
  const RampEnds e{0, -1, 0.1, 0};
  const auto gentle = MinAccelerationRamp(e, {1, 2}, 10);
  ASSERT_TRUE(gentle);
  EXPECT_LT(gentle->MinPosition(), -2.0);
  const RampBounds bounded{1, 2, -0.6, 1};
  const auto hard = MinAccelerationRamp(e, bounded, 10);
  ASSERT_TRUE(hard);
  EXPECT_NEAR(hard->MinPosition(), -0.5, 1e-12);
  EXPECT_EQ(hard->duration, 10);
  ExpectValidRamp(*hard, e, bounded);
}

// [section] random property tests

struct RandomInstance {
  RampEnds ends;
  RampBounds bounds;
};

RandomInstance RandomRamp(std::mt19937& rng) {
  std::uniform_real_distribution<double> position(-2, 2), unit(0, 1);
  RandomInstance r;
  r.bounds.acceleration_max = 0.2 + 5 * unit(rng);
  r.bounds.velocity_max = unit(rng) < 0.2 ? kInf : 0.2 + 3 * unit(rng);
  const double speed = std::isinf(r.bounds.velocity_max) ? 3.0 : r.bounds.velocity_max;
  const auto velocity = [&] {
    const double u = unit(rng);
    return u < 0.25  ? 0.0
           : u < 0.3 ? speed * (unit(rng) < 0.5 ? -1 : 1)
                     : speed * (2 * unit(rng) - 1);
  };
  r.ends = {position(rng), velocity(), position(rng), velocity()};
  return r;
}

TEST(ParabolicRampPropertyTest, MinTimeRampsAreValidAndNotBeatenByFixedDurationSolver) {
  std::mt19937 rng(20240611);
  int checked = 0;
  for (int n = 0; n < 3000; ++n) {
    const RandomInstance r = RandomRamp(rng);
    const auto ramp = MinTimeRamp(r.ends, r.bounds);
    ASSERT_TRUE(ramp) << "instance " << n;
    ExpectValidRamp(*ramp, r.ends, r.bounds);
    if (HasFatalFailure()) return;
    // optimality: no ramp of any profile family lasts 1e-6 less
    if (ramp->duration > 1e-6) {
      EXPECT_FALSE(MinAccelerationRamp(r.ends, r.bounds, ramp->duration * (1 - 1e-6)))
          << "instance " << n << " T " << ramp->duration;
    }
    ++checked;
  }
  EXPECT_EQ(checked, 3000);
}

TEST(ParabolicRampPropertyTest, FixedDurationRampsLastExactlyTAndStayBounded) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> stretch(1, 4);
  int solved = 0;
  for (int n = 0; n < 3000; ++n) {
    const RandomInstance r = RandomRamp(rng);
    const auto fastest = MinTimeRamp(r.ends, r.bounds);
    ASSERT_TRUE(fastest);
    const double T = fastest->duration * stretch(rng);
    const auto at_least = MinTimeRampAtLeast(r.ends, r.bounds, T);
    ASSERT_TRUE(at_least) << "instance " << n;
    EXPECT_GE(at_least->duration, T);
    ExpectValidRamp(*at_least, r.ends, r.bounds);
    if (HasFatalFailure()) return;
    if (auto fixed = MinAccelerationRamp(r.ends, r.bounds, T)) {
      EXPECT_EQ(fixed->duration, T);
      EXPECT_DOUBLE_EQ(at_least->duration, T);  // T itself feasible: nothing longer chosen
      ExpectValidRamp(*fixed, r.ends, r.bounds);
      ++solved;
    }
  }
  EXPECT_GT(solved, 2000);  // most stretched durations are feasible (the rest fall in gaps)
}

TEST(ParabolicRampPropertyTest, BoundedRampsStayWithinPositionLimits) {
  // With fast boundary velocities a longer ramp may not exist within the limits (slowing down
  // needs more room than there is), so only rest-to-rest instances must always be solved.
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> unit(0, 1);
  int solved = 0;
  for (int n = 0; n < 3000; ++n) {
    RandomInstance r = RandomRamp(rng);
    const bool rest_to_rest = n % 3 == 0;
    if (rest_to_rest) r.ends.v0 = r.ends.v1 = 0;
    r.bounds.position_min = std::min(r.ends.x0, r.ends.x1) - 1.5 * unit(rng);
    r.bounds.position_max = std::max(r.ends.x0, r.ends.x1) + 1.5 * unit(rng);
    const double stretch = 1 + 3 * unit(rng);
    const auto fastest = MinTimeRamp(r.ends, r.bounds);
    ASSERT_TRUE(fastest || !rest_to_rest) << "instance " << n;
    if (!fastest) continue;  // an overshoot beyond the limits is unavoidable
    ExpectValidRamp(*fastest, r.ends, r.bounds);
    const auto longer = MinTimeRampAtLeast(r.ends, r.bounds, fastest->duration * stretch);
    ASSERT_TRUE(longer || !rest_to_rest) << "instance " << n;
    if (!longer) continue;
    EXPECT_GE(longer->duration, fastest->duration * stretch);
    ExpectValidRamp(*longer, r.ends, r.bounds);
    if (HasFatalFailure()) return;
    ++solved;
  }
  EXPECT_GT(solved, 2000);
}

// [section] N-D

struct RandomND {
  VecX x0, v0, x1, v1;
  JointLimits limits;
};

RandomND RandomRampND(std::mt19937& rng, bool position_limits) {
  std::uniform_int_distribution<int> dofs(1, 6);
  const int dof = dofs(rng);
  RandomND r;
  r.x0.resize(dof);
  r.v0.resize(dof);
  r.x1.resize(dof);
  r.v1.resize(dof);
  r.limits = JointLimits::Unbounded(dof);
  for (int i = 0; i < dof; ++i) {
    const RandomInstance one = RandomRamp(rng);
    r.x0[i] = one.ends.x0;
    r.v0[i] = one.ends.v0;
    r.x1[i] = one.ends.x1;
    r.v1[i] = one.ends.v1;
    r.limits.acceleration_max[i] = one.bounds.acceleration_max;
    r.limits.velocity_max[i] = one.bounds.velocity_max;
    if (position_limits) {
      // room to brake from any speed and to run up to any end speed (v^2/(2A) <= 22.5)
      r.limits.q_min[i] = -30;
      r.limits.q_max[i] = 30;
    }
  }
  return r;
}

RampBounds Bounds(const JointLimits& limits, int i) {
  return {limits.acceleration_max[i], limits.velocity_max[i], limits.q_min[i], limits.q_max[i]};
}

TEST(ParabolicRampPropertyTest, SynchronizedRampsShareTheLongestMinimumTime) {
  std::mt19937 rng(12345);
  for (int n = 0; n < 2000; ++n) {
    const RandomND r = RandomRampND(rng, n % 2 == 1);
    std::string error;
    const auto ramp = MinTimeRampND(r.x0, r.v0, r.x1, r.v1, r.limits, &error);
    ASSERT_TRUE(ramp) << "instance " << n << ": " << error;
    const double T = ramp->Duration();
    double slowest = 0;
    for (int i = 0; i < ramp->dof(); ++i) {
      const RampEnds e{r.x0[i], r.v0[i], r.x1[i], r.v1[i]};
      const RampBounds b = Bounds(r.limits, i);
      const auto own = MinTimeRamp(e, b);
      ASSERT_TRUE(own);
      slowest = std::max(slowest, own->duration);
      EXPECT_EQ(ramp->ramps()[i].duration, T) << "DOF " << i << " ends at a different time";
      ExpectValidRamp(ramp->ramps()[i], e, b);
      if (HasFatalFailure()) return;
    }
    EXPECT_GE(T, slowest);
    EXPECT_LE(T, slowest * 1e3 + 1);  // raised only as far as some DOF needs
    EXPECT_TRUE(ramp->Evaluate(T).isApprox(r.x1, 1e-9) || (ramp->Evaluate(T) - r.x1).norm() < 1e-9);
  }
}

TEST(ParabolicRampNDTest, SlowestJointSetsTheDurationOthersUseLessAcceleration) {
  JointLimits limits = JointLimits::Unbounded(2, 1, 1);
  const VecX zero = VecX::Zero(2);
  const auto ramp = MinTimeRampND(zero, zero, (VecX(2) << 4, 1).finished(), zero, limits, nullptr);
  ASSERT_TRUE(ramp);
  EXPECT_NEAR(ramp->Duration(), 5.0, 1e-12);  // 4/V + V/A
  EXPECT_EQ(std::abs(ramp->ramps()[0].a1), 1);
  EXPECT_LT(std::abs(ramp->ramps()[1].a1), 1);
  EXPECT_TRUE(ramp->Evaluate(5.0).isApprox((VecX(2) << 4, 1).finished(), 1e-12));
  EXPECT_EQ(ramp->Derivative(5.0), zero);
}

TEST(ParabolicRampNDTest, RejectsBadInputWithAMessage) {
  const JointLimits limits = JointLimits::Unbounded(2, 1, 1);
  std::string error;
  EXPECT_FALSE(
      MinTimeRampND(VecX::Zero(2), VecX::Zero(3), VecX::Zero(2), VecX::Zero(2), limits, &error));
  EXPECT_EQ(error, "start velocity has 3 entries, expected 2");
  VecX nan = VecX::Zero(2);
  nan[1] = std::nan("");
  EXPECT_FALSE(MinTimeRampND(VecX::Zero(2), VecX::Zero(2), nan, VecX::Zero(2), limits, &error));
  EXPECT_EQ(error, "target position has a NaN or infinite entry");
  JointLimits frozen = limits;
  frozen.velocity_max[1] = 0;
  EXPECT_FALSE(LinearRampND(VecX::Zero(2), VecX::Ones(2), frozen, &error));
  EXPECT_FALSE(error.empty());
}

TEST(ParabolicRampNDTest, LinearRampStaysOnTheSegment) {
  JointLimits limits = JointLimits::Unbounded(3, 1, 2);
  limits.velocity_max[2] = 0.5;
  const VecX a = (VecX(3) << 0, 1, 2).finished();
  const VecX b = (VecX(3) << 2, 1, 1).finished();
  const auto ramp = LinearRampND(a, b, limits, nullptr);
  ASSERT_TRUE(ramp);
  // s in [0, 1]: V_s = min(1/2, 0.5/1) = 0.5, A_s = min(2/2, 2/1) = 1: sqrt(A_s) > V_s so
  // trapezoidal, T = 1/V_s + V_s/A_s = 2.5
  EXPECT_NEAR(ramp->Duration(), 2.5, 1e-12);
  for (double t = 0; t <= 2.5; t += 0.01) {
    const VecX q = ramp->Evaluate(t);
    const double s = (q[0] - a[0]) / (b[0] - a[0]);
    EXPECT_NEAR((a + s * (b - a) - q).norm(), 0, 1e-12);
    EXPECT_LE(std::abs(ramp->Derivative(t)[2]), 0.5 + 1e-12);
  }
  EXPECT_TRUE(ramp->Evaluate(2.5).isApprox(b, 1e-12));
}

TEST(ParabolicRampNDTest, PlanJointRampAppliesThePreClamps) {
  JointLimits limits = JointLimits::Unbounded(1, 1, 1);
  limits.q_min[0] = -1;
  limits.q_max[0] = 1;
  const VecX start = VecX::Constant(1, 1.5);  // outside: the bounds widen to include it
  const auto ramp = PlanJointRamp(start, VecX::Constant(1, 3), VecX::Constant(1, 5),
                                  VecX::Constant(1, 2), limits, nullptr);
  ASSERT_TRUE(ramp);
  const Ramp1D& r = ramp->ramps()[0];
  EXPECT_EQ(r.v0, 1);                  // start speed clamped to V
  EXPECT_NEAR(r.x1, 1 - 2e-7, 1e-15);  // target into [q_min + eps range, q_max - eps range]
  EXPECT_NEAR(r.v1, 1 - 2e-7, 1e-15);  // target speed into +-(1 - 2e-7) V
  // braking from 1.5 at v = 1, A = 1 reaches 2: the bounds widen to [-1, 2]; the run-up to
  // v1 ~ 1 at x1 ~ 1 starts from rest at ~0.5
  EXPECT_NEAR(r.MaxPosition(), 2.0, 1e-12);
  EXPECT_NEAR(r.MinPosition(), 0.5, 1e-6);
}

}  // namespace
}  // namespace lamina::core
