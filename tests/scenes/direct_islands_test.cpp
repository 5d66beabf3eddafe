// SPDX-License-Identifier: MIT
// The exact solver's direct solve of robot islands (core/sim/direct_solver.h, object_islands.h)
// against dWorldStep solving the same robots itself: the same rows and law, so the same runs to
// the solvers' rounding where friction does not saturate.
#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "core/control/send_motion.h"
#include "core/io/trajectory_file.h"
#include "core/sim/simulator.h"
#include "tests/common/test_support.h"

namespace lamina {
namespace {

// the largest gap between the two runs' link frames (m) after each 0.1 s
double LinkGap(core::Simulator& a, core::Simulator& b) {
  double gap = 0.0;
  for (int r = 0; r < a.robot_count(); ++r) {
    for (int l = 0; l < a.world().robots[r].dof(); ++l) {
      const int id = a.world().RobotLinkId(r, l);
      gap = std::max(
          gap, (a.body(id).GetTransform().translation() - b.body(id).GetTransform().translation())
                   .norm());
    }
  }
  return gap;
}

struct Runs {
  double gap = 0.0;
  long islands = 0, fallbacks = 0;
};

Runs CompareRuns(const core::WorldDesc& world, double duration, const std::string& motion = "") {
  core::Simulator direct(world, {core::SolverType::kStep, 20});
  direct.SetDirectRobotMinimumBodies(1);  // small robots too (dWorldStep is faster on them)
  direct.SetRobotNewtonStep(false);       // the direct solve alone
  core::Simulator ode(world, {core::SolverType::kStep, 20});
  ode.SetDirectRobotSolve(false);
  if (!motion.empty()) {
    core::Diagnostics diagnostics;
    const auto milestones = core::ReadMotionFile(test::WorldsPath(motion), diagnostics);
    EXPECT_TRUE(milestones.has_value()) << diagnostics.FormatAll();
    std::string error;
    EXPECT_TRUE(core::SendMotion(*milestones, &direct.controller(0), &error)) << error;
    EXPECT_TRUE(core::SendMotion(*milestones, &ode.controller(0), &error)) << error;
  }
  Runs runs;
  for (double t = 0.0; t < duration - 1e-9; t += 0.1) {
    direct.Simulate(0.1);
    ode.Simulate(0.1);
    runs.gap = std::max(runs.gap, LinkGap(direct, ode));
  }
  std::printf("%s: largest gap %g m\n", world.robots[0].name.c_str(), runs.gap);
  runs.islands = direct.statistics().direct_islands;
  runs.fallbacks = direct.statistics().direct_fallbacks;
  EXPECT_EQ(ode.statistics().direct_islands, 0);
  return runs;
}

TEST(DirectIslandsTest, HumanoidStandingOnAPlaneRunsAsWithDWorldStep) {
  // HRP-2's 30 servoed hinges with joint friction on its soles' contacts
  const Runs runs = CompareRuns(test::LoadShippedWorld("klampt/hrp2_plane.xml"), 1.0);
  EXPECT_LE(runs.gap, 1e-8);  // 3e-10 m measured
  EXPECT_EQ(runs.islands, 1000);
  EXPECT_EQ(runs.fallbacks, 0);
}

TEST(DirectIslandsTest, ArmFollowingMilestonesRunsAsWithDWorldStep) {
  // the TX90L's six servos through its first reach (its friction rows slip as it starts and
  // stops)
  const Runs runs = CompareRuns(test::LoadShippedWorld("examples/tx90l_milestones.xml"), 1.5,
                                "examples/tx90l_reach.milestones");
  EXPECT_LE(runs.gap, 1e-6);  // 3e-8 m measured
  EXPECT_GE(runs.islands, 1500);
  EXPECT_EQ(runs.fallbacks, 0);
}

TEST(DirectIslandsTest, CartPushedIntoItsSliderStopRunsAsWithDWorldStep) {
  // the cart-pole's cart pushed at 20 N along its slider into the stop at -3 m (1.34 s)
  const std::unique_ptr<test::LoadedRobot> cartpole =
      test::LoadRobot(test::WorldsPath("klampt/robots/cartpole.rob"));
  ASSERT_FALSE(cartpole->diagnostics.HasErrors()) << cartpole->diagnostics.FormatAll();
  core::WorldDesc world;
  world.robots.push_back(cartpole->robot);
  core::Simulator direct(world, {core::SolverType::kStep, 20});
  direct.SetDirectRobotMinimumBodies(1);
  direct.SetRobotNewtonStep(false);
  core::Simulator ode(world, {core::SolverType::kStep, 20});
  ode.SetDirectRobotSolve(false);
  const int cart = world.RobotLinkId(0, 0);
  double before_stop = 0.0, after = 0.0;
  for (int i = 0; i < 2000; ++i) {
    for (core::Simulator* simulator : {&direct, &ode}) {
      simulator->SetAppliedWrench(cart, core::Vec3(-20.0, 0.0, 0.0), core::Vec3::Zero());
      simulator->Simulate(0.001);
    }
    (i < 1340 ? before_stop : after) =
        std::max(i < 1340 ? before_stop : after, LinkGap(direct, ode));
  }
  std::printf("cart-pole: %g m to the stop, %g m after\n", before_stop, after);
  EXPECT_LE(before_stop, 1e-11);  // 4e-13 m measured
  EXPECT_LE(after, 1e-8);         // 7e-10 m measured
  EXPECT_NEAR(direct.GetRobotConfig(0)[0], world.robots[0].links[0].q_min, 1e-3);
  EXPECT_GE(direct.statistics().direct_islands, 2000);
}

// A large robot's island first gets one Newton step (object_islands.h): a humanoid standing on a
// plane is settled by it nearly every step, and runs as with the direct solve alone; on rough
// ground, where it seldom settles, a robot whose Newton step keeps failing goes straight to the
// direct solve for up to 16 steps, so few Newton steps are tried.
TEST(DirectIslandsTest, OneNewtonStepFirstAndNotWhereItKeepsFailing) {
  const core::WorldDesc plane = test::LoadShippedWorld("klampt/hrp2_plane.xml");
  core::Simulator first(plane, {core::SolverType::kStep, 20});
  core::Simulator direct(plane, {core::SolverType::kStep, 20});
  direct.SetRobotNewtonStep(false);
  double gap = 0.0;
  for (int i = 0; i < 5; ++i) {
    first.Simulate(0.1);
    direct.Simulate(0.1);
    gap = std::max(gap, LinkGap(first, direct));
  }
  std::printf("hrp2 plane: gap %g m, %ld Newton islands, %ld direct\n", gap,
              first.statistics().newton_islands, first.statistics().direct_islands);
  EXPECT_LE(gap, 1e-8);  // 7.8e-15 m measured
  // of 500 steps, while it settles on its feet: 482 and 30 measured
  EXPECT_GE(first.statistics().newton_islands, 450);
  EXPECT_LE(first.statistics().direct_islands, 50);
  EXPECT_EQ(direct.statistics().newton_islands, 0);
  EXPECT_EQ(direct.statistics().direct_islands, 500);

  core::Simulator rough(test::LoadShippedWorld("examples/hrp2_rough.xml"),
                        {core::SolverType::kStep, 20});
  rough.Simulate(0.5);
  const core::SimStatistics& statistics = rough.statistics();
  std::printf("hrp2 rough: %ld steps, %ld Newton islands, %ld direct\n", statistics.steps,
              statistics.newton_islands, statistics.direct_islands);
  EXPECT_GE(statistics.direct_islands, statistics.steps * 9 / 10);  // 472 of 502 measured
  EXPECT_LE(statistics.newton_islands, statistics.steps / 4);       // 63
}

TEST(DirectIslandsTest, OnlyRobotsOfTwelveBodiesOrMoreAreSolvedDirectly) {
  core::Simulator arm(test::LoadShippedWorld("examples/tx90l_milestones.xml"));
  arm.Simulate(0.05);
  EXPECT_EQ(arm.statistics().direct_islands, 0);  // 6 bodies: dWorldStep
  core::Simulator humanoid(test::LoadShippedWorld("klampt/hrp2_plane.xml"));
  humanoid.SetRobotNewtonStep(false);
  humanoid.Simulate(0.05);
  EXPECT_EQ(humanoid.statistics().direct_islands, 50);
}

}  // namespace
}  // namespace lamina
