// SPDX-License-Identifier: MIT
// The one live-edit path into a running simulation (Simulator::SetParam and the setters built on
// it): setters refuse exactly what the table refuses, every apply kind reaches the simulation,
// driver data lives once (gains edited live survive Reset, reach UpdateWorld and the saved
// file), a simulation stopped by an error is revived by SetState, Reset or Rebuild, results do
// not depend on the Simulate chunking, held wrenches last, step observers see every accepted step,
// and one change rule decides what a teleport invalidates (FakeSimulate like SetRobotConfig).
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "core/io/world_file.h"
#include "core/sim/simulator.h"
#include "tests/common/scene_builders.h"
#include "tests/common/test_support.h"

namespace lamina {
namespace {

using core::ElementIndex;
using core::ParamValue;
using core::Vec3;
using core::VecX;

using test::kBoxSide;

const core::ParamSpec& Row(std::string_view key, core::ElementKind kind) {
  const core::ParamSpec* spec = core::FindParam(key, kind);
  EXPECT_NE(spec, nullptr) << key;
  return *spec;
}

// two boxes resting on a plane, one pushed to slide
core::WorldDesc TwoBoxes() {
  core::WorldDesc world;
  world.terrains.push_back(test::PlaneTerrain(0.5, 0.0));
  world.objects.push_back(test::BoxObject(kBoxSide, 1.0, Vec3(0, 0, kBoxSide / 2)));
  world.objects.push_back(test::BoxObject(kBoxSide, 1.0, Vec3(1, 0, kBoxSide / 2)));
  world.objects[0].initial_velocity.linear = Vec3(1.0, 0, 0);
  return world;
}

// the pendulum of tests/common/scene_builders.h, started at 0.3 rad
core::WorldDesc Pendulum(const std::string& extra) {
  return test::PendulumWorld(extra, 0.3);
}

TEST(LiveEditTest, SettersRefuseWhatTheReadersRefuse) {
  core::Simulator simulator(TwoBoxes());
  core::SimBody box = simulator.body(1);
  const core::SurfaceDesc good = box.GetSurface();
  core::SurfaceDesc bouncy = good;
  bouncy.restitution = 1.5;  // a file with kRestitution="1.5" does not load
  EXPECT_THROW(box.SetSurface(bouncy), std::invalid_argument);
  core::SurfaceDesc limp = good;
  limp.stiffness = 0.0;  // kStiffness must be > 0
  EXPECT_THROW(box.SetSurface(limp), std::invalid_argument);
  EXPECT_EQ(box.GetSurface(), good);  // nothing of a refused surface was written
  EXPECT_THROW(simulator.SetGravity(Vec3(std::nan(""), 0, 0)), std::invalid_argument);
  EXPECT_EQ(simulator.world().settings.gravity, Vec3(0, 0, -9.8));
  EXPECT_THROW(simulator.SetSimStep(-0.001), std::invalid_argument);  // once ignored silently
  EXPECT_THROW(simulator.SetSimStep(0.0), std::invalid_argument);
  EXPECT_EQ(simulator.sim_step(), 0.001);
  std::string error;
  EXPECT_FALSE(simulator.SetParam(ElementIndex::Object(0),
                                  Row("kRestitution", core::ElementKind::kObject), {1.5}, &error));
  EXPECT_EQ(error, "objects[0].kRestitution must be in [0, 1], got 1.5");
  EXPECT_THROW(simulator.body(99).GetTransform(), std::out_of_range);
  EXPECT_THROW(simulator.GetObjectPose(2), std::out_of_range);
  EXPECT_THROW(simulator.controller(0), std::out_of_range);
}

// a box sliding at v0 on μ stops after v0² / (2 μ g)
TEST(LiveEditTest, AFrictionEditActsFromTheNextStep) {
  core::Simulator simulator(TwoBoxes());
  std::string error;
  // the box on the plane: blended μ is the harmonic mean of the two bodies' 0.5 and 0.2
  ASSERT_TRUE(simulator.SetParam(ElementIndex::Object(0),
                                 Row("kFriction", core::ElementKind::kObject), {0.2}, &error))
      << error;
  simulator.Simulate(1.0);
  const double mu = 2 * 0.5 * 0.2 / (0.5 + 0.2);
  EXPECT_NEAR(simulator.GetObjectPose(0).translation().x(), 1.0 / (2 * mu * 9.8), 0.01);
}

TEST(LiveEditTest, PaddingRebuildsGeometryAndMassRebuildsTheSimulationKeepingItsState) {
  core::Simulator simulator(TwoBoxes());
  simulator.Simulate(0.05);
  std::string error;
  ASSERT_TRUE(simulator.SetParam(ElementIndex::Object(1),
                                 Row("padding", core::ElementKind::kObject), {0.004}, &error));
  EXPECT_EQ(simulator.world().objects[1].sim.padding, 0.004);
  const core::SimState before = simulator.GetState();
  ASSERT_TRUE(simulator.SetParam(ElementIndex::Object(1), Row("mass", core::ElementKind::kObject),
                                 {3.0}, &error));
  EXPECT_EQ(simulator.GetState(), before);  // rebuilt, the state restored bit for bit
  EXPECT_EQ(simulator.world().objects[1].mass, 3.0);
  // a new centre of mass keeps the object's frame where it was (the mass moves)
  const core::Pose frame = simulator.GetObjectPose(1);
  ASSERT_TRUE(simulator.SetParam(ElementIndex::Object(1), Row("com", core::ElementKind::kObject),
                                 {0.01, 0, 0}, &error));
  EXPECT_NEAR((simulator.GetObjectPose(1).matrix() - frame.matrix()).norm(), 0.0, 1e-15);
  simulator.Simulate(0.5);
  EXPECT_FALSE(simulator.halted());
}

TEST(LiveEditTest, InitialConditionEditsChangeOnlyWhatResetStartsFrom) {
  core::Simulator simulator(TwoBoxes());
  simulator.Simulate(0.1);
  const core::SimState now = simulator.GetState();
  core::Pose start = core::Pose::Identity();
  start.translation() = Vec3(2, 0, kBoxSide / 2);
  std::string error;
  ASSERT_TRUE(simulator.SetParam(ElementIndex::Object(1),
                                 Row("transform", core::ElementKind::kObject),
                                 core::PoseToValue(start), &error));
  EXPECT_EQ(simulator.GetState(), now);
  simulator.Reset();
  EXPECT_EQ(simulator.GetObjectPose(1).translation(), Vec3(2, 0, kBoxSide / 2));
}

TEST(LiveEditTest, GainsAndFrictionEditedLiveSurviveResetAndReachTheSavedWorld) {
  core::Simulator simulator(Pendulum("servoP 10\nservoI 0\nservoD 1\nqMin -1\nqMax 1\n"));
  std::string error;
  ASSERT_TRUE(simulator.SetParam(ElementIndex::Driver(0, 0),
                                 Row("servoP", core::ElementKind::kDriver), {80.0}, &error));
  ASSERT_TRUE(simulator.SetParam(ElementIndex::Driver(0, 0),
                                 Row("dryFriction", core::ElementKind::kDriver), {0.3}, &error));
  simulator.SetJointLimits(0, 0, -0.8, 0.9);
  // the controller's drivers are the simulation's description: one copy
  EXPECT_EQ(simulator.controller(0).drivers()[0].servo_p, 80.0);
  simulator.Simulate(0.2);
  simulator.Reset();
  EXPECT_EQ(simulator.controller(0).drivers()[0].servo_p, 80.0);  // once lost on Reset
  EXPECT_EQ(simulator.controller(0).drivers()[0].dry_friction, 0.3);
  VecX kp, ki, kd;
  simulator.controller(0).GetPIDGains(&kp, &ki, &kd);
  EXPECT_EQ(kp[0], 80.0);
  core::WorldDesc updated = Pendulum("servoP 10\nservoI 0\nservoD 1\nqMin -1\nqMax 1\n");
  simulator.UpdateWorld(&updated);
  EXPECT_EQ(updated.robots[0].drivers[0].servo_p, 80.0);  // once never written back
  EXPECT_EQ(updated.robots[0].drivers[0].dry_friction, 0.3);
  EXPECT_EQ(updated.robots[0].links[0].q_min, -0.8);  // joint limits were never written back
  // saved and loaded again
  const std::string path = test::ScratchDir() + "/pendulum.xml";
  core::Diagnostics diagnostics;
  ASSERT_TRUE(core::SaveWorldFile(simulator.world(), path, diagnostics)) << diagnostics.FormatAll();
  test::LoadedWorld loaded;
  test::LoadWorld(path, &loaded);
  ASSERT_TRUE(loaded.ok) << loaded.diagnostics.FormatAll();
  EXPECT_EQ(loaded.world.robots[0].drivers[0].servo_p, 80.0);
  EXPECT_EQ(loaded.world.robots[0].drivers[0].dry_friction, 0.3);
  EXPECT_EQ(loaded.world.robots[0].links[0].q_max, 0.9);
}

// an absurd torque on a robot joint (1e200 N·m) makes ODE fail inside its step, before the robot
// guard can put the robot back (core/sim/robot_guard.h); ODE cannot be trusted after that, so the
// simulation stops
TEST(LiveEditTest, ASimulationStoppedByAnErrorIsRevivedBySetStateResetAndRebuild) {
  const std::string gains = "servoP 50\nservoI 0\nservoD 5\n";
  core::Simulator simulator(Pendulum(gains));
  simulator.Simulate(0.05);
  const core::SimState good = simulator.GetState();
  const auto break_it = [&] {
    ASSERT_TRUE(simulator.controller(0).SetTorque(VecX::Constant(1, 1e200)));
    EXPECT_EQ(simulator.Simulate(0.01), core::StepStatus::kError);
    ASSERT_TRUE(simulator.halted());
    EXPECT_EQ(simulator.Simulate(0.01), core::StepStatus::kError);
  };
  break_it();
  simulator.SetState(good);  // once only Reset revived it
  EXPECT_FALSE(simulator.halted());
  EXPECT_EQ(simulator.GetState(), good);
  EXPECT_NE(simulator.Simulate(0.1), core::StepStatus::kError);
  // the revived run is the run from that state in a fresh simulator
  core::Simulator fresh(Pendulum(gains));
  fresh.SetState(good);
  fresh.Simulate(0.1);
  EXPECT_EQ(simulator.GetState(), fresh.GetState());
  EXPECT_TRUE(simulator.GetRobotConfig(0).allFinite());
  break_it();
  simulator.Reset();  // Reset revives too
  EXPECT_NE(simulator.Simulate(0.01), core::StepStatus::kError);
  const double before = simulator.time();
  break_it();
  simulator.Rebuild();  // and Rebuild, at the start of the step that failed
  EXPECT_FALSE(simulator.halted());
  EXPECT_EQ(simulator.time(), before);
  EXPECT_TRUE(simulator.GetRobotConfig(0).allFinite());
  core::SimState broken = good;
  broken.objects.emplace_back();
  broken.robots[0].bodies[0].com_position.x() = std::nan("");
  EXPECT_THROW(simulator.SetState(broken), std::invalid_argument);
}

TEST(LiveEditTest, RebuildKeepsWhatIsNotStateEither) {
  core::Simulator simulator(TwoBoxes());
  simulator.body(2).EnableDynamics(false);
  simulator.body(1).Enable(false);
  simulator.SetAppliedWrench(2, Vec3(1, 0, 0), Vec3::Zero());
  simulator.Simulate(0.02);
  const core::SimState state = simulator.GetState();
  simulator.Rebuild();
  EXPECT_EQ(simulator.GetState(), state);
  EXPECT_FALSE(simulator.body(2).dynamics_enabled());
  EXPECT_FALSE(simulator.body(1).enabled());
}

core::WorldDesc Stack() {
  core::WorldDesc world;
  world.terrains.push_back(test::PlaneTerrain(0.5, 0.2));
  for (int i = 0; i < 4; ++i) {
    world.objects.push_back(test::BoxObject(kBoxSide, 1.0, Vec3(0.01 * i, 0, 0.06 + 0.105 * i)));
  }
  return world;
}

// Simulate(0.01) once and Simulate(0.001) ten times take the same steps (the last sub-step of a
// call once absorbed the call's rounding: 0.017 s in 0.001 s steps ended with a step of
// 0.0010000000000000009 s)
TEST(ChunkingTest, OneCallAndTenCallsGiveBitIdenticalStates) {
  for (const int steps : {10, 17}) {
    core::Simulator whole(Stack()), chunked(Stack());
    for (int frame = 0; frame < 30; ++frame) {
      whole.Simulate(0.001 * steps);
      for (int i = 0; i < steps; ++i) chunked.Simulate(0.001);
      ASSERT_EQ(whole.GetState(), chunked.GetState()) << steps << " steps, frame " << frame;
    }
    EXPECT_EQ(whole.time(), chunked.time());
    EXPECT_EQ(whole.statistics().steps, chunked.statistics().steps);
  }
}

TEST(ChunkingTest, ARobotUnderItsControllerToo) {
  const std::string gains = "servoP 50\nservoI 5\nservoD 2\n";
  core::Simulator whole(Pendulum(gains)), chunked(Pendulum(gains));
  ASSERT_TRUE(whole.controller(0).SetMilestone(VecX::Constant(1, -0.4)));
  ASSERT_TRUE(chunked.controller(0).SetMilestone(VecX::Constant(1, -0.4)));
  for (int frame = 0; frame < 50; ++frame) {
    whole.Simulate(0.017);
    for (int i = 0; i < 17; ++i) chunked.Simulate(0.001);
    ASSERT_EQ(whole.GetRobotConfig(0), chunked.GetRobotConfig(0)) << "frame " << frame;
  }
}

// a held force F on a box on a frictionless plane for 1 s in 60 frames: v = F t / m, as in one
// call; a one-call force applied once acts for its call only
TEST(HeldWrenchTest, AHeldForceLastsAcrossCallsUntilCleared) {
  core::WorldDesc world;
  world.terrains.push_back(test::PlaneTerrain(0.0, 0.0));
  world.objects.push_back(test::BoxObject(kBoxSide, 2.0, Vec3(0, 0, kBoxSide / 2)));
  world.objects[0].sim.surface.friction = 0.0;
  core::Simulator held(world), once(world);
  held.SetAppliedWrench(1, Vec3(4, 0, 0), Vec3::Zero());
  once.body(1).ApplyWrench(Vec3(4, 0, 0), Vec3::Zero());
  for (int frame = 0; frame < 60; ++frame) {
    held.Simulate(1.0 / 60);
    once.Simulate(1.0 / 60);
  }
  EXPECT_NEAR(held.GetObjectVelocity(0).linear.x(), 4.0 * 1.0 / 2.0, 1e-6);
  EXPECT_NEAR(once.GetObjectVelocity(0).linear.x(), 4.0 / 60 / 2.0, 1e-6);
  held.ClearAppliedWrench(1);
  held.Simulate(0.5);
  EXPECT_NEAR(held.GetObjectVelocity(0).linear.x(), 2.0, 1e-6);
  // at a point of the body: a force at +z above the centre spins the box about y
  core::Simulator at_point(world);
  at_point.SetAppliedForceAtLocalPoint(1, Vec3(1, 0, 0), Vec3(0, 0, 0.05));
  at_point.Simulate(0.001);
  EXPECT_GT(at_point.GetObjectVelocity(0).angular.y(), 0.0);
}

TEST(StepObserverTest, EveryAcceptedStepIsReportedWhateverTheChunking) {
  core::Simulator whole(Stack()), chunked(Stack());
  std::vector<double> whole_times, chunked_times;
  core::SimStatistics accumulated;
  whole.AddStepObserver([&](const core::StepEvent& event) {
    whole_times.push_back(event.time);
    core::AccumulateStep(event, &accumulated);
  });
  const int id =
      chunked.AddStepObserver([&](const core::StepEvent& e) { chunked_times.push_back(e.time); });
  whole.Simulate(0.3);
  for (int i = 0; i < 30; ++i) chunked.Simulate(0.01);
  EXPECT_EQ(whole_times, chunked_times);
  EXPECT_EQ(static_cast<long>(whole_times.size()), whole.statistics().steps);
  EXPECT_EQ(accumulated.contact_joints, whole.statistics().contact_joints);
  EXPECT_EQ(accumulated.max_penetration, whole.statistics().max_penetration);
  EXPECT_EQ(whole_times.back(), whole.time());
  chunked.RemoveStepObserver(id);
  chunked.Simulate(0.01);
  EXPECT_EQ(chunked_times.size(), whole_times.size());
}

// a box resting on a robot's flat link holds a friction anchor with it; moving the robot by
// hand drops that anchor, by SetRobotConfig and by FakeSimulate alike (FakeSimulate once kept it,
// so the box was pulled back towards where the link had been)
TEST(ChangeRuleTest, FakeSimulateInvalidatesLikeSetRobotConfig) {
  for (const bool fake : {false, true}) {
    core::WorldDesc world = Pendulum("servoP 200\nservoI 0\nservoD 20\n");
    // the link carries a 0.4 x 0.4 x 0.02 plate at its frame; a box rests on it
    world.robots[0].links[0].geometry = {
        test::PrimitiveGeometry(core::Primitive::Box(Vec3(0.4, 0.4, 0.02)))};
    world.robots[0].links[0].com = Vec3::Zero();
    world.robots[0].config = VecX::Zero(1);
    world.objects.push_back(test::BoxObject(kBoxSide, 0.2, Vec3(0, 0, 1.0 + 0.01 + kBoxSide / 2)));
    core::Simulator simulator(world);
    simulator.Simulate(0.5);
    const int link = simulator.world().RobotLinkId(0, 0);
    const auto link_anchors = [&] {
      int count = 0;
      for (const core::FrictionAnchor& anchor : simulator.GetState().anchors) {
        count += anchor.a == link || anchor.b == link ? 1 : 0;
      }
      return count;
    };
    ASSERT_EQ(link_anchors(), 1) << "fake " << fake;
    if (fake) {
      ASSERT_TRUE(simulator.controller(0).SetPIDCommand(VecX::Constant(1, 0.05), VecX::Zero(1)));
      simulator.FakeSimulate(0.01);
    } else {
      simulator.SetRobotConfig(0, VecX::Constant(1, 0.05));
    }
    EXPECT_EQ(link_anchors(), 0) << "fake " << fake;
  }
}

// a rebuild restores bodies at their centres of mass: a link whose centre of mass moved, or a
// continuous joint built at another reference, is placed again by its configuration
TEST(RebuildTest, RobotLinksStayWhereTheyWereAndContinuousJointsKeepTheirTurns) {
  core::Simulator simulator(Pendulum("servoP 50\nservoI 0\nservoD 5\n"));  // no limits: wide
  simulator.SetRobotConfig(0, VecX::Constant(1, 4.0));  // past a half turn from where it was built
  const int link = simulator.world().RobotLinkId(0, 0);
  const core::Pose frame = simulator.body(link).GetTransform();
  std::string error;
  ASSERT_TRUE(simulator.SetParam(ElementIndex::Robot(0), Row("config", core::ElementKind::kRobot),
                                 {4.0}, &error));  // the next build counts turns from 4
  ASSERT_TRUE(simulator.SetParam(ElementIndex::Link(0, 0), Row("com", core::ElementKind::kLink),
                                 {0.0, 0.0, -0.3}, &error));  // rebuilt; the body's COM moved
  EXPECT_NEAR(simulator.GetRobotConfig(0)[0], 4.0, 1e-12);
  EXPECT_TRUE(simulator.body(link).GetTransform().isApprox(frame, 1e-12));
}

TEST(RebuildTest, ControllersAndTheirSettingsSurviveARebuild) {
  core::Simulator simulator(Pendulum("servoP 50\nservoI 0\nservoD 5\n"));
  core::RobotController& controller = simulator.controller(0);
  controller.SetGravityCompensation(true);
  ASSERT_TRUE(controller.SetControlPeriod(0.002));
  std::string error;
  ASSERT_TRUE(simulator.SetParam(ElementIndex::Link(0, 0), Row("mass", core::ElementKind::kLink),
                                 {3.0}, &error));
  EXPECT_EQ(&simulator.controller(0), &controller);  // references stay valid
  EXPECT_TRUE(simulator.controller(0).gravity_compensation());
  EXPECT_EQ(simulator.controller(0).control_period(), 0.002);
}

TEST(LiveEditTest, VelocityAndTorqueLimitsReachTheControllersRampsLive) {
  core::Simulator simulator(Pendulum("servoP 50\nservoI 0\nservoD 5\nqMin -1\nqMax 1\n"));
  std::string error;
  ASSERT_TRUE(simulator.SetParam(ElementIndex::Driver(0, 0),
                                 Row("velocityLimits", core::ElementKind::kDriver), {-0.5, 0.5},
                                 &error));
  EXPECT_EQ(simulator.controller(0).limits().velocity_max[0], 0.5);  // once only after Reset
  ASSERT_TRUE(simulator.SetParam(
      ElementIndex::Link(0, 0), Row("jointLimits", core::ElementKind::kLink), {-0.7, 0.9}, &error));
  EXPECT_EQ(simulator.controller(0).limits().q_max[0], 0.9);
  EXPECT_EQ(simulator.world().robots[0].drivers[0].q_max, 0.9);  // the driver's copy follows
}

TEST(LiveEditTest, UpdateWorldWritesEveryRowAndTheCurrentState) {
  core::Simulator simulator(TwoBoxes());
  std::string error;
  ASSERT_TRUE(simulator.SetParam(ElementIndex::Object(1), Row("mass", core::ElementKind::kObject),
                                 {2.5}, &error));
  ASSERT_TRUE(simulator.SetParam(ElementIndex::Settings(),
                                 Row("frictionAnchorGain", core::ElementKind::kSettings), {0.3},
                                 &error));
  simulator.Simulate(0.1);
  core::WorldDesc world = TwoBoxes();
  simulator.UpdateWorld(&world);
  EXPECT_EQ(world.objects[1].mass, 2.5);
  EXPECT_EQ(world.settings.friction_anchor_gain, 0.3);
  EXPECT_EQ(world.objects[0].pose.translation(), simulator.GetObjectPose(0).translation());
  core::WorldDesc other = TwoBoxes();
  other.objects.pop_back();
  EXPECT_THROW(simulator.UpdateWorld(&other), std::invalid_argument);
}

TEST(LiveEditTest, BadArgumentsAreRefusedWithAMessage) {
  core::Simulator simulator(TwoBoxes());
  EXPECT_THROW(simulator.Simulate(std::numeric_limits<double>::infinity()), std::invalid_argument);
  EXPECT_THROW(simulator.Simulate(-1.0), std::invalid_argument);
  EXPECT_THROW(simulator.SetSolver({core::SolverType::kQuickStep, 2000000}), std::invalid_argument);
  core::Pose sheared = core::Pose::Identity();
  sheared.linear()(0, 1) = 0.5;
  EXPECT_THROW(simulator.body(1).SetTransform(sheared), std::invalid_argument);
  core::SimState state = simulator.GetState();
  state.objects[0].orientation.coeffs() *= 2.0;
  EXPECT_THROW(simulator.SetState(state), std::invalid_argument);
  core::DragSpringSettings limp;
  limp.frequency = 0.0;
  EXPECT_THROW(simulator.StartDrag(1, Vec3(0, 0, kBoxSide), limp), std::invalid_argument);
  EXPECT_FALSE(simulator.dragging());
}

TEST(StepObserverTest, AnObserverMayRemoveItselfWhileCalled) {
  core::Simulator simulator(TwoBoxes());
  int calls = 0, id = -1;
  id = simulator.AddStepObserver([&](const core::StepEvent&) {
    ++calls;
    simulator.RemoveStepObserver(id);
  });
  int others = 0;
  simulator.AddStepObserver([&](const core::StepEvent&) { ++others; });
  simulator.Simulate(0.005);
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(others, 5);
}

}  // namespace
}  // namespace lamina
