// SPDX-License-Identifier: MIT
// What Klamp't's files contain that Klamp't reads and Lamina used to refuse, one class at a time,
// each on a file written for the test and in every format that has it: a line continuation glued
// to the last value, an inertia asymmetric by rounding, a collision pair naming one link twice.
// Each is read as Klamp't reads it, with a warning whose exact file:line text is checked; what
// is really wrong stays an error.
#include <memory>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/io/object_file.h"
#include "core/io/robot_file.h"
#include "core/io/trajectory_file.h"
#include "tests/common/test_support.h"

namespace lamina {
namespace {

using core::Severity;
using ::testing::ElementsAre;
using ::testing::IsEmpty;

const std::string kTwoLinks = "TParent 1 0 0 0 1 0 0 0 1 0 0 0  1 0 0 0 1 0 0 0 1 0 0 1\n";

std::unique_ptr<test::LoadedRobot> RobotText(const std::string& name, const std::string& text,
                                             std::string* path) {
  *path = test::WriteScratchFile(name, text);
  return test::LoadRobot(*path);
}

struct LoadedObject {
  core::Diagnostics diagnostics;
  core::MeshCache meshes;
  core::RigidObjectDesc object;
  bool ok = false;
};

// an `.obj` object file as a world file would load it
std::unique_ptr<LoadedObject> LoadObject(const std::string& path) {
  auto loaded = std::make_unique<LoadedObject>();
  core::LoadContext context{loaded->diagnostics, loaded->meshes};
  loaded->ok = core::LoadRigidObjectFile(path, {"w.xml", 1, 0}, context, &loaded->object);
  return loaded;
}

std::vector<std::string> Warnings(const core::Diagnostics& diagnostics) {
  return diagnostics.Messages(Severity::kWarning);
}

// ---- a continuation backslash glued to the value ("39\") ----------------------------------

TEST(Leniency, GluedContinuationInARobFileReadsTheValueAndContinues) {
  std::string path;
  auto loaded = RobotText("glued.rob",
                          "TParent 1 0 0 0 1 0 0 0 1 0 0 0  1 0 0 0 1 0 0 0 1 0 0 1\n"
                          "qmin -1\\\n"
                          "  -2\n"
                          "qmax 1 2\n"
                          "mass 3 0.162157\\\n",
                          &path);
  ASSERT_TRUE(loaded->ok) << loaded->diagnostics.FormatAll();
  EXPECT_EQ(loaded->robot.links[1].q_min, -2.0);
  EXPECT_EQ(loaded->robot.links[1].q_max, 2.0);  // the statement after it is still read
  EXPECT_EQ(loaded->robot.links[1].mass, 0.162157);
  EXPECT_THAT(
      Warnings(loaded->diagnostics),
      ElementsAre(path + ":2:6: warning: '-1\\': the line continuation is glued to the value; "
                         "read as '-1', continued on the next line (as Klamp't)",
                  path + ":5:8: warning: '0.162157\\': the line continuation is glued to the "
                         "value; read as '0.162157', continued on the next line (as Klamp't)"));
}

TEST(Leniency, GluedContinuationInPathAndObjectFiles) {
  core::Diagnostics diagnostics;
  const auto path = core::ParseLinearPath("0 2 0 0\\\n1 2 1 1\n", "motion.path", diagnostics);
  // the continuation joins the lines into one statement, as in Klamp't: "0 2 0 0 1 2 1 1" is
  // one milestone with 4 numbers after N = 2, which Klamp't would misread too; it is an error
  EXPECT_FALSE(path.has_value());
  EXPECT_THAT(Warnings(diagnostics),
              ElementsAre("motion.path:1:7: warning: '0\\': the line continuation is glued to the "
                          "value; read as '0', continued on the next line (as Klamp't)"));
  const std::string mesh = test::WorldsPath("klampt/objects/cube.off");
  const std::string object =
      test::WriteScratchFile("glued.obj", "mesh \"" + mesh + "\"\nmass 2\\\n\nkFriction 0.3\n");
  const auto loaded = LoadObject(object);
  ASSERT_TRUE(loaded->ok) << loaded->diagnostics.FormatAll();
  EXPECT_EQ(loaded->object.mass, 2.0);
  EXPECT_THAT(Warnings(loaded->diagnostics),
              ElementsAre(object + ":2:6: warning: '2\\': the line continuation is glued to the "
                                   "value; read as '2', continued on the next line (as Klamp't)"));
}

// ---- an inertia asymmetric by the rounding of its printed digits ----------------------------

// HRP-2's link 6 as its .rob prints it: (1,2) 8.84e-06 against (2,1) 8.85e-06
const std::string kRoundedInertia =
    "0.00285998 -1.434e-05 -0.00055582 -1.434e-05 0.00352974 8.84e-06 -0.00055582 8.85e-06 "
    "0.00145427";
const std::string kRoundedWarning =
    "is not symmetric: its off-diagonal pairs differ by up to 1e-08 (2.8e-06 of its largest "
    "entry, rounding in the file); (I + I^T)/2 is used";

TEST(Leniency, InertiaAsymmetricByRoundingIsSymmetrisedInRobObjAndWorldFiles) {
  std::string path;
  auto robot = RobotText("rounded.rob",
                         kTwoLinks + "inertia 1 0 0 0 1 0 0 0 1  " + kRoundedInertia + "\n", &path);
  ASSERT_TRUE(robot->ok) << robot->diagnostics.FormatAll();
  EXPECT_DOUBLE_EQ(robot->robot.links[1].inertia(1, 2), 8.845e-06);
  EXPECT_DOUBLE_EQ(robot->robot.links[1].inertia(2, 1), 8.845e-06);
  EXPECT_EQ(robot->robot.links[1].inertia(0, 1), -1.434e-05);
  EXPECT_THAT(Warnings(robot->diagnostics),
              ElementsAre(path + ":2: warning: inertia of link 1 " + kRoundedWarning));

  const std::string mesh = test::WorldsPath("klampt/objects/cube.off");
  const std::string object = test::WriteScratchFile(
      "rounded.obj", "mesh \"" + mesh + "\"\nmass 1\ninertia " + kRoundedInertia + "\n");
  const auto loaded_object = LoadObject(object);
  ASSERT_TRUE(loaded_object->ok) << loaded_object->diagnostics.FormatAll();
  EXPECT_DOUBLE_EQ(loaded_object->object.inertia(2, 1), 8.845e-06);
  EXPECT_THAT(Warnings(loaded_object->diagnostics),
              ElementsAre(object + ":3: warning: 'inertia' " + kRoundedWarning));

  const std::string world = test::WriteScratchFile(
      "rounded.xml", "<world>\n  <rigidObject name=\"b\">\n    <geometry mesh=\"" + mesh +
                         "\"/>\n    <physics mass=\"1\" inertia=\"" + kRoundedInertia +
                         "\"/>\n  </rigidObject>\n</world>\n");
  test::LoadedWorld loaded;
  test::LoadWorld(world, &loaded);
  ASSERT_TRUE(loaded.ok) << loaded.diagnostics.FormatAll();
  EXPECT_DOUBLE_EQ(loaded.world.objects[0].inertia(1, 2), 8.845e-06);
  EXPECT_THAT(
      Warnings(loaded.diagnostics),
      ElementsAre(world + ":4: warning: <physics>: attribute 'inertia' " + kRoundedWarning));
}

TEST(Leniency, ARealAsymmetryIsStillAnError) {
  std::string path;
  // (1,2) 0.1 against (2,1) 0.2: half of the largest entry
  auto robot = RobotText("asymmetric.rob",
                         kTwoLinks + "inertia 1 0 0 0 1 0 0 0 1  1 0 0 0 1 0.1 0 0.2 1\n", &path);
  EXPECT_FALSE(robot->ok);
  EXPECT_THAT(robot->diagnostics.Messages(Severity::kError),
              ElementsAre(path + ":2: error: inertia of link 1 must be a symmetric positive "
                                 "semi-definite 3x3 matrix, got '1 0 0 0 1 0.1 0 0.2 1'"));
  EXPECT_THAT(Warnings(robot->diagnostics), IsEmpty());
}

// ---- a collision pair naming one link twice ---------------------------------------------------

TEST(Leniency, APairNamingOneLinkTwiceIsIgnoredWithAWarning) {
  std::string path;
  auto robot = RobotText("pairs.rob",
                         "links \"a\" \"b\"\n" + kTwoLinks +
                             "noselfcollision a b  b 1\n"
                             "selfcollision 0 0\n",
                         &path);
  ASSERT_TRUE(robot->ok) << robot->diagnostics.FormatAll();
  EXPECT_EQ(robot->robot.no_self_collision, (std::vector<std::pair<int, int>>{{0, 1}}));
  EXPECT_TRUE(robot->robot.self_collision.empty());
  EXPECT_THAT(Warnings(robot->diagnostics),
              ElementsAre(path + ":4: warning: 'selfcollision' pair names link 0 twice ('0' and "
                                 "'0'); ignored",
                          path + ":3: warning: 'noselfcollision' pair names link 1 twice ('b' "
                                 "and '1'); ignored"));
  const std::string urdf = test::WriteScratchFile(
      "pairs.urdf",
      "<robot name=\"r\">\n  <link name=\"a\"/>\n  <link name=\"b\"/>\n"
      "  <joint name=\"j\" type=\"revolute\"><parent link=\"a\"/><child link=\"b\"/>"
      "<axis xyz=\"0 0 1\"/><limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/></joint>\n"
      "  <klampt>\n    <noselfcollision pairs=\"a b b b\"/>\n  </klampt>\n</robot>\n");
  auto from_urdf = test::LoadRobot(urdf);
  ASSERT_TRUE(from_urdf->ok) << from_urdf->diagnostics.FormatAll();
  // Klamp't puts the URDF's root on a floating base: a is its sixth link (5), b is 6
  EXPECT_EQ(from_urdf->robot.no_self_collision, (std::vector<std::pair<int, int>>{{5, 6}}));
  EXPECT_THAT(Warnings(from_urdf->diagnostics),
              ElementsAre(urdf + ":6: warning: 'noselfcollision' pair names link 6 twice ('b' "
                                 "and 'b'); ignored"));
}

}  // namespace
}  // namespace lamina
