// SPDX-License-Identifier: MIT
// Geometric queries on one primitive placed in the world, shared by the primitive contact
// routines (internal to core/contact): the signed distance from a point to the shape with the
// closest surface point, its outward normal and the kind of surface feature there; the part of
// a segment that faces the same flat or straight feature; and a fixed-iteration 1-D minimiser.
#pragma once

#include <algorithm>

#include "core/geometry/primitive.h"

namespace lamina::core::primitive_detail {

/// +1 for 0 and above, -1 below: the side of a face or axis a point is on, ties to the + side.
inline double SignOf(double value) {
  return value < 0.0 ? -1.0 : 1.0;
}

/// A primitive and the world pose of its own frame (X_W_body * primitive.pose).
struct PlacedPrimitive {
  const Primitive* shape = nullptr;  ///< not owned
  Pose X_WS = Pose::Identity();

  Vec3 Center() const { return X_WS.translation(); }
  /// World point `p_W` in the shape's frame.
  Vec3 ToLocal(const Vec3& p_W) const { return X_WS.linear().transpose() * (p_W - Center()); }
  /// World direction of local axis `i` (0 = x, 1 = y, 2 = z).
  Vec3 Axis(int i) const { return X_WS.linear().col(i); }
  /// Box half extents (m).
  Vec3 HalfSize() const { return 0.5 * shape->size; }
  /// World point of the cylinder or capsule axis at local z = `side` * length / 2.
  Vec3 AxisEnd(double side) const { return X_WS * Vec3(0.0, 0.0, 0.5 * side * shape->length); }
  /// World corner `index` (0..7) of a box: bit i of the index set means +half size on axis i.
  Vec3 BoxCorner(int index) const;
  /// World ends of box edge `index` (0..11): the edge runs along local axis index / 4 (from -
  /// to +) and bits 0 and 1 of index % 4 pick the sides on the two other axes in order.
  void BoxEdge(int index, Vec3* start, Vec3* end) const;
};

/// A direction in the cone of outward normals of box edge `index` at its point `p_W`.
Vec3 EdgeOutward(const PlacedPrimitive& box, int index, const Vec3& p_W);

/// What kind of surface carries the closest point; decides which contacts a flat feature adds.
enum class SurfaceFeature {
  kFlat,   ///< a planar face: a box face (`face_axis`), a cylinder cap, the plane
  kSide,   ///< the straight side of a cylinder or capsule, between its ends
  kPoint,  ///< anything else: box edge or corner, cylinder rim, sphere, capsule end
};

/// The surface point of a shape closest to a query point.
struct SurfacePoint {
  double distance = 0.0;      ///< signed distance of the query point, < 0 inside (m)
  Vec3 point = Vec3::Zero();  ///< closest surface point (world)
  /// Outward unit normal there (world): query point = point + distance * normal.
  Vec3 normal = Vec3::UnitZ();
  SurfaceFeature feature = SurfaceFeature::kPoint;
  int face_axis = 2;  ///< local axis of the box face (box, kFlat only)
};

/// Closest surface point of `shape` to the world point `p_W`. For a point inside a box or
/// cylinder (or within 1e-9 m outside), the exit face is the nearest one among those whose normal
/// opposes `outward_W`, the outward direction of the querying shape's surface at the point (a
/// corner's or rim's mean normal; zero when unknown), or the nearest of all when none does; lowest
/// axis first on ties.
SurfacePoint QueryPoint(const PlacedPrimitive& shape, const Vec3& p_W,
                        const Vec3& outward_W = Vec3::Zero());

/// The parameters [*t_begin, *t_end] within [0, 1] of the segment p0 + t (p1 - p0) whose points
/// face the same flat or straight feature as `closest` (the query result of one of its points):
/// the face's prism for a box face, the disk's cylinder for a cap, the slab between the ends for
/// a cylinder or capsule side, all of it for a plane. False for point features or no overlap.
bool FeatureSpan(const PlacedPrimitive& shape, const SurfacePoint& closest, const Vec3& p0_W,
                 const Vec3& p1_W, double* t_begin, double* t_end);

/// The point of a segment nearest to a shape.
struct SegmentNearest {
  double t = 0.0;             ///< parameter in [0, 1] along the segment
  Vec3 point = Vec3::Zero();  ///< the segment point (world)
  SurfacePoint closest;       ///< the shape's surface point closest to it
};

/// The point of segment p0 p1 of least signed distance to `shape`. Exact up to the minimiser's
/// bracket because that distance is convex along a segment (every primitive is convex).
SegmentNearest NearestOnSegment(const Vec3& p0_W, const Vec3& p1_W, const PlacedPrimitive& shape);

/// Golden-section steps of MinimizeUnimodal: shrinks the bracket by 0.618^64 < 1e-13.
inline constexpr int kGoldenSteps = 64;

/// Argument of the minimum of `f` over [lo, hi] for a unimodal (e.g. convex) `f`, by a fixed
/// number of golden-section steps; the ends are checked too, so a minimum at an end is exact.
/// On a flat minimum it returns a deterministic point of it (`lo` if f(lo) is minimal).
template <typename Function>
double MinimizeUnimodal(const Function& f, double lo, double hi) {
  constexpr double kInverseGolden = 0.6180339887498949;
  double a = lo;
  double b = hi;
  double c = b - kInverseGolden * (b - a);
  double d = a + kInverseGolden * (b - a);
  double f_c = f(c);
  double f_d = f(d);
  for (int step = 0; step < kGoldenSteps; ++step) {
    if (f_c <= f_d) {
      b = d;
      d = c;
      f_d = f_c;
      c = b - kInverseGolden * (b - a);
      f_c = f(c);
    } else {
      a = c;
      c = d;
      f_c = f_d;
      d = a + kInverseGolden * (b - a);
      f_d = f(d);
    }
  }
  double best = f_c <= f_d ? c : d;
  double f_best = std::min(f_c, f_d);
  // the search only approaches the ends; check them exactly
  const double f_lo = f(lo);
  if (f_lo <= f_best) {
    best = lo;
    f_best = f_lo;
  }
  if (f(hi) < f_best) best = hi;
  return best;
}

}  // namespace lamina::core::primitive_detail
