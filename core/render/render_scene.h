// SPDX-License-Identifier: MIT
// RenderScene: what one frame shows, independent of any graphics API — meshes with transforms,
// colours and flags, plus debug points, lines and arrows in world coordinates. The core extracts
// it from a world (scene_extract.h); a renderer draws it.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/render/display_color.h"
#include "core/render/render_mesh.h"

namespace lamina::core {

enum DrawFlags : std::uint32_t {
  kDrawNone = 0,
  kDrawTerrain = 1u << 0,      ///< ground: drawn with a world-space checker
  kDrawSelected = 1u << 1,     ///< the highlighted body
  kDrawTranslucent = 1u << 2,  ///< blended after the opaque items, casts no shadow
  kDrawUnlit = 1u << 3,        ///< flat colour (debug geometry)
};

struct DrawItem {
  std::shared_ptr<const RenderMesh> mesh;
  /// Mesh coordinates -> world (may scale, shear or mirror).
  Eigen::Matrix4f transform = Eigen::Matrix4f::Identity();
  Rgba color = Rgba(1.0f, 1.0f, 1.0f, 1.0f);
  std::uint32_t flags = kDrawNone;
  int world_id = -1;  ///< Klamp't world id of the body drawn, -1 for none

  bool has(DrawFlags flag) const { return (flags & flag) != 0; }
};

struct DebugPoint {
  Eigen::Vector3f position;
  float radius = 0.005f;  ///< m
  Rgba color;
};

struct DebugLine {
  Eigen::Vector3f from;
  Eigen::Vector3f to;
  Rgba color;
};

struct DebugArrow {
  Eigen::Vector3f from;
  Eigen::Vector3f to;     ///< the tip
  float radius = 0.003f;  ///< shaft radius, m
  Rgba color;
};

struct RenderScene {
  std::vector<DrawItem> items;
  std::vector<DebugPoint> points;
  std::vector<DebugLine> lines;
  std::vector<DebugArrow> arrows;
  /// Bounds of every finite body (infinite planes excluded); empty for an empty world.
  Eigen::AlignedBox3d bounds;
  /// Bounds of the rigid objects and robots only (what moves); empty when there are none.
  Eigen::AlignedBox3d body_bounds;
};

}  // namespace lamina::core
