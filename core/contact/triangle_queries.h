// SPDX-License-Identifier: MIT
// Exact geometric queries on single triangles used by the mesh contact routines: the closest
// point of a triangle to a point, the crossing of two triangles, and the distance between a
// triangle and a convex shape given by its support mapping (GJK). Internal to core/contact.
#pragma once

#include <array>

#include "core/math_types.h"

namespace lamina::core::mesh_detail {

using Triangle3 = std::array<Vec3, 3>;

/// A point of a triangle and its barycentric coordinates (weights of corners 0, 1, 2).
struct TrianglePoint {
  Vec3 point = Vec3::Zero();
  Vec3 barycentric = Vec3(1.0, 0.0, 0.0);
};

/// The point of `triangle` closest to `p` (degenerate triangles included).
TrianglePoint ClosestPointOnTriangle(const Vec3& p, const Triangle3& triangle);

/// Barycentric coordinates of `p` (assumed on the triangle) in `triangle`; (1, 0, 0) for a
/// degenerate triangle.
Vec3 BarycentricCoordinates(const Vec3& p, const Triangle3& triangle);

/// BarycentricCoordinates for many points of one triangle: the triangle's part is computed
/// once. Gives bitwise the same coordinates.
class BarycentricMap {
 public:
  explicit BarycentricMap(const Triangle3& triangle);
  Vec3 operator()(const Vec3& p) const;

 private:
  Vec3 origin_, e0_, e1_;
  double d00_, d01_, d11_, denominator_;
  bool degenerate_;
};

/// Closest points of two triangles: the nearest of the vertex-triangle and edge-edge pairs
/// (exact for triangles that do not cross).
struct TrianglePairPoints {
  double distance = 0.0;
  Vec3 on_a = Vec3::Zero();
  Vec3 on_b = Vec3::Zero();
};
TrianglePairPoints ClosestPointsOfTriangles(const Triangle3& a, const Triangle3& b);

/// If the two triangles properly cross (each passes through the other's plane and the
/// crossings overlap by more than a rounding error; touching and coplanar triangles do not
/// count), sets `midpoint` to the middle of the intersection segment and returns true.
bool TrianglesCross(const Triangle3& a, const Triangle3& b, Vec3* midpoint);

/// A convex shape by its support mapping, placed by `pose` (shape frame -> query frame): a
/// box (`half_extents`), a segment along z (`half_length`) or a cylinder about z (`radius`,
/// `half_length`).
struct SupportShape {
  enum class Type { kBox, kSegment, kCylinder };
  Type type = Type::kBox;
  Pose pose = Pose::Identity();
  Vec3 half_extents = Vec3::Zero();
  double radius = 0.0;
  double half_length = 0.0;

  /// A point of the shape farthest along `direction` (query frame).
  Vec3 Support(const Vec3& direction) const;
};

/// The point of a shape's surface nearest to a point, the signed distance to it (negative
/// inside) and the shape's outward unit normal there (from the surface toward an outside
/// point; zero when the point is on a segment).
struct SurfacePoint {
  double distance = 0.0;
  Vec3 point = Vec3::Zero();
  Vec3 normal = Vec3::Zero();
};
SurfacePoint ClosestSurfacePoint(const SupportShape& shape, const Vec3& p);

/// Result of TriangleShapeDistance. When `intersecting`, the other fields are unset.
struct TriangleShapeDistanceResult {
  bool intersecting = false;
  double distance = 0.0;
  TrianglePoint on_triangle;
  Vec3 on_shape = Vec3::Zero();
};

/// Distance and closest points between a triangle and a convex shape (GJK; exact up to
/// rounding for boxes and segments, to about 1e-6 of the distance for cylinders).
TriangleShapeDistanceResult TriangleShapeDistance(const Triangle3& triangle,
                                                  const SupportShape& shape);

}  // namespace lamina::core::mesh_detail
