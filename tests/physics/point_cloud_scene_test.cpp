// SPDX-License-Identifier: MIT
// Point clouds in the simulator: a 0.2 m cube sampled on its surface (1016 points, the example
// `.pcd`) dropped on a plane primitive and on a mesh terrain rests with its lowest points at its
// padding above the ground (each point is a ball of the padding), within 1 mm; in the example
// world a mesh block rests on the cloud's top at the two paddings' sum. Label physics (seconds of
// simulated contact each): the sanitizer build leaves it out, point_cloud_contacts_test covers
// the contact code there.
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>

#include <gtest/gtest.h>

#include "core/geometry/mass_properties.h"
#include "core/io/load_context.h"
#include "core/io/mesh_file.h"
#include "core/io/point_cloud_file.h"
#include "core/sim/simulator.h"
#include "tests/common/scene_builders.h"
#include "tests/common/test_support.h"

namespace lamina {
namespace {

using core::Pose;
using core::Vec3;

constexpr double kPadding = 0.0025;
// the brief's bar for the resting height
constexpr double kHeightTolerance = 0.001;

core::GeometryDesc CubeCloud() {
  core::Diagnostics diagnostics;
  std::optional<core::PointCloud> cloud = core::ReadPointCloudFile(
      test::WorldsPath("examples/point_clouds/cube_rgb_ascii.pcd"), {}, diagnostics);
  EXPECT_TRUE(cloud) << diagnostics.FormatAll();
  core::GeometryDesc geometry;
  geometry.kind = core::GeometryKind::kPointCloud;
  geometry.point_cloud =
      std::make_shared<const core::PointCloud>(cloud.value_or(core::PointCloud()));
  return geometry;
}

// the cube cloud, 1 kg (automass: equal point masses), dropped from 5 cm above the ground
core::RigidObjectDesc FallingCubeCloud() {
  core::RigidObjectDesc cube;
  cube.name = "cube_cloud";
  cube.geometry = CubeCloud();
  cube.mass = 1.0;
  const core::MassProperties mass = core::ComputeMassProperties(cube.geometry, 1.0, 1.0);
  EXPECT_TRUE(mass.valid);
  cube.com = mass.com;
  cube.inertia = mass.inertia;
  cube.pose.translation() = Vec3(0.0, 0.0, 0.15);
  cube.sim = core::DefaultObjectSimParams();
  cube.sim.padding = kPadding;
  cube.sim.surface.restitution = 0.0;
  return cube;
}

// the lowest of the object's points in the world (m)
double LowestPoint(const core::Simulator& simulator, int object,
                   const core::GeometryDesc& geometry) {
  const Pose pose = simulator.GetObjectPose(object);
  double lowest = core::kInf;
  for (const Vec3& p : geometry.point_cloud->points) lowest = std::min(lowest, (pose * p).z());
  return lowest;
}

void ExpectRestingOnItsPadding(core::WorldDesc world) {
  world.objects.push_back(FallingCubeCloud());
  core::Simulator simulator(world);
  simulator.Simulate(1.5);
  const double lowest = LowestPoint(simulator, 0, world.objects[0].geometry);
  EXPECT_NEAR(lowest, kPadding, kHeightTolerance);
  // level and still: the whole bottom face carries it
  const Pose pose = simulator.GetObjectPose(0);
  EXPECT_LT(Eigen::AngleAxisd(pose.linear()).angle(), 1e-3);
  EXPECT_LT(simulator.GetObjectVelocity(0).linear.norm(), 1e-3);
  EXPECT_LT(std::abs(pose.translation().x()) + std::abs(pose.translation().y()), 1e-3);
  std::cout << "lowest point " << std::fixed << std::setprecision(4) << lowest * 1000
            << " mm above the ground\n";
}

TEST(PointCloudSceneTest, CubeCloudRestsOnAPlaneAtItsPadding) {
  core::WorldDesc world;
  world.terrains.push_back(test::PlaneTerrain(0.5, 0.0));
  ExpectRestingOnItsPadding(world);
}

TEST(PointCloudSceneTest, CubeCloudRestsOnAMeshTerrainAtItsPadding) {
  core::Diagnostics diagnostics;
  std::optional<core::TriangleMesh> plane =
      core::ReadMeshFile(test::WorldsPath("klampt/terrains/plane.off"), {}, diagnostics);
  ASSERT_TRUE(plane) << diagnostics.FormatAll();
  core::WorldDesc world;
  world.terrains.push_back(test::PlaneTerrain(0.5, 0.0));
  world.terrains[0].geometry =
      test::MeshGeometry(std::make_shared<const core::TriangleMesh>(std::move(*plane)));
  ExpectRestingOnItsPadding(world);
}

// worlds/examples/point_clouds.xml: the cube cloud on the floor, the mesh block on the cloud
TEST(PointCloudSceneTest, TheExampleWorldSettlesWithABlockOnTheCloud) {
  test::LoadedWorld loaded;
  test::LoadWorld(test::WorldsPath("examples/point_clouds.xml"), &loaded);
  ASSERT_TRUE(loaded.ok) << loaded.diagnostics.FormatAll();
  core::Simulator simulator(loaded.world);
  simulator.Simulate(2.0);
  const double cube_z = simulator.GetObjectPose(0).translation().z();
  EXPECT_NEAR(LowestPoint(simulator, 0, loaded.world.objects[0].geometry), kPadding,
              kHeightTolerance);
  EXPECT_NEAR(LowestPoint(simulator, 1, loaded.world.objects[1].geometry), kPadding,
              kHeightTolerance);
  // the block (origin at its centre, 10 cm) on the cloud's top points, both layers between
  const double block_z = simulator.GetObjectPose(2).translation().z();
  EXPECT_NEAR(block_z, cube_z + 0.1 + 2 * kPadding + 0.05, kHeightTolerance);
}

}  // namespace
}  // namespace lamina
