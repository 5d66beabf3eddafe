// SPDX-License-Identifier: MIT
// WriteRob: every example robot (and the URDF one) reads back identically, field by field.
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "core/io/paths.h"
#include "core/io/robot_file.h"
#include "tests/common/test_support.h"

namespace lamina {
namespace {

using test::LoadedRobot;
using test::LoadRobot;

std::unique_ptr<LoadedRobot> Parse(const std::string& text, const std::string& path) {
  auto loaded = std::make_unique<LoadedRobot>();
  loaded->ok = core::ParseRob(text, path, loaded->context, &loaded->robot);
  return loaded;
}

void ExpectSameGeometry(const core::GeometryDesc& a, const core::GeometryDesc& b) {
  EXPECT_EQ(a.kind, b.kind);
  EXPECT_EQ(a.path, b.path);
  EXPECT_EQ(a.Matrix().matrix(), b.Matrix().matrix());
  EXPECT_EQ(a.margin, b.margin);
  EXPECT_EQ(a.triangle_count(), b.triangle_count());
}

void ExpectSameLink(const core::LinkDesc& a, const core::LinkDesc& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.parent, b.parent);
  EXPECT_EQ(a.axis_type, b.axis_type);
  EXPECT_EQ(a.axis, b.axis);
  EXPECT_EQ(a.parent_transform.matrix(), b.parent_transform.matrix());
  EXPECT_EQ(a.q_min, b.q_min);
  EXPECT_EQ(a.q_max, b.q_max);
  EXPECT_EQ(a.q_initial, b.q_initial);
  EXPECT_EQ(a.velocity_min, b.velocity_min);
  EXPECT_EQ(a.velocity_max, b.velocity_max);
  EXPECT_EQ(a.acceleration_max, b.acceleration_max);
  EXPECT_EQ(a.torque_max, b.torque_max);
  EXPECT_EQ(a.power_max, b.power_max);
  EXPECT_EQ(a.mass, b.mass);
  EXPECT_EQ(a.com, b.com);
  EXPECT_EQ(a.inertia, b.inertia);
  EXPECT_EQ(a.sim, b.sim);
  ASSERT_EQ(a.geometry.size(), b.geometry.size());
  for (size_t g = 0; g < a.geometry.size(); ++g) ExpectSameGeometry(a.geometry[g], b.geometry[g]);
}

void ExpectSameDriver(const core::DriverDesc& a, const core::DriverDesc& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.type, b.type);
  EXPECT_EQ(a.links, b.links);
  EXPECT_EQ(a.affine_scale, b.affine_scale);
  EXPECT_EQ(a.affine_offset, b.affine_offset);
  EXPECT_EQ(a.q_min, b.q_min);
  EXPECT_EQ(a.q_max, b.q_max);
  EXPECT_EQ(a.velocity_min, b.velocity_min);
  EXPECT_EQ(a.velocity_max, b.velocity_max);
  EXPECT_EQ(a.torque_min, b.torque_min);
  EXPECT_EQ(a.torque_max, b.torque_max);
  EXPECT_EQ(a.acceleration_min, b.acceleration_min);
  EXPECT_EQ(a.acceleration_max, b.acceleration_max);
  EXPECT_EQ(a.servo_p, b.servo_p);
  EXPECT_EQ(a.servo_i, b.servo_i);
  EXPECT_EQ(a.servo_d, b.servo_d);
  EXPECT_EQ(a.dry_friction, b.dry_friction);
  EXPECT_EQ(a.viscous_friction, b.viscous_friction);
}

void ExpectSameRobot(const core::RobotDesc& a, const core::RobotDesc& b) {
  ASSERT_EQ(a.dof(), b.dof());
  for (int i = 0; i < a.dof(); ++i) {
    SCOPED_TRACE("link " + std::to_string(i));
    ExpectSameLink(a.links[i], b.links[i]);
  }
  ASSERT_EQ(a.joints.size(), b.joints.size());
  for (size_t i = 0; i < a.joints.size(); ++i) {
    SCOPED_TRACE("joint " + std::to_string(i));
    EXPECT_EQ(a.joints[i].type, b.joints[i].type);
    EXPECT_EQ(a.joints[i].link, b.joints[i].link);
    EXPECT_EQ(a.joints[i].base, b.joints[i].base);
  }
  ASSERT_EQ(a.drivers.size(), b.drivers.size());
  for (size_t i = 0; i < a.drivers.size(); ++i) {
    SCOPED_TRACE("driver " + std::to_string(i));
    ExpectSameDriver(a.drivers[i], b.drivers[i]);
  }
  EXPECT_EQ(a.self_collision, b.self_collision);
  EXPECT_EQ(a.no_self_collision, b.no_self_collision);
  EXPECT_EQ(a.properties, b.properties);
  EXPECT_EQ(a.config, b.config);
  EXPECT_EQ(a.velocity, b.velocity);
}

// writes `robot` for a .rob in `directory`, reads it back, and writes it again
void ExpectRoundTrip(const core::RobotDesc& robot, const std::string& directory) {
  const std::string text = core::WriteRob(robot, directory);
  const std::string path = directory + "/written.rob";
  auto parsed = Parse(text, path);
  ASSERT_TRUE(parsed->ok) << parsed->diagnostics.FormatAll() << text;
  EXPECT_EQ(parsed->diagnostics.warning_count(), 0) << parsed->diagnostics.FormatAll();
  ExpectSameRobot(robot, parsed->robot);
  EXPECT_EQ(core::WriteRob(parsed->robot, directory), text);
}

class RobWriterExamples : public ::testing::TestWithParam<const char*> {};

TEST_P(RobWriterExamples, ReadsBackIdentically) {
  const std::string path = test::WorldsPath(std::string("klampt/robots/") + GetParam());
  auto loaded = LoadRobot(path);
  ASSERT_TRUE(loaded->ok) << loaded->diagnostics.FormatAll();
  ExpectRoundTrip(loaded->robot, core::DirectoryOf(path));
}

INSTANTIATE_TEST_SUITE_P(Klampt, RobWriterExamples,
                         ::testing::Values("athlete.rob", "cartpole.rob", "footed_2d_biped.rob",
                                           "free_cube.rob", "planar3R.rob", "sphere.rob",
                                           "sphere1cm.rob", "swingup.rob", "tx90l.rob", "ur5.rob",
                                           "mirobot.urdf"));

TEST(RobWriter, MountedRobotReadsBackFromAnotherDirectory) {
  auto loaded = LoadRobot(test::DataPath("robots/arm.rob"));
  ASSERT_TRUE(loaded->ok) << loaded->diagnostics.FormatAll();
  ExpectRoundTrip(loaded->robot, test::ScratchDir());
  // mesh paths are written relative to the new directory
  const std::string text = core::WriteRob(loaded->robot, test::ScratchDir());
  const std::string relative =
      core::RelativePath(test::DataPath("robots/box.off"), test::ScratchDir());
  EXPECT_NE(text.find("\"" + relative + "\""), std::string::npos) << text;
}

TEST(RobWriter, DriverTypesPropertiesAndGeometryTransforms) {
  const std::string box = test::DataPath("robots/box.off");
  std::string frames = "TParent";
  for (int i = 0; i < 7; ++i) {
    frames += " 1 0 0 0 1 0 0 0 1 0 0 0." + std::to_string(i) + (i < 6 ? " \\\n" : "\n");
  }
  const std::string text =
      "links \"x\" \"y\" \"yaw\" \"a\" \"b\" \"c\" \"d\"\n" + frames +
      "jointtype p p r r r r r\n"
      "geometry \"\" \"\" \"" +
      box + "\" \"" + box +
      "\" \"\" \"\" \"\"\n"
      "geomscale 1 1 0.5 1 1 1 1\n"
      "geommargin 0 0 0.002 0.002 0 0 0\n"
      "geomtransform 3  0 -1 0 0.1  1 0 0 0.2  0 0 1 0.3  0 0 0 1\n"
      "mount 6 \"" +
      box +
      "\" 0 -1 0 1 0 0 0 0 1 0 0 1\n"
      "joint floatingplanar 2 -1\n"
      "joint ballandsocket 5 2\n"
      "joint spin 6\n"
      "driver translation 0 2\n"
      "driver rotation 2 2\n"
      "driver affine 2  3 4  1 -2  0 0.5  -1 1 -2 2 -3 3\n"
      "driver normal 6\n"
      "servoP 1 2 3 4\n"
      "selfcollision 2 6\n"
      "noselfcollision 3 6\n"
      "property controller <controller type=\"JointTrackingController\"  rate=\"100\"/>\n"
      "property note \"a # is kept\"\n";
  auto parsed = Parse(text, test::ScratchDir() + "/source.rob");
  ASSERT_TRUE(parsed->ok) << parsed->diagnostics.FormatAll() << text;
  ASSERT_EQ(parsed->robot.drivers.size(), 4u);
  ASSERT_EQ(parsed->robot.links[6].geometry.size(), 2u);
  ExpectRoundTrip(parsed->robot, test::ScratchDir());
}

TEST(RobWriter, NonUniformScaleIsFoldedIntoTheGeomTransform) {
  auto loaded = LoadRobot(test::DataPath("robots/arm.rob"));
  ASSERT_TRUE(loaded->ok) << loaded->diagnostics.FormatAll();
  core::RobotDesc robot = loaded->robot;
  robot.links[1].geometry[0].scale = core::Vec3(1, 2, 3);
  robot.links[1].geometry[0].transform.translation() = core::Vec3(0.5, 0, 0);
  const std::string text = core::WriteRob(robot, test::ScratchDir());
  EXPECT_NE(text.find("geomtransform 1 1 0 0 0.5 0 2 0 0 0 0 3 0 0 0 0 1\n"), std::string::npos)
      << text;
  auto parsed = Parse(text, test::ScratchDir() + "/written.rob");
  ASSERT_TRUE(parsed->ok) << parsed->diagnostics.FormatAll();
  EXPECT_EQ(parsed->robot.links[1].geometry[0].Matrix().matrix(),
            robot.links[1].geometry[0].Matrix().matrix());
}

TEST(RobWriter, InlinePrimitivesAreNotedAsNotSaved) {
  core::RobotDesc robot;
  robot.links.resize(1);
  robot.links[0].name = "ball";
  core::GeometryDesc ball;
  ball.kind = core::GeometryKind::kPrimitive;
  ball.primitive = core::Primitive::Sphere(0.1);
  robot.links[0].geometry = {ball};
  robot.joints = {{core::JointType::kWeld, 0, -1}};
  const std::string text = core::WriteRob(robot, test::ScratchDir());
  EXPECT_EQ(text.substr(0, text.find('\n') + 1),
            "# link 0 ('ball'): an inline sphere without a file is not saved\n");
  EXPECT_NE(text.find("geometry \"\"\n"), std::string::npos) << text;
}

}  // namespace
}  // namespace lamina
