// SPDX-License-Identifier: MIT
// Point queries and feature spans of placed primitives (see primitive_queries.h). Every query
// works in the shape's own frame and maps its answer back to the world.
#include "core/contact/primitive_queries.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>

namespace lamina::core::primitive_detail {
namespace {

// A point within this distance outside a box or cylinder counts as on its surface when choosing
// the face it leaves through (m): far above rounding at robot scales, far below any layer.
constexpr double kOnSurface = 1e-9;

/// Ball around the local point `centre` (a sphere, or the nearest point of a capsule axis).
SurfacePoint QueryBall(const Vec3& centre, double radius, const Vec3& p) {
  const Vec3 offset = p - centre;
  const double length = offset.norm();
  SurfacePoint result;
  // a point at the centre has no direction: any normal is as good, take local +x
  result.normal = length > 0.0 ? Vec3(offset / length) : Vec3::UnitX();
  result.distance = length - radius;
  result.point = centre + radius * result.normal;
  return result;
}

/// A face (or the side) a point could leave through: its outward normal and the point's signed
/// distance to it (negative inside).
struct ExitFace {
  Vec3 normal = Vec3::UnitZ();
  double excess = -kInf;
};

/// Index of the face of largest excess (the least penetration) among those whose normal opposes
/// `outward`, the direction the querying surface faces at the point; among all faces when none
/// does (outward zero or unknown). The first wins ties. Preferring opposed faces keeps a corner
/// or rim sunk into a face from being pushed out sideways through a nearer side face.
template <std::size_t kCount>
int PickExitFace(const std::array<ExitFace, kCount>& faces, const Vec3& outward) {
  int best = -1;
  for (int pass = 0; pass < 2 && best < 0; ++pass) {
    for (int i = 0; i < static_cast<int>(kCount); ++i) {
      if (pass == 0 && !(faces[i].normal.dot(outward) < 0.0)) continue;
      if (best < 0 || faces[i].excess > faces[best].excess) best = i;
    }
  }
  return best;
}

SurfacePoint QueryBox(const Vec3& half, const Vec3& p, const Vec3& outward) {
  SurfacePoint result;
  const Vec3 excess = p.cwiseAbs() - half;
  const Vec3 clamped = p.cwiseMax(-half).cwiseMin(half);
  const double outside_length = (p - clamped).norm();
  int outside_axes = 0;
  int axis = 0;
  for (int i = 0; i < 3; ++i) {
    outside_axes += excess[i] > kOnSurface ? 1 : 0;
    axis = excess[i] > excess[axis] ? i : axis;
  }
  if (outside_axes > 1) {
    // beyond an edge or a corner
    result.distance = outside_length;
    result.point = clamped;
    result.normal = (p - clamped) / outside_length;
    result.feature = SurfaceFeature::kPoint;
    return result;
  }
  result.feature = SurfaceFeature::kFlat;
  result.face_axis = axis;
  if (outside_axes == 1) {
    // beyond one face (counting a point within kOnSurface of its prism as in it)
    result.distance = excess[axis];
    result.normal = SignOf(p[axis]) * Vec3::Unit(axis);
    result.point = clamped;
    result.point[axis] = SignOf(p[axis]) * half[axis];
    return result;
  }
  // inside or on the surface: each axis's nearer face, then its farther one, preferring faces
  // that oppose the querying surface
  std::array<ExitFace, 6> faces;
  for (int i = 0; i < 3; ++i) {
    const double near_side = SignOf(p[i]);
    faces[2 * i] = {near_side * Vec3::Unit(i), std::abs(p[i]) - half[i]};
    faces[2 * i + 1] = {-near_side * Vec3::Unit(i), -std::abs(p[i]) - half[i]};
  }
  const int face = PickExitFace(faces, outward);
  result.face_axis = face / 2;
  result.distance = faces[face].excess;
  result.normal = faces[face].normal;
  result.point = p;
  result.point[result.face_axis] = result.normal[result.face_axis] * half[result.face_axis];
  return result;
}

SurfacePoint QueryCylinder(double radius, double half_length, const Vec3& p, const Vec3& outward) {
  const double rho = std::hypot(p.x(), p.y());
  // on the axis any radial direction will do: local +x
  const Vec3 radial = rho > 0.0 ? Vec3(p.x() / rho, p.y() / rho, 0.0) : Vec3::UnitX();
  const double near_cap = SignOf(p.z());
  const double side_excess = rho - radius;
  const double cap_excess = std::abs(p.z()) - half_length;
  const bool outside = std::max(side_excess, cap_excess) > kOnSurface;
  SurfacePoint result;
  if (side_excess > kOnSurface && cap_excess > kOnSurface) {
    // beyond the rim
    result.point = radius * radial + Vec3(0.0, 0.0, near_cap * half_length);
    result.distance = (p - result.point).norm();
    result.normal = (p - result.point) / result.distance;
    result.feature = SurfaceFeature::kPoint;
    return result;
  }
  // beside the side, beyond a cap, or inside (or on the surface, preferring faces that oppose
  // the querying surface): near cap, side, far cap, the side only when strictly nearer so that
  // a point on the rim circle belongs to the cap
  const std::array<ExitFace, 3> faces = {
      ExitFace{Vec3(0.0, 0.0, near_cap), cap_excess}, ExitFace{radial, side_excess},
      ExitFace{Vec3(0.0, 0.0, -near_cap), -std::abs(p.z()) - half_length}};
  const int face = PickExitFace(faces, outside ? Vec3::Zero() : outward);
  result.distance = faces[face].excess;
  result.normal = faces[face].normal;
  if (face == 1) {
    result.point = Vec3(radius * radial.x(), radius * radial.y(), p.z());
    result.feature = SurfaceFeature::kSide;
  } else {
    result.point = Vec3(p.x(), p.y(), result.normal.z() * half_length);
    result.feature = SurfaceFeature::kFlat;
  }
  return result;
}

SurfacePoint QueryCapsule(double radius, double half_length, const Vec3& p) {
  const double axis_z = std::clamp(p.z(), -half_length, half_length);
  SurfacePoint result = QueryBall(Vec3(0.0, 0.0, axis_z), radius, p);
  // a point within kOnSurface beyond an end still faces the side (as for the other shapes)
  result.feature =
      std::abs(p.z()) < half_length + kOnSurface ? SurfaceFeature::kSide : SurfaceFeature::kPoint;
  return result;
}

SurfacePoint QueryLocal(const Primitive& shape, const Vec3& p, const Vec3& outward) {
  switch (shape.type) {
    case PrimitiveType::kSphere:
      return QueryBall(Vec3::Zero(), shape.radius, p);
    case PrimitiveType::kBox:
      return QueryBox(0.5 * shape.size, p, outward);
    case PrimitiveType::kCylinder:
      return QueryCylinder(shape.radius, 0.5 * shape.length, p, outward);
    case PrimitiveType::kCapsule:
      return QueryCapsule(shape.radius, 0.5 * shape.length, p);
    case PrimitiveType::kPlane:
      break;
  }
  SurfacePoint result;
  result.distance = p.z();
  result.point = Vec3(p.x(), p.y(), 0.0);
  result.feature = SurfaceFeature::kFlat;
  return result;
}

/// Narrows [*t_begin, *t_end] to where |a + t (b - a)| <= half; false when that is empty.
bool ClipToSlab(double a, double b, double half, double* t_begin, double* t_end) {
  const double slope = b - a;
  if (slope == 0.0) return std::abs(a) <= half && *t_begin <= *t_end;
  double enter = (-half - a) / slope;
  double leave = (half - a) / slope;
  if (enter > leave) std::swap(enter, leave);
  *t_begin = std::max(*t_begin, enter);
  *t_end = std::min(*t_end, leave);
  return *t_begin <= *t_end;
}

/// Narrows [*t_begin, *t_end] to where the local xy distance from the axis is <= radius.
bool ClipToDisk(const Vec3& p0, const Vec3& p1, double radius, double* t_begin, double* t_end) {
  const Eigen::Vector2d start = p0.head<2>();
  const Eigen::Vector2d step = (p1 - p0).head<2>();
  // |start + t step|^2 <= radius^2, a quadratic in t
  const double a = step.squaredNorm();
  const double half_b = start.dot(step);
  const double c = start.squaredNorm() - radius * radius;
  if (a == 0.0) return c <= 0.0 && *t_begin <= *t_end;
  const double discriminant = half_b * half_b - a * c;
  if (discriminant < 0.0) return false;
  const double root = std::sqrt(discriminant);
  *t_begin = std::max(*t_begin, (-half_b - root) / a);
  *t_end = std::min(*t_end, (-half_b + root) / a);
  return *t_begin <= *t_end;
}

}  // namespace

Vec3 PlacedPrimitive::BoxCorner(int index) const {
  const Vec3 half = HalfSize();
  Vec3 corner = Vec3::Zero();
  for (int i = 0; i < 3; ++i) corner[i] = (index >> i & 1) != 0 ? half[i] : -half[i];
  return X_WS * corner;
}

void PlacedPrimitive::BoxEdge(int index, Vec3* start, Vec3* end) const {
  const Vec3 half = HalfSize();
  const int axis = index / 4;
  Vec3 corner = Vec3::Zero();
  for (int k = 1; k <= 2; ++k) {
    const int other = (axis + k) % 3;
    corner[other] = ((index % 4) >> (k - 1) & 1) != 0 ? half[other] : -half[other];
  }
  corner[axis] = -half[axis];
  *start = X_WS * corner;
  corner[axis] = half[axis];
  *end = X_WS * corner;
}

Vec3 EdgeOutward(const PlacedPrimitive& box, int index, const Vec3& p_W) {
  // the offset from the centre without its component along the edge
  const Vec3 offset = p_W - box.Center();
  const Vec3 along = box.Axis(index / 4);
  return offset - along.dot(offset) * along;
}

namespace {

/// QueryBox's distance alone (outward zero: the nearest face inside), for the minimiser.
double BoxDistance(const Vec3& half, const Vec3& p) {
  const Vec3 excess = p.cwiseAbs() - half;
  int outside_axes = 0;
  for (int i = 0; i < 3; ++i) outside_axes += excess[i] > kOnSurface ? 1 : 0;
  return outside_axes > 1 ? excess.cwiseMax(0.0).norm() : excess.maxCoeff();
}

/// Argument in [0, 1] of the least signed distance along p0 p1 to `shape`. A box is searched in
/// its own frame (the segment transformed once: the search's 66 distances are its cost).
double SegmentMinimum(const Vec3& p0_W, const Vec3& p1_W, const PlacedPrimitive& shape) {
  if (shape.shape->type == PrimitiveType::kBox) {
    const Vec3 p0 = shape.ToLocal(p0_W);
    const Vec3 p1 = shape.ToLocal(p1_W);
    const Vec3 half = 0.5 * shape.shape->size;
    return MinimizeUnimodal([&](double t) { return BoxDistance(half, p0 + t * (p1 - p0)); }, 0.0,
                            1.0);
  }
  return MinimizeUnimodal(
      [&](double t) { return QueryPoint(shape, p0_W + t * (p1_W - p0_W)).distance; }, 0.0, 1.0);
}

}  // namespace

SegmentNearest NearestOnSegment(const Vec3& p0_W, const Vec3& p1_W, const PlacedPrimitive& shape) {
  SegmentNearest nearest;
  nearest.t = SegmentMinimum(p0_W, p1_W, shape);
  nearest.point = p0_W + nearest.t * (p1_W - p0_W);
  nearest.closest = QueryPoint(shape, nearest.point);
  return nearest;
}

SurfacePoint QueryPoint(const PlacedPrimitive& shape, const Vec3& p_W, const Vec3& outward_W) {
  const Mat3 R_WS = shape.X_WS.linear();
  const Vec3 p_S = R_WS.transpose() * (p_W - shape.X_WS.translation());
  SurfacePoint result = QueryLocal(*shape.shape, p_S, R_WS.transpose() * outward_W);
  result.point = shape.X_WS * result.point;
  result.normal = R_WS * result.normal;
  return result;
}

bool FeatureSpan(const PlacedPrimitive& shape, const SurfacePoint& closest, const Vec3& p0_W,
                 const Vec3& p1_W, double* t_begin, double* t_end) {
  *t_begin = 0.0;
  *t_end = 1.0;
  if (closest.feature == SurfaceFeature::kPoint) return false;
  const Vec3 p0 = shape.ToLocal(p0_W);
  const Vec3 p1 = shape.ToLocal(p1_W);
  const Primitive& primitive = *shape.shape;
  switch (primitive.type) {
    case PrimitiveType::kBox: {
      const Vec3 half = 0.5 * primitive.size;
      bool inside = true;
      for (int i = 0; i < 3; ++i) {
        if (i == closest.face_axis) continue;
        inside = inside && ClipToSlab(p0[i], p1[i], half[i], t_begin, t_end);
      }
      return inside;
    }
    case PrimitiveType::kCylinder:
      if (closest.feature == SurfaceFeature::kFlat) {
        return ClipToDisk(p0, p1, primitive.radius, t_begin, t_end);
      }
      return ClipToSlab(p0.z(), p1.z(), 0.5 * primitive.length, t_begin, t_end);
    case PrimitiveType::kCapsule:
      return ClipToSlab(p0.z(), p1.z(), 0.5 * primitive.length, t_begin, t_end);
    case PrimitiveType::kPlane:
      return true;
    case PrimitiveType::kSphere:
      break;
  }
  return false;
}

}  // namespace lamina::core::primitive_detail
