// SPDX-License-Identifier: MIT
// A camera sensor's pictures through the renderer (OSMesa): a depth camera 1.5 m above the
// ground looking straight down reads 1.5 m everywhere on the ground (depth is along the optical
// axis, so a plane square to it reads one depth) and 1.0 m on top of a 0.5 m box below it; the
// colour image shows the box where the depth does; a simulation without a renderer leaves its
// camera's measurements at zero.
#include "ui/render/sensor_camera.h"

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/render/render_mesh_cache.h"
#include "core/render/scene_extract.h"
#include "core/render/world_poses.h"
#include "core/sim/simulator.h"
#include "tests/common/scene_builders.h"
#include "ui/platform/osmesa_context.h"
#include "ui/render/renderer.h"

namespace lamina {
namespace {

using core::Vec3;

constexpr int kWidth = 32, kHeight = 24;

// a pendulum robot (it does not matter) carrying a world-fixed camera looking down from 1.5 m;
// a 0.5 m terrain box under the image's left half
core::WorldDesc CameraWorld() {
  core::WorldDesc world = test::PendulumWorld("servoP 0\nservoI 0\nservoD 0\n", 0.0);
  world.robots[0].links[0].parent_transform.translation() = Vec3(10, 0, 1);  // out of view
  world.robots[0].properties["sensors"] =
      "<sensors><CameraSensor name=\"cam\" link=\"-1\" "
      "Tsensor=\"1 0 0  0 -1 0  0 0 -1  0 0 1.5\" xres=\"32\" yres=\"24\" xfov=\"1.0\" "
      "zmin=\"0.1\" zmax=\"5\"/></sensors>";
  world.terrains.push_back(test::PlaneTerrain(0.5, 0.0));
  core::TerrainDesc box;
  box.name = "box";
  core::Pose at = core::Pose::Identity();
  at.translation() = Vec3(-0.5, 0, 0.25);  // x in [-1, 0]: the image's left half
  box.geometry = test::PrimitiveGeometry(core::Primitive::Box(Vec3(1, 2, 0.5), at));
  world.terrains.push_back(box);
  return world;
}

class SensorCameraTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string error;
    ASSERT_TRUE(context_.Create(1, 1, &error)) << error;
    ASSERT_TRUE(renderer_.Initialize(&error)) << error;
  }
  ui::OsmesaContext context_;
  ui::Renderer renderer_;
  core::RenderMeshCache meshes_;
};

TEST_F(SensorCameraTest, ADepthCameraFacingAPlaneReadsItsDistance) {
  core::Simulator sim(CameraWorld());
  ui::SceneCamera camera(&renderer_, [&](core::RenderScene* scene) {
    core::ExtractScene(sim.world(), core::CurrentPoses(sim), {}, {}, &meshes_, scene);
  });
  sim.SetCameraRenderer(&camera);
  sim.Simulate(0.01);
  EXPECT_EQ(camera.pictures(), 1);
  const std::vector<double>& m = sim.sensors(0).sensor(0).measurements();
  ASSERT_EQ(m.size(), 2u * kWidth * kHeight);
  const double* depth = m.data() + kWidth * kHeight;
  // camera x is world x (its y is world -y): columns 0..15 see the box, 16..31 the ground
  for (int y = 2; y < kHeight - 2; ++y) {
    for (int x : {1, 8, 14}) EXPECT_NEAR(depth[y * kWidth + x], 1.0, 1e-3) << x << "," << y;
    for (int x : {18, 24, 30}) EXPECT_NEAR(depth[y * kWidth + x], 1.5, 1e-3) << x << "," << y;
  }
  // the colour image: the box's top and the ground differ (lit the same, but the ground is
  // checkered and the box is not at the same depth in the haze-free view: compare a whole row)
  int differing = 0;
  for (int x = 0; x < kWidth; ++x) differing += m[12 * kWidth + x] != m[12 * kWidth + 31];
  EXPECT_GT(differing, 0);
  EXPECT_NE(m[12 * kWidth + 5], 0.0);  // drawn, not black
}

TEST_F(SensorCameraTest, WithoutARendererACameraMeasuresNothing) {
  core::Simulator sim(CameraWorld());
  sim.Simulate(0.05);
  for (double v : sim.sensors(0).sensor(0).measurements()) ASSERT_EQ(v, 0.0);
}

}  // namespace
}  // namespace lamina
