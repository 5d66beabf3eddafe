// SPDX-License-Identifier: MIT
// The seed example of batch simulation (docs/batch.md): Klamp't's control/world1.xml, a 1R planar
// robot on a continuous "spin" joint (torqueMax 50, velMax 1, accMax 1), 100 runs of 5 s from
// uniform start angles, PID gains kP 20, kI 8, kD 5, to 0 or to sampled targets. Label physics
// (long runs: left out of the sanitizer build).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/batch/batch_output.h"
#include "core/batch/batch_sim.h"
#include "core/batch/batch_spec.h"
#include "tests/batch/batch_test_support.h"

namespace lamina {
namespace {

using core::BatchSpec;
using core::BatchTable;
using core::RunResult;
using test::AllRuns;
using test::LoadSpec;
using test::RunBatch;
using test::ScratchSpec;

// The link (1 kg, centre of mass 0.5 m out along x, hinge about y) hangs in gravity: the hold
// torque at angle q is m g c cos(q) = 4.9 cos(q) N·m. The milestone is a time-optimal ramp with
// accMax 1 rad/s² and velMax 1 rad/s: from |q0| <= pi it arrives within pi + 1 = 4.14 s < 5 s.
// PD alone would leave the static sag m g c / kP = 4.9 / 20 = 0.245 rad (toward +q, gravity
// pulls the link down); the integral (kI 8) removes it with a time constant of about
// kP / kI = 2.5 s, so at 5 s a run that arrived early sags 0.245 e^-2 = 0.033 rad and the
// latest ones (arrived at 4.14 s) about 0.15 rad. Seen: 0.034 to 0.150 rad over the 100 runs.
constexpr double kGravityTorque = 1.0 * 9.8 * 0.5;  // m g c, N·m
constexpr double kMaxSag = 0.16;                    // rad at 5 s, see above
constexpr double kMinSag = 0.03;                    // rad: 0.245 e^-2, less 10 %

void ExpectHeldBySag(const RunResult& run, double commanded) {
  const double q = run.items[0][0];
  EXPECT_EQ(run.status, "normal") << run.error;
  EXPECT_NEAR(run.time, 5.0, 1e-9);
  EXPECT_NEAR(run.items[2][0], commanded, 1e-6) << "run " << run.index;  // the ramp arrived
  EXPECT_GT(q - commanded, kMinSag) << "run " << run.index;
  EXPECT_LT(q - commanded, kMaxSag) << "run " << run.index;
  EXPECT_LT(run.items[1][0], 0.0) << "run " << run.index;  // still closing the sag
  // quasi-static: the motor carries the weight (the torque's sign is the joint's: -q side)
  if (run.items.size() > 3) {
    EXPECT_NEAR(run.items[3][0], -kGravityTorque * std::cos(q), 0.1) << "run " << run.index;
  }
}

TEST(BatchSeedExampleTest, HundredRunsFromUniformStartsSettleAtZero) {
  const BatchSpec spec = LoadSpec("batch/spin_to_zero.json");
  ASSERT_EQ(spec.runs, 100);
  const BatchTable table = RunBatch(spec, AllRuns(spec), 0);
  ASSERT_EQ(table.runs.size(), 100u);
  double lowest = 0, highest = 0, worst_sag = 0;
  for (const RunResult& run : table.runs) {
    const double start = run.sampled[0][0];
    lowest = std::min(lowest, start);
    highest = std::max(highest, start);
    ExpectHeldBySag(run, 0.0);
    worst_sag = std::max(worst_sag, run.items[0][0]);
  }
  // the starts cover [-pi, pi] (the joint's qMin 0 does not clamp them: a spin joint has no
  // stops, and the description's config is only checked to be finite)
  EXPECT_LT(lowest, -3.0);
  EXPECT_GT(highest, 3.0);
  EXPECT_GT(worst_sag, 0.12);  // the late arrivals sag most
}

// a start at pi: the commanded ramp is still moving at 4.0 s and has arrived at 4.5 s
TEST(BatchSeedExampleTest, TheRampFromPiArrivesAfterPiPlusOneSeconds) {
  std::string error;
  const auto spec =
      ScratchSpec("pi.json",
                  "\"duration\": 5, \"N\": 2, \"samplers\": {\"robots[0].config[0]\": {\"list\": "
                  "[3.141592653589793, -3.141592653589793]}}, "
                  "\"setup\": [{\"kP\": [20], \"kI\": [8], \"kD\": [5], \"milestones\": [[0]]}], "
                  "\"return\": [\"controllers[0].commandedConfig[0]\"], \"trace\": {\"rate\": 0.5}",
                  &error);
  ASSERT_TRUE(spec) << error;
  for (const RunResult& run : RunBatch(*spec, AllRuns(*spec), 2).runs) {
    ASSERT_EQ(run.trace_time.size(), 11u);
    EXPECT_NEAR(run.trace_time[8], 4.0, 1e-9);  // the simulator's clock: a sum of 1 ms steps
    // 0.14 s before arrival the ramp is 0.5 * 0.14^2 = 0.01 rad away (within a control period)
    EXPECT_NEAR(std::abs(run.trace[8][0][0]), 0.01, 0.003);
    EXPECT_NEAR(run.trace[9][0][0], 0.0, 1e-6);
    // after 1 s of acceleration at 1 rad/s²: 0.5 rad travelled
    EXPECT_NEAR(std::abs(run.trace[2][0][0]), std::numbers::pi - 0.5, 0.02);
  }
}

// targets in [-0.5, 0.5] passed as args: the controller clamps its milestones to the joint
// limits [qMin, qMax] = [0, 6.28319], so a negative target is commanded as 0 (up to the limits'
// 1e-7 of margin) and those runs end where the target-0 runs do
TEST(BatchSeedExampleTest, SampledTargetsAreReachedOrClampedAtQMin) {
  const BatchSpec spec = LoadSpec("batch/spin_to_target.json");
  const BatchTable table = RunBatch(spec, AllRuns(spec), 0);
  int clamped = 0;
  for (const RunResult& run : table.runs) {
    const double target = run.sampled[1][0];
    ASSERT_GE(target, -0.5);
    ASSERT_LT(target, 0.5);
    clamped += target < 0;
    ExpectHeldBySag(run, std::max(target, 0.0));
  }
  EXPECT_GT(clamped, 30);  // about half of 100
  EXPECT_LT(clamped, 70);
}

}  // namespace
}  // namespace lamina
