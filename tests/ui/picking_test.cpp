// SPDX-License-Identifier: MIT
// Picking: camera rays through pixels and the nearest body they hit (core/render/picking.h).
#include "core/render/picking.h"

#include <memory>

#include <gtest/gtest.h>

namespace lamina::core {
namespace {

// a 2 x 2 square in the z = 0 plane of its own frame, centred on the origin, facing +z
std::shared_ptr<const RenderMesh> Square() {
  auto mesh = std::make_shared<RenderMesh>();
  const Eigen::Vector3f a(-1, -1, 0), b(1, -1, 0), c(1, 1, 0), d(-1, 1, 0);
  mesh->positions = {a, b, c, a, c, d};
  mesh->normals.assign(6, Eigen::Vector3f::UnitZ());
  for (const auto& p : mesh->positions) mesh->bounds.extend(p);
  mesh->serial = NextRenderMeshSerial();
  return mesh;
}

DrawItem SquareAt(double height, int world_id, std::uint32_t flags = kDrawNone) {
  DrawItem item;
  item.mesh = Square();
  item.transform(2, 3) = static_cast<float>(height);
  item.world_id = world_id;
  item.flags = flags;
  return item;
}

Ray DownFrom(double x, double y, double z) {
  return Ray{Eigen::Vector3d(x, y, z), -Eigen::Vector3d::UnitZ()};
}

TEST(RayTriangle, HitsInsideMissesOutsideAndParallel) {
  const Eigen::Vector3d a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  EXPECT_NEAR(RayTriangleDistance({0.2, 0.2, 3}, {0, 0, -1}, a, b, c), 3.0, 1e-12);
  EXPECT_LT(RayTriangleDistance({0.8, 0.8, 3}, {0, 0, -1}, a, b, c), 0.0);           // outside
  EXPECT_LT(RayTriangleDistance({0.2, 0.2, 3}, {1, 0, 0}, a, b, c), 0.0);            // parallel
  EXPECT_NEAR(RayTriangleDistance({0.2, 0.2, -2}, {0, 0, 1}, a, b, c), 2.0, 1e-12);  // back side
}

TEST(PixelRay, CentreOfTheViewLooksAtTheTarget) {
  OrbitCamera camera;
  camera.target = Eigen::Vector3d(1, 2, 3);
  camera.yaw = 30;
  camera.pitch = 20;
  camera.distance = 4;
  const Ray ray = PixelRay(camera, 640, 480, 320, 240);
  EXPECT_TRUE(ray.origin.isApprox(camera.Eye()));
  EXPECT_TRUE(ray.direction.isApprox((camera.target - camera.Eye()).normalized(), 1e-12));
}

TEST(PixelRay, PointsOnTheRayProjectToThePixel) {
  OrbitCamera camera;
  camera.yaw = -70;
  camera.pitch = 35;
  camera.fov_y = 60;
  const int width = 800, height = 500;
  const double x = 123.5, y = 401.5;
  const Ray ray = PixelRay(camera, width, height, x, y);
  const Eigen::Vector3d point = ray.origin + 3.0 * ray.direction;
  const Eigen::Vector4d clip = camera.ProjectionMatrix(double(width) / height, 10.0) *
                               camera.ViewMatrix() * point.homogeneous();
  const double pixel_x = (clip.x() / clip.w() + 1.0) / 2.0 * width;
  const double pixel_y = (1.0 - clip.y() / clip.w()) / 2.0 * height;
  EXPECT_NEAR(pixel_x, x, 1e-6);
  EXPECT_NEAR(pixel_y, y, 1e-6);
}

TEST(PickBody, ReturnsTheNearestBodyAndWhereItWasHit) {
  RenderScene scene;
  scene.items = {SquareAt(0.0, 1), SquareAt(1.0, 2), SquareAt(0.5, 3)};
  const PickHit hit = PickBody(scene, DownFrom(0.3, -0.4, 5.0));
  EXPECT_EQ(hit.world_id, 2);
  EXPECT_NEAR(hit.distance, 4.0, 1e-9);
  EXPECT_TRUE(hit.point.isApprox(Eigen::Vector3d(0.3, -0.4, 1.0), 1e-6));
}

TEST(PickBody, FollowsScaledAndRotatedTransforms) {
  DrawItem item = SquareAt(0.0, 7);
  // scaled 3x in x and turned 90 degrees about z: covers |x| <= 1, |y| <= 3
  Eigen::Matrix4f transform = Eigen::Matrix4f::Identity();
  transform.topLeftCorner<3, 3>() =
      Eigen::AngleAxisf(1.5707963f, Eigen::Vector3f::UnitZ()).toRotationMatrix() *
      Eigen::Vector3f(3, 1, 1).asDiagonal();
  transform(2, 3) = 2.0f;
  item.transform = transform;
  RenderScene scene;
  scene.items = {item};
  EXPECT_EQ(PickBody(scene, DownFrom(0.5, 2.5, 10.0)).world_id, 7);
  EXPECT_NEAR(PickBody(scene, DownFrom(0.5, 2.5, 10.0)).distance, 8.0, 1e-5);
  EXPECT_FALSE(PickBody(scene, DownFrom(2.5, 0.5, 10.0)).hit());
}

TEST(PickBody, SkipsDebugGeometryTranslucentLayersAndItemsWithoutId) {
  RenderScene scene;
  scene.items = {SquareAt(0.0, 1), SquareAt(3.0, 5, kDrawUnlit), SquareAt(2.0, 6, kDrawTranslucent),
                 SquareAt(1.0, -1)};
  EXPECT_EQ(PickBody(scene, DownFrom(0, 0, 5)).world_id, 1);
  PickFilter with_layers;
  with_layers.translucent = true;
  EXPECT_EQ(PickBody(scene, DownFrom(0, 0, 5), with_layers).world_id, 6);
}

TEST(PickBody, TerrainsCanBeLeftOut) {
  RenderScene scene;
  scene.items = {SquareAt(0.0, 0, kDrawTerrain), SquareAt(-1.0, 4)};
  EXPECT_EQ(PickBody(scene, DownFrom(0, 0, 5)).world_id, 0);
  PickFilter no_terrain;
  no_terrain.terrains = false;
  EXPECT_EQ(PickBody(scene, DownFrom(0, 0, 5), no_terrain).world_id, 4);
}

TEST(PickBody, MissingEverythingGivesNoBody) {
  RenderScene scene;
  scene.items = {SquareAt(0.0, 1)};
  EXPECT_FALSE(PickBody(scene, DownFrom(5, 5, 5)).hit());
  EXPECT_FALSE(PickBody(scene, Ray{Eigen::Vector3d(0, 0, 5), Eigen::Vector3d::UnitZ()}).hit());
  EXPECT_FALSE(PickBody(RenderScene(), DownFrom(0, 0, 5)).hit());
}

}  // namespace
}  // namespace lamina::core
