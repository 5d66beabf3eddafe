// SPDX-License-Identifier: MIT
// Robot links in the step guard (core/sim/robot_guard.h): the three-link arm of
// worlds/stress/absurd_torque.xml given 1e12 N·m on its middle joint, through the controller or as
// a held torque on the link. The run goes on with the step flagged (status "unstable"), every
// state stays finite, and the arm stays where it was instead of the run ending with an error. And
// a servo too stiff for QuickStep's explicit law at its step: solved implicitly, or flagged.
#include <cmath>

#include <gtest/gtest.h>

#include "core/sim/simulator.h"
#include "tests/common/test_support.h"

namespace lamina::core {
namespace {

WorldDesc Arm(SolverType solver) {
  test::LoadedWorld loaded;
  test::LoadWorld(test::WorldsPath("stress/absurd_torque.xml"), &loaded);
  EXPECT_TRUE(loaded.ok) << loaded.diagnostics.FormatAll();
  loaded.world.settings.solver = solver;
  return loaded.world;
}

// the largest distance of a link origin from where it started, m
double LargestMove(Simulator* simulator, const std::vector<Vec3>& start) {
  double moved = 0.0;
  for (int l = 0; l < 3; ++l) {
    const Vec3 now =
        simulator->body(simulator->world().RobotLinkId(0, l)).GetTransform().translation();
    moved = std::max(moved, (now - start[l]).norm());
  }
  return moved;
}

std::vector<Vec3> Origins(Simulator* simulator) {
  std::vector<Vec3> origins;
  for (int l = 0; l < 3; ++l) {
    origins.push_back(
        simulator->body(simulator->world().RobotLinkId(0, l)).GetTransform().translation());
  }
  return origins;
}

TEST(RobotInstabilityTest, AbsurdTorqueCommandIsFlaggedAndTheRunGoesOn) {
  for (SolverType solver : {SolverType::kStep, SolverType::kQuickStep}) {
    Simulator simulator(Arm(solver));
    const std::vector<Vec3> start = Origins(&simulator);
    simulator.controller(0).SetTorque(Vec3(0.0, 1e12, 0.0));
    const StepStatus status = simulator.Simulate(0.1);
    const SimStatistics& statistics = simulator.statistics();
    EXPECT_FALSE(simulator.halted()) << statistics.error;
    EXPECT_EQ(status, StepStatus::kUnstable) << statistics.error;
    EXPECT_GT(statistics.instability_corrections, 0);
    EXPECT_EQ(statistics.steps, 100);
    EXPECT_TRUE(simulator.GetRobotConfig(0).allFinite());
    EXPECT_TRUE(simulator.GetRobotVelocity(0).allFinite());
    EXPECT_LT(LargestMove(&simulator, start), 0.01);
  }
}

TEST(RobotInstabilityTest, OnceTheTorqueIsSaneTheArmMovesAgainUnflagged) {
  Simulator simulator(Arm(SolverType::kStep));
  simulator.controller(0).SetTorque(Vec3(0.0, 1e12, 0.0));
  simulator.Simulate(0.05);
  const long corrections = simulator.statistics().instability_corrections;
  simulator.controller(0).SetTorque(Vec3(0.0, 0.01, 0.0));
  const VecX before = simulator.GetRobotConfig(0);
  EXPECT_EQ(simulator.Simulate(0.1), StepStatus::kNormal);
  EXPECT_EQ(simulator.statistics().instability_corrections, corrections);
  // no gains left in torque mode: the arm falls from horizontal under gravity
  EXPECT_GT((simulator.GetRobotConfig(0) - before).norm(), 0.05);
}

TEST(RobotInstabilityTest, AbsurdHeldTorqueOnALinkIsFlaggedAndTheRunGoesOn) {
  Simulator simulator(Arm(SolverType::kStep));
  const std::vector<Vec3> start = Origins(&simulator);
  simulator.SetAppliedWrench(simulator.world().RobotLinkId(0, 1), Vec3::Zero(), Vec3(0, 1e12, 0));
  simulator.Simulate(0.1);
  EXPECT_FALSE(simulator.halted()) << simulator.statistics().error;
  EXPECT_EQ(simulator.statistics().worst_status, StepStatus::kUnstable);
  EXPECT_TRUE(simulator.GetRobotVelocity(0).allFinite());
  EXPECT_LT(LargestMove(&simulator, start), 0.01);
}

// worlds/accuracy/gripper_pad.xml under QuickStep at 10 ms: the pad's PID (servoP 1e4 N/m, servoD
// 100 N·s/m on 0.2 kg) is too stiff for the explicit law there (kD·h/m = 5: explicit_pd.h). With
// no torque limit the servo is solved implicitly and the pad holds, within its stops; with a
// limit the explicit law stays (Klamp't's), swings the pad through its stops, and every step that
// does so by more than 1 cm is flagged and the robot put back (robot_guard.h)
WorldDesc PadAtTenMilliseconds(double torque_limit) {
  test::LoadedWorld loaded;
  test::LoadWorld(test::WorldsPath("accuracy/gripper_pad.xml"), &loaded);
  EXPECT_TRUE(loaded.ok) << loaded.diagnostics.FormatAll();
  loaded.world.settings.solver = SolverType::kQuickStep;
  loaded.world.settings.timestep = 0.01;
  loaded.world.robots[0].drivers[0].torque_max = torque_limit;
  loaded.world.robots[0].drivers[0].torque_min = -torque_limit;
  return loaded.world;
}

TEST(RobotInstabilityTest, AnUnlimitedServoTooStiffForQuickStepIsSolvedImplicitly) {
  Simulator simulator(PadAtTenMilliseconds(kInf));
  EXPECT_LE(simulator.Simulate(1.5), StepStatus::kAdaptiveStep);
  EXPECT_EQ(simulator.statistics().instability_corrections, 0);
  // held about its 1 mm target (the contact pushes back): measured 2.6e-4 m
  EXPECT_NEAR(simulator.GetRobotConfig(0)[0], 0.0, 0.002);
}

TEST(RobotInstabilityTest, ALimitedServoTooStiffForQuickStepIsFlaggedAtItsStops) {
  Simulator simulator(PadAtTenMilliseconds(1e4));
  EXPECT_EQ(simulator.Simulate(1.5), StepStatus::kUnstable);
  EXPECT_GT(simulator.statistics().instability_corrections, 10);
  const double q = simulator.GetRobotConfig(0)[0];
  EXPECT_TRUE(std::isfinite(q));
  EXPECT_LT(std::abs(q), 0.1 + 0.01);  // never left more than 1 cm past a stop
}

}  // namespace
}  // namespace lamina::core
