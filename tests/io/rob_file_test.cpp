// SPDX-License-Identifier: MIT
// The `.rob` reader: every example robot, Klamp't's defaults and keyword semantics, mounting,
// automass, and exact diagnostics for malformed files.
#include <memory>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/io/robot_file.h"
#include "tests/common/test_support.h"

namespace lamina {
namespace {

using core::Severity;
using ::testing::ElementsAre;
using ::testing::IsEmpty;

constexpr double kDegree = core::kPi / 180.0;

using test::LoadedRobot;
using test::LoadRobot;

std::unique_ptr<LoadedRobot> LoadExample(const std::string& name) {
  return LoadRobot(test::WorldsPath("klampt/robots/" + name));
}

// writes `text` as a scratch .rob file and loads it
std::unique_ptr<LoadedRobot> LoadRobText(const std::string& text, std::string* path = nullptr) {
  const std::string file = test::WriteScratchFile("robot.rob", text);
  if (path != nullptr) *path = file;
  return LoadRobot(file);
}

std::vector<double> DriverValues(const core::RobotDesc& robot, double core::DriverDesc::*field) {
  std::vector<double> values;
  for (const core::DriverDesc& driver : robot.drivers) values.push_back(driver.*field);
  return values;
}

const std::string kBox = test::DataPath("robots/box.off");

TEST(RobFile, EveryExampleRobotLoadsWithoutErrors) {
  std::vector<std::string> warnings;
  for (const char* name :
       {"athlete.rob", "cartpole.rob", "footed_2d_biped.rob", "free_cube.rob", "planar3R.rob",
        "sphere.rob", "sphere1cm.rob", "swingup.rob", "tx90l.rob", "ur5.rob"}) {
    auto loaded = LoadExample(name);
    EXPECT_TRUE(loaded->ok) << name << "\n" << loaded->diagnostics.FormatAll();
    EXPECT_THAT(loaded->diagnostics.Messages(Severity::kError), IsEmpty()) << name;
    for (const std::string& warning : loaded->diagnostics.Messages(Severity::kWarning)) {
      warnings.push_back(warning);
    }
    EXPECT_EQ(loaded->robot.name, std::string(name).substr(0, std::string(name).find('.')));
    EXPECT_EQ(loaded->robot.source_path, test::WorldsPath(std::string("klampt/robots/") + name));
  }
  // both files continue a numeric statement into the next keyword with a trailing backslash
  EXPECT_THAT(warnings,
              ElementsAre(test::WorldsPath("klampt/robots/athlete.rob") +
                              ":247: warning: 'servoI' continues the 'servoP' statement through "
                              "a trailing backslash; read as a new statement",
                          test::WorldsPath("klampt/robots/tx90l.rob") +
                              ":9: warning: 'parents' continues the 'TParent' statement "
                              "through a trailing backslash; read as a new statement"));
}

TEST(RobFile, AthleteKeepsTheServoIValuesKlamptLoses) {
  auto loaded = LoadExample("athlete.rob");
  const core::RobotDesc& robot = loaded->robot;
  ASSERT_EQ(robot.drivers.size(), 36u);
  std::vector<double> servo_p, servo_d;
  for (int leg = 0; leg < 6; ++leg) {
    servo_p.insert(servo_p.end(), {50, 50, 50, 25, 10, 10});
    servo_d.insert(servo_d.end(), {0.5, 0.5, 0.5, 0.25, 0.1, 0.1});
  }
  EXPECT_EQ(DriverValues(robot, &core::DriverDesc::servo_p), servo_p);
  EXPECT_EQ(DriverValues(robot, &core::DriverDesc::servo_i), std::vector<double>(36, 30.0));
  EXPECT_EQ(DriverValues(robot, &core::DriverDesc::servo_d), servo_d);
  EXPECT_EQ(DriverValues(robot, &core::DriverDesc::viscous_friction), std::vector<double>(36, 1.0));
}

TEST(RobFile, AthleteStructure) {
  auto loaded = LoadExample("athlete.rob");
  const core::RobotDesc& robot = loaded->robot;
  ASSERT_EQ(robot.dof(), 42);
  ASSERT_EQ(robot.joints.size(), 37u);
  EXPECT_EQ(robot.joints[0].type, core::JointType::kFloating);
  EXPECT_EQ(robot.joints[0].link, 5);
  EXPECT_EQ(robot.joints[0].base, -1);
  EXPECT_EQ(robot.joints[1].type, core::JointType::kNormal);
  EXPECT_EQ(robot.joints[1].link, 6);
  EXPECT_EQ(robot.drivers[0].links, std::vector<int>{6});
  EXPECT_EQ(robot.drivers[0].name, "hip yaw 1");
  // 0.0388 + 6 * (0.0269 + 0.0242 + 0.0132 + 0.0171 + 0.0127 + 0.0661): decimal rounding only
  EXPECT_NEAR(robot.TotalMass(), 1.0, 1e-12);
  EXPECT_EQ(robot.links[12].parent, 5);
  EXPECT_EQ(robot.links[0].axis_type, core::LinkJointAxis::kPrismatic);
  EXPECT_EQ(robot.links[0].parent_transform.translation(), core::Vec3(0, 0, 0.66));
  // qdeg / qmindeg / qmaxdeg: revolute entries in radians, prismatic -inf untouched
  EXPECT_EQ(robot.links[7].q_initial, 30 * kDegree);
  EXPECT_EQ(robot.config[7], 30 * kDegree);
  EXPECT_EQ(robot.links[8].q_max, 180 * kDegree);
  EXPECT_EQ(robot.links[0].q_min, -core::kInf);
  EXPECT_EQ(robot.drivers[1].q_min, -90 * kDegree);
  EXPECT_EQ(robot.drivers[0].torque_max, 0.9261);
  EXPECT_EQ(robot.drivers[0].torque_min, -0.9261);
  EXPECT_EQ(robot.drivers[0].acceleration_max, 4.0);
  // geometry: the hex body scaled by 0.01, each ankle with a mounted wheel
  EXPECT_FALSE(robot.links[4].has_geometry());
  ASSERT_EQ(robot.links[5].geometry.size(), 1u);
  EXPECT_EQ(robot.links[5].geometry[0].path, test::WorldsPath("klampt/robots/athlete/hex.off"));
  EXPECT_EQ(robot.links[5].geometry[0].scale, core::Vec3::Constant(0.01));
  ASSERT_EQ(robot.links[11].geometry.size(), 2u);
  EXPECT_EQ(robot.links[11].geometry[1].path,
            test::WorldsPath("klampt/robots/athlete/wheel_scaled.off"));
  EXPECT_EQ(robot.links[11].geometry[1].transform.translation(), core::Vec3(0.184, 0, 0));
  // automass keeps the file's COM and computes the inertia about it
  EXPECT_EQ(robot.links[6].com, core::Vec3(0, 0, -0.0395));
  const core::Mat3& inertia = robot.links[6].inertia;
  EXPECT_TRUE(inertia.isApprox(inertia.transpose(), 1e-12));
  EXPECT_GT(inertia.trace(), 0.0);
  EXPECT_EQ(robot.links[0].inertia, core::Mat3::Zero());  // massless virtual link
}

TEST(RobFile, Ur5) {
  auto loaded = LoadExample("ur5.rob");
  const core::RobotDesc& robot = loaded->robot;
  ASSERT_EQ(robot.dof(), 8);
  ASSERT_EQ(robot.joints.size(), 8u);
  EXPECT_EQ(robot.joints[0].type, core::JointType::kWeld);
  EXPECT_EQ(robot.joints[0].link, 0);
  EXPECT_EQ(robot.joints[7].type, core::JointType::kWeld);
  EXPECT_EQ(robot.joints[7].link, 7);
  EXPECT_EQ(robot.no_self_collision, (std::vector<std::pair<int, int>>{{0, 2}, {4, 6}}));
  const auto pairs = robot.SelfCollisionPairs();
  EXPECT_EQ(std::count(pairs.begin(), pairs.end(), std::make_pair(0, 2)), 0);
  EXPECT_EQ(std::count(pairs.begin(), pairs.end(), std::make_pair(0, 3)), 1);
  EXPECT_EQ(robot.links[2].parent_transform.linear()(0, 0), 1.7949e-09);
  EXPECT_EQ(robot.links[2].parent_transform.linear()(2, 0), -1.0);
  EXPECT_EQ(robot.links[2].parent_transform.translation(), core::Vec3(0, 0.13585, 0));
  EXPECT_EQ(robot.links[2].mass, 8.393);
  EXPECT_EQ(robot.links[2].com, core::Vec3(0, 0, 0.28));
  EXPECT_EQ(robot.links[2].inertia.diagonal(), core::Vec3(0.226891, 0.226891, 0.0151074));
  EXPECT_EQ(robot.links[0].torque_max, core::kInf);
  ASSERT_EQ(robot.drivers.size(), 6u);
  EXPECT_EQ(robot.drivers[0].name, "shoulder_link");
  EXPECT_EQ(robot.drivers[0].q_min, -6.28319);
  EXPECT_EQ(robot.drivers[0].velocity_min, -3.15);
  EXPECT_EQ(robot.drivers[0].torque_min, -150.0);
  EXPECT_EQ(robot.drivers[0].acceleration_max, 10.0);
  EXPECT_EQ(DriverValues(robot, &core::DriverDesc::servo_p),
            (std::vector<double>{1000, 4000, 2000, 400, 300, 50}));
  EXPECT_EQ(DriverValues(robot, &core::DriverDesc::viscous_friction),
            (std::vector<double>{5, 5, 3, 3, 1, 1}));
  EXPECT_EQ(robot.links[1].sim, core::DefaultLinkSimParams());
}

TEST(RobFile, Tx90lGetsDefaultJointsAndDrivers) {
  auto loaded = LoadExample("tx90l.rob");
  const core::RobotDesc& robot = loaded->robot;
  ASSERT_EQ(robot.dof(), 7);
  ASSERT_EQ(robot.joints.size(), 7u);
  // the root's velMaxDeg 0 (and so velmin 0) makes it a weld, the rest are normal joints
  EXPECT_EQ(robot.joints[0].type, core::JointType::kWeld);
  for (int i = 1; i < 7; ++i) EXPECT_EQ(robot.joints[i].type, core::JointType::kNormal);
  ASSERT_EQ(robot.drivers.size(), 6u);
  EXPECT_EQ(robot.drivers[0].name, "Link 1");
  EXPECT_EQ(robot.drivers[5].name, "Link 6");
  EXPECT_EQ(robot.drivers[0].links, std::vector<int>{1});
  EXPECT_EQ(robot.drivers[0].q_min, -179 * kDegree);
  EXPECT_EQ(robot.drivers[0].velocity_max, 400 * kDegree);
  EXPECT_EQ(robot.drivers[0].acceleration_max, 400 * kDegree);
  EXPECT_EQ(robot.drivers[0].torque_max, 800.0);
  EXPECT_EQ(DriverValues(robot, &core::DriverDesc::servo_p),
            (std::vector<double>{40000, 50000, 20000, 4000, 1000, 100}));
  EXPECT_EQ(test::Parents(robot), (std::vector<int>{-1, 0, 1, 2, 3, 4, 5}));
  // automass on the 5 cm sphere (mass 0.1): a thin shell has I = 2/3 m r^2 (a solid would
  // have 2/5). The 960-facet tessellation lies inside the sphere: its moments fall 1.2 % short.
  const core::LinkDesc& tool = robot.links[6];
  EXPECT_LT(tool.com.norm(), 1e-3);
  const double shell = 2.0 / 3.0 * 0.1 * 0.05 * 0.05;
  EXPECT_NEAR(tool.inertia(0, 0), shell, 0.02 * shell);
  EXPECT_NEAR(tool.inertia(2, 2), shell, 0.02 * shell);
}

TEST(RobFile, KlamptDefaults) {
  auto loaded = LoadRobText(
      "TParent 1 0 0 0 1 0 0 0 1 0 0 0 \\\n"
      "        1 0 0 0 1 0 0 0 1 0 0 1\n");
  ASSERT_TRUE(loaded->ok) << loaded->diagnostics.FormatAll();
  const core::RobotDesc& robot = loaded->robot;
  EXPECT_EQ(test::LinkNames(robot), (std::vector<std::string>{"Link 0", "Link 1"}));
  EXPECT_EQ(test::Parents(robot), (std::vector<int>{-1, 0}));
  for (const core::LinkDesc& link : robot.links) {
    EXPECT_EQ(link.axis_type, core::LinkJointAxis::kRevolute);
    EXPECT_EQ(link.axis, core::Vec3::UnitZ());
    EXPECT_EQ(link.mass, 1.0);
    EXPECT_EQ(link.inertia, core::Mat3::Identity());
    EXPECT_EQ(link.q_min, -core::kInf);
    EXPECT_EQ(link.velocity_min, -core::kInf);
    EXPECT_EQ(link.acceleration_max, core::kInf);
    EXPECT_EQ(link.power_max, core::kInf);
    EXPECT_TRUE(link.geometry.empty());
  }
  ASSERT_EQ(robot.joints.size(), 2u);
  EXPECT_EQ(robot.joints[0].type, core::JointType::kNormal);  // the root can move: velmax inf
  ASSERT_EQ(robot.drivers.size(), 2u);
  EXPECT_EQ(robot.drivers[1].name, "Link 1");
  EXPECT_EQ(robot.drivers[1].servo_p, 0.0);
  EXPECT_EQ(robot.config, core::VecX::Zero(2));
  EXPECT_EQ(robot.velocity, core::VecX::Zero(2));
}

TEST(RobFile, DegreesConvertOnlyRevoluteEntriesWhateverTheKeywordOrder) {
  // Klamp't converts the prismatic entry too when qmindeg comes before jointtype
  auto loaded = LoadRobText(
      "TParent 1 0 0 0 1 0 0 0 1 0 0 0  1 0 0 0 1 0 0 0 1 0 0 1\n"
      "qMinDeg -90 -90\n"
      "qmaxdeg 90 90\n"
      "jointtype p r\n");
  ASSERT_TRUE(loaded->ok) << loaded->diagnostics.FormatAll();
  EXPECT_EQ(loaded->robot.links[0].q_min, -90.0);
  EXPECT_EQ(loaded->robot.links[0].q_max, 90.0);
  EXPECT_EQ(loaded->robot.links[1].q_min, -90 * kDegree);
  EXPECT_EQ(loaded->robot.links[1].q_max, 90 * kDegree);
}

TEST(RobFile, DenavitHartenbergParameters) {
  auto loaded = LoadRobText(
      "alphadeg 0 90\n"
      "a 0 0.5\n"
      "d 0.1 0.2\n"
      "thetadeg 0 30\n");
  ASSERT_TRUE(loaded->ok) << loaded->diagnostics.FormatAll();
  // Klamp't's (Craig) convention: Trans_x(a) Rot_x(alpha) Trans_z(d) Rot_z(theta)
  const core::Pose expected =
      Eigen::Translation3d(0.5, 0, 0) * Eigen::AngleAxisd(90 * kDegree, core::Vec3::UnitX()) *
      Eigen::Translation3d(0, 0, 0.2) * Eigen::AngleAxisd(30 * kDegree, core::Vec3::UnitZ());
  // a handful of roundings of sin/cos products
  EXPECT_TRUE(loaded->robot.links[1].parent_transform.matrix().isApprox(expected.matrix(), 1e-12));
  EXPECT_EQ(loaded->robot.links[0].parent_transform.translation(), core::Vec3(0, 0, 0.1));
}

TEST(RobFile, TranslationAndRotationPlaceTheRoots) {
  auto loaded = LoadRobText(
      "TParent 1 0 0 0 1 0 0 0 1 0 0 0.5  1 0 0 0 1 0 0 0 1 1 0 0\n"
      "translation 1 2 3\n"
      "rotation 0 -1 0  1 0 0  0 0 1\n");
  ASSERT_TRUE(loaded->ok) << loaded->diagnostics.FormatAll();
  const core::Pose& root = loaded->robot.links[0].parent_transform;
  EXPECT_EQ(root.translation(), core::Vec3(1, 2, 3.5));
  EXPECT_EQ(root.linear().col(0), core::Vec3(0, 1, 0));
  EXPECT_EQ(loaded->robot.links[1].parent_transform.translation(), core::Vec3(1, 0, 0));
}

TEST(RobFile, GeometryScaleMarginAndTransform) {
  auto loaded = LoadRobText(
      "TParent 1 0 0 0 1 0 0 0 1 0 0 0  1 0 0 0 1 0 0 0 1 0 0 1\n"
      "geometry \"" +
      kBox + "\" \"" + kBox +
      "\"\n"
      "geomscale 2 0.5\n"
      "geommargin 0.01\n"
      "geomtransform 1  0 -1 0 1  1 0 0 2  0 0 1 3  0 0 0 1\n");
  ASSERT_TRUE(loaded->ok) << loaded->diagnostics.FormatAll();
  const core::GeometryDesc& first = loaded->robot.links[0].geometry.at(0);
  const core::GeometryDesc& second = loaded->robot.links[1].geometry.at(0);
  EXPECT_EQ(first.kind, core::GeometryKind::kMesh);
  EXPECT_EQ(first.path, kBox);
  EXPECT_EQ(first.triangle_count(), 12);
  EXPECT_EQ(first.scale, core::Vec3::Constant(2));
  EXPECT_EQ(first.margin, 0.01);
  EXPECT_EQ(second.margin, 0.01);
  core::Mat4 expected;
  expected << 0, -0.5, 0, 1, 0.5, 0, 0, 2, 0, 0, 0.5, 3, 0, 0, 0, 1;
  EXPECT_EQ(second.Matrix().matrix(), expected);  // scale first, then the geomtransform
  EXPECT_EQ(loaded->meshes.size(), 1);            // one file, loaded once
}

TEST(RobFile, AutomassFromGeometry) {
  auto loaded = LoadRobText(
      "TParent 1 0 0 0 1 0 0 0 1 0 0 0  1 0 0 0 1 0 0 0 1 0 0 1 \\\n"
      "        1 0 0 0 1 0 0 0 1 0 0 0  1 0 0 0 1 0 0 0 1 0 0 1\n"
      "geometry \"" +
      kBox + "\" \"" + kBox +
      "\" \"\" \"\"\n"
      "mass 3 3 0 2\n"
      "com 0.1 0.2 0.3  0 0 0  0 0 0  0 0 0\n"
      "automass 0\n");
  ASSERT_TRUE(loaded->ok) << loaded->diagnostics.FormatAll();
  const auto& links = loaded->robot.links;
  // a solid 0.2 x 0.4 x 0.6 box of 3 kg: I = m/12 (b^2 + c^2), ...; exact up to rounding
  EXPECT_TRUE(
      links[0].inertia.isApprox(core::Vec3(0.13, 0.1, 0.05).asDiagonal().toDenseMatrix(), 1e-12));
  EXPECT_EQ(links[0].com, core::Vec3(0.1, 0.2, 0.3));  // given, kept
  // the given COM (0, 0, 0) is 0.1, 0.2, 0.3 from the box centre: parallel axes
  core::Mat3 shifted;
  shifted << 0.52, -0.06, -0.09, -0.06, 0.4, -0.18, -0.09, -0.18, 0.2;
  EXPECT_TRUE(links[1].inertia.isApprox(shifted, 1e-12)) << links[1].inertia;
  EXPECT_EQ(links[2].inertia, core::Mat3::Zero());      // massless, no geometry
  EXPECT_EQ(links[3].inertia, core::Mat3::Identity());  // mass but no geometry: kept
}

TEST(RobFile, AutomassIncludesMountedMeshes) {
  auto loaded = LoadRobText(
      "TParent 1 0 0 0 1 0 0 0 1 0 0 0\n"
      "geometry \"" +
      kBox +
      "\"\n"
      "mass 2\n"
      "mount 0 \"" +
      kBox +
      "\" 1 0 0 0 1 0 0 0 1 1 0 0\n"
      "automass\n");
  ASSERT_TRUE(loaded->ok) << loaded->diagnostics.FormatAll();
  // two equal boxes 1 m apart in x; the shell COM of each is its centre
  EXPECT_TRUE(loaded->robot.links[0].com.isApprox(core::Vec3(0.6, 0.2, 0.3), 1e-12))
      << loaded->robot.links[0].com;
  EXPECT_EQ(loaded->robot.links[0].geometry.size(), 2u);
}

TEST(RobFile, AutotorqueFollowsKlamptsHeuristic) {
  auto loaded = LoadRobText(
      "TParent 1 0 0 0 1 0 0 0 1 0 0 0  1 0 0 0 1 0 0 0 1 0 0 1\n"
      "mass 2 1\n"
      "com 0 0 0  0.5 0 0\n"
      "autotorque 1\n");
  ASSERT_TRUE(loaded->ok) << loaded->diagnostics.FormatAll();
  // link 1: 1 kg at 0.5 m -> 0.5 * 1 * 9.8; link 0: (0 * 2 + (0.5 + 0) * 1) / 3 m * 3 kg * 9.8
  EXPECT_NEAR(loaded->robot.links[1].torque_max, 4.9, 1e-12);
  EXPECT_NEAR(loaded->robot.links[0].torque_max, 4.9, 1e-12);
  EXPECT_NEAR(loaded->robot.drivers[1].torque_min, -4.9, 1e-12);
}

TEST(RobFile, MountsARobotWithAPrefix) {
  auto loaded = LoadRobot(test::DataPath("robots/arm.rob"));
  ASSERT_TRUE(loaded->ok) << loaded->diagnostics.FormatAll();
  const core::RobotDesc& robot = loaded->robot;
  EXPECT_EQ(test::LinkNames(robot),
            (std::vector<std::string>{"base", "arm", "hand:palm", "hand:finger"}));
  EXPECT_EQ(test::Parents(robot), (std::vector<int>{-1, 0, 1, 2}));
  // the mount transform (90 degrees about z, 0.6 up) applies to the sub-robot's root
  const core::Pose& palm = robot.links[2].parent_transform;
  EXPECT_EQ(palm.translation(), core::Vec3(0, 0, 0.7));
  EXPECT_EQ(palm.linear().col(0), core::Vec3(0, 1, 0));
  EXPECT_EQ(robot.links[3].parent_transform.translation(), core::Vec3(0.05, 0, 0));
  EXPECT_EQ(robot.links[3].axis_type, core::LinkJointAxis::kPrismatic);
  ASSERT_EQ(robot.joints.size(), 4u);
  EXPECT_EQ(robot.joints[2].type, core::JointType::kWeld);
  EXPECT_EQ(robot.joints[2].link, 2);
  EXPECT_EQ(robot.joints[3].link, 3);
  ASSERT_EQ(robot.drivers.size(), 2u);
  EXPECT_EQ(robot.drivers[1].name, "hand:finger");
  EXPECT_EQ(robot.drivers[1].links, std::vector<int>{3});
  EXPECT_EQ(DriverValues(robot, &core::DriverDesc::servo_p), (std::vector<double>{10, 5}));
  // "noselfcollision base hand:finger" names a mounted link
  EXPECT_EQ(robot.no_self_collision, (std::vector<std::pair<int, int>>{{0, 3}}));
  EXPECT_TRUE(robot.self_collision.empty());
  EXPECT_EQ(robot.config.size(), 4);
  EXPECT_EQ(robot.velocity.size(), 4);
}

TEST(RobFile, MountingMergesAnExplicitSelfCollisionList) {
  auto loaded = LoadRobText(
      "TParent 1 0 0 0 1 0 0 0 1 0 0 0  1 0 0 0 1 0 0 0 1 0 0 1\n"
      "geometry \"" +
      kBox + "\" \"" + kBox +
      "\"\n"
      "selfcollision 0 1\n"
      "mount 1 \"" +
      test::DataPath("robots/gripper.rob") + "\"\n");
  ASSERT_TRUE(loaded->ok) << loaded->diagnostics.FormatAll();
  // own pair, then across: link 0 with the palm (the palm sits on link 1, and the finger
  // has no geometry)
  EXPECT_EQ(loaded->robot.self_collision, (std::vector<std::pair<int, int>>{{0, 1}, {0, 2}}));
  EXPECT_EQ(test::LinkNames(loaded->robot)[2], "palm");
}

TEST(RobFile, SelfCollisionPairsByNameOrIndex) {
  auto loaded = LoadRobText(
      "links \"a\" \"b\" \"c\"\n"
      "TParent 1 0 0 0 1 0 0 0 1 0 0 0  1 0 0 0 1 0 0 0 1 0 0 1  1 0 0 0 1 0 0 0 1 0 0 1\n"
      "selfcollision a c  1 2\n"
      "noselfcollision c a\n");
  ASSERT_TRUE(loaded->ok) << loaded->diagnostics.FormatAll();
  EXPECT_EQ(loaded->robot.self_collision, (std::vector<std::pair<int, int>>{{0, 2}, {1, 2}}));
  EXPECT_EQ(loaded->robot.no_self_collision, (std::vector<std::pair<int, int>>{{2, 0}}));
}

TEST(RobFile, JointAndDriverTypes) {
  auto loaded = LoadRobText(
      "TParent 1 0 0 0 1 0 0 0 1 0 0 0 \\\n"
      "        1 0 0 0 1 0 0 0 1 0 0 0 \\\n"
      "        1 0 0 0 1 0 0 0 1 0 0 0 \\\n"
      "        1 0 0 0 1 0 0 0 1 0 0 0 \\\n"
      "        1 0 0 0 1 0 0 0 1 0 0 0\n"
      "jointtype p p r r r\n"
      "qmin -1 -2 -3 -4 -5\n"
      "joint floatingplanar 2 -1\n"
      "joint spin 3\n"
      "joint weld 4\n"
      "driver translation 0 2\n"
      "driver rotation 2 2\n"
      "driver affine 2  3 4  1 -2  0 0.5  -1 1 -2 2 -3 3\n"
      "drivers x r both\n");
  ASSERT_TRUE(loaded->ok) << loaded->diagnostics.FormatAll();
  const core::RobotDesc& robot = loaded->robot;
  ASSERT_EQ(robot.joints.size(), 3u);
  EXPECT_EQ(robot.joints[0].type, core::JointType::kFloatingPlanar);
  EXPECT_EQ(robot.joints[1].type, core::JointType::kSpin);
  ASSERT_EQ(robot.drivers.size(), 3u);
  EXPECT_EQ(robot.drivers[0].type, core::DriverType::kTranslation);
  EXPECT_EQ(robot.drivers[0].links, (std::vector<int>{0, 2}));
  EXPECT_EQ(robot.drivers[0].q_min, -1.0);  // from the axis link
  EXPECT_EQ(robot.drivers[1].type, core::DriverType::kRotation);
  const core::DriverDesc& affine = robot.drivers[2];
  EXPECT_EQ(affine.type, core::DriverType::kAffine);
  EXPECT_EQ(affine.links, (std::vector<int>{3, 4}));
  EXPECT_EQ(affine.affine_scale, (std::vector<double>{1, -2}));
  EXPECT_EQ(affine.affine_offset, (std::vector<double>{0, 0.5}));
  EXPECT_EQ(affine.q_min, -1.0);
  EXPECT_EQ(affine.torque_max, 3.0);
  EXPECT_EQ(affine.acceleration_max, core::kInf);
  EXPECT_EQ(affine.name, "both");
}

TEST(RobFile, PropertiesKeepTheirText) {
  test::WriteScratchFile("sensors.xml", "<sensors><JointPositionSensor name=\"q\"/></sensors>");
  auto loaded = LoadRobText(
      "TParent 1 0 0 0 1 0 0 0 1 0 0 0\n"
      "property controller <controller type=\"JointTrackingController\"  rate=\"100\"/>\n"
      "property sensors sensors.xml\n"
      "property note \"a # is not a comment here\"\n");
  ASSERT_TRUE(loaded->ok) << loaded->diagnostics.FormatAll();
  const auto& properties = loaded->robot.properties;
  EXPECT_EQ(properties.at("controller"),
            "<controller type=\"JointTrackingController\"  rate=\"100\"/>");
  EXPECT_EQ(properties.at("sensors"), "<sensors><JointPositionSensor name=\"q\"/></sensors>");
  EXPECT_EQ(properties.at("note"), "a # is not a comment here");
}

TEST(RobFile, KeywordsAreCaseInsensitive) {
  auto loaded = LoadRobText(
      "TPARENT 1 0 0 0 1 0 0 0 1 0 0 0\n"
      "Mass 4\n"
      "ServoP 7\n");
  ASSERT_TRUE(loaded->ok) << loaded->diagnostics.FormatAll();
  EXPECT_EQ(loaded->robot.links[0].mass, 4.0);
  EXPECT_EQ(loaded->robot.drivers[0].servo_p, 7.0);
}

// ---- malformed input -----------------------------------------------------------------------

struct RobBadCase {
  const char* name;
  const char* lines;                  // appended to a valid two-link robot (from line 4)
  std::vector<std::string> messages;  // errors, without the "path:" prefix
};

constexpr char kTwoLinkRob[] =
    "links \"a\" \"b\"\n"
    "TParent 1 0 0 0 1 0 0 0 1 0 0 0 \\\n"
    "        1 0 0 0 1 0 0 0 1 0 0 1\n";

class RobFileErrors : public ::testing::TestWithParam<RobBadCase> {};

TEST_P(RobFileErrors, ReportsExactMessages) {
  std::string path;
  auto loaded = LoadRobText(std::string(kTwoLinkRob) + GetParam().lines, &path);
  std::vector<std::string> expected;
  for (const std::string& message : GetParam().messages) {
    std::string text = message;
    const size_t at = text.find("DIR/");
    if (at != std::string::npos) text.replace(at, 3, test::ScratchDir());
    expected.push_back(path + ":" + text);
  }
  EXPECT_FALSE(loaded->ok);
  EXPECT_EQ(loaded->diagnostics.Messages(Severity::kError), expected);
}

INSTANTIATE_TEST_SUITE_P(
    Rob, RobFileErrors,
    ::testing::Values(
        RobBadCase{"UnknownKeyword",
                   "qmaxx 1 1\n",
                   {"4: error: unknown keyword 'qmaxx' (did you mean 'qmax'?)"}},
        RobBadCase{"BadNumber", "mass 1 abc\n", {"4: error: 'abc' in 'mass' is not a number"}},
        RobBadCase{"NaN", "mass nan 1\n", {"4: error: 'nan' in 'mass' is not a number"}},
        RobBadCase{
            "NegativeMass", "mass 1 -2\n", {"4: error: mass of link 1 must be >= 0, got '-2'"}},
        RobBadCase{"WrongLength",
                   "qmin 0 0 0\n",
                   {"4: error: 'qmin' expects 2 values (one per link), got 3"}},
        RobBadCase{"NotAMultiple",
                   "com 0 0\n",
                   {"4: error: 'com' expects a multiple of 3 numbers, got 2",
                    "4: error: 'com' expects 6 numbers (3 per link), got 2"}},
        RobBadCase{"ParentOutOfRange",
                   "parents -1 5\n",
                   {"4: error: parent of link 1 must be -1 or a link index below 1, got 5"}},
        RobBadCase{"ParentCycle",
                   "parents 1 0\n",
                   {"4: error: parent of link 0 must be -1 or a link index below 0, got 1"}},
        RobBadCase{"JointTypeLetter",
                   "jointtype r x\n",
                   {"4: error: invalid joint type 'x', expected 'r' or 'p'"}},
        RobBadCase{"JointLinkOutOfRange",
                   "joint normal 0\njoint normal 7\n",
                   {"5: error: 'joint' link 7 is out of range (robot has 2 links)"}},
        RobBadCase{"UnknownJointType",
                   "joint hinge 1\n",
                   {"4: error: unknown joint type 'hinge', expected normal, spin, weld, floating, "
                    "floatingplanar or ballandsocket"}},
        RobBadCase{"FloatingBaseNotAnAncestor",
                   "joint floating 0 1\njoint normal 1\n",
                   {"4: error: joint base 1 is not an ancestor of link 0"}},
        RobBadCase{"FloatingPlanarSpan",
                   "joint floatingplanar 1 -1\n",
                   {"4: error: 'floatingplanar' joint must span 3 links, got 2"}},
        RobBadCase{"LinkInTwoJoints",
                   "joint normal 0\njoint normal 1\njoint weld 1\n",
                   {"6: error: link 1 is already part of the joint on line 5"}},
        RobBadCase{
            "InertiaNotSymmetric",
            "inertia 1 2 0 0 1 0 0 0 1  1 0 0 0 1 0 0 0 1\n",
            {"4: error: inertia of link 0 must be a symmetric positive semi-definite 3x3 matrix, "
             "got '1 2 0 0 1 0 0 0 1'"}},
        RobBadCase{
            "InertiaNegativeMoment",
            "inertiadiag 1 -1 1  1 1 1\n",
            {"4: error: inertia of link 0 must be a symmetric positive semi-definite 3x3 matrix, "
             "got '1 0 0 0 -1 0 0 0 1'"}},
        RobBadCase{
            "QminAboveQmax",
            "qmin 1 0\nqmax 0 0\n",
            {"4: error: jointLimits of link 0 (qmin, qmax) must be 2 numbers min <= max (inf and "
             "-inf allowed), got '1 0'"}},
        RobBadCase{"ServoCount",
                   "servoP 1 2 3\n",
                   {"4: error: 'servoP' expects 2 values (one per driver), got 3"}},
        RobBadCase{"ServoNegative",
                   "servoP 1 -5\n",
                   {"4: error: 'servoP' of driver 1 must be >= 0, got '-5'"}},
        RobBadCase{"DriverNamesCount",
                   "drivers \"x\"\n",
                   {"4: error: 'drivers' expects 2 names (one per driver), got 1"}},
        RobBadCase{"DrivenTwice",
                   "driver normal 1\ndriver normal 1\n",
                   {"5: error: link 1 is already driven by the driver on line 4"}},
        RobBadCase{"UnknownDriverType",
                   "driver pwm 1\n",
                   {"4: error: unknown driver type 'pwm', expected normal, affine, translation or "
                    "rotation"}},
        RobBadCase{"AffineCounts",
                   "driver affine 2 0 1 1\n",
                   {"4: error: 'driver affine' expects a count n >= 1, then n links, n scales, n "
                    "offsets and optionally 6 limits, got 4 values"}},
        RobBadCase{"MissingMesh",
                   "geometry \"nope.off\" \"\"\n",
                   {"4: error: cannot open mesh file 'DIR/nope.off'"}},
        RobBadCase{"GeometryCount",
                   "geometry \"\"\n",
                   {"4: error: 'geometry' expects 2 file names (one per link), got 1"}},
        RobBadCase{"GeomTransformLastRow",
                   "geomtransform 0 1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 2\n",
                   {"4: error: 'geomtransform' matrix must end with the row '0 0 0 1'"}},
        RobBadCase{
            "Scale", "scale 2\n", {"4: error: 'scale' other than 1 is not supported, got '2'"}},
        RobBadCase{
            "Collision",
            "collision 0\nnocollision 1\n",
            {"4: error: 'collision' is not supported", "5: error: 'nocollision' is not supported"}},
        RobBadCase{"MountTransform",
                   "mount 0 \"x.off\" 1 0 0\n",
                   {"4: error: 'mount' transform expects 12 numbers, got 3"}},
        RobBadCase{"MountLink",
                   "mount 5 \"x.rob\"\nmount wrist \"x.off\"\n",
                   {"4: error: 'mount' link 5 is out of range (robot has 2 links)",
                    "5: error: 'mount' link 'wrist' is not a link name or index"}},
        RobBadCase{"MissingMountedRobot",
                   "mount 0 \"missing.rob\"\n",
                   {"4: error: cannot open robot file 'DIR/missing.rob'"}},
        RobBadCase{"UnknownPairLink",
                   "noselfcollision a c\n",
                   {"4: error: unknown link 'c' in 'noselfcollision'"}},
        RobBadCase{"AutomassFraction",
                   "automass 2\n",
                   {"4: error: 'automass' surface fraction must be in [0, 1], got '2'"}},
        RobBadCase{"TranslationCount",
                   "translation 1 2\n",
                   {"4: error: 'translation' expects 3 numbers, got 2"}}),
    [](const ::testing::TestParamInfo<RobBadCase>& param_info) { return param_info.param.name; });

TEST(RobFile, NoLinkFrames) {
  std::string path;
  auto loaded = LoadRobText("links \"a\"\nmass 1\n", &path);
  EXPECT_FALSE(loaded->ok);
  EXPECT_THAT(loaded->diagnostics.Messages(Severity::kError),
              ElementsAre(path + ": error: no link frames: expected 'tparent' or all of 'alpha', "
                                 "'a', 'd', 'theta'"));
}

TEST(RobFile, ReportsEveryProblemOfAFileInOneRun) {
  const std::string path = test::DataPath("bad/rob_many_errors.rob");
  auto loaded = LoadRobot(path);
  EXPECT_FALSE(loaded->ok);
  EXPECT_THAT(loaded->diagnostics.Messages(Severity::kError),
              ElementsAre(path + ":6: error: 'fast' in 'velmax' is not a number",
                          path + ":9: error: unknown keyword 'velmaks' (did you mean 'velmax'?)",
                          path + ":7: error: mass of link 1 must be >= 0, got '-1'",
                          path + ":10: error: 'joint' link 3 is out of range (robot has 3 links)",
                          path + ":14: error: 'servoD' expects 2 values (one per driver), got 1"));
}

TEST(RobFile, RejectsARobotThatMountsItself) {
  const std::string path = test::DataPath("bad/rob_mount_self.rob");
  auto loaded = LoadRobot(path);
  EXPECT_FALSE(loaded->ok);
  EXPECT_THAT(
      loaded->diagnostics.Messages(Severity::kError),
      ElementsAre(path + ":3: error: 'mount' of '" + path + "' would mount a robot inside itself"));
}

TEST(RobFile, MissingOrUnsupportedRobotFile) {
  core::Diagnostics diagnostics;
  core::MeshCache meshes;
  core::LoadContext context{diagnostics, meshes};
  core::RobotDesc robot;
  const std::string missing = test::DataPath("robots/none.rob");
  EXPECT_FALSE(core::LoadRobotFile(missing, {"world.xml", 7}, context, &robot));
  EXPECT_FALSE(core::LoadRobotFile(kBox, {"world.xml", 8}, context, &robot));
  EXPECT_THAT(diagnostics.Messages(Severity::kError),
              ElementsAre("world.xml:7: error: cannot open robot file '" + missing + "'",
                          "world.xml:8: error: unsupported robot file '" + kBox +
                              "': expected a .rob or .urdf file"));
}

}  // namespace
}  // namespace lamina
