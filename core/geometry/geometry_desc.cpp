// SPDX-License-Identifier: MIT
#include "core/geometry/geometry_desc.h"

#include "core/geometry/tessellate.h"

namespace lamina::core {

int GeometryDesc::triangle_count() const {
  return (kind == GeometryKind::kMesh && mesh) ? mesh->triangle_count() : 0;
}

int GeometryDesc::point_count() const {
  return (kind == GeometryKind::kPointCloud && point_cloud) ? point_cloud->point_count() : 0;
}

TriangleMesh BakedMesh(const GeometryDesc& geometry) {
  TriangleMesh out;
  switch (geometry.kind) {
    case GeometryKind::kNone:
    case GeometryKind::kPointCloud:
      return out;
    case GeometryKind::kMesh:
      if (geometry.mesh) out = *geometry.mesh;
      break;
    case GeometryKind::kPrimitive:
      out = Tessellate(geometry.primitive);
      break;
  }
  const Affine matrix = geometry.Matrix();
  for (Vec3& v : out.vertices) v = matrix * v;
  if (matrix.linear().determinant() < 0) {
    // a mirroring map turns the winding inside out; restore outward orientation
    for (Eigen::Vector3i& t : out.triangles) std::swap(t[1], t[2]);
  }
  return out;
}

std::vector<Vec3> BakedPoints(const GeometryDesc& geometry) {
  if (geometry.kind != GeometryKind::kPointCloud || !geometry.point_cloud) return {};
  return TransformedPoints(*geometry.point_cloud, geometry.Matrix());
}

}  // namespace lamina::core
