// SPDX-License-Identifier: MIT
// The step's tunnelling check (core/sim/simulator_sweep.cpp): 100 m/s balls against a
// one-triangle mesh wall and a 1 cm box (worlds/accuracy/high_speed.xml) at 10 ms steps, where a
// step carries a ball 1 m, five diameters. With adaptive stepping the steps are halved until the
// layer catches the ball and it bounces back (restitution 0.5: about −50 m/s); without it the
// ball passes but the run says "contact unreliable". Objects that may not collide
// (rigidObjectCollisions off) fly through each other without a rollback.
#include <gtest/gtest.h>

#include "core/sim/simulator.h"
#include "tests/common/scene_builders.h"
#include "tests/common/test_support.h"

namespace lamina::core {
namespace {

WorldDesc HighSpeed(bool adaptive) {
  test::LoadedWorld loaded;
  test::LoadWorld(test::WorldsPath("accuracy/high_speed.xml"), &loaded);
  EXPECT_TRUE(loaded.ok) << loaded.diagnostics.FormatAll();
  loaded.world.settings.timestep = 0.01;
  loaded.world.settings.adaptive_time_stepping = adaptive;
  return loaded.world;
}

TEST(TunnellingTest, FastBallsBounceOffThinWallsAtTenMillisecondSteps) {
  Simulator simulator(HighSpeed(true));
  simulator.Simulate(0.05);
  for (int ball = 0; ball < 2; ++ball) {
    EXPECT_LT(simulator.GetObjectPose(ball).translation().x(), 0.0) << ball;
    EXPECT_NEAR(simulator.GetObjectVelocity(ball).linear.x(), -50.0, 5.0) << ball;
  }
  EXPECT_GT(simulator.statistics().rollbacks, 0);
  EXPECT_NE(simulator.statistics().worst_status, StepStatus::kError);
}

TEST(TunnellingTest, WithoutAdaptiveSteppingAPassThroughIsFlagged) {
  Simulator simulator(HighSpeed(false));
  simulator.Simulate(0.05);
  EXPECT_GT(simulator.statistics().unreliable_steps, 0);
  EXPECT_EQ(simulator.statistics().worst_status, StepStatus::kContactUnreliable);
}

WorldDesc TwoBalls(bool collide) {
  WorldDesc world;
  world.settings.gravity = Vec3::Zero();
  world.settings.timestep = 0.01;
  world.settings.rigid_object_collisions = collide;
  world.objects = {test::SphereObject(0.1, 1.0, Vec3(-1.37, 0, 0)),
                   test::SphereObject(0.1, 1.0, Vec3(0.05, 0, 0))};
  world.objects[0].initial_velocity.linear = Vec3(100, 0, 0);
  return world;
}

TEST(TunnellingTest, OnlyBodiesThatMayCollideAreChecked) {
  Simulator apart(TwoBalls(false));
  apart.Simulate(0.05);
  EXPECT_EQ(apart.statistics().rollbacks, 0);
  EXPECT_GT(apart.GetObjectPose(0).translation().x(), 3.0);  // straight through, untouched
  Simulator hit(TwoBalls(true));
  hit.Simulate(0.05);
  EXPECT_GT(hit.statistics().rollbacks, 0);
  EXPECT_GT(hit.GetObjectVelocity(1).linear.x(), 10.0);  // the struck ball took the momentum
  EXPECT_LT(hit.GetObjectPose(0).translation().x(), hit.GetObjectPose(1).translation().x());
}

}  // namespace
}  // namespace lamina::core
