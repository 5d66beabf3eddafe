// SPDX-License-Identifier: MIT
// MotionQueue: ramps replayed in 1 ms steps, Cut mid-motion then a new ramp continuing from the
// current state, linear and cubic segment end points, timed appends, constant velocity,
// remaining time, live limit edits, rejected input with messages, front trimming.
#include "core/control/motion_queue.h"

#include <cmath>

#include <gtest/gtest.h>

#include "core/control/parabolic_ramp.h"
#include "tests/common/test_support.h"

namespace lamina::core {
namespace {

using test::Vec;

JointLimits TwoJointLimits() {
  JointLimits limits = JointLimits::Unbounded(2, 1.0, 2.0);
  limits.q_min = Vec({-3, -3});
  limits.q_max = Vec({3, 3});
  return limits;
}

TEST(MotionQueueTest, AppendRampReplaysTheRampInMillisecondSteps) {
  MotionQueue queue(TwoJointLimits());
  ASSERT_TRUE(queue.SetConstant(Vec({0, 0})));
  const VecX target = Vec({2, -0.5});
  ASSERT_TRUE(queue.AppendRamp(target)) << queue.last_error();
  const auto ramp =
      MinTimeRampND(Vec({0, 0}), Vec({0, 0}), target, Vec({0, 0}), TwoJointLimits(), nullptr);
  ASSERT_TRUE(ramp);
  // joint 0: trapezoid, T = d/V + V/A = 2 + 0.5
  EXPECT_NEAR(ramp->Duration(), 2.5, 1e-12);
  EXPECT_NEAR(queue.end_time(), 2.5, 1e-12);
  VecX q, v;
  for (int step = 1; step <= 3000; ++step) {
    queue.Advance(0.001);
    const double t = step * 0.001;
    queue.Config(&q);
    queue.Velocity(&v);
    ASSERT_LT((q - ramp->Evaluate(t)).norm(), 1e-9) << "t " << t;
    if (t < 2.5 - 1e-9) {
      ASSERT_LT((v - ramp->Derivative(t)).norm(), 1e-9) << "t " << t;
    }
  }
  EXPECT_LT((queue.Config() - target).norm(), 1e-12);
  EXPECT_EQ(queue.Velocity(), Vec({0, 0}));  // past the end: held at rest
  EXPECT_EQ(queue.RemainingTime(), 0);
}

TEST(MotionQueueTest, CutThenRampContinuesFromTheCurrentState) {
  MotionQueue queue(TwoJointLimits());
  queue.SetConstant(Vec({0, 0}));
  ASSERT_TRUE(queue.AppendRamp(Vec({2, 1})));
  for (int i = 0; i < 800; ++i) queue.Advance(0.001);
  const VecX q_cut = queue.Config();
  const VecX v_cut = queue.Velocity();
  ASSERT_GT(v_cut.norm(), 0.1);  // mid-motion
  queue.Cut();
  EXPECT_DOUBLE_EQ(queue.end_time(), queue.time());
  EXPECT_LT((queue.EndConfig() - q_cut).norm(), 1e-12);
  EXPECT_LT((queue.EndVelocity() - v_cut).norm(), 1e-12);
  ASSERT_TRUE(queue.AppendRamp(Vec({-1, 0.5})));
  // continuous position and velocity across the cut
  const double t = queue.time();
  EXPECT_LT((queue.Eval(t + 1e-7) - q_cut).norm(), 1e-6);
  EXPECT_LT((queue.Deriv(t + 1e-7) - v_cut).norm(), 1e-6);
  EXPECT_LT((queue.Eval(queue.end_time()) - Vec({-1, 0.5})).norm(), 1e-9);
  // the new ramp is the one PlanJointRamp computes from the cut state
  const auto ramp =
      PlanJointRamp(q_cut, v_cut, Vec({-1, 0.5}), Vec({0, 0}), TwoJointLimits(), nullptr);
  ASSERT_TRUE(ramp);
  EXPECT_NEAR(queue.RemainingTime(), ramp->Duration(), 1e-12);
  EXPECT_LT((queue.Eval(t + 0.3) - ramp->Evaluate(0.3)).norm(), 1e-9);
}

TEST(MotionQueueTest, LinearAndCubicSegmentsHitTheirEndPoints) {
  MotionQueue queue(TwoJointLimits());
  queue.SetConstant(Vec({1, 1}));
  ASSERT_TRUE(queue.AppendLinear(Vec({2, 3}), 2.0));
  EXPECT_DOUBLE_EQ(queue.end_time(), 2.0);
  EXPECT_LT((queue.Eval(1.0) - Vec({1.5, 2})).norm(), 1e-15);
  EXPECT_LT((queue.Deriv(1.0) - Vec({0.5, 1})).norm(), 1e-15);  // the slope
  ASSERT_TRUE(queue.AppendCubic(Vec({0, 0}), Vec({-1, 2}), 1.0));
  EXPECT_DOUBLE_EQ(queue.end_time(), 3.0);
  EXPECT_LT((queue.EndConfig() - Vec({0, 0})).norm(), 1e-14);
  EXPECT_LT((queue.EndVelocity() - Vec({-1, 2})).norm(), 1e-14);
  // the cubic starts from the linear segment's end state (slope 0.5, 1)
  EXPECT_LT((queue.Deriv(2.0 + 1e-9) - Vec({0.5, 1})).norm(), 1e-7);
  EXPECT_EQ(queue.Eval(10.0), queue.EndConfig());  // held after the end
  EXPECT_EQ(queue.Deriv(10.0), Vec({0, 0}));
  EXPECT_EQ(queue.Eval(-1.0), Vec({1, 1}));  // held before the start
}

TEST(MotionQueueTest, TimedAppendsUseAbsoluteQueueTime) {
  MotionQueue queue(TwoJointLimits());
  queue.SetConstant(Vec({0, 0}));
  queue.Advance(0.5);
  ASSERT_TRUE(queue.AppendTimedLinear(1.5, Vec({1, 2})));  // starts now (the queue ran out)
  EXPECT_DOUBLE_EQ(queue.end_time(), 1.5);
  EXPECT_LT((queue.Eval(1.0) - Vec({0.5, 1})).norm(), 1e-15);
  ASSERT_TRUE(queue.AppendTimedCubic(2.5, Vec({0, 0}), Vec({0, 0})));
  EXPECT_LT((queue.Eval(2.5) - Vec({0, 0})).norm(), 1e-15);
  EXPECT_FALSE(queue.AppendTimedLinear(2.0, Vec({0, 0})));
  EXPECT_EQ(queue.last_error(),
            "AppendTimedLinear: time 2.000000 s is before the queue's end time 2.500000 s");
  EXPECT_DOUBLE_EQ(queue.end_time(), 2.5);                 // unchanged
  ASSERT_TRUE(queue.AppendTimedLinear(2.5, Vec({5, 5})));  // same time: a jump
  EXPECT_EQ(queue.Eval(2.5), Vec({5, 5}));
}

TEST(MotionQueueTest, ConstantVelocityMovesUntilTheGivenTimeThenHolds) {
  MotionQueue queue(TwoJointLimits());
  queue.SetConstant(Vec({1, 0}));
  queue.AppendLinear(Vec({2, 2}), 10);
  queue.Advance(1.0);  // at (1.1, 0.2)
  ASSERT_TRUE(queue.SetConstantVelocity(Vec({0.5, -1}), 3.0));
  EXPECT_DOUBLE_EQ(queue.end_time(), 3.0);
  EXPECT_DOUBLE_EQ(queue.RemainingTime(), 2.0);
  EXPECT_LT((queue.Eval(2.0) - Vec({1.6, -0.8})).norm(), 1e-14);
  EXPECT_LT((queue.Deriv(2.0) - Vec({0.5, -1})).norm(), 1e-15);
  EXPECT_LT((queue.Eval(7.0) - Vec({2.1, -1.8})).norm(), 1e-14);  // held
  EXPECT_EQ(queue.Deriv(7.0), Vec({0, 0}));
  EXPECT_FALSE(queue.SetConstantVelocity(Vec({0, 0}), 0.5));  // before now
}

TEST(MotionQueueTest, SetLimitsAffectsTheNextAppend) {
  MotionQueue queue(JointLimits::Unbounded(1, 10.0, 1.0));
  queue.SetConstant(Vec({0}));
  ASSERT_TRUE(queue.AppendRamp(Vec({1})));
  EXPECT_NEAR(queue.end_time(), 2.0, 1e-12);  // triangular: 2 sqrt(d/A)
  ASSERT_TRUE(queue.SetLimits(JointLimits::Unbounded(1, 10.0, 4.0)));
  const double before = queue.end_time();
  ASSERT_TRUE(queue.AppendRamp(Vec({0})));
  EXPECT_NEAR(queue.end_time() - before, 1.0, 1e-12);  // 2 sqrt(1/4)
  ASSERT_TRUE(queue.SetLimits(JointLimits::Unbounded(1, 1.0, 4.0)));
  ASSERT_TRUE(queue.AppendRamp(Vec({1})));
  EXPECT_NEAR(queue.end_time() - before, 1.0 + 1.25, 1e-12);  // trapezoid d/V + V/A
  EXPECT_FALSE(queue.SetLimits(JointLimits::Unbounded(2, 1.0, 1.0)));
  EXPECT_EQ(queue.last_error(),
            "SetLimits: joint limits have sizes q_min 2, q_max 2, velocity_max 2, "
            "acceleration_max 2; expected 1");
}

TEST(MotionQueueTest, PositionLimitsClampTheTarget) {
  MotionQueue queue(TwoJointLimits());
  queue.SetConstant(Vec({0, 0}));
  ASSERT_TRUE(queue.AppendRamp(Vec({5, -1})));
  EXPECT_NEAR(queue.EndConfig()[0], 3 - 6e-7, 1e-12);  // q_max - 1e-7 * range
  ASSERT_TRUE(queue.AppendLinearRamp(Vec({-4, 0})));
  EXPECT_NEAR(queue.EndConfig()[0], -3 + 6e-7, 1e-12);
}

TEST(MotionQueueTest, BadInputIsRejectedWithAMessageAndChangesNothing) {
  MotionQueue queue(TwoJointLimits());
  EXPECT_FALSE(queue.AppendRamp(Vec({1, 1})));
  EXPECT_EQ(queue.last_error(), "AppendRamp: the queue is empty (call SetConstant first)");
  EXPECT_FALSE(queue.SetConstant(Vec({1, 2, 3})));
  EXPECT_EQ(queue.last_error(), "SetConstant: configuration has 3 entries, expected 2");
  ASSERT_TRUE(queue.SetConstant(Vec({0, 0})));
  EXPECT_TRUE(queue.last_error().empty());
  const std::size_t pieces = queue.piece_count();
  EXPECT_FALSE(queue.AppendLinear(Vec({0, std::nan("")}), 1));
  EXPECT_EQ(queue.last_error(), "AppendLinear: configuration has a NaN or inf entry");
  EXPECT_FALSE(queue.AppendLinear(Vec({0, 0}), -1));
  EXPECT_EQ(queue.last_error(), "AppendLinear: duration -1.000000 must be finite and >= 0");
  EXPECT_FALSE(queue.AppendCubic(Vec({0, 0}), Vec({1}), 1));
  EXPECT_FALSE(queue.AppendRamp(Vec({0, 0}), Vec({0, kInf})));
  EXPECT_FALSE(queue.SetConstantVelocity(Vec({0, 0, 0}), 2));
  EXPECT_EQ(queue.piece_count(), pieces);
  EXPECT_EQ(queue.end_time(), 0);
  queue.Advance(-1);
  EXPECT_EQ(queue.time(), 0);
  EXPECT_FALSE(queue.last_error().empty());
}

TEST(MotionQueueTest, ImpossibleRampFailsAndAppendsNothing) {
  JointLimits limits = TwoJointLimits();
  limits.velocity_max[1] = 0;  // joint 1 frozen
  MotionQueue queue(limits);
  queue.SetConstant(Vec({0, 0}));
  EXPECT_FALSE(queue.AppendRamp(Vec({1, 1})));
  EXPECT_NE(queue.last_error().find("joint 1"), std::string::npos) << queue.last_error();
  EXPECT_EQ(queue.end_time(), 0);
  EXPECT_TRUE(queue.AppendRamp(Vec({1, 0})));  // joint 1 stays: fine
}

TEST(MotionQueueTest, FrontTrimmingKeepsMemoryBoundedAndEvaluationCorrect) {
  MotionQueue queue(JointLimits::Unbounded(1, 2.0, 4.0));
  queue.SetConstant(Vec({0}));
  // every 10 ms tick the target 50 ms ahead, for 100 s of queue time: a controller streaming
  for (int tick = 0; tick < 10000; ++tick) {
    const double t_end = queue.time() + 0.05;
    ASSERT_TRUE(queue.AppendTimedLinear(t_end, Vec({std::sin(t_end)})));
    queue.Advance(0.01);
    ASSERT_LT(queue.piece_count(), 60u) << "tick " << tick;
    // the queued line through sin samples stays within 1e-3 of sin (chord error h^2/8)
    ASSERT_NEAR(queue.Config()[0], std::sin(queue.time()), 2e-3);
  }
  EXPECT_NEAR(queue.time(), 100.0, 1e-9);
  EXPECT_GT(queue.start_time(), 99.0);
}

TEST(MotionQueueTest, RampAfterTheQueueRanOutStartsNowFromRest) {
  MotionQueue queue(JointLimits::Unbounded(1, 1.0, 1.0));
  queue.SetConstant(Vec({0}));
  queue.AppendLinear(Vec({1}), 1.0);  // ends at t = 1 with velocity 1
  queue.Advance(5.0);
  ASSERT_TRUE(queue.AppendRamp(Vec({0})));
  EXPECT_DOUBLE_EQ(queue.Eval(5.0)[0], 1.0);
  EXPECT_NEAR(queue.end_time(), 5.0 + 2.0, 1e-12);  // rest to rest, d = 1, A = 1
}

}  // namespace
}  // namespace lamina::core
