// SPDX-License-Identifier: MIT
// RenderMesh: a triangle mesh prepared for drawing — unwelded corners with float positions and
// normals (smooth across gentle edges, sharp across creases), ready to upload as-is.
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/geometry/triangle_mesh.h"

namespace lamina::core {

struct RenderMesh {
  /// Three corners per triangle, counter-clockwise seen from outside.
  std::vector<Eigen::Vector3f> positions;
  /// Unit normal of each corner.
  std::vector<Eigen::Vector3f> normals;
  /// Bounds of the positions (empty box when there are no triangles); for one colour group of a
  /// point cloud, of the whole cloud (RenderMeshCache::ColoredShapes), so boxes show the body.
  Eigen::AlignedBox3f bounds;
  /// Unique per built mesh in this process: renderers key their GPU copies on it.
  std::uint64_t serial = 0;

  int corner_count() const { return static_cast<int>(positions.size()); }
  bool empty() const { return positions.empty(); }
};

/// Edges whose faces meet at more than this angle stay sharp (radians).
inline constexpr double kDefaultCreaseAngle = 0.6;  // about 34 degrees

/// Builds the corners of `mesh` with normals averaged over the faces around each vertex that
/// lie within `crease_angle` of the corner's own face (area weighted).
RenderMesh BuildRenderMesh(const TriangleMesh& mesh, double crease_angle = kDefaultCreaseAngle);

/// `mesh` with every vertex moved `distance` along its area-weighted vertex normal (an
/// approximate offset surface: exact for smooth convex shapes, slightly thinner at sharp edges).
TriangleMesh OffsetMesh(const TriangleMesh& mesh, double distance);

/// A fresh serial number for a RenderMesh built by hand.
std::uint64_t NextRenderMeshSerial();

}  // namespace lamina::core
