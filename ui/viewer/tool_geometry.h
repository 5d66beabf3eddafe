// SPDX-License-Identifier: MIT
// The geometry of the mouse tools, pure (no GL, no ImGui): where the cursor's ray meets the
// plane a drag moves in, axis locks, turning a body with the mouse, and projecting a world point
// to pixels for the tools' overlays. Units: metres, radians, framebuffer pixels from the
// top-left corner.
#pragma once

#include <optional>

#include "core/math_types.h"
#include "core/render/camera.h"
#include "core/render/picking.h"

namespace lamina::ui {

/// Where `ray` meets the plane through `point` with `normal`; nullopt when it is parallel to the
/// plane or meets it behind the eye.
std::optional<core::Vec3> RayPlane(const core::Ray& ray, const core::Vec3& point,
                                   const core::Vec3& normal);

/// The normal of the plane a drag moves in: facing the camera (MuJoCo's default), or vertical
/// (+z) for a drag in the horizontal plane.
core::Vec3 DragPlaneNormal(const core::OrbitCamera& camera, bool horizontal);

/// `moved` projected onto the line through `start` along world axis `axis` (0 x, 1 y, 2 z).
core::Vec3 LockToAxis(const core::Vec3& start, const core::Vec3& moved, int axis);

/// The turn a mouse motion of (`dx`, `dy`) pixels asks for: about the camera's up axis by dx and
/// its right axis by dy, `radians_per_pixel` each (MuJoCo's rotate perturbation).
core::Mat3 TurnFromMouse(const core::OrbitCamera& camera, double dx, double dy,
                         double radians_per_pixel);

/// Pixel position of world point `p` in a `width` x `height` view; nullopt behind the eye.
std::optional<core::Vec3> ProjectToPixels(const core::OrbitCamera& camera, int width, int height,
                                          const core::Vec3& p);

}  // namespace lamina::ui
