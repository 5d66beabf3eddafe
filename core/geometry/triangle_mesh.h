// SPDX-License-Identifier: MIT
// An indexed triangle mesh in the coordinates of the file it came from.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/math_types.h"

namespace lamina::core {

struct TriangleMesh {
  std::vector<Vec3> vertices;
  std::vector<Eigen::Vector3i> triangles;  ///< counter-clockwise seen from outside

  int triangle_count() const { return static_cast<int>(triangles.size()); }
  int vertex_count() const { return static_cast<int>(vertices.size()); }
  /// Axis-aligned bounds; min > max when empty.
  Eigen::AlignedBox3d Bounds() const;
  /// Bounds of the mesh mapped through `matrix`.
  Eigen::AlignedBox3d Bounds(const Affine& matrix) const;
};

}  // namespace lamina::core
