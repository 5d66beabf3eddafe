// SPDX-License-Identifier: MIT
#include "core/geometry/point_cloud.h"

namespace lamina::core {

Eigen::AlignedBox3d PointCloud::Bounds() const {
  Eigen::AlignedBox3d bounds;
  for (const Vec3& p : points) bounds.extend(p);
  return bounds;
}

std::vector<Vec3> TransformedPoints(const PointCloud& cloud, const Affine& matrix) {
  std::vector<Vec3> out;
  out.reserve(cloud.points.size());
  for (const Vec3& p : cloud.points) out.push_back(matrix * p);
  return out;
}

}  // namespace lamina::core
