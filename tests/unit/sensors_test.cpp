// SPDX-License-Identifier: MIT
// The sensor emulators as pure functions of their inputs (core/sensors): link motion against
// finite differences of forward kinematics, the settings' text, each type's reading of inputs
// with a known answer, the wrappers, the noise generator's statistics and determinism, the
// schedule, and parsing `<sensors>` with its diagnostics.
#include <cmath>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/robot/kinematics.h"
#include "core/sensors/link_motion.h"
#include "core/sensors/robot_sensors.h"
#include "core/sensors/sensor_text.h"
#include "tests/common/scene_builders.h"

namespace lamina {
namespace {

using core::Pose;
using core::Vec3;
using core::VecX;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

// a three-link chain: a slider along x, a hinge about z, a hinge about y, with offsets
core::RobotDesc Chain() {
  core::WorldDesc world = test::WorldWithRobot(
      "links \"slide\" \"turn\" \"tilt\"\nparents -1 0 1\n"
      "TParent 1 0 0  0 1 0  0 0 1  0 0 0.5   1 0 0  0 1 0  0 0 1  0.3 0 0.1   "
      "1 0 0  0 1 0  0 0 1  0.4 0.1 0\n"
      "axis 1 0 0  0 0 1  0 1 0\njointtype p r r\nmass 1 2 3\n"
      "com 0 0 0  0.1 0 0  0.2 0 0\ninertia 0.1 0 0 0 0.1 0 0 0 0.1  0.1 0 0 0 0.2 0 0 0 0.3  "
      "0.3 0 0 0 0.2 0 0 0 0.1\n");
  return world.robots[0];
}

core::SensorInputs InputsAt(const core::RobotDesc& robot, const VecX& q, const VecX& dq,
                            const VecX& ddq) {
  core::SensorInputs in;
  in.robot = &robot;
  in.q = q;
  in.dq = dq;
  in.ddq = ddq;
  in.motion = core::ComputeLinkMotion(robot, q, dq, ddq);
  in.driver_torques = VecX::Zero(robot.drivers.size());
  return in;
}

std::unique_ptr<core::Sensor> Make(
    const std::string& type, const core::RobotDesc& robot,
    const std::vector<std::pair<std::string, std::string>>& settings) {
  std::unique_ptr<core::Sensor> sensor = core::MakeSensor(type, robot);
  EXPECT_NE(sensor, nullptr) << type;
  for (const auto& [key, text] : settings) {
    std::string error;
    EXPECT_TRUE(sensor->SetSetting(key, text, &error)) << key << ": " << error;
  }
  return sensor;
}

// the motion of a point along a trajectory q(t) = q0 + v t + a t²/2, by central differences
TEST(LinkMotionTest, VelocitiesAndAccelerationsMatchFiniteDifferencesOfKinematics) {
  const core::RobotDesc robot = Chain();
  const VecX q0 = (VecX(3) << 0.2, 0.7, -0.4).finished();
  const VecX v = (VecX(3) << 0.5, -1.3, 2.1).finished();
  const VecX a = (VecX(3) << -0.8, 0.9, 1.7).finished();
  const auto position = [&](double t, int link) -> Vec3 {
    return core::LinkTransforms(robot, VecX(q0 + v * t + 0.5 * a * t * t))[link].translation();
  };
  const auto rotation = [&](double t, int link) -> core::Mat3 {
    return core::LinkTransforms(robot, VecX(q0 + v * t + 0.5 * a * t * t))[link].linear();
  };
  const core::LinkMotion m = core::ComputeLinkMotion(robot, q0, v, a);
  const double h = 1e-4;
  for (int link = 0; link < 3; ++link) {
    SCOPED_TRACE(link);
    const Vec3 vel = (position(h, link) - position(-h, link)) / (2 * h);
    const Vec3 acc = (position(h, link) - 2 * position(0, link) + position(-h, link)) / (h * h);
    EXPECT_LT((m.linear_velocity[link] - vel).norm(), 1e-6);
    EXPECT_LT((m.linear_acceleration[link] - acc).norm(), 1e-5);
    // ω from Ṙ Rᵀ, α from the difference of ω
    const auto omega = [&](double t) {
      const core::Mat3 w =
          (rotation(t + h, link) - rotation(t - h, link)) / (2 * h) * rotation(t, link).transpose();
      return Vec3(w(2, 1), w(0, 2), w(1, 0));
    };
    EXPECT_LT((m.angular_velocity[link] - omega(0)).norm(), 1e-6);
    EXPECT_LT((m.angular_acceleration[link] - (omega(h) - omega(-h)) / (2 * h)).norm(), 1e-4);
  }
}

TEST(SensorTextTest, ReadsKlamptsSpellingsAndRefusesBadText) {
  std::vector<double> list;
  std::string error;
  ASSERT_TRUE(core::ReadSensorList("3 0.1 0.2 0.3", &list, &error));
  EXPECT_THAT(list, ElementsAre(0.1, 0.2, 0.3));  // Klamp't's count dropped
  ASSERT_TRUE(core::ReadSensorList("0.1 0.2", &list, &error));
  EXPECT_THAT(list, ElementsAre(0.1, 0.2));  // its manual's spelling
  std::array<bool, 3> flags{};
  ASSERT_TRUE(core::ReadSensorBool3("1 0 true", &flags, &error));
  EXPECT_THAT(flags, ElementsAre(true, false, true));
  EXPECT_FALSE(core::ReadSensorBool3("1 0", &flags, &error));
  EXPECT_THAT(error, HasSubstr("expected 3 booleans"));
  Pose pose;
  ASSERT_TRUE(core::ReadSensorPose("0 1 0  -1 0 0  0 0 1  1 2 3", &pose, &error));
  EXPECT_EQ(pose.linear()(0, 1), 1.0);  // row by row
  EXPECT_EQ(pose.translation(), Vec3(1, 2, 3));
  EXPECT_FALSE(core::ReadSensorPose("2 0 0  0 1 0  0 0 1  0 0 0", &pose, &error));
  EXPECT_THAT(error, HasSubstr("not a rotation"));
  double value = 0;
  EXPECT_FALSE(core::ReadSensorDouble("nan", &value, &error));
  const core::RobotDesc robot = Chain();
  int link = 0;
  ASSERT_TRUE(core::ReadSensorLink("tilt", robot, false, &link, &error));
  EXPECT_EQ(link, 2);
  EXPECT_FALSE(core::ReadSensorLink("5", robot, false, &link, &error));
  EXPECT_THAT(error, HasSubstr("out of range"));
}

TEST(SensorTest, AnUnknownSettingOrBadValueIsRefusedAndChangesNothing) {
  const core::RobotDesc robot = Chain();
  auto sensor = Make("Accelerometer", robot, {{"link", "1"}});
  std::string error;
  EXPECT_FALSE(sensor->SetSetting("hasAxes", "1 1 1", &error));
  EXPECT_EQ(error, "unknown setting 'hasAxes' of a Accelerometer");
  EXPECT_FALSE(sensor->SetSetting("link", "9", &error));
  EXPECT_EQ(sensor->link(), 1);
  EXPECT_FALSE(sensor->SetSetting("rate", "-1", &error));
  std::string text;
  ASSERT_TRUE(sensor->GetSetting("link", &text));
  EXPECT_EQ(text, "1");
  ASSERT_TRUE(sensor->GetSetting("hasAxis", &text));
  EXPECT_EQ(text, "1 1 1");
}

TEST(SensorTest, JointSensorsMeasureTheirIndicesWithKlamptsNames) {
  const core::RobotDesc robot = Chain();
  const VecX q = (VecX(3) << 0.1, 0.2, 0.3).finished();
  auto encoders = Make("JointPositionSensor", robot, {{"indices", "2 0"}, {"qresolution", "0.25"}});
  encoders->Simulate(InputsAt(robot, q, VecX::Zero(3), VecX::Zero(3)));
  EXPECT_THAT(encoders->MeasurementNames(), ElementsAre("q[2]", "q[0]"));
  EXPECT_THAT(encoders->measurements(), ElementsAre(0.25, 0.0));  // quantised to 0.25
  auto rates = Make("JointVelocitySensor", robot, {});
  rates->Simulate(InputsAt(robot, q, q * 2, VecX::Zero(3)));
  EXPECT_THAT(rates->measurements(), ElementsAre(0.2, 0.4, 0.6));
}

// specific force: at rest −g (up), on a point turning at ω at radius r, −ω² r towards the axis
TEST(SensorTest, AnAccelerometerReadsSpecificForceInItsOwnAxes) {
  const core::RobotDesc robot = Chain();
  VecX q = VecX::Zero(3), dq = VecX::Zero(3);
  auto accel = Make("Accelerometer", robot, {{"link", "turn"}});
  accel->Simulate(InputsAt(robot, q, dq, VecX::Zero(3)));
  EXPECT_NEAR(accel->measurements()[2], 9.8, 1e-12);
  // on the turning link 0.5 m out along x, turning at 2 rad/s: 4 · 0.5 = 2 m/s² inwards
  accel =
      Make("Accelerometer", robot, {{"link", "turn"}, {"Tsensor", "1 0 0 0 1 0 0 0 1 0.5 0 0"}});
  dq[1] = 2.0;
  accel->Simulate(InputsAt(robot, q, dq, VecX::Zero(3)));
  EXPECT_NEAR(accel->measurements()[0], -2.0, 1e-12);
  EXPECT_NEAR(accel->measurements()[2], 9.8, 1e-12);
  // a sensor turned upside down about x reads −9.8 along its own z
  accel = Make("Accelerometer", robot,
               {{"link", "0"}, {"Tsensor", "1 0 0 0 -1 0 0 0 -1 0 0 0"}, {"hasAxis", "0 1 1"}});
  accel->Simulate(InputsAt(robot, q, VecX::Zero(3), VecX::Zero(3)));
  EXPECT_THAT(accel->measurements(), ElementsAre(0.0, 0.0, -9.8));
}

TEST(SensorTest, GyroAndTiltReadTheLinksRateAndAnglesInItsFrame) {
  const core::RobotDesc robot = Chain();
  VecX q = VecX::Zero(3), dq = VecX::Zero(3);
  q[1] = 0.5 * core::kPi;  // the tilt link's y axis now points along world -x
  dq[2] = 1.5;             // turning about its own y
  auto gyro = Make("GyroSensor", robot, {{"link", "2"}, {"hasAngVel", "1"}, {"hasRotation", "1"}});
  gyro->Simulate(InputsAt(robot, q, dq, VecX::Zero(3)));
  const std::vector<double>& m = gyro->measurements();
  ASSERT_EQ(m.size(), 15u);
  EXPECT_NEAR(m[9], 0.0, 1e-12);  // angVel in the link frame: (0, 1.5, 0)
  EXPECT_NEAR(m[10], 1.5, 1e-12);
  EXPECT_NEAR(m[1], -1.0, 1e-12);  // R_xy: the link's y axis along world -x
  auto tilt = Make("TiltSensor", robot, {{"link", "2"}, {"hasAxis", "1 1 1"}});
  q = VecX::Zero(3);
  q[2] = 0.3;  // pitched 0.3 rad about y: up is (-sin 0.3, 0, cos 0.3), a_y = asin(-d_x)
  tilt->Simulate(InputsAt(robot, q, VecX::Zero(3), VecX::Zero(3)));
  EXPECT_NEAR(tilt->measurements()[0], 0.0, 1e-12);
  EXPECT_NEAR(tilt->measurements()[1], 0.3, 1e-12);
}

TEST(SensorTest, ForceTorqueReadsTheStaticLoadOfItsSubtreeOnTheParent) {
  const core::RobotDesc robot = Chain();
  auto ft = Make("ForceTorqueSensor", robot, {{"link", "turn"}});
  core::SensorInputs in = InputsAt(robot, VecX::Zero(3), VecX::Zero(3), VecX::Zero(3));
  ft->Simulate(in);
  // links turn (2 kg, com 0.1 m out) and tilt (3 kg, com at 0.4 + 0.2 m out, 0.1 m aside)
  const double weight = 5 * 9.8;
  const std::vector<double>& m = ft->measurements();
  EXPECT_NEAR(m[2], -weight, 1e-9);
  EXPECT_NEAR(m[3], -3 * 9.8 * 0.1, 1e-9);             // (r × F)_x = r_y F_z
  EXPECT_NEAR(m[4], (2 * 0.1 + 3 * 0.6) * 9.8, 1e-9);  // (r × F)_y = −r_x F_z
  // a contact pushing the tilt link up by its own weight takes it off the joint
  in.contacts.push_back({2, in.motion.frames[2] * Vec3(0.2, 0, 0), Vec3(0, 0, 3 * 9.8)});
  ft->Simulate(in);
  EXPECT_NEAR(ft->measurements()[2], -2 * 9.8, 1e-9);
  EXPECT_NEAR(ft->measurements()[4], 2 * 0.1 * 9.8, 1e-9);
}

TEST(SensorTest, AContactSensorSumsTheForcesInsideItsPatch) {
  core::RobotDesc robot = Chain();
  auto patch = Make("ContactSensor", robot,
                    {{"link", "1"},
                     {"Tsensor", "1 0 0 0 1 0 0 0 1 0 0 0.05"},
                     {"patchMin", "-0.1 -0.1"},
                     {"patchMax", "0.1 0.1"},
                     {"hasForce", "0 0 1"},
                     {"fSensitivity", "0.5"}});
  EXPECT_THAT(patch->MeasurementNames(), ElementsAre("contact", "force_z"));
  core::SensorInputs in = InputsAt(robot, VecX::Zero(3), VecX::Zero(3), VecX::Zero(3));
  const Pose link = in.motion.frames[1];
  in.contacts = {{1, link * Vec3(0.05, 0, 0.05), Vec3(0, 0, -3)},   // inside
                 {1, link * Vec3(0.05, 0, 0.051), Vec3(0, 0, -4)},  // inside, within tolerance
                 {1, link * Vec3(0.3, 0, 0.05), Vec3(0, 0, -100)},  // outside the patch
                 {2, link * Vec3(0, 0, 0.05), Vec3(0, 0, -100)}};   // another link
  patch->Simulate(in);
  EXPECT_THAT(patch->measurements(), ElementsAre(1.0, -7.0));
  in.contacts.resize(0);
  patch->Simulate(in);
  EXPECT_THAT(patch->measurements(), ElementsAre(0.0, 0.0));
}

TEST(SensorTest, ALaserReadsItsRaysDistancesWithinResolutionAndMaxForMisses) {
  const core::RobotDesc robot = Chain();
  auto laser = Make("LaserRangeSensor", robot,
                    {{"measurementCount", "3"},
                     {"xSweepMagnitude", "0.5"},
                     {"depthResolution", "0.01"},
                     {"depthMaximum", "10"}});
  core::SensorInputs in = InputsAt(robot, VecX::Zero(3), VecX::Zero(3), VecX::Zero(3));
  // a wall at z = 2 in the world (the sensor at the origin looking along z)
  in.ray = [](const Vec3& origin, const Vec3& dir, double max, int) {
    const double t = (2.0 - origin.z()) / dir.z();
    return dir.z() > 0 && t <= max ? t : core::kInf;
  };
  laser->Simulate(in);
  const std::vector<double>& d = laser->measurements();
  ASSERT_EQ(d.size(), 3u);
  EXPECT_NEAR(d[0], 2.0 / std::cos(0.5), 0.005);
  EXPECT_NEAR(d[1], 2.0, 1e-12);
  EXPECT_NEAR(d[2], 2.0 / std::cos(0.5), 0.005);
  EXPECT_NEAR(std::remainder(d[0], 0.01), 0.0, 1e-9);  // quantised
  in.ray = [](const Vec3&, const Vec3&, double, int) { return core::kInf; };
  laser->Simulate(in);
  EXPECT_THAT(laser->measurements(), ElementsAre(10.0, 10.0, 10.0));
}

// the wrappers through RobotSensors: transformed, corrupted, filtered, delayed
TEST(SensorTest, WrappersTransformFilterAndDelayTheSensorTheyWrap) {
  core::RobotDesc robot = Chain();
  robot.properties["sensors"] =
      "<sensors><JointPositionSensor name=\"q\"/>"
      "<TransformedSensor name=\"scaled\" sensor=\"q\" scale=\"2\" bias=\"1\" maximum=\"1.5\"/>"
      "<FilteredSensor name=\"smooth\" sensor=\"q\" smoothing=\"0.5\"/>"
      "<TimeDelayedSensor name=\"late\" sensor=\"q\" delay=\"0.02\"/></sensors>";
  core::Diagnostics diagnostics;
  core::RobotSensors sensors(robot, &diagnostics);
  ASSERT_EQ(sensors.size(), 4) << diagnostics.FormatAll();
  VecX q = VecX::Zero(3);
  std::vector<std::vector<double>> delayed;
  for (int k = 0; k < 5; ++k) {
    q[0] = 0.1 * k;
    core::SensorInputs in = InputsAt(robot, q, VecX::Zero(3), VecX::Zero(3));
    in.time = 0.01 * k;
    sensors.Sample(in, 0.001, 0.01);
    delayed.push_back(sensors.sensor(3).measurements());
  }
  // last sample q0 = 0.4: 2·0.4 + 1 = 1.8, clamped to 1.5; the others 1
  EXPECT_THAT(sensors.sensor(1).measurements(), ElementsAre(1.5, 1.0, 1.0));
  // smoothing 0.5 over 0, 0.1, 0.2, 0.3, 0.4
  EXPECT_NEAR(sensors.sensor(2).measurements()[0],
              0.5 * 0.4 + 0.25 * 0.3 + 0.125 * 0.2 + 0.0625 * 0.1, 1e-12);
  EXPECT_TRUE(delayed[0].empty());  // nothing delivered yet
  EXPECT_TRUE(delayed[1].empty());
  EXPECT_NEAR(delayed[2][0], 0.0, 1e-12);  // two samples late
  EXPECT_NEAR(delayed[4][0], 0.2, 1e-12);
}

TEST(SensorTest, NoiseHasItsVarianceAndRepeatsFromItsCount) {
  core::SensorNoise noise(42);
  const int n = 20000;
  double sum = 0, sum2 = 0;
  for (int i = 0; i < n; ++i) {
    const double x = core::Discretize(1.0, 0.0, 0.04, noise);
    sum += x;
    sum2 += x * x;
  }
  const double mean = sum / n;
  const double sd = std::sqrt(sum2 / n - mean * mean);
  EXPECT_NEAR(mean, 1.0, 4 * 0.2 / std::sqrt(n));
  EXPECT_NEAR(sd, 0.2, 0.02 * 0.2);
  noise.set_count(7);
  const double a = noise.Normal();
  noise.set_count(7);
  EXPECT_EQ(noise.Normal(), a);
}

TEST(RobotSensorsTest, ARobotWithoutSensorsHasKlamptsDefaultsQAndDq) {
  const core::RobotDesc robot = Chain();
  core::RobotSensors sensors(robot, nullptr);
  ASSERT_EQ(sensors.size(), 2);
  EXPECT_TRUE(sensors.defaults());
  EXPECT_EQ(sensors.sensor(0).name(), "q");
  EXPECT_EQ(sensors.sensor(1).name(), "dq");
  EXPECT_EQ(sensors.Find("dq"), 1);
  EXPECT_THAT(sensors.sensor(1).MeasurementNames(), ElementsAre("dq[0]", "dq[1]", "dq[2]"));
}

// rate 25 Hz at 1 ms steps: samples at 0, 0.04, 0.08 (and held between)
TEST(RobotSensorsTest, EachSensorSamplesAtItsRateAndHoldsBetween) {
  core::RobotDesc robot = Chain();
  robot.properties["sensors"] =
      "<sensors><JointPositionSensor name=\"slow\" rate=\"25\"/>"
      "<JointPositionSensor name=\"off\" enabled=\"0\"/></sensors>";
  core::RobotSensors sensors(robot, nullptr);
  std::vector<double> seen;
  for (int k = 0; k <= 100; ++k) {
    VecX q = VecX::Constant(3, 0.001 * k);
    core::SensorInputs in = InputsAt(robot, q, VecX::Zero(3), VecX::Zero(3));
    in.time = 0.001 * k;
    sensors.Sample(in, 0.001, 0.01);
    seen.push_back(sensors.sensor(0).measurements()[0]);
  }
  EXPECT_EQ(seen[0], 0.0);
  EXPECT_EQ(seen[39], 0.0);
  EXPECT_NEAR(seen[40], 0.040, 1e-12);
  EXPECT_NEAR(seen[79], 0.040, 1e-12);
  EXPECT_NEAR(seen[80], 0.080, 1e-12);
  EXPECT_NEAR(seen[100], 0.080, 1e-12);
  EXPECT_THAT(sensors.sensor(1).measurements(), ElementsAre(0.0, 0.0, 0.0));  // disabled
}

TEST(RobotSensorsTest, ProblemsAreReportedAtTheirLineAndTheRestLoads) {
  const core::RobotDesc robot = Chain();
  core::Diagnostics diagnostics;
  const std::string xml =
      "<sensors>\n"
      "  <Gyroscope name=\"g\" link=\"1\"/>\n"
      "  <Accelerometer name=\"a\" link=\"tilt\" hasAxis=\"1 1\"/>\n"
      "  <FilteredSensor name=\"f\" sensor=\"nothing\"/>\n"
      "  <TiltSensor name=\"t\" link=\"9\"/>\n"
      "</sensors>\n";
  const auto sensors = core::ParseSensorsXml(xml, robot, {"robot.rob", 10, 0}, &diagnostics);
  ASSERT_EQ(sensors.size(), 2u);
  EXPECT_EQ(sensors[0]->link(), 2);
  EXPECT_THAT(diagnostics.Messages(core::Severity::kError),
              ElementsAre("robot.rob:11: error: unknown sensor type 'Gyroscope'; the sensor is "
                          "left out",
                          "robot.rob:13: error: FilteredSensor 'f': no earlier sensor named "
                          "'nothing' to wrap; the sensor is left out"));
  EXPECT_THAT(diagnostics.Messages(core::Severity::kWarning),
              ElementsAre("robot.rob:12: warning: Accelerometer 'a' hasAxis: expected 3 booleans "
                          "(0 or 1), got '1 1'; ignored",
                          "robot.rob:14: warning: TiltSensor 't' link: link 9 is out of range "
                          "(the robot has 3 links); ignored"));
}

}  // namespace
}  // namespace lamina
