// SPDX-License-Identifier: MIT
// Picking: the ray from the camera through a pixel, and the body of a RenderScene that ray hits
// first (ray against the transformed triangles of every draw item, Möller–Trumbore). Pure
// functions, no GL: the viewer highlights and selects with them.
#pragma once

#include <Eigen/Core>

#include "core/render/camera.h"
#include "core/render/render_scene.h"

namespace lamina::core {

struct Ray {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();  ///< unit
};

/// The ray from the eye through point (`x`, `y`) of a `width` x `height` viewport, in pixels
/// from the top-left corner as windows report the mouse (the centre of pixel i is i + 0.5).
Ray PixelRay(const OrbitCamera& camera, int width, int height, double x, double y);

struct PickHit {
  int world_id = -1;      ///< Klamp't world id of the body hit; -1 when nothing was hit
  double distance = 0.0;  ///< along the ray, m
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  ///< world
  bool hit() const { return world_id >= 0; }
};

/// Which items a pick may return.
struct PickFilter {
  bool terrains = true;      ///< items flagged kDrawTerrain
  bool translucent = false;  ///< kDrawTranslucent items (padding shells)
};

/// The nearest item of `scene` with a world id that `ray` hits (debug geometry, items without
/// an id and, by default, translucent layers are ignored).
PickHit PickBody(const RenderScene& scene, const Ray& ray, const PickFilter& filter = {});

/// Distance along the ray to triangle (a, b, c), either side; negative when missed.
double RayTriangleDistance(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                           const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                           const Eigen::Vector3d& c);

}  // namespace lamina::core
