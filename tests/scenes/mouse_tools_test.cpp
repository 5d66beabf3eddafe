// SPDX-License-Identifier: MIT
// The interaction primitives the mouse tools call (interaction.h): the implicit mouse spring
// scaled by the effective mass at the grabbed point (the same drag moves a 0.1 kg and a 100 kg
// box alike, the force never exceeds its cap, releasing adds no energy), and kinematic targets
// (a moving box pushes another and carries one resting on it by friction; on release it keeps
// its velocity). Both work on robot links too.
#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "core/sim/simulator.h"
#include "tests/common/scene_builders.h"

namespace lamina {
namespace {

using core::Pose;
using core::Vec3;
using core::VecX;

constexpr double kFrame = 1.0 / 60;  // what the viewer advances per frame (s)

core::WorldDesc BoxOnPlane(double mass) {
  core::WorldDesc world;
  world.terrains.push_back(test::PlaneTerrain(0.5, 0.3));
  world.objects.push_back(test::BoxObject(0.1, mass, Vec3(0, 0, 0.05)));
  return world;
}

struct DragRun {
  std::vector<Vec3> path;     ///< box origin every frame
  double largest_force = 0;   ///< N, over every step
  double cap = 0;             ///< N
  double effective_mass = 0;  ///< kg at the grabbed point
};

// grabs the box at its top edge and moves the target by the frame: 0.3 m along x over 1 s and
// 0.2 m up, then a 1 m jump that the caps must absorb
DragRun DragBox(double mass) {
  core::Simulator simulator(BoxOnPlane(mass));
  simulator.Simulate(0.1);  // settle
  const Vec3 grab(0.0, 0.0, 0.1);
  EXPECT_TRUE(simulator.StartDrag(1, grab));
  DragRun run;
  run.cap = simulator.drag().spring.max_force;
  run.effective_mass = simulator.drag().effective_mass;
  simulator.AddStepObserver([&](const core::StepEvent& event) {
    run.largest_force = std::max(run.largest_force, event.simulator.drag().force.norm());
  });
  for (int frame = 0; frame < 150; ++frame) {
    const double s = std::min(1.0, frame * kFrame);
    const double smooth = 0.5 - 0.5 * std::cos(core::kPi * s);
    Vec3 target = grab + Vec3(0.3 * smooth, 0.0, 0.2 * smooth);
    if (frame >= 100) target += Vec3(0.0, 1.0, 0.0);  // flung
    simulator.SetDragTarget(target);
    simulator.Simulate(kFrame);
    run.path.push_back(simulator.GetObjectPose(0).translation());
  }
  return run;
}

TEST(MouseSpringTest, TheSameDragMovesALightAndAHeavyBoxAlike) {
  const DragRun light = DragBox(0.1);
  const DragRun heavy = DragBox(100.0);
  double largest_move = 0.0, largest_difference = 0.0;
  for (size_t i = 0; i < light.path.size(); ++i) {
    largest_move = std::max(largest_move, (light.path[i] - light.path.front()).norm());
    largest_difference = std::max(largest_difference, (light.path[i] - heavy.path[i]).norm());
  }
  EXPECT_GT(largest_move, 0.25);  // it really moved with the mouse
  EXPECT_LT(largest_difference, 0.05 * largest_move);
  // the lift followed the target within the spring's lag
  EXPECT_NEAR(light.path[99].z(), 0.05 + 0.2, 0.03);
}

TEST(MouseSpringTest, TheForceNeverExceedsItsCap) {
  for (const double mass : {0.1, 100.0}) {
    const DragRun run = DragBox(mass);
    EXPECT_GT(run.largest_force, 0.5 * run.cap) << mass;  // the 1 m jump made it pull hard
    EXPECT_LE(run.largest_force, run.cap * (1 + 1e-9)) << mass;
    // the top face's centre, ~0.05 m above the centre of a 0.1 m cube: 3 / (3/m + 2 r² 6/(m s²))
    // = m/2 at r = s/2 (the resting box sits a little higher, on its padding)
    EXPECT_NEAR(run.effective_mass, 0.5 * mass, 0.03 * mass);
    EXPECT_NEAR(run.cap, 20 * run.effective_mass * 9.8, 1e-9 * mass);
  }
}

// frames of whole 1 ms steps: ½v² + g·z is read with the velocity half a step behind the position
// (gravity_kick.h), so the release is read after a step as long as those that follow it (after a
// 0.67 ms sliver the box rising at 0.4 m/s read 6.3e-4 J more a step later)
TEST(MouseSpringTest, ReleasingAddsNoEnergy) {
  constexpr double kWholeFrame = 0.017;  // s
  core::Simulator simulator(BoxOnPlane(1.0));
  simulator.Simulate(0.1);
  ASSERT_TRUE(simulator.StartDrag(1, Vec3(0.03, 0.02, 0.1)));
  for (int frame = 0; frame < 60; ++frame) {
    simulator.SetDragTarget(Vec3(0.2 * frame * kWholeFrame, 0.0, 0.1 + 0.4 * frame * kWholeFrame));
    simulator.Simulate(kWholeFrame);
  }
  simulator.EndDrag();
  const auto energy = [&] { return simulator.KineticEnergy() + simulator.PotentialEnergy(); };
  const double released = energy();
  double largest = released;
  simulator.AddStepObserver([&](const core::StepEvent&) { largest = std::max(largest, energy()); });
  simulator.Simulate(2.0);
  EXPECT_FALSE(simulator.dragging());
  EXPECT_LE(largest, released + 1e-6);
  EXPECT_LT(energy(), released - 1.0);  // it fell, bounced and came to rest
}

// the pendulum of tests/common/scene_builders.h with its servo off
core::WorldDesc Pendulum() {
  return test::PendulumWorld("servoP 0\nservoI 0\nservoD 0\n");
}

TEST(MouseSpringTest, ARobotLinkIsPulledWithItsArticulatedEffectiveMass) {
  core::Simulator simulator(Pendulum());
  ASSERT_TRUE(simulator.controller(0).SetTorque(VecX::Zero(1)));
  const int link = simulator.world().RobotLinkId(0, 0);
  const Vec3 bob(0.0, 0.0, 0.5);  // the centre of mass, 0.5 m below the pivot
  ASSERT_TRUE(simulator.StartDrag(link, bob));
  // the hinge lets the point move along x only: 3 I_pivot / L² (interaction_test.cpp)
  EXPECT_NEAR(simulator.drag().effective_mass, 3 * (0.01 + 2 * 0.25) / 0.25, 1e-6);
  // pulled 0.3 m sideways and held: the pendulum swings over until gravity balances the spring
  simulator.SetDragTarget(bob + Vec3(0.3, 0, 0));
  double largest = 0.0;
  simulator.AddStepObserver([&](const core::StepEvent& e) {
    largest = std::max(largest, e.simulator.drag().force.norm());
  });
  simulator.Simulate(3.0);
  const double q = simulator.GetRobotConfig(0)[0];
  EXPECT_LT(q, -0.2);  // swung towards +x (a negative turn about y lifts the bob towards +x)
  EXPECT_LE(largest, simulator.drag().spring.max_force * (1 + 1e-9));
  simulator.EndDrag();
}

core::WorldDesc PlateWithBoxes() {
  core::WorldDesc world;
  world.terrains.push_back(test::PlaneTerrain(0.6, 0.0));
  core::RigidObjectDesc plate = test::BoxObject(0.1, 5.0, Vec3(0, 0, 0.05));
  plate.geometry = test::PrimitiveGeometry(core::Primitive::Box(Vec3(0.4, 0.4, 0.1)));
  world.objects.push_back(plate);
  world.objects.push_back(test::BoxObject(0.1, 1.0, Vec3(0, 0, 0.1 + 0.05)));  // on the plate
  world.objects.push_back(test::BoxObject(0.1, 1.0, Vec3(0.6, 0, 0.05)));      // in the way
  return world;
}

TEST(KinematicTargetTest, AMovingBodyPushesWhatItMeetsAndCarriesWhatRestsOnIt) {
  core::Simulator simulator(PlateWithBoxes());
  simulator.Simulate(0.3);  // settle
  const Vec3 start_top = simulator.GetObjectPose(1).translation();
  const Vec3 start_plate = simulator.GetObjectPose(0).translation();
  const Vec3 start_other = simulator.GetObjectPose(2).translation();
  const int plate = 1;  // world id (the plane is 0)
  double largest_slip = 0.0;
  // 0.6 m along x in 2 s, smoothly (peak acceleration 0.6·π²/(2·4) = 0.74 m/s² < μ g), by frame
  for (int frame = 1; frame <= 120; ++frame) {
    const double s = 0.5 - 0.5 * std::cos(core::kPi * frame * kFrame / 2.0);
    Pose target = Pose::Identity();
    target.translation() = start_plate + Vec3(0.6 * s, 0, 0);
    simulator.SetKinematicTarget(plate, target, kFrame);
    simulator.Simulate(kFrame);
    const Vec3 relative = (simulator.GetObjectPose(1).translation() - start_top) -
                          (simulator.GetObjectPose(0).translation() - start_plate);
    largest_slip = std::max(largest_slip, relative.head<2>().norm());
  }
  EXPECT_NEAR(simulator.GetObjectPose(0).translation().x(), start_plate.x() + 0.6, 1e-9);
  EXPECT_LT(largest_slip, 1e-3);  // carried by friction
  // the box in the way was pushed along by the plate's edge (0.2 + 0.05 from the plate centre)
  EXPECT_GT(simulator.GetObjectPose(2).translation().x(), start_other.x() + 0.08);
  EXPECT_FALSE(simulator.body(plate).dynamics_enabled());
}

TEST(KinematicTargetTest, OnReleaseItBecomesDynamicWithTheVelocityItMovedAt) {
  core::WorldDesc world;
  world.objects.push_back(test::BoxObject(0.1, 1.0, Vec3(0, 0, 1.0)));
  core::Simulator simulator(world);
  const Vec3 speed(1.5, 0.0, 0.5);
  for (int frame = 1; frame <= 30; ++frame) {
    Pose target = Pose::Identity();
    target.translation() = Vec3(0, 0, 1.0) + speed * frame * kFrame;
    target.linear() = Eigen::AngleAxisd(0.6 * frame * kFrame, Vec3::UnitZ()).toRotationMatrix();
    simulator.SetKinematicTarget(0, target, kFrame);
    simulator.Simulate(kFrame);
  }
  EXPECT_NEAR((simulator.GetObjectPose(0).translation() - (Vec3(0, 0, 1) + speed * 0.5)).norm(),
              0.0, 1e-9);
  simulator.ReleaseKinematicTarget(0);
  EXPECT_TRUE(simulator.body(0).dynamics_enabled());
  EXPECT_FALSE(simulator.HasKinematicTarget(0));
  const core::Twist thrown = simulator.GetObjectVelocity(0);
  EXPECT_NEAR((thrown.linear - speed).norm(), 0.0, 1e-9);
  EXPECT_NEAR((thrown.angular - Vec3(0, 0, 0.6)).norm(), 0.0, 1e-9);
  // then it flies: v_z = 0.5 - g t
  simulator.Simulate(0.1);
  EXPECT_NEAR(simulator.GetObjectVelocity(0).linear.z(), 0.5 - 9.8 * 0.1, 1e-6);
  // a body held still longer than its last move took is released at rest
  for (int frame = 0; frame < 5; ++frame) {
    simulator.SetKinematicTarget(0, simulator.GetObjectPose(0), kFrame);
    simulator.Simulate(kFrame);
  }
  simulator.Simulate(0.1);  // standing on its target
  simulator.ReleaseKinematicTarget(0);
  EXPECT_EQ(simulator.GetObjectVelocity(0).linear, Vec3::Zero());
}

TEST(KinematicTargetTest, ARobotLinkFollowsItsTarget) {
  core::Simulator simulator(Pendulum());
  ASSERT_TRUE(simulator.controller(0).SetTorque(VecX::Zero(1)));
  const int link = simulator.world().RobotLinkId(0, 0);
  // turn the link 0.5 rad about its hinge in 0.5 s
  for (int frame = 1; frame <= 30; ++frame) {
    Pose target = Pose::Identity();
    target.translation() = Vec3(0, 0, 1);
    target.linear() = Eigen::AngleAxisd(-0.5 * frame / 30.0, Vec3::UnitY()).toRotationMatrix();
    simulator.SetKinematicTarget(link, target, kFrame);
    simulator.Simulate(kFrame);
  }
  EXPECT_NEAR(simulator.GetRobotConfig(0)[0], -0.5, 1e-6);
  simulator.ReleaseKinematicTarget(link);
  simulator.Simulate(0.5);  // it swings back down
  EXPECT_GT(simulator.GetRobotConfig(0)[0], -0.45);
}

// a box held still on the spring is pushed by it: it never falls asleep in the air, and it falls
// when released
TEST(MouseSpringTest, ABodyHeldStillStaysAwakeAndFallsWhenReleased) {
  core::Simulator simulator(BoxOnPlane(1.0));
  simulator.SetSleeping(true);
  simulator.Simulate(0.1);
  ASSERT_TRUE(simulator.StartDrag(1, Vec3(0, 0, 0.1)));
  simulator.SetDragTarget(Vec3(0, 0, 0.4));  // and never again
  simulator.Simulate(2.0);
  EXPECT_FALSE(simulator.ObjectAsleep(0));
  const double held = simulator.GetObjectPose(0).translation().z();
  EXPECT_GT(held, 0.3);
  simulator.EndDrag();
  simulator.Simulate(0.2);
  EXPECT_LT(simulator.GetObjectPose(0).translation().z(), held - 0.1);
}

TEST(KinematicTargetTest, ABodyThatWasKinematicBeforeStaysSoAndStandsOnRelease) {
  core::WorldDesc world;
  world.objects.push_back(test::BoxObject(0.1, 1.0, Vec3(0, 0, 1.0)));
  core::Simulator simulator(world);
  simulator.body(0).EnableDynamics(false);
  Pose target = Pose::Identity();
  target.translation() = Vec3(0.5, 0, 1.0);
  ASSERT_TRUE(simulator.SetKinematicTarget(0, target, 0.5));
  simulator.Simulate(0.25);
  simulator.ReleaseKinematicTarget(0);
  EXPECT_FALSE(simulator.body(0).dynamics_enabled());
  EXPECT_EQ(simulator.GetObjectVelocity(0).linear, Vec3::Zero());
  simulator.Simulate(0.25);
  EXPECT_NEAR(simulator.GetObjectPose(0).translation().x(), 0.25, 1e-9);
  // a disabled body takes no target
  simulator.body(0).Enable(false);
  EXPECT_FALSE(simulator.SetKinematicTarget(0, target, 0.5));
}

}  // namespace
}  // namespace lamina
