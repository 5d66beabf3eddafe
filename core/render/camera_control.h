// SPDX-License-Identifier: MIT
// Mouse control of the orbit camera as pure functions of button, modifiers and pixel deltas, so
// that any window (GLFW today) can feed them. Conventions of MuJoCo's simulate and Klamp't:
// left drag orbits, right drag (or Shift/Ctrl + left) pans, middle drag (or Alt + left) and the
// scroll wheel zoom.
#pragma once

#include "core/render/camera.h"

namespace lamina::core {

enum class MouseButton { kNone, kLeft, kRight, kMiddle };

struct MouseDrag {
  MouseButton button = MouseButton::kNone;
  bool shift = false;
  bool control = false;
  bool alt = false;
  double dx = 0.0;  ///< pixels moved right since the last event
  double dy = 0.0;  ///< pixels moved down since the last event
};

enum class CameraMotion { kNone, kOrbit, kPan, kZoom };

/// Degrees of orbit per pixel of drag.
inline constexpr double kOrbitDegreesPerPixel = 0.3;
/// Relative zoom per pixel of vertical drag (distance *= exp(kZoomPerPixel * dy)).
inline constexpr double kZoomPerPixel = 0.005;
/// Distance factor per scroll notch (scrolling up brings the camera closer).
inline constexpr double kZoomPerScrollNotch = 0.9;

/// Which motion a drag with these buttons and modifiers performs.
CameraMotion MotionForDrag(const MouseDrag& drag);

/// The camera after `drag` in a viewport `viewport_height` pixels high. Orbit turns yaw and pitch
/// (pitch clamped to +-89°); pan moves the target in the view plane so the point under the mouse
/// follows it; zoom scales the distance.
OrbitCamera ApplyMouseDrag(const OrbitCamera& camera, const MouseDrag& drag, int viewport_height);

/// The camera after `notches` of scroll (positive = away from the user = closer).
OrbitCamera ApplyScroll(const OrbitCamera& camera, double notches);

}  // namespace lamina::core
