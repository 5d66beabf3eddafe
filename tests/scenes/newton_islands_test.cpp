// SPDX-License-Identifier: MIT
// Solver "newton" (core/sim/object_islands.h) against ODE's dWorldStep on the same worlds: the
// same rows, so the same steps where the Dantzig solver is exact.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <functional>
#include <string>

#include <gtest/gtest.h>

#include "core/sim/simulator.h"
#include "tests/common/test_support.h"

namespace lamina {
namespace {

struct Gap {
  double position = 0.0;  ///< m
  double velocity = 0.0;  ///< m/s
  double force = 0.0;     ///< contact force on an object, relative to the world's weight
};

Gap Compare(core::Simulator& a, core::Simulator& b) {  // (body() is not const)
  Gap gap;
  for (int k = 0; k < a.object_count(); ++k) {
    gap.position = std::max(
        gap.position, (a.GetObjectPose(k).translation() - b.GetObjectPose(k).translation()).norm());
    const core::Twist va = a.GetObjectVelocity(k), vb = b.GetObjectVelocity(k);
    gap.velocity = std::max(gap.velocity, (va.linear - vb.linear).norm());
  }
  // robots: every link's frame and velocity (the joint values read from ODE's hinges carry the
  // joints' misalignment, about 1e-8 rad, with a sign that rounding decides)
  for (int r = 0; r < a.robot_count(); ++r) {
    for (int l = 0; l < a.world().robots[r].dof(); ++l) {
      const int id = a.world().RobotLinkId(r, l);
      gap.position = std::max(gap.position, (a.body(id).GetTransform().translation() -
                                             b.body(id).GetTransform().translation())
                                                .norm());
      gap.velocity = std::max(
          gap.velocity, (a.body(id).GetVelocity().linear - b.body(id).GetVelocity().linear).norm());
    }
  }
  double weight = 0.0;
  for (const core::RigidObjectDesc& object : a.world().objects) weight += object.mass * 9.8;
  for (int k = 0; k < a.object_count(); ++k) {
    const int id = a.world().ObjectId(k);
    gap.force = std::max(gap.force, (a.ContactForce(id) - b.ContactForce(id)).norm() / weight);
  }
  return gap;
}

using WorldSetup = std::function<void(core::Simulator*)>;

// dWorldStep alone and `fast_solver` (the Newton solver, or the exact solver with its own
// islands: object_islands.h) from the world's start (after `setup`), step by step
Gap LockStep(const std::string& world_file, double step, int steps, core::SimStatistics* newton,
             const WorldSetup& setup = nullptr, double friction = -1.0,
             core::SolverType fast_solver = core::SolverType::kNewton) {
  test::LoadedWorld loaded;
  test::LoadWorld(test::WorldsPath(world_file), &loaded);
  EXPECT_TRUE(loaded.ok) << world_file;
  if (friction >= 0.0) {  // every surface's
    for (core::TerrainDesc& terrain : loaded.world.terrains)
      terrain.sim.surface.friction = friction;
    for (core::RigidObjectDesc& object : loaded.world.objects)
      object.sim.surface.friction = friction;
    for (core::RobotDesc& robot : loaded.world.robots) {
      for (core::LinkDesc& link : robot.links) link.sim.surface.friction = friction;
    }
  }
  core::Simulator exact(loaded.world, {core::SolverType::kStep, 20});
  exact.SetDirectRobotSolve(false);     // dWorldStep's own LCP for robots too
  exact.SetNewtonObjectIslands(false);  // and for every island of objects
  core::Simulator fast(loaded.world, {fast_solver, 20});
  fast.SetDirectRobotSolve(false);  // the Newton solver's own iterations for robots too
  if (setup) {
    setup(&exact);
    setup(&fast);
  }
  exact.EnableContactFeedbackAll();
  fast.EnableContactFeedbackAll();
  Gap worst;
  for (int i = 0; i < steps; ++i) {
    exact.Simulate(step);
    fast.Simulate(step);
    const Gap gap = Compare(exact, fast);
    worst.position = std::max(worst.position, gap.position);
    worst.velocity = std::max(worst.velocity, gap.velocity);
    worst.force = std::max(worst.force, gap.force);
  }
  *newton = fast.statistics();
  return worst;
}

struct Case {
  const char* world;
  double step;  ///< s
  int steps;
  double position;     ///< largest gap allowed (m)
  double velocity;     ///< m/s
  bool newton = true;  ///< false: every island is ODE's (robots, world joints), the runs are one
  double friction = -1.0;  ///< >= 0: every surface's friction coefficient
};

// Resting, stacked, rolling, bouncing: both solvers meet the same rows and ODE's Dantzig solver
// is exact there, so the two runs agree to the Newton tolerance (1e-12 m/s per step, growing
// slowly over the steps). Sliding: ODE bounds each friction row by the normal force of the
// moment it pivots the row in, the Newton solver by the final one (newton_solver.h): the runs
// differ by 1.5e-7 m/s (measured), 1e-6 allowed.
const Case kCases[] = {
    {"accuracy/box_stack.xml", 0.01, 150, 1e-12, 1e-10},
    {"accuracy/heavy_on_light_1000.xml", 0.01, 300, 1e-12, 1e-10},
    {"stress/box_stack_20.xml", 0.01, 50, 1e-12, 1e-10},
    {"accuracy/bouncing_ball.xml", 0.001, 2000, 1e-12, 1e-10},
    {"accuracy/slide_to_roll.xml", 0.001, 1000, 1e-10, 1e-10},
    // slides along a diagonal until it rolls: 6.7e-11 m, 1.5e-10 m/s measured
    {"accuracy/slide_to_roll_spin.xml", 0.001, 1000, 1e-9, 1e-8},
    {"accuracy/mesh_jitter.xml", 0.001, 1000, 1e-12, 1e-10},
    {"accuracy/stiffness.xml", 0.001, 300, 1e-12, 1e-10},
    {"accuracy/incline.xml", 0.001, 500, 1e-8, 1e-6},
    {"accuracy/sliding_block_22_5.xml", 0.001, 1000, 1e-8, 1e-6},
    {"examples/door_drawer.xml", 0.001, 500, 0.0, 0.0, false},
    {"examples/two_blocks.xml", 0.001, 500, 1e-12, 1e-10},
    // robots (ode_joint_rows.h): their hinges, servos and joint friction
    {"examples/sensors.xml", 0.001, 500, 1e-12, 1e-10},    // a robot and a free object
    {"stress/chain_robot.xml", 0.001, 500, 1e-11, 1e-10},  // 1.9e-12 m, 1.5e-11 m/s
    // HRP-2 standing: without friction 5.9e-15 m, 4.1e-12 m/s; with it its feet's friction
    // saturates in places, as on the incline (1.6e-9 m, 9.6e-7 m/s measured)
    {"klampt/hrp2_plane.xml", 0.001, 300, 1e-12, 1e-10, true, 0.0},
    {"klampt/hrp2_plane.xml", 0.001, 300, 1e-8, 5e-6},
    // (its wheels land at 22 ms, sliding: with friction the runs part there by 0.03 rad/s, as
    // the sliding cases above do by less)
    {"klampt/athlete_plane.xml", 0.001, 300, 1e-12, 1e-10, true, 0.0},
};

// a test's name from its world file: accuracy/box_stack_20.xml -> BoxStack20
std::string CaseName(const std::string& world) {
  std::string name = world.substr(world.rfind('/') + 1);
  name = name.substr(0, name.find('.'));
  std::string camel;
  for (size_t i = 0; i < name.size(); ++i) {
    if (name[i] == '_') continue;
    const bool first = i == 0 || name[i - 1] == '_';
    camel += first ? static_cast<char>(std::toupper(name[i])) : name[i];
  }
  return camel;
}

class NewtonIslandsWorldTest : public testing::TestWithParam<Case> {};

TEST_P(NewtonIslandsWorldTest, StepsAsDWorldStepDoes) {
  const Case& c = GetParam();
  core::SimStatistics statistics;
  const Gap gap = LockStep(c.world, c.step, c.steps, &statistics, nullptr, c.friction);
  std::printf(
      "%s: gap %g m, %g m/s, %g of the weight; islands %ld, fallbacks %ld, Newton "
      "steps %ld\n",
      c.world, gap.position, gap.velocity, gap.force, statistics.newton_islands,
      statistics.newton_fallbacks, statistics.newton_iterations);
  EXPECT_LE(gap.position, c.position);
  EXPECT_LE(gap.velocity, c.velocity);
  // contact feedback comes from λ, which moves by 1e-3 N per 1e-12 m/s on a hard row
  // (object_islands.h): within 1e-3 of the world's weight (at most 3.9e-4 measured)
  EXPECT_LE(gap.force, 1e-3);
  if (c.newton) {
    EXPECT_GT(statistics.newton_islands, 0);
  } else {
    EXPECT_EQ(statistics.newton_islands, 0);
  }
  // a fallback hands the island to dWorldStep (the same answer, more time): rare
  EXPECT_LE(statistics.newton_fallbacks * 500, statistics.newton_islands);
}

INSTANTIATE_TEST_SUITE_P(Worlds, NewtonIslandsWorldTest, testing::ValuesIn(kCases),
                         [](const testing::TestParamInfo<Case>& param_info) {
                           const std::string name = CaseName(param_info.param.world);
                           return param_info.param.friction == 0.0 ? name + "Frictionless" : name;
                         });

// The exact solver's own object islands (object_islands.h): an island of free objects with at
// least kNewtonObjectContacts contacts is the Newton solver's, a smaller one stays with
// dWorldStep (the runs are then one, bit for bit). The same law, so the same steps where the
// Dantzig solver is exact; stiffness_test.xml's hard balls bounce with their friction saturated
// (ODE fixes each friction bound when it pivots the row in: newton_solver.h), and the runs part
// by micrometres; without friction they agree to rounding.
struct ExactCase {
  const char* world;
  double step;  ///< s
  int steps;
  double position;         ///< largest gap allowed (m)
  double velocity;         ///< m/s
  bool newton;             ///< the Newton solver takes islands (else none: the runs are one)
  double friction = -1.0;  ///< >= 0: every surface's friction coefficient
};

const ExactCase kExactCases[] = {
    {"accuracy/box_stack.xml", 0.01, 150, 1e-12, 1e-10, true},            // 40 contacts
    {"accuracy/heavy_on_light_1000.xml", 0.01, 300, 1e-12, 1e-10, true},  // 8
    // 8.3e-6 m, 2.5e-5 m/s measured; frictionless 1.2e-14 m, 1.0e-12 m/s
    {"klampt/simulation_test_worlds/stiffness_test.xml", 0.001, 800, 2e-5, 1e-4, true},
    {"klampt/simulation_test_worlds/stiffness_test.xml", 0.001, 800, 1e-12, 1e-10, true, 0.0},
    {"accuracy/sliding_block_22_5.xml", 0.001, 500, 0.0, 0.0, false},  // 4 contacts
};

class ExactObjectIslandsTest : public testing::TestWithParam<ExactCase> {};

TEST_P(ExactObjectIslandsTest, StepAsDWorldStepDoes) {
  const ExactCase& c = GetParam();
  core::SimStatistics statistics;
  const Gap gap =
      LockStep(c.world, c.step, c.steps, &statistics, nullptr, c.friction, core::SolverType::kStep);
  std::printf("%s: gap %g m, %g m/s; Newton islands %ld, fallbacks %ld, steps %ld\n", c.world,
              gap.position, gap.velocity, statistics.newton_islands, statistics.newton_fallbacks,
              statistics.newton_iterations);
  EXPECT_LE(gap.position, c.position);
  EXPECT_LE(gap.velocity, c.velocity);
  EXPECT_EQ(statistics.direct_islands, 0);
  if (c.newton) {
    EXPECT_GE(statistics.newton_islands, c.steps / 2);
  } else {
    EXPECT_EQ(statistics.newton_islands, 0);
  }
  EXPECT_LE(statistics.newton_fallbacks * 500, statistics.newton_islands);
}

INSTANTIATE_TEST_SUITE_P(Worlds, ExactObjectIslandsTest, testing::ValuesIn(kExactCases),
                         [](const testing::TestParamInfo<ExactCase>& param_info) {
                           const std::string name = CaseName(param_info.param.world);
                           return param_info.param.friction == 0.0 ? name + "Frictionless" : name;
                         });

// A kinematic pusher (infinite mass, its velocity in the rows' right-hand side) shoves a box that
// a held force pushes sideways, and the mouse spring holds a box (an ODE joint: the island goes
// back to dWorldStep while it holds). Without friction the runs agree through the impact; with
// friction 0.5 they part at the impact by 9e-4 m/s (measured): the box is shoved into sliding,
// friction saturates on the floor and on the pusher at once, and ODE fixes each friction bound
// from the normal force of the moment it pivots the row in (newton_solver.h).
TEST(NewtonIslandsTest, KinematicPushersHeldForcesAndTheMouseSpringStepAsDWorldStepDoes) {
  const WorldSetup push = [](core::Simulator* simulator) {
    core::SimBody pusher = simulator->body(1);  // two_blocks.xml: the floor, pusher, pushed
    pusher.EnableDynamics(false);
    pusher.SetVelocity({core::Vec3(0.5, 0.0, 0.0), core::Vec3::Zero()});
    simulator->SetAppliedWrench(2, core::Vec3(0.0, 0.2, 0.0), core::Vec3(0.0, 0.0, 0.01));
  };
  core::SimStatistics statistics;
  Gap gap = LockStep("examples/two_blocks.xml", 0.001, 800, &statistics, push, 0.0);
  EXPECT_LE(gap.position, 1e-10);  // the pusher reaches the box at 0.39 s; 7.7e-12 m measured
  EXPECT_LE(gap.velocity, 1e-10);
  EXPECT_EQ(statistics.newton_islands, 800);  // the box's, every step (a kinematic body joins none)
  EXPECT_GT(statistics.newton_islands, 0);
  const WorldSetup drag = [](core::Simulator* simulator) {
    const core::Vec3 point = simulator->GetObjectPose(1).translation();
    ASSERT_TRUE(simulator->StartDrag(2, point));
    simulator->SetDragTarget(point + core::Vec3(0.0, 0.0, 0.2));
  };
  gap = LockStep("examples/two_blocks.xml", 0.001, 300, &statistics, drag);
  EXPECT_LE(gap.position, 1e-12);  // the dragged box is dWorldStep's, the resting pusher Newton's
  EXPECT_LE(gap.velocity, 1e-10);
  EXPECT_EQ(statistics.newton_islands, 300);  // the pusher's, every step
}

// The 210-box pyramid with one Newton step a time step (SetNewtonBudget): its island (about 4,800
// rows) is too large for dWorldStep's dense LCP (object_islands.h kMostHandBackRows: a hand-back
// would take about 30 s and 180 MB a step), so a step the Newton solver does not settle is relaxed
// by Gauss–Seidel sweeps (row_relaxation.h) and says so ("contact unreliable", newton.unconverged),
// under both solvers; the pyramid stands all the same. The 10-box stack (120 rows) is still
// handed back.
struct BudgetRun {
  core::SimStatistics statistics;
  double top_moved = 0.0;  ///< how far the last object moved, m
};

BudgetRun RunWithNewtonBudget(const std::string& world_file, core::SolverType solver, int steps) {
  test::LoadedWorld loaded;
  test::LoadWorld(test::WorldsPath(world_file), &loaded);
  EXPECT_TRUE(loaded.ok) << world_file;
  loaded.world.settings.solver = solver;
  core::Simulator simulator(loaded.world);
  simulator.SetNewtonBudget(1);
  const int top = simulator.object_count() - 1;
  const core::Vec3 start = simulator.GetObjectPose(top).translation();
  for (int k = 0; k < steps; ++k) simulator.Simulate(loaded.world.settings.timestep);
  BudgetRun run;
  run.statistics = simulator.statistics();
  run.top_moved = (simulator.GetObjectPose(top).translation() - start).norm();
  return run;
}

TEST(NewtonIslandsTest, AnIslandTooLargeForDWorldStepIsRelaxedAndFlagsTheStep) {
  for (const core::SolverType solver : {core::SolverType::kStep, core::SolverType::kNewton}) {
    const BudgetRun run = RunWithNewtonBudget("accuracy/pyramid_20.xml", solver, 40);
    const core::SimStatistics& s = run.statistics;
    // every step's pyramid island relaxed (a few small islands of the first steps, before every
    // box touches, went back to dWorldStep); measured: 40, top box 6.1e-5 m, overlap 2.0e-5 m
    EXPECT_EQ(s.newton_unconverged, 40);
    EXPECT_EQ(s.unreliable_steps, 40);
    EXPECT_EQ(s.worst_status, core::StepStatus::kContactUnreliable);
    EXPECT_EQ(s.instability_corrections, 0);
    EXPECT_LT(s.max_penetration, 2.5e-3);  // within the padding
    EXPECT_LT(run.top_moved, 1e-3);        // the pyramid stands
  }
  const BudgetRun small =
      RunWithNewtonBudget("accuracy/box_stack.xml", core::SolverType::kNewton, 40);
  EXPECT_GT(small.statistics.newton_fallbacks, 0);
  EXPECT_EQ(small.statistics.newton_unconverged, 0);
  EXPECT_EQ(small.statistics.unreliable_steps, 0);
  EXPECT_LT(small.top_moved, 1e-3);
}

// The TX90's wrist driven into its stops by constant torques (hinge stop rows: the stop ERP,
// one-sided bounds) and its arm falling under torque mode (no servo rows, joint friction only):
// the same steps as dWorldStep's.
TEST(NewtonIslandsTest, RobotJointsDrivenIntoTheirStopsStepAsDWorldStepDoes) {
  const WorldSetup drive = [](core::Simulator* simulator) {
    core::RobotController& controller = simulator->controller(0);
    core::VecX torque = core::VecX::Zero(static_cast<int>(controller.drivers().size()));
    torque.tail<3>().setConstant(1.0);  // N·m on the wrist
    ASSERT_TRUE(controller.SetTorque(torque));
  };
  core::SimStatistics statistics;
  const Gap gap = LockStep("examples/sensors.xml", 0.001, 1500, &statistics, drive, 0.0);
  std::printf("stops: gap %g m, %g m/s\n", gap.position, gap.velocity);
  EXPECT_LE(gap.position, 1e-10);  // 3.9e-12 m measured
  EXPECT_LE(gap.velocity, 1e-8);   // 6.6e-10 m/s
  EXPECT_EQ(statistics.newton_fallbacks, 0);
  // the wrist reached a stop (within the stop's ERP correction)
  test::LoadedWorld loaded;
  test::LoadWorld(test::WorldsPath("examples/sensors.xml"), &loaded);
  core::Simulator simulator(loaded.world, {core::SolverType::kNewton, 20});
  drive(&simulator);
  simulator.Simulate(1.5);
  const core::RobotDesc& robot = simulator.world().robots[0];
  const core::VecX q = simulator.GetRobotConfig(0);
  int at_stop = 0;
  for (int l = 0; l < robot.dof(); ++l) {
    const double distance = std::min(q[l] - robot.links[l].q_min, robot.links[l].q_max - q[l]);
    if (distance < 1e-3) ++at_stop;
  }
  EXPECT_GE(at_stop, 1);
}

// The cart-pole: a slider (its three rotation rows, two rows on the axis, the stop row with the
// torque decoupling of a linear row) and its linear motor, with the pole's hinge on the cart.
// Pushed by a held force, the cart reaches its stop at 1.33 s: the runs agree to 1e-12 m/s until
// then and to 2e-10 m/s through the first impact on the stop (measured). Held against the stop,
// the cart then rattles on it (the stop row turns on and off, and its friction motor is off
// within 1e-9 of the stop), each step deciding both at a threshold: there the runs part, by
// 4e-6 m/s after 2 s (measured), as any two runs 1e-10 apart would. And a robot while one of its
// links is dragged (the mouse spring is an ODE joint on its body) stays with dWorldStep, and goes
// back to the Newton solver when the drag ends.
TEST(NewtonIslandsTest, SlidersStepAsDWorldStepDoesAndDraggedRobotsStayWithIt) {
  const std::unique_ptr<test::LoadedRobot> cartpole =
      test::LoadRobot(test::WorldsPath("klampt/robots/cartpole.rob"));
  ASSERT_FALSE(cartpole->diagnostics.HasErrors()) << cartpole->diagnostics.FormatAll();
  core::WorldDesc world;
  world.robots.push_back(cartpole->robot);
  core::Simulator exact(world, {core::SolverType::kStep, 20});
  exact.SetDirectRobotSolve(false);  // dWorldStep's own LCP
  core::Simulator fast(world, {core::SolverType::kNewton, 20});
  const int cart = world.RobotLinkId(0, 0);
  Gap before_stop, after;
  for (int i = 0; i < 2000; ++i) {
    for (core::Simulator* simulator : {&exact, &fast}) {
      simulator->SetAppliedWrench(cart, core::Vec3(-20.0, 0.0, 0.0), core::Vec3::Zero());
      simulator->Simulate(0.001);
    }
    Gap& gap = i < 1340 ? before_stop : after;
    for (int l = 0; l < world.robots[0].dof(); ++l) {
      const int id = world.RobotLinkId(0, l);
      gap.position = std::max(gap.position, (exact.body(id).GetTransform().translation() -
                                             fast.body(id).GetTransform().translation())
                                                .norm());
      gap.velocity = std::max(
          gap.velocity,
          (exact.body(id).GetVelocity().linear - fast.body(id).GetVelocity().linear).norm());
    }
  }
  std::printf("cart-pole: gap %g m, %g m/s to the first impact on the stop, %g m, %g m/s after\n",
              before_stop.position, before_stop.velocity, after.position, after.velocity);
  EXPECT_LE(before_stop.position, 1e-11);  // 2e-12 m measured
  EXPECT_LE(before_stop.velocity, 1e-9);
  EXPECT_LE(after.position, 1e-7);
  EXPECT_LE(after.velocity, 1e-4);
  EXPECT_GE(fast.statistics().newton_islands, 2000);
  EXPECT_EQ(fast.statistics().newton_fallbacks, 0);
  // the cart reached its stop (qMin -3 m) and stays there
  EXPECT_NEAR(fast.GetRobotConfig(0)[0], world.robots[0].links[0].q_min, 1e-3);

  test::LoadedWorld loaded;
  test::LoadWorld(test::WorldsPath("stress/chain_robot.xml"), &loaded);
  ASSERT_TRUE(loaded.ok);
  core::Simulator chain(loaded.world, {core::SolverType::kNewton, 20});
  const int link = loaded.world.RobotLinkId(0, 20);
  const core::Vec3 point = chain.body(link).GetTransform().translation();
  ASSERT_TRUE(chain.StartDrag(link, point));
  chain.SetDragTarget(point + core::Vec3(0.1, 0.0, 0.0));
  chain.Simulate(0.1);
  EXPECT_EQ(chain.statistics().newton_islands, 0);
  EXPECT_EQ(chain.statistics().direct_islands, 0);
  chain.EndDrag();
  chain.Simulate(0.1);
  EXPECT_GE(chain.statistics().newton_islands, 100);  // every step once the drag has ended
  EXPECT_EQ(chain.statistics().newton_fallbacks, 0);
}

}  // namespace
}  // namespace lamina
