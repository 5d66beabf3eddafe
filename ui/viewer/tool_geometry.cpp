// SPDX-License-Identifier: MIT
#include "ui/viewer/tool_geometry.h"

#include <cmath>

namespace lamina::ui {

std::optional<core::Vec3> RayPlane(const core::Ray& ray, const core::Vec3& point,
                                   const core::Vec3& normal) {
  const double facing = ray.direction.dot(normal);
  if (std::abs(facing) < 1e-9) return std::nullopt;
  const double distance = (point - ray.origin).dot(normal) / facing;
  if (!(distance > 0.0)) return std::nullopt;
  return core::Vec3(ray.origin + distance * ray.direction);
}

core::Vec3 DragPlaneNormal(const core::OrbitCamera& camera, bool horizontal) {
  if (horizontal) return core::Vec3::UnitZ();
  return (camera.target - camera.Eye()).normalized();
}

core::Vec3 LockToAxis(const core::Vec3& start, const core::Vec3& moved, int axis) {
  core::Vec3 locked = start;
  locked[axis] = moved[axis];
  return locked;
}

core::Mat3 TurnFromMouse(const core::OrbitCamera& camera, double dx, double dy,
                         double radians_per_pixel) {
  const core::Vec3 forward = (camera.target - camera.Eye()).normalized();
  core::Vec3 right = forward.cross(core::Vec3::UnitZ());
  if (right.norm() < 1e-9) right = core::Vec3::UnitX();  // looking straight down or up
  right.normalize();
  const core::Vec3 up = right.cross(forward);
  return (Eigen::AngleAxisd(dx * radians_per_pixel, up) *
          Eigen::AngleAxisd(dy * radians_per_pixel, right))
      .toRotationMatrix();
}

std::optional<core::Vec3> ProjectToPixels(const core::OrbitCamera& camera, int width, int height,
                                          const core::Vec3& p) {
  const Eigen::Vector4d clip = camera.ProjectionMatrix(static_cast<double>(width) / height, 1.0) *
                               camera.ViewMatrix() * p.homogeneous();
  if (!(clip.w() > 1e-9)) return std::nullopt;
  const double x = (clip.x() / clip.w() * 0.5 + 0.5) * width;
  const double y = (0.5 - clip.y() / clip.w() * 0.5) * height;
  return core::Vec3(x, y, clip.w());
}

}  // namespace lamina::ui
