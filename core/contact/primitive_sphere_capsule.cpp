// SPDX-License-Identifier: MIT
// Sphere and capsule contacts. A sphere is a ball around a point and a capsule a ball swept
// along a segment, so both reduce to point queries on the other shape: the sphere's centre, and
// the capsule axis point of least distance (distance to a convex shape is convex along a
// segment). A capsule lying along a flat or straight feature gets the two ends of that stretch.
#include <algorithm>

#include "core/contact/primitive_pairs.h"

namespace lamina::core::primitive_detail {

void SphereContacts(const PlacedPrimitive& sphere, const PlacedPrimitive& other,
                    ContactSink* sink) {
  const Vec3 centre = sphere.Center();
  sink->AddBall(true, centre, sphere.shape->radius, QueryPoint(other, centre));
}

void CapsuleContacts(const PlacedPrimitive& capsule, const PlacedPrimitive& other,
                     ContactSink* sink) {
  const double radius = capsule.shape->radius;
  const Vec3 p0 = capsule.AxisEnd(-1.0);
  const Vec3 p1 = capsule.AxisEnd(1.0);
  const auto axis_point = [&](double t) -> Vec3 { return p0 + t * (p1 - p0); };

  // the axis point nearest the other shape
  const SegmentNearest nearest = NearestOnSegment(p0, p1, other);

  // both ends of the stretch of axis along the same flat or straight feature
  double level_distance = kInf;
  double t_begin = 0.0;
  double t_end = 1.0;
  const double axis_length = (p1 - p0).norm();
  if (FeatureSpan(other, nearest.closest, p0, p1, &t_begin, &t_end) &&
      (t_end - t_begin) * axis_length > kLevelTolerance) {
    for (const double t : {t_begin, t_end}) {
      const SurfacePoint closest = QueryPoint(other, axis_point(t));
      sink->AddBall(true, axis_point(t), radius, closest);
      level_distance = std::min(level_distance, closest.distance);
    }
  }
  // the nearest point itself unless an end of the stretch is as near
  if (nearest.closest.distance < level_distance - kLevelTolerance) {
    sink->AddBall(true, nearest.point, radius, nearest.closest);
  }
}

}  // namespace lamina::core::primitive_detail
