// SPDX-License-Identifier: MIT
// The orbit camera: text description round trip and errors, default framing (the box is inside
// the view frustum), and mouse control.
#include "core/render/camera.h"

#include <gtest/gtest.h>

#include "core/render/camera_control.h"
#include "core/render/scene_camera.h"

namespace lamina::core {
namespace {

TEST(CameraTest, DescriptionRoundTripIsExact) {
  OrbitCamera camera;
  camera.target = Eigen::Vector3d(0.1, -2.0 / 3.0, 1e-7);
  camera.yaw = -123.456789;
  camera.pitch = 1.0 / 3.0;
  camera.distance = 12.345678901234567;
  camera.fov_y = 60.0;
  OrbitCamera parsed;
  std::string error;
  ASSERT_TRUE(ParseCamera(FormatCamera(camera), &parsed, &error)) << error;
  EXPECT_EQ(parsed, camera);
}

TEST(CameraTest, ParsesCompactFormAndPartialKeys) {
  OrbitCamera camera;
  std::string error;
  ASSERT_TRUE(ParseCamera("1 2 3 90 30 4", &camera, &error)) << error;
  EXPECT_EQ(camera.target, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(camera.yaw, 90.0);
  EXPECT_EQ(camera.pitch, 30.0);
  EXPECT_EQ(camera.distance, 4.0);
  ASSERT_TRUE(ParseCamera("yaw=10; fov=30", &camera, &error)) << error;
  EXPECT_EQ(camera.yaw, 10.0);
  EXPECT_EQ(camera.fov_y, 30.0);
  EXPECT_EQ(camera.distance, 4.0);  // kept
}

TEST(CameraTest, ErrorsNameTheProblem) {
  OrbitCamera camera;
  const OrbitCamera before = camera;
  std::string error;
  EXPECT_FALSE(ParseCamera("yaw=abc", &camera, &error));
  EXPECT_NE(error.find("yaw expects a number, got 'abc'"), std::string::npos) << error;
  EXPECT_FALSE(ParseCamera("zoom=2", &camera, &error));
  EXPECT_NE(error.find("unknown key 'zoom'"), std::string::npos) << error;
  EXPECT_FALSE(ParseCamera("pitch=95", &camera, &error));
  EXPECT_NE(error.find("pitch must be in (-90, 90)"), std::string::npos) << error;
  EXPECT_FALSE(ParseCamera("target=1,2", &camera, &error));
  EXPECT_NE(error.find("target expects three numbers"), std::string::npos) << error;
  EXPECT_FALSE(ParseCamera("1 2 3", &camera, &error));
  EXPECT_NE(error.find("got 3 numbers"), std::string::npos) << error;
  EXPECT_EQ(camera, before);  // failures leave the camera alone
}

// every corner of `box` projects inside the viewport and between the clip planes
void ExpectBoxInView(const Eigen::AlignedBox3d& box, double aspect) {
  const OrbitCamera camera = FramingCamera(box, aspect);
  const double radius = 0.5 * box.diagonal().norm();
  const Eigen::Matrix4d view_projection =
      camera.ProjectionMatrix(aspect, radius) * camera.ViewMatrix();
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d corner = box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(i));
    const Eigen::Vector4d clip = view_projection * corner.homogeneous();
    ASSERT_GT(clip.w(), 0.0);
    const Eigen::Vector3d ndc = clip.head<3>() / clip.w();
    EXPECT_LE(std::abs(ndc.x()), 1.0) << "corner " << i << " aspect " << aspect;
    EXPECT_LE(std::abs(ndc.y()), 1.0) << "corner " << i << " aspect " << aspect;
    EXPECT_LT(std::abs(ndc.z()), 1.0) << "corner " << i;
  }
}

TEST(CameraTest, FramingKeepsTheWholeBoxInView) {
  const Eigen::AlignedBox3d boxes[] = {
      {Eigen::Vector3d(-2, -2, -0.1), Eigen::Vector3d(2, 2, 1)},
      {Eigen::Vector3d(-10, -10, -1), Eigen::Vector3d(10, 10, 6)},
      {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.1, 0.1, 3)},
  };
  for (const Eigen::AlignedBox3d& box : boxes) {
    for (double aspect : {0.5, 1.0, 16.0 / 9.0}) ExpectBoxInView(box, aspect);
  }
}

TEST(CameraTest, ScenePresetsAndDescriptions) {
  RenderScene scene;
  scene.bounds = Eigen::AlignedBox3d(Eigen::Vector3d(-5, -5, 0), Eigen::Vector3d(5, 5, 1));
  scene.body_bounds = Eigen::AlignedBox3d(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 1));
  OrbitCamera world, bodies, custom;
  std::string error;
  ASSERT_TRUE(CameraForScene("", scene, 1.5, &world, &error));
  ASSERT_TRUE(CameraForScene("bodies", scene, 1.5, &bodies, &error));
  EXPECT_LT(bodies.distance, world.distance);
  EXPECT_EQ(bodies.target, Eigen::Vector3d(0.5, 0.5, 0.5));
  ASSERT_TRUE(CameraForScene("yaw=100", scene, 1.5, &custom, &error));
  EXPECT_EQ(custom.yaw, 100.0);
  EXPECT_EQ(custom.distance, world.distance);
  EXPECT_FALSE(CameraForScene("sideways", scene, 1.5, &custom, &error));
  EXPECT_NE(error.find("preset: world, bodies"), std::string::npos) << error;
}

TEST(CameraControlTest, LeftOrbitsRightPansScrollZooms) {
  OrbitCamera camera;
  MouseDrag drag;
  drag.button = MouseButton::kLeft;
  drag.dx = 10.0;
  drag.dy = 5.0;
  const OrbitCamera orbited = ApplyMouseDrag(camera, drag, 600);
  EXPECT_DOUBLE_EQ(orbited.yaw, camera.yaw - 3.0);
  EXPECT_DOUBLE_EQ(orbited.pitch, camera.pitch + 1.5);
  EXPECT_EQ(orbited.target, camera.target);

  drag.button = MouseButton::kRight;
  const OrbitCamera panned = ApplyMouseDrag(camera, drag, 600);
  EXPECT_EQ(panned.distance, camera.distance);
  const Eigen::Vector3d moved = panned.target - camera.target;
  const Eigen::Vector3d forward = (camera.target - camera.Eye()).normalized();
  EXPECT_GT(moved.norm(), 0.0);
  EXPECT_NEAR(moved.dot(forward), 0.0, 1e-12);  // in the view plane
  drag.shift = true;
  drag.button = MouseButton::kLeft;
  EXPECT_EQ(MotionForDrag(drag), CameraMotion::kPan);

  EXPECT_LT(ApplyScroll(camera, 1.0).distance, camera.distance);
  EXPECT_GT(ApplyScroll(camera, -1.0).distance, camera.distance);
  drag = MouseDrag();
  drag.button = MouseButton::kMiddle;
  drag.dy = 20.0;
  EXPECT_GT(ApplyMouseDrag(camera, drag, 600).distance, camera.distance);
}

TEST(CameraControlTest, PitchStaysBelowTheVertical) {
  OrbitCamera camera;
  MouseDrag drag;
  drag.button = MouseButton::kLeft;
  drag.dy = 1e4;
  EXPECT_LT(ApplyMouseDrag(camera, drag, 600).pitch, 90.0);
  drag.dy = -1e4;
  EXPECT_GT(ApplyMouseDrag(camera, drag, 600).pitch, -90.0);
}

}  // namespace
}  // namespace lamina::core
