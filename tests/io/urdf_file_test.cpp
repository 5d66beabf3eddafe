// SPDX-License-Identifier: MIT
// The URDF reader: mirobot (Klamp't's example), every joint type, primitives and mesh paths,
// Klamp't's floating base and <klampt> extension, and exact diagnostics for bad files.
#include <cmath>
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

using test::LoadedRobot;
using test::LoadRobot;

std::unique_ptr<LoadedRobot> LoadUrdfText(const std::string& text, std::string* path = nullptr) {
  const std::string file = test::WriteScratchFile("robot.urdf", text);
  if (path != nullptr) *path = file;
  return LoadRobot(file);
}

TEST(UrdfFile, Mirobot) {
  const std::string path = test::WorldsPath("klampt/robots/mirobot.urdf");
  auto loaded = LoadRobot(path);
  ASSERT_TRUE(loaded->ok) << loaded->diagnostics.FormatAll();
  // the file misspells Klamp't's default_acc_max; Klamp't ignores it silently
  EXPECT_THAT(loaded->diagnostics.Messages(Severity::kWarning),
              ElementsAre(path + ":436: warning: <klampt>: unknown attribute 'defaultAccMax' "
                                 "ignored (did you mean 'default_acc_max'?)"));
  const core::RobotDesc& robot = loaded->robot;
  EXPECT_EQ(robot.name, "mirobot");
  // the "world" root is the fixed frame: 8 URDF links give 7 robot links
  EXPECT_EQ(test::LinkNames(robot), (std::vector<std::string>{"base_link", "Link1", "Link2",
                                                              "Link3", "Link4", "Link5", "Link6"}));
  EXPECT_EQ(test::Parents(robot), (std::vector<int>{-1, 0, 1, 2, 3, 4, 5}));
  ASSERT_EQ(robot.joints.size(), 7u);
  EXPECT_EQ(robot.joints[0].type, core::JointType::kWeld);
  for (int i = 1; i < 7; ++i) EXPECT_EQ(robot.joints[i].type, core::JointType::kNormal);
  for (const core::LinkDesc& link : robot.links) {
    ASSERT_EQ(link.geometry.size(), 1u) << link.name;
    EXPECT_EQ(link.geometry[0].kind, core::GeometryKind::kMesh) << link.name;
    EXPECT_GT(link.geometry[0].triangle_count(), 0) << link.name;
  }
  EXPECT_EQ(robot.links[0].geometry[0].path,
            test::WorldsPath("klampt/robots/mirobot/base_link.STL"));
  // joint1: lower="-1.7453" upper="2.7925" effort="1" velocity="0.7"
  const core::DriverDesc& joint1 = robot.drivers.at(0);
  EXPECT_EQ(joint1.name, "Link1");
  EXPECT_EQ(joint1.links, std::vector<int>{1});
  EXPECT_EQ(joint1.q_min, -1.7453);
  EXPECT_EQ(joint1.q_max, 2.7925);
  EXPECT_EQ(joint1.velocity_min, -0.7);
  EXPECT_EQ(joint1.velocity_max, 0.7);
  EXPECT_EQ(joint1.torque_min, -1.0);
  EXPECT_EQ(joint1.torque_max, 1.0);
  EXPECT_EQ(joint1.acceleration_max, 10.0);  // Klamp't's default_acc_max
  // <klampt><link name="Link1" servoP="10" servoI="0" servoD="1"/>
  EXPECT_EQ(joint1.servo_p, 10.0);
  EXPECT_EQ(joint1.servo_i, 0.0);
  EXPECT_EQ(joint1.servo_d, 1.0);
  EXPECT_EQ(robot.drivers.at(5).servo_d, 0.2);
  // the fixed joint to the world: a weld with zero limits
  EXPECT_EQ(robot.links[0].q_max, 0.0);
  EXPECT_EQ(robot.links[0].velocity_max, 0.0);
  EXPECT_EQ(robot.links[0].com, core::Vec3(0.00072554, 2.2065E-05, 0.024268));
  EXPECT_EQ(robot.links[0].mass, 0.1);
  // joint2 origin: rpy="3.1402 -1.5708 1.5722" (through urdfdom's quaternion: rounding only)
  const core::Pose& frame = robot.links[2].parent_transform;
  EXPECT_TRUE(
      frame.linear().isApprox(core::RotationFromRollPitchYaw(3.1402, -1.5708, 1.5722), 1e-12));
  EXPECT_EQ(frame.translation(), core::Vec3(0.029687, -0.022, 0.061593));
  EXPECT_EQ(robot.links[5].axis, core::Vec3(0, 0, -1));
  EXPECT_EQ(robot.config, core::VecX::Zero(7));
}

TEST(UrdfFile, EveryJointTypePrimitivesAndPackages) {
  const std::string path = test::DataPath("robots/urdf/all_joints.urdf");
  auto loaded = LoadRobot(path);
  ASSERT_TRUE(loaded->ok) << loaded->diagnostics.FormatAll();
  EXPECT_THAT(loaded->diagnostics.Messages(Severity::kWarning), IsEmpty());
  EXPECT_THAT(loaded->diagnostics.Messages(Severity::kNote),
              ElementsAre(path + ":46: note: link 'wheel_link' has no <collision>; its <visual> "
                                 "geometry is used"));
  const core::RobotDesc& robot = loaded->robot;
  // depth first, children in urdfdom's order (by joint name): free, shoulder, table; slider,
  // wheel
  EXPECT_EQ(
      test::LinkNames(robot),
      (std::vector<std::string>{"base", "free_base0", "free_base1", "free_base2", "free_base3",
                                "free_base4", "drone", "upper", "slide", "finger_link",
                                "wheel_link", "table_base0", "table_base1", "puck"}));
  EXPECT_EQ(test::Parents(robot), (std::vector<int>{-1, 0, 1, 2, 3, 4, 5, 0, 7, 8, 7, 0, 11, 12}));
  ASSERT_EQ(robot.joints.size(), 7u);
  const std::vector<std::vector<int>> joints = {{0, -1}, {6, 0},   {7, -1}, {8, -1},
                                                {9, -1}, {10, -1}, {13, 0}};
  const std::vector<core::JointType> types = {
      core::JointType::kWeld,          core::JointType::kFloating, core::JointType::kNormal,
      core::JointType::kNormal,        core::JointType::kNormal,   core::JointType::kSpin,
      core::JointType::kFloatingPlanar};
  for (size_t i = 0; i < joints.size(); ++i) {
    EXPECT_EQ(robot.joints[i].type, types[i]) << i;
    EXPECT_EQ(robot.joints[i].link, joints[i][0]) << i;
    EXPECT_EQ(robot.joints[i].base, joints[i][1]) << i;
  }

  // base: inertia given in a frame turned 0.5 rad about z: I_link = R diag(1, 2, 3) R^T
  const core::LinkDesc& base = robot.links[0];
  EXPECT_EQ(base.parent_transform.translation(), core::Vec3(0, 0, 0.1));
  EXPECT_EQ(base.mass, 2.0);
  EXPECT_EQ(base.com, core::Vec3(0.1, 0, 0));
  const double c = std::cos(0.5), s = std::sin(0.5);
  // rounding through urdfdom's quaternion
  EXPECT_NEAR(base.inertia(0, 0), c * c + 2 * s * s, 1e-12);
  EXPECT_NEAR(base.inertia(0, 1), (1 - 2) * s * c, 1e-12);
  EXPECT_NEAR(base.inertia(2, 2), 3.0, 1e-12);
  ASSERT_EQ(base.geometry.size(), 2u);
  EXPECT_EQ(base.geometry[0].kind, core::GeometryKind::kPrimitive);
  EXPECT_EQ(base.geometry[0].primitive.type, core::PrimitiveType::kBox);
  EXPECT_EQ(base.geometry[0].primitive.size, core::Vec3(0.2, 0.4, 0.6));
  EXPECT_EQ(base.geometry[0].transform.translation(), core::Vec3(0, 0, 0.05));
  EXPECT_EQ(base.geometry[1].path, test::DataPath("robots/urdf/pkg_dir/meshes/tetra.off"));
  EXPECT_EQ(base.geometry[1].scale, core::Vec3(1, 2, 3));

  // drone: 5 virtual links from the joint origin, then the drone turning about x
  EXPECT_EQ(robot.links[1].parent_transform.translation(), core::Vec3(1, 0, 0));
  EXPECT_EQ(robot.links[1].axis_type, core::LinkJointAxis::kPrismatic);
  EXPECT_EQ(robot.links[1].axis, core::Vec3::UnitX());
  EXPECT_EQ(robot.links[4].axis, core::Vec3::UnitZ());
  EXPECT_EQ(robot.links[4].axis_type, core::LinkJointAxis::kRevolute);
  EXPECT_EQ(robot.links[4].mass, 0.0);
  EXPECT_EQ(robot.links[6].axis, core::Vec3::UnitX());
  EXPECT_EQ(robot.links[6].mass, 0.5);
  EXPECT_EQ(robot.links[6].geometry.at(0).path, test::DataPath("robots/box.off"));

  // upper: revolute with limits, dynamics and Klamp't's import gains
  const core::LinkDesc& upper = robot.links[7];
  EXPECT_EQ(upper.axis, core::Vec3(0, 1, 0));
  EXPECT_EQ(upper.q_min, -1.0);
  EXPECT_EQ(upper.q_max, 2.0);
  EXPECT_EQ(upper.velocity_min, -3.0);
  EXPECT_EQ(upper.torque_max, 30.0);
  EXPECT_EQ(upper.acceleration_max, 10.0);
  EXPECT_EQ(upper.geometry.at(0).primitive.type, core::PrimitiveType::kCylinder);
  EXPECT_EQ(upper.geometry.at(0).primitive.radius, 0.05);
  EXPECT_EQ(upper.geometry.at(0).primitive.length, 0.4);
  ASSERT_EQ(robot.drivers.size(), 3u);
  const core::DriverDesc& shoulder = robot.drivers[0];
  EXPECT_EQ(shoulder.name, "upper");
  EXPECT_EQ(shoulder.servo_p, 100.0);
  EXPECT_EQ(shoulder.servo_i, 0.0);
  EXPECT_EQ(shoulder.servo_d, 10.0);
  EXPECT_EQ(shoulder.dry_friction, 0.25);
  EXPECT_EQ(shoulder.viscous_friction, 0.5);
  EXPECT_EQ(shoulder.torque_min, -30.0);

  // slider with the mimicking finger: one affine driver, q_finger = 0.05 - 2 q_slider
  const core::DriverDesc& slider = robot.drivers[1];
  EXPECT_EQ(slider.type, core::DriverType::kAffine);
  EXPECT_EQ(slider.links, (std::vector<int>{8, 9}));
  EXPECT_EQ(slider.affine_scale, (std::vector<double>{1, -2}));
  EXPECT_EQ(slider.affine_offset, (std::vector<double>{0, 0.05}));
  EXPECT_EQ(slider.q_max, 0.3);
  EXPECT_EQ(robot.links[8].axis_type, core::LinkJointAxis::kPrismatic);
  EXPECT_EQ(robot.links[8].geometry.at(0).path,
            test::DataPath("robots/box.off"));  // package://robots
  EXPECT_EQ(robot.links[9].mass, 0.0);          // no <inertial>

  // wheel: continuous -> spin, unlimited position, limited velocity and effort
  const core::LinkDesc& wheel = robot.links[10];
  EXPECT_EQ(wheel.q_min, -core::kInf);
  EXPECT_EQ(wheel.q_max, core::kInf);
  EXPECT_EQ(wheel.velocity_max, 10.0);
  EXPECT_EQ(wheel.torque_max, 5.0);
  EXPECT_EQ(wheel.geometry.at(0).primitive.type, core::PrimitiveType::kSphere);
  EXPECT_EQ(robot.drivers[2].name, "wheel_link");

  // puck: planar about z -> prismatic x, prismatic y, revolute z
  EXPECT_EQ(robot.links[11].axis, core::Vec3::UnitX());
  EXPECT_EQ(robot.links[12].axis, core::Vec3::UnitY());
  EXPECT_EQ(robot.links[12].axis_type, core::LinkJointAxis::kPrismatic);
  EXPECT_EQ(robot.links[13].axis, core::Vec3::UnitZ());
  EXPECT_EQ(robot.links[13].axis_type, core::LinkJointAxis::kRevolute);
}

constexpr char kFloatingRobot[] = R"(<?xml version="1.0"?>
<robot name="floating">
  <link name="body">
    <inertial><mass value="3"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial>
  </link>
  <link name="arm"/>
  <joint name="hinge" type="revolute">
    <parent link="body"/>
    <child link="arm"/>
    <limit lower="-1" upper="1" effort="2" velocity="1"/>
  </joint>
)";

TEST(UrdfFile, ARootOtherThanTheWorldFloats) {
  auto loaded = LoadUrdfText(std::string(kFloatingRobot) + "</robot>\n");
  ASSERT_TRUE(loaded->ok) << loaded->diagnostics.FormatAll();
  const core::RobotDesc& robot = loaded->robot;
  // Klamp't's floating base: x, y, z, yaw, pitch virtual links; the body itself is the roll
  EXPECT_EQ(test::LinkNames(robot),
            (std::vector<std::string>{"base0", "base1", "base2", "base3", "base4", "body", "arm"}));
  ASSERT_EQ(robot.joints.size(), 2u);
  EXPECT_EQ(robot.joints[0].type, core::JointType::kFloating);
  EXPECT_EQ(robot.joints[0].link, 5);
  EXPECT_EQ(robot.joints[0].base, -1);
  EXPECT_EQ(robot.links[5].axis, core::Vec3::UnitX());
  EXPECT_EQ(robot.links[5].mass, 3.0);
  EXPECT_EQ(robot.links[5].torque_max, 0.0);
  EXPECT_EQ(robot.links[3].axis, core::Vec3::UnitZ());
  EXPECT_EQ(robot.links[0].axis_type, core::LinkJointAxis::kPrismatic);
  ASSERT_EQ(robot.drivers.size(), 1u);
  EXPECT_EQ(robot.drivers[0].links, std::vector<int>{6});
  EXPECT_EQ(robot.links[6].axis, core::Vec3::UnitX());  // URDF's default axis
}

TEST(UrdfFile, KlamptExtension) {
  const std::string box = test::DataPath("robots/box.off");
  auto loaded =
      LoadUrdfText(std::string(kFloatingRobot) +
                   "  <klampt freeze_root_link=\"1\" default_acc_max=\"3\" "
                   "default_mass=\"0.25\">\n"
                   "    <link name=\"arm\" servoP=\"7\" dryFriction=\"0.5\" accMax=\"4\"/>\n"
                   "    <noselfcollision pairs=\"body arm\"/>\n"
                   "    <mount link=\"arm\" file=\"" +
                   box +
                   "\" transform=\"1 0 0 0 1 0 0 0 1 0 0 1\"/>\n"
                   "    <sensors><JointPositionSensor name=\"q\"/></sensors>\n"
                   "  </klampt>\n</robot>\n");
  ASSERT_TRUE(loaded->ok) << loaded->diagnostics.FormatAll();
  const core::RobotDesc& robot = loaded->robot;
  ASSERT_EQ(robot.joints.size(), 7u);  // six welds for the frozen base, then the hinge
  EXPECT_EQ(robot.joints[0].type, core::JointType::kWeld);
  EXPECT_EQ(robot.joints[5].type, core::JointType::kWeld);
  EXPECT_EQ(robot.joints[5].link, 5);
  EXPECT_EQ(robot.links[6].mass, 0.25);  // no <inertial>: default_mass
  EXPECT_EQ(robot.links[6].acceleration_max, 4.0);
  EXPECT_EQ(robot.drivers[0].servo_p, 7.0);
  EXPECT_EQ(robot.drivers[0].servo_d, 10.0);
  EXPECT_EQ(robot.drivers[0].dry_friction, 0.5);
  EXPECT_EQ(robot.drivers[0].acceleration_max, 4.0);
  EXPECT_EQ(robot.no_self_collision, (std::vector<std::pair<int, int>>{{5, 6}}));
  ASSERT_EQ(robot.links[6].geometry.size(), 2u);  // no own geometry, then the mounted box
  EXPECT_TRUE(robot.links[6].geometry[0].empty());
  EXPECT_EQ(robot.links[6].geometry[1].transform.translation(), core::Vec3(0, 0, 1));
  EXPECT_EQ(robot.properties.at("sensors"), "<sensors><JointPositionSensor name=\"q\"/></sensors>");
}

TEST(UrdfFile, FileSchemeAndVisualGeometryOption) {
  const std::string box = test::DataPath("robots/box.off");
  auto loaded = LoadUrdfText(
      "<robot name=\"r\">\n"
      "  <link name=\"world\"/>\n"
      "  <joint name=\"j\" type=\"fixed\"><parent link=\"world\"/><child link=\"a\"/></joint>\n"
      "  <link name=\"a\">\n"
      "    <collision><geometry><sphere radius=\"1\"/></geometry></collision>\n"
      "    <visual><geometry><mesh filename=\"file://" +
      box +
      "\"/></geometry></visual>\n"
      "  </link>\n"
      "  <klampt use_vis_geom=\"1\"/>\n"
      "</robot>\n");
  ASSERT_TRUE(loaded->ok) << loaded->diagnostics.FormatAll();
  ASSERT_EQ(loaded->robot.links.at(0).geometry.size(), 1u);
  EXPECT_EQ(loaded->robot.links[0].geometry[0].path, box);
  EXPECT_EQ(loaded->diagnostics.entries().size(), 0u);
}

TEST(UrdfFile, MimicChainsComposeIntoOneAffineDriver) {
  std::string path;
  const std::string limit = "<limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/>";
  auto loaded = LoadUrdfText(
      "<robot name=\"r\">\n"
      "  <link name=\"world\"/><link name=\"a\"/><link name=\"b\"/><link name=\"c\"/>\n"
      "  <link name=\"d\"/>\n"
      "  <joint name=\"j_a\" type=\"revolute\"><parent link=\"world\"/><child link=\"a\"/>" +
          limit +
          "</joint>\n"
          "  <joint name=\"j_b\" type=\"revolute\"><parent link=\"a\"/><child link=\"b\"/>" +
          limit +
          "<mimic joint=\"j_a\" multiplier=\"2\" offset=\"0.1\"/></joint>\n"
          "  <joint name=\"j_c\" type=\"revolute\"><parent link=\"b\"/><child link=\"c\"/>" +
          limit +
          "<mimic joint=\"j_b\" multiplier=\"3\" offset=\"0.2\"/></joint>\n"
          "  <joint name=\"j_d\" type=\"fixed\"><parent link=\"c\"/><child link=\"d\"/>"
          "</joint>\n"
          "  <joint name=\"j_e\" type=\"revolute\"><parent link=\"d\"/><child link=\"e\"/>" +
          limit +
          "<mimic joint=\"j_d\"/></joint>\n"
          "  <link name=\"e\"/>\n"
          "</robot>\n",
      &path);
  ASSERT_TRUE(loaded->ok) << loaded->diagnostics.FormatAll();
  // q_c = 3 (2 q_a + 0.1) + 0.2 = 6 q_a + 0.5 (0.3 + 0.2 rounds to 0.5 exactly)
  const core::RobotDesc& robot = loaded->robot;
  ASSERT_EQ(robot.drivers.size(), 2u);
  EXPECT_EQ(robot.drivers[0].type, core::DriverType::kAffine);
  EXPECT_EQ(robot.drivers[0].links, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(robot.drivers[0].affine_scale, (std::vector<double>{1, 2, 6}));
  EXPECT_NEAR(robot.drivers[0].affine_offset[2], 0.5, 1e-15);
  EXPECT_EQ(robot.drivers[1].links, std::vector<int>{4});
  EXPECT_THAT(loaded->diagnostics.Messages(Severity::kWarning),
              ElementsAre(path + ":8: warning: joint 'j_e' mimics 'j_d', which has no driver; it "
                                 "keeps its own driver"));
}

// ---- malformed input -----------------------------------------------------------------------

std::vector<std::string> Errors(const std::string& path) {
  auto loaded = LoadRobot(path);
  EXPECT_FALSE(loaded->ok);
  return loaded->diagnostics.Messages(Severity::kError);
}

// tinyxml2 names the element left open (line 4) when </link> arrives
TEST(UrdfFile, BadXmlNamesTheLine) {
  const std::string path = test::DataPath("bad/urdf_bad_xml.urdf");
  EXPECT_THAT(Errors(path),
              ElementsAre(path + ":4: error: XML: XML_ERROR_MISMATCHED_ELEMENT: XMLElement "
                                 "name=inertial"));
}

TEST(UrdfFile, UnknownParentLink) {
  const std::string path = test::DataPath("bad/urdf_unknown_parent.urdf");
  EXPECT_THAT(Errors(path),
              ElementsAre(path + ":6: error: joint 'j' names parent link 'nope', which is not "
                                 "defined"));
}

TEST(UrdfFile, MissingMeshAndPackage) {
  const std::string path = test::DataPath("bad/urdf_missing_mesh.urdf");
  const std::string directory = test::DataPath("bad");
  EXPECT_THAT(
      Errors(path),
      ElementsAre(path + ":6: error: cannot open mesh file '" + directory + "/meshes/nope.stl'",
                  path +
                      ":11: error: cannot find package 'nowhere_to_be_found' for "
                      "'package://nowhere_to_be_found/x.stl' (searched upward from '" +
                      directory + "')"));
}

TEST(UrdfFile, UrdfdomErrorsAreReported) {
  const std::string path = test::DataPath("bad/urdf_no_limits.urdf");
  EXPECT_THAT(Errors(path),
              ElementsAre(path + ":2: error: urdfdom: Joint [j] is of type REVOLUTE but it does "
                                 "not specify limits",
                          path + ":2: error: urdfdom: joint xml is not initialized correctly"));
}

TEST(UrdfFile, StructuralErrors) {
  std::string path;
  auto loaded = LoadUrdfText(
      "<robot name=\"r\">\n"
      "  <link name=\"a\"/>\n"
      "  <link name=\"a\"/>\n"
      "  <link/>\n"
      "  <joint name=\"j\" type=\"fixed\"><parent link=\"a\"/></joint>\n"
      "</robot>\n",
      &path);
  EXPECT_FALSE(loaded->ok);
  EXPECT_THAT(loaded->diagnostics.Messages(Severity::kError),
              ElementsAre(path + ":3: error: link 'a' is defined twice (first on line 2)",
                          path + ":4: error: <link> has no 'name' attribute",
                          path + ":5: error: joint 'j' has no <child link=...>"));
  auto world = LoadUrdfText("<world/>\n", &path);
  EXPECT_THAT(world->diagnostics.Messages(Severity::kError),
              ElementsAre(path + ":1: error: expected a <robot> root element, got <world>"));
}

}  // namespace
}  // namespace lamina
