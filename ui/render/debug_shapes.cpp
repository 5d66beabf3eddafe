// SPDX-License-Identifier: MIT
// Unit debug shapes and their placement.
#include "ui/render/debug_shapes.h"

#include <algorithm>
#include <cmath>

#include "core/geometry/tessellate.h"

namespace lamina::ui {

namespace {

constexpr int kSegments = 16;

core::TriangleMesh Cone(int segments) {
  core::TriangleMesh cone;
  cone.vertices.emplace_back(0.0, 0.0, 1.0);  // apex
  cone.vertices.emplace_back(0.0, 0.0, 0.0);  // base centre
  for (int i = 0; i < segments; ++i) {
    const double phi = 2.0 * core::kPi * i / segments;
    cone.vertices.emplace_back(std::cos(phi), std::sin(phi), 0.0);
  }
  for (int i = 0; i < segments; ++i) {
    const int a = 2 + i, b = 2 + (i + 1) % segments;
    cone.triangles.emplace_back(0, a, b);
    cone.triangles.emplace_back(1, b, a);
  }
  return cone;
}

// a frame whose z axis is `direction` (unit)
Eigen::Matrix3f FrameAlong(const Eigen::Vector3f& direction) {
  const Eigen::Vector3f helper =
      std::abs(direction.z()) < 0.9f ? Eigen::Vector3f::UnitZ() : Eigen::Vector3f::UnitX();
  const Eigen::Vector3f x = helper.cross(direction).normalized();
  Eigen::Matrix3f frame;
  frame << x, direction.cross(x), direction;
  return frame;
}

Eigen::Matrix4f Placement(const Eigen::Matrix3f& frame, const Eigen::Vector3f& scale,
                          const Eigen::Vector3f& origin) {
  Eigen::Matrix4f m = Eigen::Matrix4f::Identity();
  m.topLeftCorner<3, 3>() = frame * scale.asDiagonal();
  m.topRightCorner<3, 1>() = origin;
  return m;
}

std::shared_ptr<const core::RenderMesh> Share(const core::TriangleMesh& mesh) {
  return std::make_shared<const core::RenderMesh>(core::BuildRenderMesh(mesh));
}

}  // namespace

DebugShapes BuildDebugShapes() {
  DebugShapes shapes;
  shapes.sphere = Share(core::Tessellate(core::Primitive::Sphere(1.0), kSegments));
  core::Pose half_up = core::Pose::Identity();
  half_up.translation() = core::Vec3(0.0, 0.0, 0.5);
  shapes.cylinder =
      Share(core::Tessellate(core::Primitive::Cylinder(1.0, 1.0, half_up), kSegments));
  shapes.cone = Share(Cone(kSegments));
  return shapes;
}

Eigen::Matrix4f PointTransform(const core::DebugPoint& point) {
  return Placement(Eigen::Matrix3f::Identity(), Eigen::Vector3f::Constant(point.radius),
                   point.position);
}

void ArrowTransforms(const core::DebugArrow& arrow, Eigen::Matrix4f* shaft, Eigen::Matrix4f* head) {
  const Eigen::Vector3f along = arrow.to - arrow.from;
  const float length = along.norm();
  const Eigen::Matrix3f frame = FrameAlong(along / length);
  const float head_length = std::min(0.4f * length, 6.0f * arrow.radius);
  const float head_radius = 2.2f * arrow.radius;
  *shaft = Placement(frame, Eigen::Vector3f(arrow.radius, arrow.radius, length - head_length),
                     arrow.from);
  *head = Placement(frame, Eigen::Vector3f(head_radius, head_radius, head_length),
                    arrow.to - head_length * (along / length));
}

}  // namespace lamina::ui
