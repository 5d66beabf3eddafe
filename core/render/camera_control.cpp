// SPDX-License-Identifier: MIT
// Orbit, pan and zoom from mouse deltas.
#include "core/render/camera_control.h"

#include <algorithm>
#include <cmath>

#include "core/math_types.h"

namespace lamina::core {

namespace {

constexpr double kMaxPitch = 89.0;
constexpr double kMinDistance = 1e-3;

OrbitCamera Orbit(OrbitCamera camera, double dx, double dy) {
  camera.yaw = std::remainder(camera.yaw - kOrbitDegreesPerPixel * dx, 360.0);
  camera.pitch = std::clamp(camera.pitch + kOrbitDegreesPerPixel * dy, -kMaxPitch, kMaxPitch);
  return camera;
}

OrbitCamera Pan(OrbitCamera camera, double dx, double dy, int viewport_height) {
  const double height = std::max(viewport_height, 1);
  // world metres per pixel at the target's depth
  const double scale = 2.0 * camera.distance * std::tan(0.5 * camera.fov_y * kPi / 180.0) / height;
  const Eigen::Matrix4d view = camera.ViewMatrix();
  const Eigen::Vector3d right = view.block<1, 3>(0, 0).transpose();
  const Eigen::Vector3d up = view.block<1, 3>(1, 0).transpose();
  camera.target += scale * (-dx * right + dy * up);
  return camera;
}

OrbitCamera Zoom(OrbitCamera camera, double factor) {
  camera.distance = std::max(camera.distance * factor, kMinDistance);
  return camera;
}

}  // namespace

CameraMotion MotionForDrag(const MouseDrag& drag) {
  switch (drag.button) {
    case MouseButton::kLeft:
      if (drag.shift || drag.control) return CameraMotion::kPan;
      if (drag.alt) return CameraMotion::kZoom;
      return CameraMotion::kOrbit;
    case MouseButton::kRight:
      return CameraMotion::kPan;
    case MouseButton::kMiddle:
      return CameraMotion::kZoom;
    case MouseButton::kNone:
      break;
  }
  return CameraMotion::kNone;
}

OrbitCamera ApplyMouseDrag(const OrbitCamera& camera, const MouseDrag& drag, int viewport_height) {
  switch (MotionForDrag(drag)) {
    case CameraMotion::kOrbit:
      return Orbit(camera, drag.dx, drag.dy);
    case CameraMotion::kPan:
      return Pan(camera, drag.dx, drag.dy, viewport_height);
    case CameraMotion::kZoom:
      return Zoom(camera, std::exp(kZoomPerPixel * drag.dy));
    case CameraMotion::kNone:
      break;
  }
  return camera;
}

OrbitCamera ApplyScroll(const OrbitCamera& camera, double notches) {
  return Zoom(camera, std::pow(kZoomPerScrollNotch, notches));
}

}  // namespace lamina::core
