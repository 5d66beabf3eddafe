// SPDX-License-Identifier: MIT
// Trajectories from Klamp't motion files: values at the knots equal the file's, derivatives of
// linear segments equal their slopes, cubic segments meet the given velocities, untimed
// milestones are joined by the synchronized ramps, evaluation is clamped outside the range,
// and a trajectory replays through a MotionQueue. Also PiecewisePolynomial edge cases.
#include "core/control/trajectory.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/control/motion_queue.h"
#include "core/control/parabolic_ramp.h"
#include "core/io/trajectory_file.h"
#include "tests/common/test_support.h"

namespace lamina::core {
namespace {

using test::DataPath;
using test::WorldsPath;

using test::Vec;

void ExpectNear(const VecX& actual, const VecX& expected, double tolerance) {
  ASSERT_EQ(actual.size(), expected.size());
  EXPECT_LE((actual - expected).lpNorm<Eigen::Infinity>(), tolerance)
      << "actual   " << actual.transpose() << "\nexpected " << expected.transpose();
}

TEST(TrajectoryTest, LinearPathHitsTheKnotsWithSlopesBetween) {
  Diagnostics diagnostics;
  const auto path = LoadTrajectory(DataPath("motions/arm.path"), diagnostics);
  ASSERT_TRUE(path) << diagnostics.FormatAll();
  EXPECT_EQ(path->dof(), 3);
  EXPECT_EQ(path->StartTime(), 0);
  EXPECT_EQ(path->EndTime(), 2);
  EXPECT_EQ(path->Duration(), 2);
  ExpectNear(path->Eval(0), Vec({0, 0, 0}), 0);
  // two milestones at t = 0.5: the later one is the value there, the earlier the left limit
  ExpectNear(path->Eval(0.5), Vec({0.1, 0.25, -0.3}), 1e-15);
  ExpectNear(path->Eval(0.5 - 1e-12), Vec({0.1, 0.2, -0.3}), 1e-11);
  ExpectNear(path->Eval(2), Vec({1e-3, -25, 0}), 1e-15);
  ExpectNear(path->Deriv(0.25), Vec({0.2, 0.4, -0.6}), 1e-14);
  ExpectNear(path->Deriv(1.0), Vec({(1e-3 - 0.1) / 1.5, -25.25 / 1.5, 0.2}), 1e-14);
  ExpectNear(path->Eval(1.25), Vec({0.1 + 0.5 * (1e-3 - 0.1), 0.25 - 12.625, -0.15}), 1e-14);
  // clamped outside [0, 2]
  ExpectNear(path->Eval(-3), Vec({0, 0, 0}), 0);
  ExpectNear(path->Eval(7), Vec({1e-3, -25, 0}), 1e-15);
  ExpectNear(path->Deriv(-3), Vec({0, 0, 0}), 0);
  ExpectNear(path->Deriv(7), Vec({0, 0, 0}), 0);
}

TEST(TrajectoryTest, AthleteFlexPathMatchesTheFile) {
  Diagnostics diagnostics;
  const std::string file = WorldsPath("klampt/motions/athlete_flex.path");
  const auto sequence = ReadMotionFile(file, diagnostics);
  const auto path = LoadTrajectory(file, diagnostics);
  ASSERT_TRUE(sequence && path) << diagnostics.FormatAll();
  EXPECT_EQ(path->dof(), 42);
  EXPECT_EQ(path->Duration(), 2);
  for (std::size_t k = 0; k < sequence->times.size(); ++k) {
    ExpectNear(path->Eval(sequence->times[k]), sequence->configs[k], 1e-12);
  }
  ExpectNear(path->Deriv(0.5), sequence->configs[1] - sequence->configs[0], 1e-12);
  ExpectNear(path->Eval(1.5), 0.5 * (sequence->configs[1] + sequence->configs[2]), 1e-12);
}

TEST(TrajectoryTest, TimedMultiPathWithVelocitiesIsCubicHermite) {
  Diagnostics diagnostics;
  const auto path = LoadTrajectory(DataPath("motions/arm_sections.xml"), diagnostics);
  ASSERT_TRUE(path) << diagnostics.FormatAll();
  EXPECT_EQ(path->EndTime(), 3);
  ExpectNear(path->Eval(0), Vec({0, 0, 0}), 0);
  ExpectNear(path->Eval(1), Vec({0.5, 0, 0}), 1e-15);
  ExpectNear(path->Eval(3), Vec({1, 1, 1}), 1e-14);
  ExpectNear(path->Deriv(0), Vec({0, 0, 0}), 0);
  ExpectNear(path->Deriv(1 - 1e-12), Vec({1, 0, 0}), 1e-10);  // the milestone velocity
  ExpectNear(path->Deriv(1), Vec({1, 0, 0}), 1e-14);
  ExpectNear(path->Deriv(3), Vec({0, 0, 0}), 1e-14);
  // first section, joint 0: Hermite (0, 0) -> (0.5, 1) on [0, 1] is x = 0.5 t^2
  EXPECT_NEAR(path->Eval(0.5)[0], 0.125, 1e-15);
  EXPECT_NEAR(path->Deriv(0.5)[0], 0.5, 1e-15);
}

TEST(TrajectoryTest, UntimedMilestonesAreJoinedBySynchronizedRamps) {
  Diagnostics diagnostics;
  const JointLimits limits = JointLimits::Unbounded(3, 5.0, 10.0);
  const auto path = LoadTrajectory(DataPath("motions/arm.milestones"), diagnostics, limits);
  ASSERT_TRUE(path) << diagnostics.FormatAll();
  const VecX q0 = Vec({0, 0, 0}), q1 = Vec({0.1, 0.2, -0.3}), q2 = Vec({1, 1, 1});
  const VecX v0 = Vec({0, 0, 0}), v1 = Vec({1, 2, 3});
  const auto first = MinTimeRampND(q0, v0, q1, v1, limits, nullptr);
  const auto second = MinTimeRampND(q1, v1, q2, v0, limits, nullptr);
  ASSERT_TRUE(first && second);
  const double t1 = first->Duration();
  EXPECT_NEAR(path->Duration(), t1 + second->Duration(), 1e-12);
  ExpectNear(path->Eval(0), q0, 0);
  ExpectNear(path->Eval(t1), q1, 1e-9);
  ExpectNear(path->Deriv(t1), v1, 1e-9);
  ExpectNear(path->Eval(path->EndTime()), q2, 1e-9);
  ExpectNear(path->Eval(0.4 * t1), first->Evaluate(0.4 * t1), 1e-9);
  // every DOF within the limits, sampled
  for (double t = 0; t <= path->EndTime(); t += 1e-3) {
    ASSERT_LE(path->Deriv(t).lpNorm<Eigen::Infinity>(), 5.0 * (1 + 1e-9));
  }
}

TEST(TrajectoryTest, UntimedMilestonesWithoutLimitsUseUnitLimitsAndSaySo) {
  Diagnostics diagnostics;
  const std::string file = DataPath("motions/arm.milestones");
  const auto path = LoadTrajectory(file, diagnostics);
  ASSERT_TRUE(path) << diagnostics.FormatAll();
  EXPECT_THAT(diagnostics.Messages(Severity::kNote),
              testing::ElementsAre(file + ": note: untimed milestones are timed with unit "
                                          "limits (velocity 1 per s, acceleration 1 per s^2)"));
  ExpectNear(path->Eval(path->EndTime()), Vec({1, 1, 1}), 1e-9);
  for (double t = 0; t <= path->EndTime(); t += 1e-3) {
    ASSERT_LE(path->Deriv(t).lpNorm<Eigen::Infinity>(), 1 + 1e-9);
  }
}

TEST(TrajectoryTest, ConfigFileIsAPoint) {
  Diagnostics diagnostics;
  const auto path = LoadTrajectory(DataPath("motions/arm.config"), diagnostics);
  ASSERT_TRUE(path) << diagnostics.FormatAll();
  EXPECT_EQ(path->Duration(), 0);
  ExpectNear(path->Eval(1), Vec({0.1, -0.2, 0.3}), 0);
}

TEST(TrajectoryTest, BadSequencesAreRejectedWithAMessage) {
  std::string error;
  EXPECT_FALSE(Trajectory::FromTimedLinear({0, 1}, {Vec({0}), Vec({0, 1})}, &error));
  EXPECT_EQ(error, "milestone 1 has a different size than milestone 0");
  EXPECT_FALSE(Trajectory::FromTimedLinear({1, 0}, {Vec({0}), Vec({1})}, &error));
  EXPECT_EQ(error, "milestone 1: times must be finite and nondecreasing");
  EXPECT_FALSE(Trajectory::FromTimedLinear({}, {}, &error));
  EXPECT_EQ(error, "no milestones");
  Diagnostics diagnostics;
  EXPECT_FALSE(LoadTrajectory(DataPath("motions/missing.path"), diagnostics));
  EXPECT_TRUE(diagnostics.HasErrors());
}

TEST(TrajectoryTest, AppendToQueueReplaysAfterTheTransition) {
  Diagnostics diagnostics;
  const auto path = LoadTrajectory(DataPath("motions/arm.path"), diagnostics);
  ASSERT_TRUE(path);
  MotionQueue queue(JointLimits::Unbounded(3, 1, 1));
  queue.SetConstant(Vec({1, 1, 1}));
  ASSERT_TRUE(path->AppendTo(queue, 0.1)) << queue.last_error();
  EXPECT_NEAR(queue.end_time(), 2.1, 1e-12);
  ExpectNear(queue.Eval(0.05), Vec({0.5, 0.5, 0.5}), 1e-12);  // the transition line
  for (double t : {0.0, 0.25, 0.5, 1.0, 2.0}) ExpectNear(queue.Eval(0.1 + t), path->Eval(t), 1e-12);
  MotionQueue wrong(JointLimits::Unbounded(2, 1, 1));
  wrong.SetConstant(Vec({0, 0}));
  EXPECT_FALSE(path->AppendTo(wrong));
  EXPECT_EQ(wrong.last_error(), "AppendCurves: 3 curves, expected 2");
  EXPECT_EQ(wrong.end_time(), 0);
}

// [section] PiecewisePolynomial

TEST(PiecewisePolynomialTest, AppendTrimCutAndHold) {
  PiecewisePolynomial curve;
  EXPECT_EQ(curve.Eval(3), 0);
  ASSERT_TRUE(curve.Append(PolynomialPiece::Linear(0, 1, 0, 1)));
  ASSERT_TRUE(curve.Append(PolynomialPiece::Hermite(1, 2, 1, 1, 0, 0)));
  EXPECT_FALSE(curve.Append(PolynomialPiece::Linear(3, 4, 0, 1)));  // gap
  EXPECT_EQ(curve.piece_count(), 2u);
  EXPECT_NEAR(curve.Eval(0.5), 0.5, 1e-15);
  EXPECT_NEAR(curve.Deriv(1.0), 1.0, 1e-15);  // continuous slope at the knot
  EXPECT_NEAR(curve.Eval(2), 0, 1e-15);
  EXPECT_EQ(curve.Deriv(2.5), 0);  // held after the end
  EXPECT_EQ(curve.Eval(-1), 0);    // held before the start
  curve.CutAfter(1.5);
  EXPECT_EQ(curve.EndTime(), 1.5);
  const double at_cut = curve.Eval(1.5);
  EXPECT_EQ(curve.Eval(1.9), at_cut);
  curve.TrimFront(1.2);
  EXPECT_EQ(curve.piece_count(), 1u);
  EXPECT_EQ(curve.StartTime(), 1);
  EXPECT_EQ(curve.Eval(1.5), at_cut);
  curve.TrimFront(10);  // the last piece is always kept
  EXPECT_EQ(curve.piece_count(), 1u);
}

}  // namespace
}  // namespace lamina::core
