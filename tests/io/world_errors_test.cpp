// SPDX-License-Identifier: MIT
// Malformed world XML: each bad input gives an exact `file:line: error:` message naming the
// element and value; a file with several problems reports all of them; nothing crashes.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/io/world_file.h"
#include "tests/common/test_support.h"

namespace lamina {
namespace {

using core::Severity;
using test::LoadedWorld;
using test::WorldsPath;
using ::testing::ElementsAre;

std::string Cube() {
  return WorldsPath("klampt/objects/cube.off");
}

// an object element around `physics` with a valid geometry
std::string ObjectWith(const std::string& object_attributes, const std::string& physics) {
  return "<world>\n  <rigidObject name=\"b\" " + object_attributes + ">\n    <geometry mesh=\"" +
         Cube() + "\"/>\n    " + physics + "\n  </rigidObject>\n</world>\n";
}

struct BadWorld {
  const char* name;
  std::string xml;
  std::vector<std::string> errors;  // messages after "path:"
};

class WorldErrorTest : public ::testing::TestWithParam<BadWorld> {};

TEST_P(WorldErrorTest, ReportsExactMessage) {
  const BadWorld& bad = GetParam();
  const std::string path = test::WriteScratchFile(std::string(bad.name) + ".xml", bad.xml);
  LoadedWorld loaded;
  test::LoadWorld(path, &loaded);
  EXPECT_FALSE(loaded.ok);
  std::vector<std::string> expected;
  for (std::string error : bad.errors) {
    const size_t scratch = error.find("SCRATCH");
    if (scratch != std::string::npos) error.replace(scratch, 7, test::ScratchDir());
    expected.push_back(path + ":" + error);
  }
  EXPECT_EQ(loaded.diagnostics.Messages(Severity::kError), expected);
}

INSTANTIATE_TEST_SUITE_P(
    Malformed, WorldErrorTest,
    ::testing::Values(
        BadWorld{"unclosed",
                 "<world>\n  <terrain file=\"x.off\">\n</world>\n",
                 // tinyxml2 names the line of the element left open
                 {"2: error: malformed XML: XML_ERROR_MISMATCHED_ELEMENT"}},
        BadWorld{"empty", "", {" error: malformed XML: XML_ERROR_EMPTY_DOCUMENT"}},
        BadWorld{"wrong_root",
                 "<robot name=\"r\"/>\n",
                 {"1: error: root element must be <world>, got <robot>"}},
        BadWorld{"robot_without_file",
                 "<world>\n  <robot name=\"r\"/>\n</world>\n",
                 {"2: error: <robot name=\"r\">: missing attribute 'file'"}},
        BadWorld{"terrain_without_file",
                 "<world>\n\n  <terrain/>\n</world>\n",
                 {"3: error: <terrain>: missing attribute 'file'"}},
        BadWorld{"object_without_geometry",
                 "<world>\n  <rigidObject name=\"b\"/>\n</world>\n",
                 {"2: error: <rigidObject name=\"b\">: has no geometry (give 'file' or a "
                  "<geometry mesh=...> child)"}},
        BadWorld{"negative_mass",
                 ObjectWith("", "<physics mass=\"-2\"/>"),
                 {"4: error: <physics>: attribute 'mass' must be >= 0, got '-2'"}},
        BadWorld{"nan_position",
                 ObjectWith("position=\"0 nan 1\"", ""),
                 {"2: error: <rigidObject name=\"b\">: attribute 'position' has 'nan', which is "
                  "not a number"}},
        BadWorld{"short_position",
                 ObjectWith("position=\"0 1\"", ""),
                 {"2: error: <rigidObject name=\"b\">: attribute 'position' expects 3 numbers, "
                  "got '0 1'"}},
        BadWorld{"inertia_length",
                 ObjectWith("", "<physics inertia=\"1 0 0 0 1 0 0 0\"/>"),
                 {"4: error: <physics>: attribute 'inertia' expects 9 numbers, got '1 0 0 0 1 0 "
                  "0 0'"}},
        BadWorld{"restitution_range",
                 ObjectWith("", "<physics kRestitution=\"1.5\"/>"),
                 {"4: error: <physics>: attribute 'kRestitution' must be in [0, 1], got '1.5'"}},
        BadWorld{
            "negative_friction",
            ObjectWith("", "<physics kFriction=\"-0.1\"/>"),
            {"4: error: <physics>: attribute 'kFriction' must be >= 0 (inf allowed), got '-0.1'"}},
        // Lamina's rolling and spinning friction: finite, >= 0, wherever kFriction is read
        BadWorld{"negative_rolling_friction",
                 ObjectWith("", "<physics kRollingFriction=\"-0.01\"/>"),
                 {"4: error: <physics>: attribute 'kRollingFriction' must be >= 0, got '-0.01'"}},
        BadWorld{"infinite_spinning_friction",
                 ObjectWith("", "<physics kSpinningFriction=\"inf\"/>"),
                 {"4: error: <physics>: attribute 'kSpinningFriction' must be >= 0, got 'inf'"}},
        BadWorld{"terrain_rolling_friction",
                 "<world>\n  <terrain file=\"" + WorldsPath("klampt/terrains/cube.off") +
                     "\"\n           kRollingFriction=\"abc\"/>\n</world>\n",
                 {"2: error: <terrain>: attribute 'kRollingFriction' has 'abc', which is not a "
                  "number"}},
        BadWorld{"sim_spinning_friction",
                 "<world>\n  <terrain file=\"" + WorldsPath("klampt/terrains/cube.off") +
                     "\"/>\n  <simulation>\n    <terrain index=\"0\">\n      <geometry "
                     "kSpinningFriction=\"-1\"/>\n    </terrain>\n  </simulation>\n</world>\n",
                 {"5: error: <geometry>: attribute 'kSpinningFriction' must be >= 0, got '-1'"}},
        BadWorld{"zero_scale",
                 "<world>\n  <terrain file=\"" + WorldsPath("klampt/terrains/cube.off") +
                     "\" scale=\"0\"/>\n</world>\n",
                 {"2: error: <terrain>: attribute 'scale' must not be zero, got '0'"}},
        BadWorld{"missing_mesh",
                 "<world>\n  <rigidObject name=\"b\">\n    <geometry mesh=\"nowhere.off\"/>\n"
                 "  </rigidObject>\n</world>\n",
                 {"3: error: cannot open mesh file 'SCRATCH/nowhere.off'",
                  "2: error: <rigidObject name=\"b\">: has no geometry (give 'file' or a "
                  "<geometry mesh=...> child)"}},
        BadWorld{"sim_index_range",
                 "<world>\n  <simulation>\n    <object index=\"3\"/>\n  </simulation>\n</world>\n",
                 {"3: error: <object index=\"3\">: attribute 'index' is 3 but the world has 0 "
                  "objects"}},
        BadWorld{"bad_preshrink",
                 "<world>\n  <terrain file=\"" + WorldsPath("klampt/terrains/cube.off") +
                     "\"/>\n  <simulation>\n    <terrain index=\"0\"><geometry preshrink=\"3\"/>"
                     "</terrain>\n  </simulation>\n</world>\n",
                 {"4: error: <geometry>: attribute 'preshrink' must be none, copy or in-place, got "
                  "'3'"}},
        BadWorld{
            "bad_timestep",
            "<world>\n  <simulation>\n    <globals timestep=\"-0.001\" maxContacts=\"0\" "
            "adaptiveTimeStepping=\"maybe\"/>\n  </simulation>\n</world>\n",
            {"3: error: <globals>: attribute 'timestep' must be > 0, got '-0.001'",
             "3: error: <globals>: attribute 'maxContacts' must be a whole number in [1, 1e+06], "
             "got '0'",
             "3: error: <globals>: attribute 'adaptiveTimeStepping' must be true or false (1 "
             "or 0), got 'maybe'"}},
        BadWorld{"config_size",
                 "<world>\n  <robot name=\"arm\" file=\"" +
                     WorldsPath("klampt/robots/planar3R.rob") +
                     "\" config=\"2  0 0\"/>\n</world>\n",
                 {"2: error: <robot name=\"arm\">: configuration has 2 values but robot 'arm' has "
                  "3 links"}},
        BadWorld{"config_count",
                 "<world>\n  <robot name=\"arm\" file=\"" +
                     WorldsPath("klampt/robots/planar3R.rob") +
                     "\" config=\"3  0 0\"/>\n</world>\n",
                 {"2: error: <robot name=\"arm\">: attribute 'config' declares 3 values but gives "
                  "2"}},
        BadWorld{"robot_body_range",
                 "<world>\n  <robot name=\"arm\" file=\"" +
                     WorldsPath("klampt/robots/planar3R.rob") +
                     "\"/>\n  <simulation>\n    <robot index=\"0\" body=\"7\"/>\n  </simulation>\n"
                     "</world>\n",
                 {"4: error: <robot index=\"0\">: attribute 'body' is 7 but robot 'arm' has 3 "
                  "links (-1 means all)"}}),
    [](const ::testing::TestParamInfo<BadWorld>& param_info) {
      return std::string(param_info.param.name);
    });

TEST(WorldErrorsTest, UnknownSimulationNameIsAnError) {
  const std::string path = test::WriteScratchFile(
      "w.xml",
      ObjectWith("", "").replace(ObjectWith("", "").find("</world>"), 8,
                                 "<simulation>\n<object name=\"c\"/>\n</simulation>\n</world>"));
  LoadedWorld loaded;
  test::LoadWorld(path, &loaded);
  EXPECT_THAT(loaded.diagnostics.Messages(Severity::kError),
              ElementsAre(path + ":7: error: <object name=\"c\">: attribute 'name' is 'c' but no "
                                 "object has that name"));
}

TEST(WorldErrorsTest, ManyProblemsAreAllReportedInOneRun) {
  const std::string path = test::WriteScratchFile(
      "many.xml",
      "<world>\n  <robot name=\"r\"/>\n  <terrain/>\n" +
          ObjectWith("position=\"1 2\"", "<physics mass=\"-1\" kFriction=\"x\"/>").substr(8));
  LoadedWorld loaded;
  test::LoadWorld(path, &loaded);
  EXPECT_FALSE(loaded.ok);
  EXPECT_EQ(loaded.diagnostics.error_count(), 5) << loaded.diagnostics.FormatAll();
}

TEST(WorldErrorsTest, MissingWorldFile) {
  LoadedWorld loaded;
  const std::string path = test::ScratchDir() + "/absent.xml";
  test::LoadWorld(path, &loaded);
  EXPECT_THAT(loaded.diagnostics.Messages(Severity::kError),
              ElementsAre(path + ": error: cannot open world file '" + path + "'"));
}

TEST(WorldErrorsTest, UnsupportedFileType) {
  LoadedWorld loaded;
  const std::string path = test::WriteScratchFile("thing.txt", "hello");
  test::LoadWorld(path, &loaded);
  EXPECT_THAT(loaded.diagnostics.Messages(Severity::kError),
              ElementsAre(path + ": error: unsupported file type '.txt' (expected a world .xml, "
                                 ".rob, .urdf, .obj, .env, mesh or .pcd)"));
}

}  // namespace
}  // namespace lamina
