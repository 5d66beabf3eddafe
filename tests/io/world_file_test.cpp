// SPDX-License-Identifier: MIT
// World XML loading: every Klamp't example world with its counts, transforms, the
// <simulation> block, ids, and single-element files opened as worlds.
#include "core/io/world_file.h"

#include <cmath>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/model/world_summary.h"
#include "tests/common/test_support.h"

namespace lamina {
namespace {

using core::Severity;
using test::LoadedWorld;
using test::WorldsPath;
using ::testing::ElementsAre;
using ::testing::IsEmpty;

struct ExpectedCounts {
  const char* file;
  int terrains;
  int objects;
  int robots;
  int terrain0_triangles;
};

class KlamptWorldTest : public ::testing::TestWithParam<ExpectedCounts> {};

TEST_P(KlamptWorldTest, LoadsWithoutErrorsAndRightCounts) {
  const ExpectedCounts expected = GetParam();
  LoadedWorld loaded;
  test::LoadWorld(WorldsPath(std::string("klampt/") + expected.file), &loaded);
  EXPECT_TRUE(loaded.ok) << loaded.diagnostics.FormatAll();
  EXPECT_THAT(loaded.diagnostics.Messages(Severity::kError), IsEmpty());
  EXPECT_EQ(static_cast<int>(loaded.world.terrains.size()), expected.terrains);
  EXPECT_EQ(static_cast<int>(loaded.world.objects.size()), expected.objects);
  EXPECT_EQ(static_cast<int>(loaded.world.robots.size()), expected.robots);
  ASSERT_FALSE(loaded.world.terrains.empty());
  EXPECT_EQ(loaded.world.terrains[0].geometry.triangle_count(), expected.terrain0_triangles);
  for (const auto& object : loaded.world.objects) {
    EXPECT_FALSE(object.geometry.empty()) << object.name;
    // every object must end up with a usable inertia (Klamp't's zero default is fixed)
    EXPECT_GT(object.inertia.trace(), 0.0) << object.name;
  }
}

INSTANTIATE_TEST_SUITE_P(
    AllExamples, KlamptWorldTest,
    ::testing::Values(ExpectedCounts{"athlete_fractal_1.xml", 1, 0, 1, 32768},
                      ExpectedCounts{"athlete_plane.xml", 1, 0, 1, 2},
                      ExpectedCounts{"block.xml", 1, 1, 1, 12},
                      ExpectedCounts{"simulation_test_worlds/bounce_test.xml", 1, 10, 0, 12},
                      ExpectedCounts{"simulation_test_worlds/fastdroptest.xml", 1, 2, 0, 12},
                      ExpectedCounts{"simulation_test_worlds/heavyblocktest.xml", 1, 2, 0, 12},
                      ExpectedCounts{"simulation_test_worlds/slideblock.xml", 2, 2, 0, 2},
                      ExpectedCounts{"simulation_test_worlds/stacktest.xml", 1, 10, 0, 12},
                      ExpectedCounts{"simulation_test_worlds/stiffness_test.xml", 1, 10, 0, 12}));

TEST(WorldFileTest, AthleteHas42LinksAndKlamptIds) {
  LoadedWorld loaded;
  test::LoadWorld(WorldsPath("klampt/athlete_fractal_1.xml"), &loaded);
  ASSERT_TRUE(loaded.ok) << loaded.diagnostics.FormatAll();
  const core::WorldDesc& world = loaded.world;
  ASSERT_EQ(world.robots.size(), 1u);
  const core::RobotDesc& athlete = world.robots[0];
  EXPECT_EQ(athlete.name, "ATHLETE");
  EXPECT_EQ(athlete.dof(), 42);
  EXPECT_EQ(athlete.drivers.size(), 36u);
  // the world's config attribute replaces the .rob's q: value 6 is 0 and value 3 0.141412
  ASSERT_EQ(athlete.config.size(), 42);
  EXPECT_DOUBLE_EQ(athlete.config[3], 0.141412);
  EXPECT_DOUBLE_EQ(athlete.config[5], 5.99001);
  // ids: terrain 0, robot 1, links 2..43
  EXPECT_EQ(world.TerrainId(0), 0);
  EXPECT_EQ(world.RobotId(0), 1);
  EXPECT_EQ(world.RobotLinkId(0, 41), 43);
  EXPECT_EQ(world.IdCount(), 44);
  const core::WorldId link = world.Resolve(43);
  EXPECT_EQ(link.kind, core::WorldId::Kind::kRobotLink);
  EXPECT_EQ(link.link, 41);
  EXPECT_EQ(world.Resolve(44).kind, core::WorldId::Kind::kInvalid);
  // the terrain is translated by (-10, -10, 0): its 129x129 grid spans [-10, 10] in x and y
  const auto bounds = world.terrains[0].geometry.mesh->Bounds(world.terrains[0].geometry.Matrix());
  EXPECT_NEAR(bounds.min().x(), -10.0, 1e-12);
  EXPECT_NEAR(bounds.max().y(), 10.0, 1e-12);
}

TEST(WorldFileTest, GeometryRotationsComposeInKlamptOrder) {
  LoadedWorld loaded;
  test::LoadWorld(WorldsPath("klampt/simulation_test_worlds/fastdroptest.xml"), &loaded);
  ASSERT_TRUE(loaded.ok) << loaded.diagnostics.FormatAll();
  const core::GeometryDesc& geometry = loaded.world.objects[1].geometry;
  // rotateX="0.5" rotateY="0.8": R = Ry(0.8) * Rx(0.5), applied after scale 0.1
  const core::Mat3 expected =
      (Eigen::AngleAxisd(0.8, core::Vec3::UnitY()) * Eigen::AngleAxisd(0.5, core::Vec3::UnitX()))
          .toRotationMatrix() *
      0.1;
  EXPECT_TRUE(geometry.Matrix().linear().isApprox(expected, 1e-14));
  EXPECT_TRUE(geometry.Matrix().translation().isApprox(core::Vec3(-0.05, -0.05, -0.05), 1e-14));
  EXPECT_DOUBLE_EQ(loaded.world.objects[1].pose.translation().z(), 15.0);
}

TEST(WorldFileTest, SimulationBlockSetsPerBodyParameters) {
  LoadedWorld loaded;
  test::LoadWorld(WorldsPath("klampt/simulation_test_worlds/stiffness_test.xml"), &loaded);
  ASSERT_TRUE(loaded.ok) << loaded.diagnostics.FormatAll();
  const core::WorldDesc& world = loaded.world;
  // <object name="ball_soft_1"> and <object index="1">
  const core::BodySimParams& soft = world.objects[0].sim;
  EXPECT_EQ(soft.surface.stiffness, 50.0);
  EXPECT_EQ(soft.surface.damping, 4.0);
  EXPECT_EQ(soft.padding, 0.04);
  EXPECT_EQ(soft.preshrink, core::Preshrink::kCopy);
  EXPECT_EQ(world.objects[1].sim.surface.stiffness, 500.0);
  EXPECT_EQ(world.objects[9].sim.surface.stiffness, core::kInf);
  // terrain: restitution from the block, padding and rigidity from Lamina's terrain defaults
  EXPECT_EQ(world.terrains[0].sim.surface.restitution, 0.7);
  EXPECT_EQ(world.terrains[0].sim.padding, 0.0);
  EXPECT_EQ(world.terrains[0].sim.surface.stiffness, core::kInf);
}

TEST(WorldFileTest, InitialVelocityFromSimulationBlock) {
  LoadedWorld loaded;
  test::LoadWorld(WorldsPath("klampt/simulation_test_worlds/slideblock.xml"), &loaded);
  ASSERT_TRUE(loaded.ok) << loaded.diagnostics.FormatAll();
  EXPECT_EQ(loaded.world.objects[0].initial_velocity.linear, core::Vec3(1, 0, 0));
  EXPECT_EQ(loaded.world.objects[1].sim.surface.friction, 0.01);
  EXPECT_EQ(loaded.world.objects[1].sim.padding, 0.002);
}

TEST(WorldFileTest, AutomassOfStackBlockIsAThinCubeShell) {
  LoadedWorld loaded;
  test::LoadWorld(WorldsPath("klampt/simulation_test_worlds/stacktest.xml"), &loaded);
  ASSERT_TRUE(loaded.ok) << loaded.diagnostics.FormatAll();
  const core::RigidObjectDesc& block = loaded.world.objects[0];
  // automass with Klamp't's default surface fraction 1: a thin-walled cube of side a has
  // I = 5/18 m a^2 about each axis; the geometry is centred by translation -a/2
  const double a = 0.1;
  EXPECT_NEAR(block.inertia(0, 0), 5.0 / 18.0 * 1.0 * a * a, 1e-12);
  EXPECT_NEAR(block.inertia(2, 2), 5.0 / 18.0 * a * a, 1e-12);
  EXPECT_NEAR(block.inertia(0, 1), 0.0, 1e-12);
  EXPECT_NEAR(block.com.norm(), 0.0, 1e-12);
}

TEST(WorldFileTest, TyposInKlamptExamplesAreWarnedNotFatal) {
  LoadedWorld loaded;
  const std::string path = WorldsPath("klampt/block.xml");
  test::LoadWorld(path, &loaded);
  EXPECT_TRUE(loaded.ok) << loaded.diagnostics.FormatAll();
  const auto warnings = loaded.diagnostics.Messages(Severity::kWarning);
  EXPECT_THAT(warnings,
              ::testing::Contains(path + ":7: warning: <geometry>: unknown attribute "
                                         "'translate' ignored (did you mean 'translation'?)"));
  // as in Klamp't the geometry stays where the mesh puts it: cube corner at the origin
  EXPECT_TRUE(loaded.world.objects[0].geometry.transform.translation().isZero());
}

TEST(WorldFileTest, StiffnessAttributeSuggestsKStiffness) {
  const std::string path = test::WriteScratchFile("w.xml", R"(<world>
  <terrain file=")" + WorldsPath("klampt/terrains/cube.off") + R"("/>
  <simulation>
    <terrain index="0"><geometry stiffness="1000" preshink="1"/></terrain>
  </simulation>
</world>)");
  LoadedWorld loaded;
  test::LoadWorld(path, &loaded);
  EXPECT_TRUE(loaded.ok);
  EXPECT_THAT(loaded.diagnostics.Messages(Severity::kWarning),
              ElementsAre(path + ":4: warning: <geometry>: unknown attribute 'stiffness' ignored "
                                 "(did you mean 'kStiffness'?)",
                          path + ":4: warning: <geometry>: unknown attribute 'preshink' ignored "
                                 "(did you mean 'preshrink'?)"));
  EXPECT_EQ(loaded.world.terrains[0].sim.surface.stiffness, core::kInf);
}

TEST(WorldFileTest, RobotReferenceWithoutBodyMeansAllLinks) {
  const std::string path = test::WriteScratchFile("robots.xml", R"(<world>
  <robot name="arm" file=")" + WorldsPath("klampt/robots/planar3R.rob") +
                                                                    R"(" position="1 2 3"/>
  <simulation>
    <robot name="arm"><geometry padding="0.01" kFriction="0.3"/></robot>
    <robot index="0" body="1"><geometry padding="0.02"/></robot>
  </simulation>
</world>)");
  LoadedWorld loaded;
  test::LoadWorld(path, &loaded);
  ASSERT_TRUE(loaded.ok) << loaded.diagnostics.FormatAll();
  const core::RobotDesc& arm = loaded.world.robots[0];
  ASSERT_EQ(arm.dof(), 3);
  EXPECT_EQ(arm.links[0].sim.padding, 0.01);
  EXPECT_EQ(arm.links[1].sim.padding, 0.02);
  EXPECT_EQ(arm.links[2].sim.padding, 0.01);
  EXPECT_EQ(arm.links[2].sim.surface.friction, 0.3);
  // the robot's position moves its root link only
  EXPECT_EQ(arm.links[0].parent_transform.translation(), core::Vec3(1, 2, 3));
  EXPECT_EQ(arm.links[1].parent_transform.translation(), core::Vec3(1, 0, 0));
}

TEST(WorldFileTest, SingleFilesOpenAsWorlds) {
  for (const char* file : {"klampt/robots/ur5.rob", "klampt/objects/block.obj",
                           "klampt/terrains/plane.env", "klampt/terrains/ridges.off"}) {
    LoadedWorld loaded;
    test::LoadWorld(WorldsPath(file), &loaded);
    EXPECT_TRUE(loaded.ok) << file << "\n" << loaded.diagnostics.FormatAll();
    EXPECT_EQ(
        loaded.world.robots.size() + loaded.world.objects.size() + loaded.world.terrains.size(), 1u)
        << file;
  }
}

TEST(WorldFileTest, SummaryJsonNamesEveryElement) {
  LoadedWorld loaded;
  test::LoadWorld(WorldsPath("klampt/block.xml"), &loaded);
  const std::string json = core::WorldSummaryJson(loaded.world);
  EXPECT_THAT(json, ::testing::HasSubstr("\"name\": \"block\""));
  EXPECT_THAT(json, ::testing::HasSubstr("\"kStiffness\": 10000.0"));
  EXPECT_THAT(json, ::testing::HasSubstr("\"kStiffness\": \"inf\""));
}

}  // namespace
}  // namespace lamina
