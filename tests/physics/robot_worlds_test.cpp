// SPDX-License-Identifier: MIT
// Klamp't's robot example worlds simulated: ATHLETE dropped on fractal terrain stands, moves a
// leg through milestones and settles again; arms hold their pose; a floating cube comes to rest.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "core/control/trajectory.h"
#include "core/io/trajectory_file.h"
#include "core/robot/dynamics.h"
#include "core/sim/simulator.h"
#include "tests/common/scene_builders.h"
#include "tests/common/test_support.h"

namespace lamina {
namespace {

using core::Vec3;
using core::VecX;

core::WorldDesc LoadRobotWorld(const std::string& relative) {
  test::LoadedWorld loaded;
  test::LoadWorld(test::WorldsPath(relative), &loaded);
  EXPECT_TRUE(loaded.ok) << loaded.diagnostics.FormatAll();
  return loaded.world;
}

// leg 1's hip pitch and how far it is raised (rad)
constexpr int kLiftJoint = 7;
constexpr double kLiftAngle = -0.6;
// PID tracking of the flex motion with ATHLETE's own gains (rad): while moving (measured 0.118
// mean, 0.63 worst) and in the last 0.5 s of holding its end (0.034 mean, 0.19 worst: the feet
// on the fractal terrain cannot all reach a configuration made for flat ground)
constexpr double kFlexMeanError = 0.15;
constexpr double kFlexWorstError = 0.75;
constexpr double kFlexHeldMeanError = 0.05;
constexpr double kFlexHeldWorstError = 0.25;

Vec3 BasePosition(const core::Simulator& simulator) {
  return simulator.GetRobotConfig(0).head<3>();
}

// ATHLETE dropped on the fractal terrain stands: its base moves less than the 1 cm over
// the last 2 of 5 s
// `handed_back`: the largest share of the direct solves that may go back to dWorldStep
void ExpectAthleteStands(const core::SolverSettings& solver, double handed_back = 0.002,
                         bool joint_coordinates = false) {
  core::WorldDesc world = LoadRobotWorld("klampt/athlete_fractal_1.xml");
  world.settings.joint_coordinates = joint_coordinates;
  core::Simulator simulator(world, solver);
  const auto start = std::chrono::steady_clock::now();
  simulator.Simulate(3.0);
  const Vec3 at_three = BasePosition(simulator);
  simulator.Simulate(2.0);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const core::SimStatistics& stats = simulator.statistics();
  std::printf(
      "athlete: base (%g %g %g) -> (%g %g %g), %ld steps, %ld rollbacks, %ld corrections, "
      "max penetration %g m, %ld of %ld direct solves handed back, wall %.2f s\n",
      at_three.x(), at_three.y(), at_three.z(), BasePosition(simulator).x(),
      BasePosition(simulator).y(), BasePosition(simulator).z(), stats.steps, stats.rollbacks,
      stats.instability_corrections, stats.max_penetration,
      static_cast<long>(stats.direct_fallbacks), static_cast<long>(stats.direct_islands), wall);
  ASSERT_NE(stats.worst_status, core::StepStatus::kError) << stats.error;
  // the wheels' friction and normal forces feed each other on the rough ground: the direct
  // solve's friction rounds settle with secant steps (bound_secant.h: 1 of 3755 measured under
  // the Newton solver; halfway steps let 20 of 2119 go back to dWorldStep, and undamped rounds
  // 4 % of the steps). Since Lamina integrates the islands it solves (object_islands.h), each
  // step starts from the last answer itself and the robot's Newton step settles it more often:
  // 2206 direct solves in 5000 steps instead of 3755, 3 of them handed back (0.14 %)
  EXPECT_LE(static_cast<double>(stats.direct_fallbacks),
            handed_back * static_cast<double>(stats.direct_islands));
  EXPECT_LT((BasePosition(simulator) - at_three).norm(), 0.01);
  EXPECT_LT(stats.max_penetration, 0.0025 + 0.0025);  // within the two paddings
  EXPECT_EQ(stats.instability_corrections, 0);
}

TEST(RobotWorldsTest, AthleteDropsOnFractalTerrainAndStands) {
  ExpectAthleteStands({core::SolverType::kStep, 20});
}

// the Newton solver: the wheels on rough ground change their rows' law often, and the islands
// one Newton step does not settle are solved directly (object_islands.h)
TEST(RobotWorldsTest, AthleteStandsWithTheNewtonSolver) {
  ExpectAthleteStands({core::SolverType::kNewton, 20});
}

// in joint coordinates (jointCoordinates: reduced_basis.h) every step's robot island is solved over
// its 42 joint coordinates, and the robot stands as in the bodies' own
TEST(RobotWorldsTest, AthleteStandsInJointCoordinates) {
  ExpectAthleteStands({core::SolverType::kNewton, 20}, 0.001, true);
}

// QuickStep leaves the friction of ATHLETE's light feet unconverged: without friction anchors
// (core/sim/friction_anchor.h) the robot creeps 18 mm in those 2 s
TEST(RobotWorldsTest, AthleteStandsWithQuickStep) {
  ExpectAthleteStands({core::SolverType::kQuickStep, 20});
}

core::WorldDesc RobotOnly(const std::string& relative, bool with_plane) {
  const std::unique_ptr<test::LoadedRobot> loaded = test::LoadRobot(test::WorldsPath(relative));
  EXPECT_FALSE(loaded->diagnostics.HasErrors()) << loaded->diagnostics.FormatAll();
  core::WorldDesc world;
  if (with_plane) world.terrains.push_back(test::PlaneTerrain(0.5, 0.0));
  world.robots.push_back(loaded->robot);
  return world;
}

// fixed-base arms hold their file configuration under gravity with their own servo gains
// fixed-base arms hold their file configuration under gravity with their own servo gains: a
// joint without an integral term settles where its spring balances gravity, q_d - τ_g(q) / kP;
// one with an integral term never sags more than that
TEST(RobotWorldsTest, ArmsHoldTheirPoseUnderGravity) {
  for (const std::string file :
       {"klampt/robots/ur5.rob", "klampt/robots/mirobot.urdf", "klampt/robots/tx90l.rob"}) {
    SCOPED_TRACE(file);
    const core::WorldDesc world = RobotOnly(file, false);
    core::Simulator simulator(world);
    const VecX start = simulator.GetRobotConfig(0);
    simulator.Simulate(3.0);
    ASSERT_NE(simulator.statistics().worst_status, core::StepStatus::kError);
    const VecX q = simulator.GetRobotConfig(0);
    const VecX holding = core::GravityTorques(world.robots[0], q, world.settings.gravity);
    for (const core::DriverDesc& driver : world.robots[0].drivers) {
      if (driver.type != core::DriverType::kNormal) continue;
      const int link = driver.links[0];
      SCOPED_TRACE(world.robots[0].links[link].name);
      const double sag = holding[link] / driver.servo_p;  // pure kP spring against gravity
      if (driver.servo_i == 0.0) {
        EXPECT_NEAR(q[link], start[link] - sag, 1e-4);
      } else {
        // the integral term only takes the sag away (time constant kP / kI, 5 s on ur5's wrist)
        EXPECT_LE(std::abs(q[link] - start[link]), std::abs(sag) + 1e-6);
      }
    }
    std::printf("%s: largest joint error %g rad after 3 s, speed %g\n", file.c_str(),
                (q - start).cwiseAbs().maxCoeff(),
                simulator.GetRobotVelocity(0).cwiseAbs().maxCoeff());
    EXPECT_LT(simulator.GetRobotVelocity(0).cwiseAbs().maxCoeff(), 0.01);
  }
}

// a floating-base cube dropped from 10 cm falls freely, lands and rests on the plane
TEST(RobotWorldsTest, FloatingCubeFallsAndRests) {
  const core::WorldDesc world = RobotOnly("klampt/robots/free_cube.rob", true);
  core::Simulator simulator(world);
  simulator.EnableContactFeedbackAll();
  // its own servo (kD 3 on a 5 cm, 50 g cube: kD h / I = 150 at 1 ms) is far beyond an explicit
  // PD's stability (it chatters at its 0.2 N·m limit in Klamp't); the implicit servo holds it
  const double z0 = simulator.GetRobotConfig(0)[2];
  simulator.Simulate(0.1);
  // free fall for 0.1 s (it has 10 cm - the cube's 2.5 mm layer and the plane's to fall)
  EXPECT_NEAR(simulator.GetRobotConfig(0)[2], z0 - 0.5 * 9.8 * 0.01, 1e-3);
  simulator.Simulate(2.9);
  const VecX settled = simulator.GetRobotConfig(0);
  simulator.Simulate(2.0);
  ASSERT_NE(simulator.statistics().worst_status, core::StepStatus::kError);
  const VecX q = simulator.GetRobotConfig(0);
  std::printf("free_cube: q");
  for (const double v : q) std::printf(" %g", v);
  std::printf("\n");
  // at rest on the plane: nothing moves by more than 1 mm or 1 mrad over the last 2 s (a
  // vibration of under 0.2 mrad amplitude between the contacts and the stiff servo remains)
  EXPECT_LT((q - settled).cwiseAbs().maxCoeff(), 1e-3);
  EXPECT_NEAR(q[2], 0.0025, 1e-3);  // the cube's 2.5 mm layer on the plane
  // contact feedback covers robot links: the plane carries the robot's weight (time average
  // over the last call, which evens out the remaining vibration)
  Vec3 support = Vec3::Zero();
  for (int link = 0; link < world.robots[0].dof(); ++link) {
    support += simulator.MeanContactForce(world.RobotLinkId(0, link), world.TerrainId(0));
  }
  const double weight = world.robots[0].TotalMass() * 9.8;
  EXPECT_NEAR(support.z(), weight, 0.01 * weight);
  EXPECT_NEAR(support.head<2>().norm(), 0.0, 0.01 * weight);
}

double LinkHeight(core::Simulator& simulator, const core::WorldDesc& world, int link) {
  return simulator.body(world.RobotLinkId(0, link)).GetTransform().translation().z();
}

// the tutorial's leg lift: setMilestone to a raised leg, addMilestone back down; the foot rises,
// comes back and the robot settles standing where it was
TEST(RobotWorldsTest, AthleteLiftsAndLowersALegThroughMilestones) {
  const core::WorldDesc world = LoadRobotWorld("klampt/athlete_fractal_1.xml");
  core::Simulator simulator(world);
  simulator.Simulate(2.0);
  core::RobotController& controller = simulator.controller(0);
  VecX down;
  ASSERT_TRUE(controller.GetCommandedConfig(&down));
  VecX up = down;
  up[kLiftJoint] += kLiftAngle;
  const int foot = 11;  // leg 1's last link (its wheel), not one of the three it stands on
  const double foot_start = LinkHeight(simulator, world, foot);
  ASSERT_TRUE(controller.SetMilestone(up)) << controller.last_error();
  ASSERT_TRUE(controller.AddMilestone(down)) << controller.last_error();
  const double motion_time = controller.RemainingTime();
  EXPECT_GT(motion_time, 0.1);
  double foot_highest = foot_start;
  for (double t = 0.0; t < motion_time; t += 0.01) {
    simulator.Simulate(0.01);
    foot_highest = std::max(foot_highest, LinkHeight(simulator, world, foot));
  }
  simulator.Simulate(2.0);
  const Vec3 settled = BasePosition(simulator);
  simulator.Simulate(1.0);
  std::printf(
      "leg lift: %.2f s of motion, foot up %.3f m, back to %.4f m off its start, base moved "
      "%.4f m in the last 1 s\n",
      motion_time, foot_highest - foot_start, LinkHeight(simulator, world, foot) - foot_start,
      (BasePosition(simulator) - settled).norm());
  ASSERT_NE(simulator.statistics().worst_status, core::StepStatus::kError);
  EXPECT_GT(foot_highest - foot_start, 0.05);
  EXPECT_NEAR(LinkHeight(simulator, world, foot), foot_start, 0.02);
  EXPECT_LT((BasePosition(simulator) - settled).norm(), 0.01);
  EXPECT_EQ(simulator.statistics().instability_corrections, 0);
}

// athlete_flex.path (the body down 0.42 m and back up in 2 s) streamed as PID commands every
// control period, as the tutorial does, then held at its end. ATHLETE's soft gains (kP 10..50)
// let the legs lag during the motion; the error is reported and bounded, and shrinks once the
// motion ends.
TEST(RobotWorldsTest, AthleteTracksTheFlexPathStreamedAsPidCommands) {
  const core::WorldDesc world = LoadRobotWorld("klampt/athlete_fractal_1.xml");
  core::Diagnostics diagnostics;
  const auto path =
      core::LoadTrajectory(test::WorldsPath("klampt/motions/athlete_flex.path"), diagnostics);
  ASSERT_TRUE(path.has_value()) << diagnostics.FormatAll();
  core::Simulator simulator(world);
  core::RobotController& controller = simulator.controller(0);
  double moving_worst = 0.0, moving_sum = 0.0, held_worst = 0.0, held_mean = 0.0;
  int samples = 0;
  const double hold = 1.5;
  for (double t = 0.0; t < path->EndTime() + hold; t += 0.01) {
    ASSERT_TRUE(controller.SetPIDCommand(path->Eval(t), path->Deriv(t))) << controller.last_error();
    simulator.Simulate(0.01);
    // driven joints only: the floating base (links 0..5) follows the terrain
    const VecX error = (simulator.GetRobotConfig(0) - path->Eval(t + 0.01)).tail(36).cwiseAbs();
    if (t >= 0.5 && t < path->EndTime()) {  // after the drop onto the terrain
      moving_worst = std::max(moving_worst, error.maxCoeff());
      moving_sum += error.mean();
      ++samples;
    }
    if (t >= path->EndTime() + hold - 0.5) {
      held_worst = std::max(held_worst, error.maxCoeff());
      held_mean = std::max(held_mean, error.mean());
    }
  }
  ASSERT_GT(samples, 0);
  std::printf(
      "flex path: %.2f s; tracking error while moving: mean %.4f rad, worst %.4f rad; "
      "held at the end: mean %.4f rad, worst %.4f rad\n",
      path->EndTime(), moving_sum / samples, moving_worst, held_mean, held_worst);
  ASSERT_NE(simulator.statistics().worst_status, core::StepStatus::kError);
  EXPECT_EQ(simulator.statistics().instability_corrections, 0);
  EXPECT_LT(moving_sum / samples, kFlexMeanError);
  EXPECT_LT(moving_worst, kFlexWorstError);
  EXPECT_LT(held_mean, kFlexHeldMeanError);
  EXPECT_LT(held_worst, kFlexHeldWorstError);
}

// Klamp't's HRP-2 (worlds/klampt/hrp2_plane.xml, copied from Klamp't's example data): its .rob
// has ten link inertias asymmetric by the rounding of their 8 printed decimals, which Lamina now
// symmetrises with a warning instead of refusing the robot; it stands on its padded feet
TEST(RobotWorldsTest, Hrp2LoadsWithItsRoundedInertiasAndStands) {
  test::LoadedWorld loaded;
  test::LoadWorld(test::WorldsPath("klampt/hrp2_plane.xml"), &loaded);
  ASSERT_TRUE(loaded.ok) << loaded.diagnostics.FormatAll();
  int symmetrised = 0;
  for (const std::string& warning : loaded.diagnostics.Messages(core::Severity::kWarning)) {
    if (warning.find("is not symmetric") != std::string::npos) ++symmetrised;
  }
  EXPECT_EQ(symmetrised, 10);
  core::Simulator simulator(loaded.world);
  ASSERT_EQ(simulator.GetRobotConfig(0).size(), 36);
  simulator.Simulate(1.0);
  ASSERT_NE(simulator.statistics().worst_status, core::StepStatus::kError);
  const VecX q = simulator.GetRobotConfig(0);
  // the base settles by the feet's 5 mm padding at most and does not tip
  EXPECT_NEAR(q[2], 0.0, 0.006);
  EXPECT_LT(q.segment(3, 3).cwiseAbs().maxCoeff(), 0.01);
  EXPECT_EQ(simulator.statistics().instability_corrections, 0);
}

// The Newton solver takes the humanoid whole (its hinges, servos and joint friction:
// object_islands.h) and it stands as with dWorldStep: the base still over the last 2 s of 5.
// With `direct` (the default), an island that one Newton step does not settle is solved
// directly (object_islands.h); without, the Newton solver takes every step alone.
void ExpectHrp2StandsWithTheNewtonSolver(bool direct) {
  test::LoadedWorld loaded;
  test::LoadWorld(test::WorldsPath("klampt/hrp2_plane.xml"), &loaded);
  ASSERT_TRUE(loaded.ok) << loaded.diagnostics.FormatAll();
  core::Simulator simulator(loaded.world, {core::SolverType::kNewton, 20});
  simulator.SetDirectRobotSolve(direct);
  simulator.Simulate(3.0);
  const VecX settled = simulator.GetRobotConfig(0);
  simulator.Simulate(2.0);
  ASSERT_NE(simulator.statistics().worst_status, core::StepStatus::kError);
  const VecX q = simulator.GetRobotConfig(0);
  EXPECT_LT((q.head<3>() - settled.head<3>()).norm(), 1e-4);  // 1e-6 m measured
  EXPECT_NEAR(q[2], 0.0, 0.006);
  EXPECT_LT(q.segment(3, 3).cwiseAbs().maxCoeff(), 0.01);
  const core::SimStatistics& statistics = simulator.statistics();
  // the robot's island, every step: the Newton solver's, or after a Newton step that did not
  // settle it, for a few steps the direct solve's alone (object_islands.h)
  EXPECT_GE(statistics.newton_islands + statistics.direct_islands, statistics.steps);
  EXPECT_GE(statistics.newton_islands, statistics.steps * 9 / 10);
  std::printf("hrp2 (newton): %ld islands, %ld solved directly, %ld of those handed back\n",
              statistics.newton_islands, statistics.direct_islands, statistics.direct_fallbacks);
  if (!direct) {
    EXPECT_EQ(statistics.direct_islands, 0);
  }
  EXPECT_LE(statistics.direct_fallbacks, statistics.steps / 100);
  EXPECT_EQ(statistics.newton_fallbacks, 0);
}

// with infinite friction (kFriction inf on the ground and every link: no sliding) the solves of
// the robot's island settle: a back contact without normal force made the bound ∞ · 0, NaN, and
// every direct solve (15 of 15 in 2 s) and 5 Newton solves went back to dWorldStep
TEST(RobotWorldsTest, Hrp2StandsOnInfiniteFrictionWithoutHandingBack) {
  test::LoadedWorld loaded;
  test::LoadWorld(test::WorldsPath("klampt/hrp2_plane.xml"), &loaded);
  ASSERT_TRUE(loaded.ok) << loaded.diagnostics.FormatAll();
  for (core::TerrainDesc& terrain : loaded.world.terrains)
    terrain.sim.surface.friction = core::kInf;
  for (core::LinkDesc& link : loaded.world.robots[0].links) link.sim.surface.friction = core::kInf;
  core::Simulator simulator(loaded.world, {core::SolverType::kNewton, 20});
  simulator.Simulate(2.0);
  const core::SimStatistics& statistics = simulator.statistics();
  ASSERT_NE(statistics.worst_status, core::StepStatus::kError) << statistics.error;
  EXPECT_GT(statistics.direct_islands, 0);
  EXPECT_EQ(statistics.direct_fallbacks, 0);
  EXPECT_EQ(statistics.newton_fallbacks, 0);
  EXPECT_LT(simulator.GetRobotConfig(0).segment(3, 3).cwiseAbs().maxCoeff(), 0.01);  // upright
}

TEST(RobotWorldsTest, Hrp2StandsWithTheNewtonSolver) {
  ExpectHrp2StandsWithTheNewtonSolver(true);
}

TEST(RobotWorldsTest, Hrp2StandsWithTheNewtonSolverAlone) {
  ExpectHrp2StandsWithTheNewtonSolver(false);
}

// HRP-2 in joint coordinates: every step's island is the reduced step's (one unknown per joint),
// its joints keep no gap, and it stands as over its bodies (the base still over the last 2 s)
TEST(RobotWorldsTest, Hrp2StandsInJointCoordinates) {
  test::LoadedWorld loaded;
  test::LoadWorld(test::WorldsPath("klampt/hrp2_plane.xml"), &loaded);
  ASSERT_TRUE(loaded.ok) << loaded.diagnostics.FormatAll();
  loaded.world.settings.joint_coordinates = true;
  core::Simulator simulator(loaded.world, {core::SolverType::kNewton, 20});
  simulator.Simulate(3.0);
  const VecX settled = simulator.GetRobotConfig(0);
  simulator.Simulate(2.0);
  const core::SimStatistics& statistics = simulator.statistics();
  ASSERT_NE(statistics.worst_status, core::StepStatus::kError);
  const VecX q = simulator.GetRobotConfig(0);
  EXPECT_LT((q.head<3>() - settled.head<3>()).norm(), 1e-4);
  EXPECT_NEAR(q[2], 0.0, 0.006);
  EXPECT_LT(q.segment(3, 3).cwiseAbs().maxCoeff(), 0.01);
  EXPECT_GE(statistics.reduced_islands, statistics.steps);
  EXPECT_EQ(statistics.reduced_fallbacks, 0);
  EXPECT_EQ(statistics.instability_corrections, 0);
}

// sphere.rob: a sphere on a translating floating base (3 virtual links) held by translation
// drivers (force along x, y, z on the base body) against gravity
TEST(RobotWorldsTest, TranslationDriversHoldAFloatingSphere) {
  const core::WorldDesc world = RobotOnly("klampt/robots/sphere.rob", false);
  core::Simulator simulator(world);
  ASSERT_EQ(simulator.GetRobotConfig(0).size(), 3);
  simulator.Simulate(3.0);
  ASSERT_NE(simulator.statistics().worst_status, core::StepStatus::kError);
  // the integral term carries the 0.49 N weight: no offset left, and no rotation
  EXPECT_LT(simulator.GetRobotConfig(0).cwiseAbs().maxCoeff(), 1e-3);
  EXPECT_TRUE(simulator.body(world.RobotLinkId(0, 2)).GetTransform().linear().isIdentity(1e-12));
  EXPECT_NEAR(simulator.GetActuatorTorques(0)[2], 0.05 * 9.8, 0.01);
}

}  // namespace
}  // namespace lamina
