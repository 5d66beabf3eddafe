// SPDX-License-Identifier: MIT
// The body API on a running simulation: kinematic bodies push dynamic ones, applied forces last
// one Simulate call, disabled bodies freeze, padding and surface edits act at once, and the
// state can be written back into a world description.
#include <cmath>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "core/sim/simulator.h"
#include "tests/common/scene_builders.h"
#include "tests/common/test_support.h"

namespace lamina {
namespace {

using core::Vec3;

using test::kGravity;

core::WorldDesc FloatingBox(double mass) {
  core::WorldDesc world;
  world.settings.gravity = Vec3::Zero();
  world.objects.push_back(test::BoxObject(0.2, mass, Vec3(0, 0, 1)));
  return world;
}

TEST(SimBodyTest, KinematicBodyPushesADynamicOneAtItsOwnSpeed) {
  core::WorldDesc world;
  world.terrains.push_back(test::PlaneTerrain(0.5, 0.0));
  core::RigidObjectDesc pushed = test::BoxObject(0.1, 1.0, Vec3(0, 0, 0.0525));
  pushed.sim.surface.restitution = 0.0;
  core::RigidObjectDesc pusher = test::BoxObject(0.1, 1.0, Vec3(-0.3, 0, 0.0525));
  pusher.sim.surface.restitution = 0.0;
  world.objects = {pushed, pusher};
  core::Simulator simulator(world);
  core::SimBody bat = simulator.body(world.ObjectId(1));
  bat.EnableDynamics(false);
  EXPECT_FALSE(bat.dynamics_enabled());
  const double speed = 0.5;
  bat.SetVelocity({Vec3(speed, 0, 0), Vec3::Zero()});
  simulator.Simulate(1.5);
  ASSERT_NE(simulator.statistics().worst_status, core::StepStatus::kError);
  // the kinematic body follows its velocity exactly: no gravity, no reaction from the box
  const Vec3 bat_position = bat.GetTransform().translation();
  EXPECT_NEAR(bat_position.x(), -0.3 + speed * 1.5, 1e-9);
  EXPECT_NEAR(bat_position.z(), 0.0525, 1e-12);
  // the pushed box moves with it, one box side plus both paddings ahead (within the layer)
  const Vec3 box_position = simulator.GetObjectPose(0).translation();
  EXPECT_NEAR(box_position.x() - bat_position.x(), 0.1 + 0.005, 0.005);
  EXPECT_NEAR(simulator.GetObjectVelocity(0).linear.x(), speed, 0.01);
  EXPECT_EQ(simulator.statistics().instability_corrections, 0);
  // dynamics back on: the former bat falls onto the plane and stops
  bat.EnableDynamics(true);
  bat.SetVelocity({});
  simulator.Simulate(0.5);
  EXPECT_NEAR(bat.GetVelocity().linear.norm(), 0.0, 1e-3);
}

TEST(SimBodyTest, AppliedWrenchLastsOneSimulateCall) {
  const core::WorldDesc world = FloatingBox(2.0);
  core::Simulator simulator(world);
  core::SimBody box = simulator.body(world.ObjectId(0));
  box.ApplyWrench(Vec3(4, 0, 0), Vec3::Zero());
  simulator.Simulate(0.5);
  // v = F t / m = 4 * 0.5 / 2
  EXPECT_NEAR(box.GetVelocity().linear.x(), 1.0, 1e-9);
  simulator.Simulate(0.5);  // the force has ended
  EXPECT_NEAR(box.GetVelocity().linear.x(), 1.0, 1e-9);
}

TEST(SimBodyTest, ForceOffTheCentreTurnsTheBody) {
  const double mass = 1.0, side = 0.2;
  const core::WorldDesc world = FloatingBox(mass);
  core::Simulator simulator(world);
  core::SimBody box = simulator.body(world.ObjectId(0));
  // 1 N along y at 0.1 m along x from the centre: torque 0.1 N·m about z
  box.ApplyForceAtPoint(Vec3(0, 1, 0), Vec3(0.1, 0, 1));
  simulator.Simulate(0.1);
  const double inertia = mass * side * side / 6.0;
  EXPECT_NEAR(box.GetVelocity().angular.z(), 0.1 * 0.1 / inertia, 1e-3 * 0.1 / inertia);
  EXPECT_NEAR(box.GetVelocity().linear.y(), 0.1 / mass, 1e-3);
}

TEST(SimBodyTest, LocalPointForceEqualsTheWorldPointForce) {
  core::WorldDesc world = FloatingBox(1.0);
  world.objects[0].pose.linear() = core::RotationFromRollPitchYaw(0.4, -0.2, 1.1);
  core::Simulator local(world), global(world);
  const Vec3 force(0.3, -1.0, 2.0), point(0.05, 0.1, -0.02);
  local.body(world.ObjectId(0)).ApplyForceAtLocalPoint(force, point);
  global.body(world.ObjectId(0)).ApplyForceAtPoint(force, world.objects[0].pose * point);
  local.Simulate(0.2);
  global.Simulate(0.2);
  const core::SimState a = local.GetState(), b = global.GetState();
  EXPECT_NEAR((a.objects[0].angular_velocity - b.objects[0].angular_velocity).norm(), 0.0, 1e-12);
  EXPECT_NEAR((a.objects[0].linear_velocity - b.objects[0].linear_velocity).norm(), 0.0, 1e-12);
}

TEST(SimBodyTest, DisabledBodyFreezesAndLeavesContact) {
  core::WorldDesc world;
  world.terrains.push_back(test::PlaneTerrain(0.5, 0.0));
  world.objects.push_back(test::BoxObject(0.1, 1.0, Vec3(0, 0, 0.5)));
  core::Simulator simulator(world);
  core::SimBody box = simulator.body(world.ObjectId(0));
  box.Enable(false);
  simulator.Simulate(0.5);
  EXPECT_EQ(simulator.GetObjectPose(0).translation(), Vec3(0, 0, 0.5));
  box.Enable(true);
  simulator.Simulate(0.1);
  // free fall resumes: 0.5 g t² below
  EXPECT_NEAR(simulator.GetObjectPose(0).translation().z(), 0.5 - 0.5 * kGravity * 0.01, 1e-3);
}

TEST(SimBodyTest, PaddingAndSurfaceEditsActOnTheRunningSimulation) {
  core::WorldDesc world;
  world.terrains.push_back(test::PlaneTerrain(0.5, 0.0));
  core::RigidObjectDesc box = test::BoxObject(0.1, 1.0, Vec3(0, 0, 0.0525));
  box.sim.surface.restitution = 0.0;
  world.objects.push_back(box);
  core::Simulator simulator(world);
  core::SimBody body = simulator.body(world.ObjectId(0));
  simulator.Simulate(0.5);
  EXPECT_NEAR(body.GetTransform().translation().z(), 0.0525, 2e-4);
  // a thicker layer lifts the box (at the 1 cm/s correction speed) to rest 7.5 mm higher
  body.SetPadding(0.01);
  EXPECT_EQ(body.GetPadding(), 0.01);
  simulator.Simulate(1.5);
  EXPECT_NEAR(body.GetTransform().translation().z(), 0.06, 2e-4);
  // a soft layer: the box sinks to m g / k into it
  core::SurfaceDesc surface = body.GetSurface();
  surface.stiffness = 1e4;
  surface.damping = 2 * std::sqrt(1e4 * 1.0);
  body.SetSurface(surface);
  simulator.Simulate(1.0);
  EXPECT_NEAR(body.GetTransform().translation().z(), 0.06 - kGravity / 1e4, 5e-5);
  // frictionless: a push keeps its speed
  surface.friction = 0.0;
  body.SetSurface(surface);
  simulator.world();  // the edits are part of the simulated world
  EXPECT_EQ(simulator.world().objects[0].sim.surface.friction, 0.0);
  body.SetVelocity({Vec3(0.3, 0, 0), Vec3::Zero()});
  simulator.Simulate(0.5);
  EXPECT_NEAR(body.GetVelocity().linear.x(), 0.3, 1e-3);
}

TEST(SimBodyTest, BadValuesAreRejected) {
  const core::WorldDesc world = FloatingBox(1.0);
  core::Simulator simulator(world);
  core::SimBody box = simulator.body(world.ObjectId(0));
  EXPECT_THROW(box.SetPadding(-0.1), std::invalid_argument);
  EXPECT_THROW(box.SetVelocity({Vec3(NAN, 0, 0), Vec3::Zero()}), std::invalid_argument);
  EXPECT_THROW(box.ApplyWrench(Vec3(INFINITY, 0, 0), Vec3::Zero()), std::invalid_argument);
  core::SurfaceDesc surface;
  surface.friction = -1;
  EXPECT_THROW(box.SetSurface(surface), std::invalid_argument);
  EXPECT_FALSE(simulator.body(99).valid());
  EXPECT_TRUE(box.valid());
}

TEST(SimBodyTest, UpdateWorldWritesTheStateBack) {
  core::WorldDesc world = FloatingBox(1.0);
  world.objects[0].initial_velocity.linear = Vec3(1, 0, 0);
  core::Simulator simulator(world);
  simulator.body(world.ObjectId(0)).SetPadding(0.007);
  simulator.Simulate(0.5);
  core::WorldDesc updated = world;
  simulator.UpdateWorld(&updated);
  EXPECT_NEAR(updated.objects[0].pose.translation().x(), 0.5, 1e-9);
  EXPECT_EQ(updated.objects[0].initial_velocity.linear, simulator.GetObjectVelocity(0).linear);
  EXPECT_EQ(updated.objects[0].sim.padding, 0.007);
  core::WorldDesc other;
  EXPECT_THROW(simulator.UpdateWorld(&other), std::invalid_argument);
}

TEST(SimBodyTest, AbsurdVelocityIsStoppedNotPropagatedAsNaN) {
  const core::WorldDesc world = FloatingBox(1.0);
  core::Simulator simulator(world);
  std::vector<int> corrected;  // the observers learn which body it was
  simulator.AddStepObserver([&corrected](const core::StepEvent& event) {
    corrected.insert(corrected.end(), event.corrected_bodies.begin(), event.corrected_bodies.end());
  });
  simulator.SetObjectVelocity(0, {Vec3(1e307, 0, 0), Vec3(0, 0, 1e307)});
  const core::StepStatus status = simulator.Simulate(0.01);
  EXPECT_EQ(status, core::StepStatus::kUnstable) << simulator.statistics().error;
  EXPECT_GE(simulator.statistics().instability_corrections, 1);
  ASSERT_FALSE(corrected.empty());
  for (int id : corrected) EXPECT_EQ(id, world.ObjectId(0));
  EXPECT_TRUE(simulator.GetObjectPose(0).translation().allFinite());
  EXPECT_TRUE(simulator.GetObjectVelocity(0).linear.allFinite());
}

}  // namespace
}  // namespace lamina
