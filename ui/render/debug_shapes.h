// SPDX-License-Identifier: MIT
// Unit shapes for the debug overlays (sphere for points, cylinder + cone for arrows) and the
// transforms that place them.
#pragma once

#include <memory>

#include <Eigen/Core>

#include "core/render/render_mesh.h"
#include "core/render/render_scene.h"

namespace lamina::ui {

struct DebugShapes {
  std::shared_ptr<const core::RenderMesh> sphere;    ///< radius 1 about the origin
  std::shared_ptr<const core::RenderMesh> cylinder;  ///< radius 1, z from 0 to 1
  std::shared_ptr<const core::RenderMesh> cone;      ///< base radius 1 at z = 0, apex at z = 1
};

DebugShapes BuildDebugShapes();

/// Places the unit sphere for `point`.
Eigen::Matrix4f PointTransform(const core::DebugPoint& point);

/// Places the unit cylinder (shaft) and unit cone (head) for `arrow`. The head is at most
/// 40 % of the arrow and about six shaft radii long.
void ArrowTransforms(const core::DebugArrow& arrow, Eigen::Matrix4f* shaft, Eigen::Matrix4f* head);

}  // namespace lamina::ui
