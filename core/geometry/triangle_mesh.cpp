// SPDX-License-Identifier: MIT
#include "core/geometry/triangle_mesh.h"

namespace lamina::core {

Eigen::AlignedBox3d TriangleMesh::Bounds() const {
  Eigen::AlignedBox3d box;
  for (const Vec3& v : vertices) box.extend(v);
  return box;
}

Eigen::AlignedBox3d TriangleMesh::Bounds(const Affine& matrix) const {
  Eigen::AlignedBox3d box;
  for (const Vec3& v : vertices) box.extend(matrix * v);
  return box;
}

}  // namespace lamina::core
