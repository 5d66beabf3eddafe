// SPDX-License-Identifier: MIT
// Saving: load -> save -> load gives the same description for every example world, edits
// survive, saving is a fixed point, and a failed save leaves the old file intact.
#include <filesystem>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/io/paths.h"
#include "core/io/world_file.h"
#include "core/model/world_compare.h"
#include "tests/common/test_support.h"

namespace lamina {
namespace {

using test::LoadedWorld;
using ::testing::IsEmpty;

// rotations are written as rotateMoment and read back through the exponential map, which
// reproduces a rotation matrix to a few ulps; every other number is written exactly
constexpr double kRoundTripTolerance = 1e-14;

void SaveAndReload(const core::WorldDesc& world, const std::string& path, LoadedWorld* out) {
  core::Diagnostics diagnostics;
  ASSERT_TRUE(core::SaveWorldFile(world, path, diagnostics)) << diagnostics.FormatAll();
  test::LoadWorld(path, out);
  ASSERT_TRUE(out->ok) << out->diagnostics.FormatAll();
  EXPECT_EQ(out->diagnostics.warning_count(), 0) << out->diagnostics.FormatAll();
}

class RoundTripTest : public ::testing::TestWithParam<const char*> {};

TEST_P(RoundTripTest, LoadSaveLoadIsIdentical) {
  LoadedWorld original;
  test::LoadWorld(test::WorldsPath(GetParam()), &original);
  ASSERT_TRUE(original.ok) << original.diagnostics.FormatAll();
  const std::string saved_path = test::ScratchDir() + "/saved.xml";
  LoadedWorld reloaded;
  SaveAndReload(original.world, saved_path, &reloaded);
  EXPECT_THAT(core::CompareWorlds(original.world, reloaded.world, kRoundTripTolerance), IsEmpty());

  // saving the reloaded world again writes the same text: saving is a fixed point
  const core::WorldFileSet first = core::WriteWorld(original.world, saved_path);
  const core::WorldFileSet second = core::WriteWorld(reloaded.world, saved_path);
  EXPECT_EQ(first.world_xml, second.world_xml);
  ASSERT_EQ(first.robot_files.size(), second.robot_files.size());
  for (size_t i = 0; i < first.robot_files.size(); ++i) {
    EXPECT_EQ(first.robot_files[i].second, second.robot_files[i].second);
  }
}

INSTANTIATE_TEST_SUITE_P(AllExamples, RoundTripTest,
                         ::testing::Values("klampt/athlete_fractal_1.xml",
                                           "klampt/athlete_plane.xml", "klampt/block.xml",
                                           "klampt/simulation_test_worlds/bounce_test.xml",
                                           "klampt/simulation_test_worlds/fastdroptest.xml",
                                           "klampt/simulation_test_worlds/heavyblocktest.xml",
                                           "klampt/simulation_test_worlds/slideblock.xml",
                                           "klampt/simulation_test_worlds/stacktest.xml",
                                           "klampt/simulation_test_worlds/stiffness_test.xml",
                                           "examples/point_clouds.xml",
                                           "examples/rolling_friction.xml",
                                           "examples/tx90l_milestones.xml"));

// Lamina's kRollingFriction and kSpinningFriction are written where the body's other surface
// rows are (an object's <physics> and every body's <simulation> <geometry>) only while they are
// on, so a world without them is written as before and stays a Klamp't world
TEST(WorldSaveTest, RollingAndSpinningFrictionAreWrittenOnlyWhenOn) {
  LoadedWorld original;
  test::LoadWorld(test::WorldsPath("klampt/block.xml"), &original);
  ASSERT_TRUE(original.ok) << original.diagnostics.FormatAll();
  const std::string path = test::ScratchDir() + "/rolling.xml";
  const std::string plain = core::WriteWorld(original.world, path).world_xml;
  EXPECT_THAT(plain, ::testing::Not(::testing::HasSubstr("Rolling")));
  EXPECT_THAT(plain, ::testing::Not(::testing::HasSubstr("Spinning")));

  core::WorldDesc edited = original.world;
  edited.objects[0].sim.surface.rolling_friction = 0.004;
  edited.terrains[0].sim.surface.spinning_friction = 0.0015;
  edited.robots[0].links[1].sim.surface.rolling_friction = 0.25;
  const std::string xml = core::WriteWorld(edited, path).world_xml;
  EXPECT_THAT(xml, ::testing::HasSubstr("kFriction=\"0.5\" kRollingFriction=\"0.004\" "
                                        "kStiffness=\"10000\""));
  EXPECT_THAT(xml, ::testing::HasSubstr("kSpinningFriction=\"0.0015\""));
  EXPECT_THAT(xml, ::testing::HasSubstr("kRollingFriction=\"0.25\""));
  LoadedWorld reloaded;
  SaveAndReload(edited, path, &reloaded);
  EXPECT_THAT(core::CompareWorlds(edited, reloaded.world, kRoundTripTolerance), IsEmpty());
  EXPECT_EQ(reloaded.world.objects[0].sim.surface.rolling_friction, 0.004);
  EXPECT_EQ(reloaded.world.terrains[0].sim.surface.spinning_friction, 0.0015);
  EXPECT_EQ(reloaded.world.robots[0].links[1].sim.surface.rolling_friction, 0.25);
  EXPECT_EQ(reloaded.world.robots[0].links[0].sim.surface.rolling_friction, 0.0);
  // switched off again, the text is the plain world's, byte for byte
  edited.objects[0].sim.surface.rolling_friction = 0.0;
  edited.terrains[0].sim.surface.spinning_friction = 0.0;
  edited.robots[0].links[1].sim.surface.rolling_friction = 0.0;
  EXPECT_EQ(core::WriteWorld(edited, path).world_xml, plain);
}

// a <terrain> element takes them beside kFriction, as a .obj object file takes them as keys
TEST(WorldSaveTest, RollingAndSpinningFrictionAreReadOnTerrainElements) {
  const std::string path = test::WriteScratchFile(
      "terrain_rolling.xml", "<world>\n  <terrain file=\"" +
                                 test::WorldsPath("klampt/terrains/plane.off") +
                                 "\" kFriction=\"0.7\" kRollingFriction=\"0.002\" "
                                 "kSpinningFriction=\"0.001\"/>\n</world>\n");
  LoadedWorld loaded;
  test::LoadWorld(path, &loaded);
  ASSERT_TRUE(loaded.ok) << loaded.diagnostics.FormatAll();
  EXPECT_EQ(loaded.diagnostics.warning_count(), 0) << loaded.diagnostics.FormatAll();
  const core::SurfaceDesc& surface = loaded.world.terrains[0].sim.surface;
  EXPECT_EQ(surface.friction, 0.7);
  EXPECT_EQ(surface.rolling_friction, 0.002);
  EXPECT_EQ(surface.spinning_friction, 0.001);
}

TEST(WorldSaveTest, EditsSurviveSaving) {
  LoadedWorld original;
  test::LoadWorld(test::WorldsPath("klampt/block.xml"), &original);
  ASSERT_TRUE(original.ok) << original.diagnostics.FormatAll();
  core::WorldDesc edited = original.world;
  edited.objects[0].sim.padding = 0.0125;
  edited.objects[0].sim.surface = {0.25, 0.8, 2.5e5, 300.0};
  edited.objects[0].mass = 2.5;
  edited.objects[0].initial_velocity.angular = core::Vec3(0, 0, 3);
  edited.objects[0].display["color"] = "1 0 0 1";
  edited.terrains[0].sim.surface.friction = 0.9;
  edited.robots[0].drivers[0].servo_p = 123.5;
  edited.robots[0].links[2].sim.padding = 0.003;
  edited.robots[0].config[1] = 0.25;
  edited.settings.timestep = 0.0005;
  edited.settings.gravity = core::Vec3(0, 0, -1.62);
  edited.settings.max_contacts = 7;
  LoadedWorld reloaded;
  SaveAndReload(edited, test::ScratchDir() + "/edited.xml", &reloaded);
  EXPECT_THAT(core::CompareWorlds(edited, reloaded.world, kRoundTripTolerance), IsEmpty());
  EXPECT_THAT(core::CompareWorlds(original.world, reloaded.world), ::testing::Not(IsEmpty()));
}

TEST(WorldSaveTest, UrdfPrimitivesAreSavedAsGeomFiles) {
  const std::string path = test::WriteScratchFile(
      "urdf_world.xml", "<world>\n  <robot name=\"r\" file=\"" +
                            test::DataPath("robots/urdf/all_joints.urdf") + "\"/>\n</world>\n");
  LoadedWorld original;
  test::LoadWorld(path, &original);
  ASSERT_TRUE(original.ok) << original.diagnostics.FormatAll();
  LoadedWorld reloaded;
  SaveAndReload(original.world, test::ScratchDir() + "/saved.xml", &reloaded);
  // the shapes come back identical; only their file names are new
  const auto differences = core::CompareWorlds(original.world, reloaded.world, 1e-12);
  EXPECT_FALSE(differences.empty());
  for (const std::string& difference : differences) {
    EXPECT_THAT(difference,
                ::testing::MatchesRegex(
                    ".*\\.geometry\\[[0-9]+\\]\\.path: '' vs '.*_link[0-9]+_[0-9]+\\.geom'"));
  }
}

TEST(WorldSaveTest, RobotsAreWrittenBesideTheWorld) {
  LoadedWorld original;
  test::LoadWorld(test::WorldsPath("klampt/athlete_plane.xml"), &original);
  ASSERT_TRUE(original.ok) << original.diagnostics.FormatAll();
  const std::string dir = test::ScratchDir();
  core::Diagnostics diagnostics;
  ASSERT_TRUE(core::SaveWorldFile(original.world, dir + "/plane.xml", diagnostics));
  EXPECT_TRUE(std::filesystem::is_regular_file(dir + "/plane_robots/ATHLETE.rob"));
}

TEST(WorldSaveTest, FailedSaveReportsAndLeavesNothingHalfWritten) {
  LoadedWorld original;
  test::LoadWorld(test::WorldsPath("klampt/simulation_test_worlds/stacktest.xml"), &original);
  const std::string missing_dir = test::ScratchDir() + "/no/such/dir/world.xml";
  core::Diagnostics diagnostics;
  EXPECT_FALSE(core::SaveWorldFile(original.world, missing_dir, diagnostics));
  ASSERT_EQ(diagnostics.error_count(), 1);
  EXPECT_EQ(diagnostics.FormatAll(), missing_dir + ": error: cannot save: directory '" +
                                         test::ScratchDir() + "/no/such/dir' does not exist\n");
  EXPECT_FALSE(std::filesystem::exists(missing_dir));
}

TEST(WorldSaveTest, SaveReplacesAnExistingFileAtomically) {
  LoadedWorld original;
  test::LoadWorld(test::WorldsPath("klampt/simulation_test_worlds/stacktest.xml"), &original);
  const std::string path = test::WriteScratchFile("existing.xml", "old contents");
  core::Diagnostics diagnostics;
  ASSERT_TRUE(core::SaveWorldFile(original.world, path, diagnostics));
  std::string text;
  ASSERT_TRUE(core::ReadFileText(path, &text));
  EXPECT_THAT(text, ::testing::StartsWith("<?xml"));
  // no temporary file is left behind
  int entries = 0;
  for (const auto& entry : std::filesystem::directory_iterator(test::ScratchDir())) {
    (void)entry;
    ++entries;
  }
  EXPECT_EQ(entries, 1);
}

}  // namespace
}  // namespace lamina
