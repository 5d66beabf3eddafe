// SPDX-License-Identifier: MIT
// Bodies without contact: free fall against the closed form of ODE's semi-implicit Euler (also
// through changes of the step, gravity_kick.h), a spinning body keeping its momentum, state
// snapshots that replay bit for bit.
#include <cmath>

#include <gtest/gtest.h>

#include "core/sim/simulator.h"

namespace lamina {
namespace {

using core::Pose;
using core::Vec3;

// a world with one 2 kg sphere primitive and no terrain
core::WorldDesc FallingSphereWorld(double height) {
  core::WorldDesc world;
  core::RigidObjectDesc ball;
  ball.name = "ball";
  ball.geometry.kind = core::GeometryKind::kPrimitive;
  ball.geometry.primitive = core::Primitive::Sphere(0.1);
  ball.mass = 2.0;
  ball.inertia = core::Mat3::Identity() * (0.4 * 2.0 * 0.01);
  ball.pose.translation() = Vec3(0, 0, height);
  world.objects.push_back(ball);
  return world;
}

class FreeFallTest : public ::testing::TestWithParam<double> {};

TEST_P(FreeFallTest, MatchesSemiImplicitEulerClosedForm) {
  const double h = GetParam();
  const double g = 9.8;
  core::Simulator simulator(FallingSphereWorld(100.0));
  simulator.SetSimStep(h);
  const double t = 2.0;
  simulator.Simulate(t);
  ASSERT_NEAR(simulator.time(), t, 1e-12);
  const double z = simulator.GetObjectPose(0).translation().z();
  const double v = simulator.GetObjectVelocity(0).linear.z();
  // velocity is exact: v = -g t
  EXPECT_NEAR(v, -g * t, 1e-9);
  // ODE integrates x_{n+1} = x_n + h v_{n+1}: z = z0 - g t^2/2 - g h t/2, a first-order error
  // of exactly g h t / 2 against the analytic fall (round-off over 2/h steps stays < 1e-9)
  EXPECT_NEAR(z, 100.0 - g * t * t / 2 - g * h * t / 2, 1e-9);
  EXPECT_LE(std::abs(z - (100.0 - g * t * t / 2)), g * h * t / 2 + 1e-9);
}

INSTANTIATE_TEST_SUITE_P(Steps, FreeFallTest, ::testing::Values(0.001, 0.002, 0.004));

// 10 steps of 1 ms, 2 of 0.5 ms, 4 of 0.25 ms, 5 of 1 ms (Simulate(dt) shorter than the step
// takes one step of dt). Gravity's kick between steps of h0 and h spans (h0 + h)/2: the positions
// stay those of the constant 1 ms step, z = z0 - g t²/2 - g h t/2 with h = 1 ms, and so does the
// velocity, -g t. Kicks of g·h at every step instead leave z 6.1e-6 m lower.
TEST(FreeFallTest, ChangesOfStepKeepTheConstantStepsPositions) {
  const double g = 9.8, h = 0.001;
  core::Simulator simulator(FallingSphereWorld(100.0));
  simulator.Simulate(10 * h);
  for (int i = 0; i < 2; ++i) simulator.Simulate(h / 2);
  for (int i = 0; i < 4; ++i) simulator.Simulate(h / 4);
  simulator.Simulate(5 * h);
  EXPECT_EQ(simulator.statistics().steps, 21);
  const double t = simulator.time();
  ASSERT_NEAR(t, 0.017, 1e-15);
  EXPECT_NEAR(simulator.GetObjectVelocity(0).linear.z(), -g * t, 1e-12);
  EXPECT_NEAR(simulator.GetObjectPose(0).translation().z(), 100.0 - g * t * t / 2 - g * h * t / 2,
              1e-12);
}

TEST(FreeBodyTest, SpinWithoutGravityKeepsAngularVelocityOfASymmetricBody) {
  core::WorldDesc world = FallingSphereWorld(0.0);
  world.settings.gravity = Vec3::Zero();
  world.objects[0].initial_velocity = {Vec3(1, 0, 0), Vec3(0, 0, 5)};
  core::Simulator simulator(world);
  simulator.Simulate(1.0);
  // a sphere's inertia is isotropic: no precession, the spin stays exactly 5 rad/s about z
  EXPECT_NEAR(simulator.GetObjectVelocity(0).angular.z(), 5.0, 1e-12);
  EXPECT_NEAR(simulator.GetObjectPose(0).translation().x(), 1.0, 1e-9);
  // 5 rad in 1 s about z
  const Eigen::AngleAxisd rotation(simulator.GetObjectPose(0).linear());
  EXPECT_NEAR(std::remainder(rotation.angle() * rotation.axis().z() - 5.0, 2 * core::kPi), 0.0,
              1e-6);
}

TEST(FreeBodyTest, OffsetComVelocityIsOfTheObjectOrigin) {
  core::WorldDesc world = FallingSphereWorld(0.0);
  world.settings.gravity = Vec3::Zero();
  world.objects[0].com = Vec3(0.5, 0, 0);
  world.objects[0].initial_velocity = {Vec3(0, 0, 0), Vec3(0, 0, 2)};
  core::Simulator simulator(world);
  // the origin is at rest initially; the COM moves at w x r = (0, 1, 0)
  EXPECT_NEAR(simulator.GetObjectVelocity(0).linear.norm(), 0.0, 1e-15);
  const core::SimState state = simulator.GetState();
  EXPECT_NEAR(state.objects[0].linear_velocity.y(), 1.0, 1e-15);
}

TEST(DeterminismTest, SetStateReplaysBitForBit) {
  core::WorldDesc world = FallingSphereWorld(10.0);
  world.objects[0].initial_velocity = {Vec3(0.3, -0.2, 1.0), Vec3(1, 2, 3)};
  world.objects[0].inertia = core::Vec3(0.01, 0.02, 0.03).asDiagonal();
  core::Simulator simulator(world);
  simulator.Simulate(0.25);
  const core::SimState middle = simulator.GetState();
  simulator.Simulate(0.5);
  const core::SimState end = simulator.GetState();
  simulator.SetState(middle);
  simulator.Simulate(0.5);
  EXPECT_EQ(simulator.GetState(), end);

  core::Simulator twin(world);
  twin.Simulate(0.25);
  twin.Simulate(0.5);
  EXPECT_EQ(twin.GetState(), end);
}

// a state taken after a shorter step keeps that step's length (SimState::last_step), on which the
// next step's gravity kick depends
TEST(DeterminismTest, StateAfterAShortStepReplaysBitForBit) {
  core::Simulator simulator(FallingSphereWorld(10.0));
  simulator.Simulate(0.0103);  // ends with a step of 0.3 ms
  const core::SimState middle = simulator.GetState();
  EXPECT_NEAR(middle.last_step, 0.0003, 1e-15);
  simulator.Simulate(0.05);
  const core::SimState end = simulator.GetState();
  core::Simulator replay(FallingSphereWorld(10.0));
  replay.SetState(middle);
  replay.Simulate(0.05);
  EXPECT_EQ(replay.GetState(), end);
}

TEST(SimulatorTest, ResetReturnsToTheWorldDescription) {
  core::Simulator simulator(FallingSphereWorld(3.0));
  simulator.Simulate(0.1);
  simulator.Reset();
  EXPECT_EQ(simulator.time(), 0.0);
  EXPECT_EQ(simulator.GetObjectPose(0).translation(), Vec3(0, 0, 3));
  EXPECT_EQ(simulator.GetObjectVelocity(0).linear, Vec3::Zero());
  EXPECT_EQ(simulator.GetState().last_step, 0.0);
}

}  // namespace
}  // namespace lamina
