// SPDX-License-Identifier: MIT
// Sleeping (Simulator::SetSleeping): an object idle for sleepTime (0.5 s) leaves the steps and
// stays exactly where it is; what touches it, a setter, a force or a gravity change wakes it;
// islands of touching objects fall asleep together; restoring a state restores who sleeps.
#include <vector>

#include <gtest/gtest.h>

#include "core/sim/simulator.h"
#include "tests/common/scene_builders.h"
#include "tests/common/test_support.h"

namespace lamina {
namespace {

using core::Vec3;

using test::kBoxSide;
constexpr double kRest = 0.5 * kBoxSide + 0.0025;  // centre height of a box resting on the plane

core::WorldDesc BoxesOnPlane(const std::vector<Vec3>& positions) {
  core::WorldDesc world;
  world.terrains.push_back(test::PlaneTerrain(0.5, 0.0));
  for (const Vec3& position : positions) {
    core::RigidObjectDesc box = test::BoxObject(kBoxSide, 1.0, position);
    box.sim.surface = {0.0, 0.5, core::kInf, core::kInf};
    world.objects.push_back(box);
  }
  return world;
}

// simulates in 1 ms calls until object `i` sleeps or `limit` s have passed; the time it fell
// asleep, or a negative number
double TimeToSleep(core::Simulator& simulator, int i, double limit) {
  while (simulator.time() < limit) {
    simulator.Simulate(0.001);
    if (simulator.ObjectAsleep(i)) return simulator.time();
  }
  return -1.0;
}

TEST(SleepTest, OffByDefault) {
  core::Simulator simulator(BoxesOnPlane({Vec3(0, 0, kRest)}));
  EXPECT_FALSE(simulator.sleeping());
  simulator.Simulate(2.0);
  EXPECT_FALSE(simulator.ObjectAsleep(0));
}

TEST(SleepTest, AnIdleBoxSleepsAfterSleepTimeAndStaysExactlyPut) {
  core::Simulator simulator(BoxesOnPlane({Vec3(0, 0, kRest + 0.01)}));  // dropped from 1 cm
  simulator.SetSleeping(true);
  const double asleep_at = TimeToSleep(simulator, 0, 3.0);
  // it lands after about 45 ms and settles; then sleepTime idle
  const double sleep_time = simulator.world().settings.sleep_time;
  ASSERT_GT(asleep_at, sleep_time);
  EXPECT_LT(asleep_at, sleep_time + 0.5);
  EXPECT_EQ(simulator.SleepingObjectCount(), 1);
  const core::Pose pose = simulator.GetObjectPose(0);
  EXPECT_NEAR(pose.translation().z(), kRest, 5e-4);
  simulator.Simulate(5.0);
  EXPECT_TRUE(simulator.ObjectAsleep(0));
  EXPECT_EQ(simulator.GetObjectPose(0).matrix(), pose.matrix());
  EXPECT_EQ(simulator.GetObjectVelocity(0).linear, Vec3::Zero());
  simulator.SetSleeping(false);
  EXPECT_FALSE(simulator.ObjectAsleep(0));
}

TEST(SleepTest, ABoxLandingOnASleeperWakesItAndTheStackSleepsAgain) {
  // box 1 rests aside until box 0 sleeps, then is dropped onto it from 5 cm
  core::Simulator simulator(BoxesOnPlane({Vec3(0, 0, kRest), Vec3(1.0, 0, kRest)}));
  simulator.SetSleeping(true);
  ASSERT_GT(TimeToSleep(simulator, 0, 2.0), 0.0);
  const double z0 = simulator.GetObjectPose(0).translation().z();
  core::Pose above = core::Pose::Identity();
  above.translation() = Vec3(0.01, 0, kRest + kBoxSide + 0.0025 + 0.05);  // 5 cm above box 0
  simulator.SetObjectPose(1, above);
  simulator.SetObjectVelocity(1, core::Twist{});
  EXPECT_FALSE(simulator.ObjectAsleep(1));
  bool woke = false;
  for (int step = 0; step < 300 && !woke; ++step) {
    simulator.Simulate(0.001);
    woke = !simulator.ObjectAsleep(0);
  }
  EXPECT_TRUE(woke);  // the impact reached the sleeper
  ASSERT_GT(TimeToSleep(simulator, 0, simulator.time() + 3.0), 0.0);
  EXPECT_TRUE(simulator.ObjectAsleep(1));  // the island sleeps together
  EXPECT_NEAR(simulator.GetObjectPose(0).translation().z(), z0, 5e-4);
  EXPECT_NEAR(simulator.GetObjectPose(1).translation().z(), z0 + kBoxSide + 2 * 0.0025, 1e-3);
}

TEST(SleepTest, ForcesSettersAndGravityWakeASleeper) {
  core::Simulator simulator(BoxesOnPlane({Vec3(0, 0, kRest)}));
  simulator.SetSleeping(true);
  ASSERT_GT(TimeToSleep(simulator, 0, 2.0), 0.0);
  // a push above the friction limit (μ m g = 4.9 N) wakes it and slides it
  const double x0 = simulator.GetObjectPose(0).translation().x();
  simulator.body(simulator.world().terrains.size()).ApplyWrench(Vec3(10, 0, 0), Vec3::Zero());
  EXPECT_FALSE(simulator.ObjectAsleep(0));
  simulator.Simulate(0.1);
  EXPECT_GT(simulator.GetObjectPose(0).translation().x() - x0, 0.01);
  ASSERT_GT(TimeToSleep(simulator, 0, simulator.time() + 3.0), 0.0);
  // gravity tilted past the friction angle: it slides away
  simulator.SetGravity(9.8 * Vec3(0.6, 0, -0.8));
  EXPECT_FALSE(simulator.ObjectAsleep(0));
  const double x1 = simulator.GetObjectPose(0).translation().x();
  simulator.Simulate(0.5);
  EXPECT_GT(simulator.GetObjectPose(0).translation().x() - x1, 0.1);
}

TEST(SleepTest, AMovingKinematicBodyWakesWhatItPushes) {
  core::Simulator simulator(BoxesOnPlane({Vec3(0, 0, kRest), Vec3(-0.3, 0, kRest)}));
  simulator.SetSleeping(true);
  ASSERT_GT(TimeToSleep(simulator, 0, 2.0), 0.0);
  const int pusher = static_cast<int>(simulator.world().terrains.size()) + 1;
  simulator.body(pusher).EnableDynamics(false);
  simulator.body(pusher).SetVelocity(core::Twist{Vec3(0.2, 0, 0), Vec3::Zero()});
  simulator.Simulate(1.5);  // 0.3 m at 0.2 m/s: contact after 1 s
  EXPECT_FALSE(simulator.ObjectAsleep(0));
  EXPECT_GT(simulator.GetObjectPose(0).translation().x(), 0.05);
}

TEST(SleepTest, AForceLastingTheCallKeepsABoxAwakeAndLeavesNoImpulseBehind) {
  core::Simulator simulator(BoxesOnPlane({Vec3(0, 0, kRest)}));
  simulator.SetSleeping(true);
  core::SimBody box = simulator.body(static_cast<int>(simulator.world().terrains.size()));
  box.ApplyWrench(Vec3(2, 0, 0), Vec3::Zero());  // below μ m g = 4.9 N: static friction holds
  simulator.Simulate(2.0);
  EXPECT_FALSE(simulator.ObjectAsleep(0));
  ASSERT_GT(TimeToSleep(simulator, 0, simulator.time() + 2.0), 0.0);
  simulator.SetObjectVelocity(0, core::Twist{});  // wakes it
  simulator.Simulate(0.01);
  EXPECT_LT(simulator.GetObjectVelocity(0).linear.norm(), 0.01);
}

TEST(SleepTest, ASleeperWhoseSupportIsMovedAwayFalls) {
  core::Simulator simulator(
      BoxesOnPlane({Vec3(0, 0, kRest), Vec3(0, 0, kRest + kBoxSide + 0.005)}));
  simulator.SetSleeping(true);
  ASSERT_GT(TimeToSleep(simulator, 1, 3.0), 0.0);
  ASSERT_TRUE(simulator.ObjectAsleep(0));
  core::Pose aside = simulator.GetObjectPose(0);
  aside.translation().x() += 2.0;
  simulator.SetObjectPose(0, aside);
  EXPECT_FALSE(simulator.ObjectAsleep(1));
  simulator.Simulate(1.0);
  EXPECT_NEAR(simulator.GetObjectPose(1).translation().z(), kRest, 1e-3);  // on the plane now
}

TEST(SleepTest, ABoxCarriedByASlowKinematicBodyNeverSleeps) {
  // a 1 m kinematic slab moving at 5 mm/s (below the sleep speed) carries a box
  core::WorldDesc world = BoxesOnPlane({Vec3(0, 0, 0.05 + kRest + 0.0025)});
  core::RigidObjectDesc slab = test::BoxObject(0.1, 10.0, Vec3(0, 0, 0.0));
  slab.geometry.primitive = core::Primitive::Box(Vec3(1.0, 1.0, 0.1));
  slab.sim.surface = {0.0, 0.5, core::kInf, core::kInf};
  world.objects.push_back(slab);
  core::Simulator simulator(world);
  simulator.SetSleeping(true);
  core::SimBody conveyor = simulator.body(static_cast<int>(world.terrains.size()) + 1);
  conveyor.EnableDynamics(false);
  conveyor.SetVelocity(core::Twist{Vec3(0.005, 0, 0), Vec3::Zero()});
  const double x0 = simulator.GetObjectPose(0).translation().x();
  for (int i = 0; i < 400; ++i) {
    simulator.Simulate(0.01);
    conveyor.SetVelocity(core::Twist{Vec3(0.005, 0, 0), Vec3::Zero()});
    ASSERT_FALSE(simulator.ObjectAsleep(0)) << "at " << simulator.time() << " s";
  }
  EXPECT_NEAR(simulator.GetObjectPose(0).translation().x() - x0, 0.02, 5e-4);
}

TEST(SleepTest, RestoringAStateRestoresWhoSleeps) {
  core::Simulator simulator(BoxesOnPlane({Vec3(0, 0, kRest + 0.01), Vec3(0.5, 0, kRest + 0.3)}));
  simulator.SetSleeping(true);
  simulator.Simulate(0.7);
  const core::SimState middle = simulator.GetState();
  ASSERT_TRUE(middle.sleep[0].asleep);
  ASSERT_FALSE(middle.sleep[1].asleep);
  simulator.Simulate(1.0);
  const core::SimState end = simulator.GetState();
  EXPECT_TRUE(end.sleep[1].asleep);
  simulator.SetState(middle);
  EXPECT_TRUE(simulator.ObjectAsleep(0));
  EXPECT_FALSE(simulator.ObjectAsleep(1));
  simulator.Simulate(1.0);
  EXPECT_EQ(simulator.GetState(), end);
  // with sleeping off, a state restores everyone awake
  simulator.SetSleeping(false);
  simulator.SetState(end);
  EXPECT_EQ(simulator.SleepingObjectCount(), 0);
}

}  // namespace
}  // namespace lamina
