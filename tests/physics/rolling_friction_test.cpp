// SPDX-License-Identifier: MIT
// Rolling and spinning friction (SurfaceDesc::rolling_friction and spinning_friction, ODE's
// dContactRolling rows; docs/contact-model.md) against the rigid-body answers:
//  - a ball of radius r rolling without slipping with rolling friction ρ decelerates at
//    ρ g / (1.4 r) and stops after v0² · 1.4 r / (2 ρ g); without it, it rolls on at v0;
//  - a ball spinning about the vertical with spinning friction ρN slows at ρN m g / (2/5 m r²);
//  - stiffness_test.xml's rigid tessellated ball, which rolls off its pole vertex without rolling
//    resistance (correct for a world that has none), stays on it with some;
//  - worlds/examples/rolling_friction.xml does what its comment says.
// These run seconds of simulated time each (label "physics").
#include <cmath>
#include <iostream>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "core/sim/simulator.h"
#include "tests/common/scene_builders.h"
#include "tests/common/test_support.h"

namespace lamina {
namespace {

using core::Vec3;

constexpr double kRadius = 0.1;  // m
constexpr double kMass = 1.0;    // kg
using test::kGravity;

// A 0.1 m, 1 kg solid ball (I = 2/5 m r²) resting on a rigid plane, both surfaces with the given
// Coulomb, rolling and spinning friction (equal sides: the harmonic mean keeps the value). The
// ball is preshrunk, so its padded surface, which is what rolls on the plane, has radius r.
core::WorldDesc BallOnPlane(double friction, double rolling, double spinning) {
  core::WorldDesc world;
  world.terrains.push_back(test::PlaneTerrain(friction, 0.0));
  core::SurfaceDesc& ground = world.terrains[0].sim.surface;
  ground.rolling_friction = rolling;
  ground.spinning_friction = spinning;
  core::RigidObjectDesc ball = test::SphereObject(kRadius, kMass, Vec3(0, 0, kRadius));
  ball.sim.preshrink = core::Preshrink::kCopy;
  ball.sim.surface = ground;
  world.objects.push_back(ball);
  return world;
}

// the ball rolling at v0 without slipping along `direction` (horizontal, unit), ω = n × v / r
core::WorldDesc RollingBall(double rolling, double v0, const Vec3& direction = Vec3::UnitX()) {
  core::WorldDesc world = BallOnPlane(0.5, rolling, 0.0);
  world.objects[0].initial_velocity.linear = v0 * direction;
  world.objects[0].initial_velocity.angular = Vec3::UnitZ().cross(direction) * (v0 / kRadius);
  return world;
}

// the ball's speed at `time`, and (checked) that it rolls along `direction` without slipping
double SpeedAt(core::Simulator* simulator, double time, const Vec3& direction = Vec3::UnitX()) {
  simulator->Simulate(time - simulator->time());
  const core::Twist twist = simulator->GetObjectVelocity(0);
  EXPECT_NEAR((twist.linear - twist.linear.dot(direction) * direction).norm(), 0.0, 1e-6)
      << "off its line at " << time << " s";
  // the contact point stands still (to 1 mm/s)
  EXPECT_NEAR(
      twist.angular.cross(Vec3(0, 0, -kRadius)).dot(direction) + twist.linear.dot(direction), 0.0,
      1e-3);
  return twist.linear.dot(direction);
}

// the deceleration over 0.5 s to 2 s of a ball launched rolling at v0 along `direction`, a
// window well inside the roll (it stops at v0 / a = 2.86 s), checked against the start too
double Deceleration(double rho, double v0, const Vec3& direction) {
  core::Simulator simulator(RollingBall(rho, v0, direction));
  const double t1 = 0.5, t2 = 2.0;
  const double v1 = SpeedAt(&simulator, t1, direction);
  const double v2 = SpeedAt(&simulator, t2, direction);
  EXPECT_NE(simulator.statistics().worst_status, core::StepStatus::kError);
  const double a = (v1 - v2) / (t2 - t1);
  EXPECT_NEAR(v1, v0 - a * t1, 0.02 * a * t1);  // the roll is established at once
  return a;
}

TEST(RollingFrictionTest, ARollingBallDeceleratesAtRhoGOver1Point4R) {
  const double rho = 0.005, v0 = 1.0;
  const double expected = rho * kGravity / (1.4 * kRadius);  // 0.35 m/s²
  const double along_x = Deceleration(rho, v0, Vec3::UnitX());
  EXPECT_NEAR(along_x, expected, 0.02 * expected);
  // ODE bounds each rolling axis separately; the axes follow the rolling, so the resistance is
  // the same in every direction (axes fixed at 45° would give √2 times as much)
  const double diagonal = Deceleration(rho, v0, Vec3(1, 1, 0).normalized());
  EXPECT_NEAR(diagonal, expected, 0.02 * expected);
  std::cout << "rolling ball, rho " << rho << " m: " << along_x << " m/s² along x, " << diagonal
            << " m/s² diagonally; expected " << expected << " m/s²\n";
}

TEST(RollingFrictionTest, ARollingBallStopsAtTheAnalyticDistanceAndStays) {
  const double rho = 0.005, v0 = 1.0;
  core::Simulator simulator(RollingBall(rho, v0));
  simulator.Simulate(4.0);  // it stops at 2.86 s
  ASSERT_NE(simulator.statistics().worst_status, core::StepStatus::kError);
  const double expected = v0 * v0 * 1.4 * kRadius / (2 * rho * kGravity);  // 1.429 m
  const double stopped = simulator.GetObjectPose(0).translation().x();
  EXPECT_NEAR(stopped, expected, 0.02 * expected);
  std::cout << "stopped at " << stopped << " m; expected " << expected << " m\n";
  EXPECT_LT(simulator.GetObjectVelocity(0).linear.norm(), 1e-3);
  // rolling resistance holds it where it stopped (static, like Coulomb friction)
  simulator.Simulate(1.0);
  EXPECT_NEAR(simulator.GetObjectPose(0).translation().x(), stopped, 1e-4);
}

TEST(RollingFrictionTest, WithoutRollingFrictionABallRollsOnAtItsSpeed) {
  const double v0 = 1.0;
  core::Simulator simulator(RollingBall(0.0, v0));
  const double v1 = SpeedAt(&simulator, 0.5);
  const double v2 = SpeedAt(&simulator, 3.0);
  ASSERT_NE(simulator.statistics().worst_status, core::StepStatus::kError);
  // nothing takes energy out of a rolling ball: within 0.1 % over 2.5 s
  EXPECT_NEAR(v1, v0, 1e-3 * v0);
  EXPECT_NEAR(v2, v0, 1e-3 * v0);
  std::cout << "without rolling friction: " << v1 << " m/s at 0.5 s, " << v2 << " m/s at 3 s\n";
}

// A slope of angle θ as gravity tilted by θ (down the slope is +x). Friction holds the ball with
// m g sin θ at the contact, whose torque r m g sin θ about the centre the rolling friction must
// balance with at most ρ m g cos θ: the ball stays while tan θ ≤ ρ / r, and beyond rolls down at
// g (sin θ − (ρ / r) cos θ) / 1.4.
double SlopeAcceleration(double rho, double degrees) {
  const double theta = degrees * std::numbers::pi / 180.0;
  core::WorldDesc world = BallOnPlane(0.5, rho, 0.0);
  world.settings.gravity = kGravity * Vec3(std::sin(theta), 0, -std::cos(theta));
  core::Simulator simulator(world);
  const double v1 = SpeedAt(&simulator, 0.5);
  const double v2 = SpeedAt(&simulator, 1.5);
  EXPECT_NE(simulator.statistics().worst_status, core::StepStatus::kError);
  return v2 - v1;  // over 1 s
}

TEST(RollingFrictionTest, OnASlopeItHoldsUpToTanThetaEqualsRhoOverR) {
  const double rho = 0.005;  // ρ / r = 0.05: 2.86°
  const double held = SlopeAcceleration(rho, 2.0);
  EXPECT_NEAR(held, 0.0, 1e-6);
  const double theta = 4.0 * std::numbers::pi / 180.0;
  const double expected =
      kGravity * (std::sin(theta) - rho / kRadius * std::cos(theta)) / 1.4;  // 0.1391 m/s²
  const double rolling = SlopeAcceleration(rho, 4.0);
  EXPECT_NEAR(rolling, expected, 0.02 * expected);
  std::cout << "slope: " << held << " m/s² at 2°, " << rolling << " m/s² at 4° (expected "
            << expected << ")\n";
}

double SpinAt(core::Simulator* simulator, double time) {
  simulator->Simulate(time - simulator->time());
  return simulator->GetObjectVelocity(0).angular.z();
}

TEST(SpinningFrictionTest, ASpinningBallSlowsAtRhoNMGOverItsInertia) {
  const double rho_n = 0.002, w0 = 5.0;
  core::WorldDesc world = BallOnPlane(0.5, 0.0, rho_n);
  world.objects[0].initial_velocity.angular = Vec3(0, 0, w0);
  core::Simulator simulator(world);
  // torque ρN m g against I = 2/5 m r²: 0.002 · 9.8 / 0.004 = 4.9 rad/s², stopping at 1.02 s
  const double expected = rho_n * kMass * kGravity / (0.4 * kMass * kRadius * kRadius);
  const double t1 = 0.2, t2 = 0.8;
  const double w1 = SpinAt(&simulator, t1);
  const double w2 = SpinAt(&simulator, t2);
  const double measured = (w1 - w2) / (t2 - t1);
  EXPECT_NEAR(measured, expected, 0.02 * expected);
  std::cout << "spinning ball, rhoN " << rho_n << " m: " << measured << " rad/s²; expected "
            << expected << " rad/s²\n";
  EXPECT_NEAR(w1, w0 - expected * t1, 0.02 * expected * t1);
  simulator.Simulate(0.5);  // past the stop
  ASSERT_NE(simulator.statistics().worst_status, core::StepStatus::kError);
  EXPECT_LT(std::abs(simulator.GetObjectVelocity(0).angular.z()), 1e-3);
  // spinning friction acts about the normal only: the ball has not moved
  EXPECT_LT(simulator.GetObjectPose(0).translation().head<2>().norm(), 1e-4);
}

// ODE fills a contact's rolling rows whenever the joint has rows besides the normal one, with or
// without its Coulomb friction rows: on a frictionless floor spinning friction still stops a
// spinning ball, and rolling friction stops a ball's rolling while it slides on at its speed
// (nothing couples its rotation to its motion).
TEST(SpinningFrictionTest, ActsOnAFrictionlessFloorToo) {
  const double rho_n = 0.002, w0 = 5.0;
  core::WorldDesc world = BallOnPlane(0.0, 0.0, rho_n);
  world.objects[0].initial_velocity.angular = Vec3(0, 0, w0);
  core::Simulator spinning(world);
  const double expected = rho_n * kGravity / (0.4 * kRadius * kRadius);
  const double w = SpinAt(&spinning, 0.5);
  EXPECT_NEAR(w, w0 - expected * 0.5, 0.02 * expected * 0.5);
  std::cout << "on ice: " << (w0 - w) / 0.5 << " rad/s² of spin lost; expected " << expected
            << " rad/s²\n";

  const double rho = 0.005, v0 = 1.0;
  world = BallOnPlane(0.0, rho, 0.0);
  world.objects[0].initial_velocity.linear = Vec3(v0, 0, 0);
  world.objects[0].initial_velocity.angular = Vec3(0, v0 / kRadius, 0);
  core::Simulator sliding(world);
  sliding.Simulate(0.5);
  ASSERT_NE(sliding.statistics().worst_status, core::StepStatus::kError);
  // the torque ρ m g alone on I = 2/5 m r²: 12.25 rad/s² off the 10 rad/s roll
  const double alpha = rho * kGravity / (0.4 * kRadius * kRadius);
  EXPECT_NEAR(sliding.GetObjectVelocity(0).angular.y(), v0 / kRadius - alpha * 0.5,
              0.02 * alpha * 0.5);
  EXPECT_NEAR(sliding.GetObjectVelocity(0).linear.x(), v0, 1e-3);
}

// stiffness_test.xml's rigid ball (sphere.off, 960 facets, 1 kg, radius 0.1 m under a 0.04 m
// padding, preshrunk) dropped from 1 m lands on its pole vertex, alone on the slab here. Without
// rolling resistance that balance is unstable and the ball rolls off after about 3 s: correct
// for a world that specifies none. With 1 mm of rolling friction on the ball and the slab it
// comes to rest on the vertex.
double RigidBallDrift(double rolling, core::Twist* end) {
  test::LoadedWorld loaded;
  test::LoadWorld(test::WorldsPath("klampt/simulation_test_worlds/stiffness_test.xml"), &loaded);
  EXPECT_TRUE(loaded.ok) << loaded.diagnostics.FormatAll();
  core::WorldDesc world = loaded.world;
  world.objects.erase(world.objects.begin(), world.objects.end() - 1);
  EXPECT_EQ(world.objects[0].name, "ball_rigid");
  world.objects[0].sim.surface.rolling_friction = rolling;
  world.terrains[0].sim.surface.rolling_friction = rolling;
  core::Simulator simulator(world);
  simulator.Simulate(8.0);
  EXPECT_NE(simulator.statistics().worst_status, core::StepStatus::kError);
  *end = simulator.GetObjectVelocity(0);
  return (simulator.GetObjectPose(0).translation() - world.objects[0].pose.translation())
      .head<2>()
      .norm();
}

TEST(RollingFrictionTest, StiffnessTestsRigidBallComesToRestOnItsVertex) {
  core::Twist end;
  const double free = RigidBallDrift(0.0, &end);
  EXPECT_GT(free, 0.05);  // rolled off (0.2 m by 8 s)
  const double held = RigidBallDrift(0.001, &end);
  EXPECT_LT(held, 1e-6);
  EXPECT_LT(end.linear.norm(), 1e-9);
  EXPECT_LT(end.angular.norm(), 1e-9);
  std::cout << "stiffness_test's rigid ball after 8 s: " << free << " m from its start without "
            << "rolling friction, " << held << " m with 1 mm\n";
}

// worlds/examples/rolling_friction.xml, as its comment describes it
TEST(RollingFrictionTest, TheExampleWorldDoesWhatItSays) {
  test::LoadedWorld loaded;
  test::LoadWorld(test::WorldsPath("examples/rolling_friction.xml"), &loaded);
  ASSERT_TRUE(loaded.ok) << loaded.diagnostics.FormatAll();
  EXPECT_EQ(loaded.diagnostics.warning_count(), 0) << loaded.diagnostics.FormatAll();
  const core::WorldDesc& world = loaded.world;
  core::Simulator simulator(world);
  simulator.Simulate(4.0);
  ASSERT_NE(simulator.statistics().worst_status, core::StepStatus::kError);
  const auto moved = [&](int i) {
    return simulator.GetObjectPose(i).translation() - world.objects[i].pose.translation();
  };
  // free: rolls on at 1 m/s; rolling: at rest 1.43 m on; spinning: stopped where it stood
  EXPECT_NEAR(simulator.GetObjectVelocity(0).linear.x(), 1.0, 1e-3);
  const double distance = 1.0 * 1.4 * kRadius / (2 * 0.005 * kGravity);  // 1.43 m
  EXPECT_NEAR(moved(1).x(), distance, 0.02 * distance);
  EXPECT_LT(simulator.GetObjectVelocity(1).linear.norm(), 1e-3);
  EXPECT_LT(std::abs(simulator.GetObjectVelocity(2).angular.z()), 1e-3);
  EXPECT_LT(moved(2).head<2>().norm(), 1e-3);
  // tessellated: at rest on its vertex
  EXPECT_LT(moved(3).head<2>().norm(), 1e-3) << moved(3).transpose();
  EXPECT_LT(simulator.GetObjectVelocity(3).linear.norm(), 1e-3);
}

}  // namespace
}  // namespace lamina
