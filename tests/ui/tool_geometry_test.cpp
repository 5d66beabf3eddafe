// SPDX-License-Identifier: MIT
// The mouse tools' geometry (ui/viewer/tool_geometry.h): the drag plane, axis locks, turning with
// the mouse and projecting to pixels, against hand-computed answers.
#include "ui/viewer/tool_geometry.h"

#include <cmath>

#include <gtest/gtest.h>

namespace lamina::ui {
namespace {

TEST(ToolGeometryTest, RayMeetsThePlaneInFrontOfTheEyeOnly) {
  core::Ray ray;
  ray.origin = core::Vec3(0, 0, 5);
  ray.direction = core::Vec3(0, 0.6, -0.8);
  const auto hit = RayPlane(ray, core::Vec3(1, 1, 1), core::Vec3::UnitZ());
  ASSERT_TRUE(hit);
  EXPECT_NEAR((*hit - core::Vec3(0, 3, 1)).norm(), 0.0, 1e-12);           // 4 m down, 3 m across
  EXPECT_FALSE(RayPlane(ray, core::Vec3(0, 0, 6), core::Vec3::UnitZ()));  // behind the eye
  ray.direction = core::Vec3::UnitX();
  EXPECT_FALSE(RayPlane(ray, core::Vec3(0, 0, 1), core::Vec3::UnitZ()));  // parallel
}

TEST(ToolGeometryTest, TheDragPlaneFacesTheCameraOrIsHorizontal) {
  core::OrbitCamera camera;
  camera.yaw = 0.0;
  camera.pitch = 0.0;  // looking from +x towards the target
  EXPECT_NEAR((DragPlaneNormal(camera, false) - core::Vec3(-1, 0, 0)).norm(), 0.0, 1e-12);
  EXPECT_EQ(DragPlaneNormal(camera, true), core::Vec3::UnitZ());
}

TEST(ToolGeometryTest, AnAxisLockKeepsOnlyThatComponentOfTheMotion) {
  const core::Vec3 start(1, 2, 3), moved(4, 6, 8);
  EXPECT_EQ(LockToAxis(start, moved, 0), core::Vec3(4, 2, 3));
  EXPECT_EQ(LockToAxis(start, moved, 1), core::Vec3(1, 6, 3));
  EXPECT_EQ(LockToAxis(start, moved, 2), core::Vec3(1, 2, 8));
}

TEST(ToolGeometryTest, HorizontalMouseMotionTurnsAboutTheScreensUpAxis) {
  core::OrbitCamera camera;
  camera.yaw = 0.0;
  camera.pitch = 0.0;                                               // screen up is world +z
  const core::Mat3 turn = TurnFromMouse(camera, 100.0, 0.0, 0.01);  // 1 rad
  const Eigen::AngleAxisd axis_angle(turn);
  EXPECT_NEAR(axis_angle.angle(), 1.0, 1e-12);
  EXPECT_NEAR(std::abs(axis_angle.axis().z()), 1.0, 1e-12);
  EXPECT_NEAR((turn * turn.transpose() - core::Mat3::Identity()).norm(), 0.0, 1e-12);
}

TEST(ToolGeometryTest, TheTargetProjectsToTheCentreOfTheView) {
  core::OrbitCamera camera;
  camera.target = core::Vec3(1, 2, 3);
  const auto pixel = ProjectToPixels(camera, 640, 480, camera.target);
  ASSERT_TRUE(pixel);
  EXPECT_NEAR(pixel->x(), 320.0, 1e-9);
  EXPECT_NEAR(pixel->y(), 240.0, 1e-9);
  EXPECT_FALSE(ProjectToPixels(camera, 640, 480, camera.Eye() + (camera.Eye() - camera.target)));
}

}  // namespace
}  // namespace lamina::ui
