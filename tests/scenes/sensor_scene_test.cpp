// SPDX-License-Identifier: MIT
// Simulated sensors against known answers: an accelerometer on a resting link reads −g in its
// frame (within its variance) and ~0 on a free-falling link; a gyro on a joint turning at a
// constant rate reads it; a force/torque sensor under a static load reads m·g and the load's
// moment; a contact sensor under a box reads its weight; a laser facing a wall reads its
// distance within its resolution; a time-delayed sensor lags by its delay; noisy runs repeat
// exactly whatever the chunking and after a state restore.
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/sim/simulator.h"
#include "tests/common/scene_builders.h"

namespace lamina {
namespace {

using core::Vec3;
using core::VecX;

constexpr double kG = 9.8;

// a 5 kg platform (1 × 1 × 0.1 m box) on a hinge about the vertical through (0, 0, 0.5): gravity
// does not turn it, the hinge carries its weight; no actuator effort (gains 0)
core::WorldDesc PlatformWorld(const std::string& sensors, double rate = 0.0) {
  core::WorldDesc world = test::WorldWithRobot(
      "links \"platform\"\nparents -1\nTParent 1 0 0  0 1 0  0 0 1  0 0 0.5\naxis 0 0 1\n"
      "jointtype r\nmass 5\ncom 0 0 0\ninertia 0.42 0 0  0 0.42 0  0 0 0.83\n"
      "joint normal 0\ndriver normal 0\nservoP 0\nservoI 0\nservoD 0\n");
  core::RobotDesc& robot = world.robots[0];
  robot.name = "rig";
  robot.links[0].geometry = {test::PrimitiveGeometry(core::Primitive::Box(Vec3(1, 1, 0.1)))};
  robot.properties["sensors"] = "<sensors>" + sensors + "</sensors>";
  robot.velocity = VecX::Constant(1, rate);
  world.terrains.push_back(test::PlaneTerrain(0.5, 0.0));
  return world;
}

std::vector<double> Read(const core::Simulator& sim, const std::string& name) {
  const core::RobotSensors& sensors = sim.sensors(0);
  const int i = sensors.Find(name);
  EXPECT_GE(i, 0) << name;
  return i >= 0 ? sensors.sensor(i).measurements() : std::vector<double>{};
}

TEST(SensorSceneTest, AnAccelerometerOnARestingLinkReadsMinusGWithinItsVariance) {
  core::Simulator sim(PlatformWorld(
      "<Accelerometer name=\"exact\" link=\"0\"/>"
      "<Accelerometer name=\"noisy\" link=\"0\" accelVariance=\"0.04 0.04 0.04\" rate=\"1000\"/>"));
  sim.Simulate(0.1);
  const std::vector<double> exact = Read(sim, "exact");
  EXPECT_NEAR(exact[0], 0.0, 1e-6);
  EXPECT_NEAR(exact[1], 0.0, 1e-6);
  EXPECT_NEAR(exact[2], kG, 1e-6);
  // 2000 noisy samples: mean within 4 σ/√n, spread within 5 %
  double sum = 0, sum2 = 0;
  const int n = 2000;
  for (int k = 0; k < n; ++k) {
    sim.Simulate(0.001);
    const double z = Read(sim, "noisy")[2];
    sum += z;
    sum2 += z * z;
  }
  const double mean = sum / n;
  EXPECT_NEAR(mean, kG, 4 * 0.2 / std::sqrt(n));
  EXPECT_NEAR(std::sqrt(sum2 / n - mean * mean), 0.2, 0.05 * 0.2);
}

// a slider along z with nothing holding it: it falls freely; the accelerometer reads 0 and the
// IMU's integrated velocity is −g t
TEST(SensorSceneTest, AnAccelerometerOnAFreeFallingLinkReadsZero) {
  core::WorldDesc world = test::WorldWithRobot(
      "links \"slider\"\nparents -1\nTParent 1 0 0  0 1 0  0 0 1  0 0 100\naxis 0 0 1\n"
      "jointtype p\nmass 1\ncom 0 0 0\ninertia 0.01 0 0  0 0.01 0  0 0 0.01\n"
      "joint normal 0\ndriver normal 0\nservoP 0\nservoI 0\nservoD 0\n");
  world.robots[0].properties["sensors"] =
      "<sensors><Accelerometer name=\"a\" link=\"0\"/>"
      "<IMUSensor name=\"imu\" link=\"0\" hasAngVel=\"1\" rate=\"1000\"/></sensors>";
  core::Simulator sim(world);
  sim.Simulate(0.5);
  const std::vector<double> a = Read(sim, "a");
  for (double v : a) EXPECT_NEAR(v, 0.0, 1e-6);
  const std::vector<double> imu = Read(sim, "imu");
  // integrated from the first sample on (t = 0 ... 0.499, one step behind the state)
  EXPECT_NEAR(imu[5], sim.GetRobotVelocity(0)[0], 0.01 * kG);
  EXPECT_NEAR(imu[2], -kG, 1e-6);  // the IMU's acceleration: the world's
}

// the platform turns freely at 2 rad/s: a gyro reads it in the link frame, an accelerometer
// 0.4 m out reads the centripetal −ω² r towards the axis and +g up
TEST(SensorSceneTest, AGyroOnAJointTurningAtAConstantRateReadsIt) {
  core::Simulator sim(PlatformWorld(
      "<GyroSensor name=\"gyro\" link=\"platform\" hasAngVel=\"1\" hasRotation=\"1\"/>"
      "<Accelerometer name=\"rim\" link=\"0\" Tsensor=\"1 0 0 0 1 0 0 0 1 0.4 0 0\"/>"
      "<TiltSensor name=\"tilt\" link=\"0\" hasAxis=\"1 1 1\"/>",
      2.0));
  sim.Simulate(1.0);
  const std::vector<double> gyro = Read(sim, "gyro");
  EXPECT_NEAR(gyro[9], 0.0, 1e-6);
  EXPECT_NEAR(gyro[10], 0.0, 1e-6);
  EXPECT_NEAR(gyro[11], 2.0, 1e-6);
  // R_xx = cos of the angle turned by the last sample (at 0.99 s, the control rate)
  EXPECT_NEAR(gyro[0], std::cos(2.0 * 0.99), 1e-6);
  const std::vector<double> rim = Read(sim, "rim");
  EXPECT_NEAR(rim[0], -4.0 * 0.4, 1e-6);
  EXPECT_NEAR(rim[1], 0.0, 1e-6);
  EXPECT_NEAR(rim[2], kG, 1e-6);
  EXPECT_NEAR(Read(sim, "tilt")[2], 0.5 * core::kPi, 1e-6);  // level: up along its z
}

// a 2 kg box resting on the platform 0.3 m off its axis: the contact sensor on the top face
// reads its weight, one beside it nothing; the force/torque sensor at the hinge carries the
// platform and the box, with the box's moment about the hinge
TEST(SensorSceneTest, ContactAndForceTorqueSensorsReadAStaticLoad) {
  core::WorldDesc world = PlatformWorld(
      "<ContactSensor name=\"top\" link=\"0\" Tsensor=\"1 0 0 0 1 0 0 0 1 0 0 0.05\" "
      "patchMin=\"0 -0.5\" patchMax=\"0.5 0.5\" patchTolerance=\"0.001\" hasForce=\"1 1 1\"/>"
      "<ContactSensor name=\"left\" link=\"0\" Tsensor=\"1 0 0 0 1 0 0 0 1 0 0 0.05\" "
      "patchMin=\"-0.5 -0.5\" patchMax=\"0 0.5\" hasForce=\"0 0 1\"/>"
      "<ForceTorqueSensor name=\"ft\" link=\"0\"/>");
  world.objects.push_back(test::BoxObject(0.2, 2.0, Vec3(0.3, 0, 0.55 + 0.1 + 0.004)));
  core::Simulator sim(world);
  sim.Simulate(1.0);
  const std::vector<double> top = Read(sim, "top");
  ASSERT_EQ(top.size(), 4u);
  EXPECT_EQ(top[0], 1.0);
  EXPECT_NEAR(top[1], 0.0, 1e-6);
  EXPECT_NEAR(top[3], -2.0 * kG, 1e-3 * 2 * kG);  // pressing in: along −z
  const std::vector<double> left = Read(sim, "left");
  EXPECT_EQ(left[0], 0.0);
  EXPECT_EQ(left[1], 0.0);
  const std::vector<double> ft = Read(sim, "ft");
  EXPECT_NEAR(ft[0], 0.0, 1e-3);
  EXPECT_NEAR(ft[2], -7.0 * kG, 1e-3 * 7 * kG);
  EXPECT_NEAR(ft[3], 0.0, 1e-3);
  EXPECT_NEAR(ft[4], 0.3 * 2.0 * kG, 1e-3 * 0.6 * kG);  // (r × F)_y = −x F_z
}

// a laser 1 m above the ground looking along +x at a wall whose face is at x = 2: three rays
// at −0.5, 0, 0.5 rad read 2 / cos θ within the 1 cm resolution; another looks down at the floor
TEST(SensorSceneTest, ALaserFacingAWallReadsItsDistanceWithinItsResolution) {
  core::WorldDesc world = PlatformWorld(
      "<LaserRangeSensor name=\"lidar\" link=\"-1\" Tsensor=\"0 0 1  1 0 0  0 1 0  0 0 1\" "
      "measurementCount=\"3\" xSweepMagnitude=\"0.5\" depthResolution=\"0.01\" "
      "depthMaximum=\"8\"/>"
      "<LaserRangeSensor name=\"down\" link=\"-1\" Tsensor=\"1 0 0  0 -1 0  0 0 -1  0.8 0 1\" "
      "measurementCount=\"1\" xSweepMagnitude=\"0\"/>");
  core::TerrainDesc wall;
  wall.name = "wall";
  core::Pose at = core::Pose::Identity();
  at.translation() = Vec3(2.1, 0, 1);
  wall.geometry = test::PrimitiveGeometry(core::Primitive::Box(Vec3(0.2, 6, 2), at));
  world.terrains.push_back(wall);
  core::Simulator sim(world);
  sim.Simulate(0.02);
  const std::vector<double> d = Read(sim, "lidar");
  ASSERT_EQ(d.size(), 3u);
  EXPECT_NEAR(d[0], 2.0 / std::cos(0.5), 0.005);
  EXPECT_NEAR(d[1], 2.0, 0.005);
  EXPECT_NEAR(d[2], 2.0 / std::cos(0.5), 0.005);
  // beside the platform, looking straight down from 1 m at the ground plane
  EXPECT_NEAR(Read(sim, "down")[0], 1.0, 1e-9);
}

// a passive pendulum: the delayed copy of its encoder at t equals the encoder at t − 0.05
TEST(SensorSceneTest, ATimeDelayedSensorLagsByItsDelay) {
  core::WorldDesc world = test::PendulumWorld("servoP 0\nservoI 0\nservoD 0\n", 0.4);
  world.robots[0].properties["sensors"] =
      "<sensors><JointPositionSensor name=\"q\" rate=\"100\"/>"
      "<TimeDelayedSensor name=\"late\" sensor=\"q\" delay=\"0.05\"/></sensors>";
  core::Simulator sim(world);
  std::map<int, double> history;  // by hundredths of a second
  for (int k = 0; k < 60; ++k) {
    sim.Simulate(0.01);
    const int tick = static_cast<int>(std::lround(sim.time() * 100)) - 1;  // last sample
    history[tick] = Read(sim, "q")[0];
    const std::vector<double> late = Read(sim, "late");
    if (tick < 5) {
      EXPECT_TRUE(late.empty()) << tick;
    } else {
      ASSERT_EQ(late.size(), 1u) << tick;
      EXPECT_EQ(late[0], history.at(tick - 5)) << tick;
    }
  }
  EXPECT_GT(std::abs(history[10] - history[15]), 0.01);  // it moves: the lag is visible
}

// noise repeats: one call or many, and from a restored state
TEST(SensorSceneTest, NoisyReadingsAreTheSameWhateverTheChunkingAndAfterARestore) {
  const std::string sensors =
      "<JointVelocitySensor name=\"dq\" dqvariance=\"1 0.01\" rate=\"500\"/>"
      "<Accelerometer name=\"a\" link=\"0\" accelVariance=\"0.1 0.1 0.1\"/>";
  core::Simulator once(PlatformWorld(sensors, 1.0));
  core::Simulator chunked(PlatformWorld(sensors, 1.0));
  once.Simulate(0.5);
  for (int k = 0; k < 50; ++k) chunked.Simulate(0.01);
  EXPECT_EQ(Read(once, "dq"), Read(chunked, "dq"));
  EXPECT_EQ(Read(once, "a"), Read(chunked, "a"));
  const core::SimState saved = once.GetState();
  once.Simulate(0.3);
  const std::vector<double> first = Read(once, "a");
  once.SetState(saved);
  once.Simulate(0.3);
  EXPECT_EQ(Read(once, "a"), first);
  EXPECT_NE(Read(once, "dq")[0], 1.0);  // it is noisy
  once.Reset();
  EXPECT_EQ(Read(once, "dq"), std::vector<double>{0.0});
}

// Klamp't's controllers read their joint sensors: with noisy encoders the controller's sensed
// configuration is the encoders' reading, not the exact state; without declared sensors it is
// the exact state at the step's start
TEST(SensorSceneTest, TheControllerReadsItsDeclaredJointSensors) {
  core::WorldDesc world = test::PendulumWorld("servoP 60\nservoI 0\nservoD 8\n", 0.4);
  world.robots[0].properties["sensors"] =
      "<sensors><JointPositionSensor name=\"encoders\" qvariance=\"0.0001\"/>"
      "<JointVelocitySensor name=\"tach\" dqresolution=\"0.5\"/></sensors>";
  core::Simulator noisy(world);
  noisy.Simulate(0.3);
  const core::RobotController& controller = noisy.controller(0);
  EXPECT_EQ(controller.sensed_config()[0], Read(noisy, "encoders")[0]);
  EXPECT_EQ(controller.sensed_velocity()[0], Read(noisy, "tach")[0]);
  EXPECT_EQ(std::remainder(controller.sensed_velocity()[0], 0.5), 0.0);  // quantised
  EXPECT_NE(controller.sensed_config()[0], noisy.GetRobotConfig(0)[0]);
  // the same robot without declared sensors: the update due at 0.29 s runs in the step from
  // 0.289 s (Klamp't's rule) and reads the exact state there
  world.robots[0].properties.erase("sensors");
  core::Simulator exact(world);
  exact.Simulate(0.289);
  const core::VecX q = exact.GetRobotConfig(0);
  exact.Simulate(0.001);
  EXPECT_EQ(exact.controller(0).sensed_config()[0], q[0]);
}

// the defaults sample the exact state at the start of the step in which they are due: the
// sample due at 0.19 s is the state after 0.19 s
TEST(SensorSceneTest, ARobotWithoutSensorsMeasuresItsStateWithQAndDq) {
  core::Simulator sim(test::PendulumWorld("servoP 0\nservoI 0\nservoD 0\n", 0.4));
  sim.Simulate(0.19);
  const VecX q = sim.GetRobotConfig(0), dq = sim.GetRobotVelocity(0);
  sim.Simulate(0.01);
  ASSERT_TRUE(sim.sensors(0).defaults());
  EXPECT_EQ(Read(sim, "q"), std::vector<double>{q[0]});
  EXPECT_EQ(Read(sim, "dq"), std::vector<double>{dq[0]});
  EXPECT_GT(std::abs(dq[0]), 0.1);  // it swings: a stale sample would differ
}

}  // namespace
}  // namespace lamina
