// SPDX-License-Identifier: MIT
// Ray casting: the ray is taken into the frame of the shape (rigid maps keep the ray parameter a
// distance). A primitive gives the span of the line inside it (a convex solid: one interval,
// found by intersecting slabs and balls); a mesh is culled by its bounds, then every triangle is
// tested. (MeshBvh is opaque outside collision_geometry.cpp, hence no hierarchy here.)
#include "core/contact/ray_cast.h"

#include <algorithm>
#include <cmath>

namespace lamina::core {

namespace {

// Slack of the barycentric tests (relative): a ray through an edge shared by two triangles hits
// at least one of them despite rounding.
constexpr double kEdgeSlack = 1e-12;
// How far the mesh bounds are grown before the cull (m): beyond any rounding of a hit there.
constexpr double kRayBoundsSlack = 1e-9;

// A ray in some frame; `direction` is unit.
struct LocalRay {
  Vec3 origin;
  Vec3 direction;
};

// The world ray in frame F, given F's pose X_WF in the world.
LocalRay InFrame(const Pose& X_WF, const Vec3& origin_W, const Vec3& direction_W) {
  const Mat3 R_FW = X_WF.linear().transpose();
  return {R_FW * (origin_W - X_WF.translation()), R_FW * direction_W};
}

// The parameters [enter, exit] of the points of the whole line origin + t direction (t of
// either sign) inside a convex solid; empty when enter > exit.
struct Span {
  double enter = -kInf;
  double exit = kInf;
  bool empty() const { return !(enter <= exit); }
};

constexpr Span kEmptySpan{kInf, -kInf};

Span Intersect(const Span& a, const Span& b) {
  return {std::max(a.enter, b.enter), std::min(a.exit, b.exit)};
}

// The span of the union of two solids whose union is convex.
Span Hull(const Span& a, const Span& b) {
  if (a.empty()) return b;
  if (b.empty()) return a;
  return {std::min(a.enter, b.enter), std::max(a.exit, b.exit)};
}

// The slab lo <= origin + t direction <= hi of one coordinate.
Span Slab(double origin, double direction, double lo, double hi) {
  if (direction == 0.0) return origin >= lo && origin <= hi ? Span{} : kEmptySpan;
  const double t0 = (lo - origin) / direction;
  const double t1 = (hi - origin) / direction;
  return {std::min(t0, t1), std::max(t0, t1)};
}

// The ball |origin + t direction| <= radius about the frame origin: a sphere in 3-D, an infinite
// cylinder in 2-D. Solved about the point of the line nearest the centre, which keeps far rays
// accurate (no difference of large squares).
template <typename Vector>
Span Ball(const Vector& origin, const Vector& direction, double radius) {
  const double a = direction.squaredNorm();
  if (a == 0.0) return origin.norm() <= radius ? Span{} : kEmptySpan;
  const double nearest = -origin.dot(direction) / a;
  const double miss = (origin + nearest * direction).squaredNorm();
  if (miss > radius * radius) return kEmptySpan;
  const double half = std::sqrt((radius * radius - miss) / a);
  return {nearest - half, nearest + half};
}

Span BoxSpan(const Vec3& size, const LocalRay& ray) {
  Span span;
  for (int i = 0; i < 3; ++i) {
    const double half = 0.5 * size[i];
    span = Intersect(span, Slab(ray.origin[i], ray.direction[i], -half, half));
  }
  return span;
}

Span CylinderSpan(double radius, double length, const LocalRay& ray) {
  const Eigen::Vector2d origin = ray.origin.head<2>();
  const Eigen::Vector2d direction = ray.direction.head<2>();
  const Span side = Ball(origin, direction, radius);
  return Intersect(side, Slab(ray.origin.z(), ray.direction.z(), -0.5 * length, 0.5 * length));
}

// The cylinder and the two end balls: convex pieces whose union is the (convex) capsule.
Span CapsuleSpan(double radius, double length, const LocalRay& ray) {
  const Vec3 end(0.0, 0.0, 0.5 * length);
  const Span caps = Hull(Ball(Vec3(ray.origin - end), ray.direction, radius),
                         Ball(Vec3(ray.origin + end), ray.direction, radius));
  return Hull(CylinderSpan(radius, length, ray), caps);
}

// The span of the ray's line inside `primitive`; the ray in the primitive's own frame.
Span PrimitiveSpan(const Primitive& primitive, const LocalRay& ray) {
  switch (primitive.type) {
    case PrimitiveType::kSphere:
      return Ball(ray.origin, ray.direction, primitive.radius);
    case PrimitiveType::kBox:
      return BoxSpan(primitive.size, ray);
    case PrimitiveType::kCylinder:
      return CylinderSpan(primitive.radius, primitive.length, ray);
    case PrimitiveType::kCapsule:
      return CapsuleSpan(primitive.radius, primitive.length, ray);
    case PrimitiveType::kPlane:
      return Slab(ray.origin.z(), ray.direction.z(), -kInf, 0.0);
  }
  return kEmptySpan;
}

// The first t >= 0 of `span` if it is at most max_distance (0 when the ray starts inside).
double FirstEntry(const Span& span, double max_distance) {
  if (span.empty() || span.exit < 0.0) return kInf;
  const double t = std::max(span.enter, 0.0);
  return t <= max_distance ? t : kInf;
}

bool InsideTriangle(double u, double v) {
  return u >= -kEdgeSlack && v >= -kEdgeSlack && u + v <= 1.0 + kEdgeSlack;
}

// Distance along the ray to triangle (a, b, c) from either side (Möller–Trumbore); +infinity
// when missed, behind the origin or parallel to the triangle.
double TriangleDistance(const LocalRay& ray, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 e1 = b - a;
  const Vec3 e2 = c - a;
  const Vec3 p = ray.direction.cross(e2);
  const double det = e1.dot(p);
  if (det == 0.0 || !std::isfinite(det)) return kInf;
  const Vec3 s = ray.origin - a;
  const Vec3 q = s.cross(e1);
  if (!InsideTriangle(s.dot(p) / det, ray.direction.dot(q) / det)) return kInf;
  const double t = e2.dot(q) / det;
  return t >= 0.0 ? t : kInf;
}

// True when the ray meets the (slightly grown) bounds within [0, max_distance].
bool CrossesBounds(const Eigen::AlignedBox3d& bounds, const LocalRay& ray, double max_distance) {
  if (bounds.isEmpty()) return false;
  Span span{0.0, max_distance};
  for (int i = 0; i < 3; ++i) {
    span = Intersect(span, Slab(ray.origin[i], ray.direction[i], bounds.min()[i] - kRayBoundsSlack,
                                bounds.max()[i] + kRayBoundsSlack));
  }
  return !span.empty();
}

// The ray in the body frame.
double MeshRayCast(const CollisionGeometry& geometry, const LocalRay& ray, double max_distance) {
  if (!CrossesBounds(geometry.local_bounds(), ray, max_distance)) return kInf;
  const TriangleMesh& mesh = geometry.mesh();
  double nearest = kInf;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    const double distance =
        TriangleDistance(ray, mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
    nearest = std::min(nearest, distance);
  }
  return nearest <= max_distance ? nearest : kInf;
}

}  // namespace

double RayCast(const CollisionGeometry& geometry, const Pose& X_W, const Vec3& origin,
               const Vec3& direction, double max_distance) {
  const double length = direction.norm();
  if (!(length > 0.0) || !std::isfinite(length) || !(max_distance >= 0.0)) return kInf;
  const Vec3 unit = direction / length;
  if (geometry.kind() == CollisionGeometry::Kind::kPointCloud) return kInf;  // no surface
  if (geometry.kind() == CollisionGeometry::Kind::kMesh) {
    return MeshRayCast(geometry, InFrame(X_W, origin, unit), max_distance);
  }
  const Primitive& primitive = geometry.primitive();
  return FirstEntry(PrimitiveSpan(primitive, InFrame(X_W * primitive.pose, origin, unit)),
                    max_distance);
}

}  // namespace lamina::core
