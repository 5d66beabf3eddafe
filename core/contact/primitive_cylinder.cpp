// SPDX-License-Identifier: MIT
// Cylinder contacts against boxes, cylinders and planes, from the features where two convex
// shapes can be nearest: every rim point of a cylinder against the other shape (a coarse scan
// around the rim refined by golden section, then 8 evenly spaced rim points starting there, so
// a cap flat on a face gives 8 contacts and a side lying on it gives one per rim), box corners
// and edges against a cylinder, and two cylinder sides against each other (their axes' common
// perpendicular). Penetrating pairs get each penetrating feature's own contact.
#include <algorithm>
#include <cmath>

#include "core/contact/primitive_pairs.h"

namespace lamina::core::primitive_detail {
namespace {

// Rim samples of the coarse scan that brackets the rim point nearest the other shape.
constexpr int kRimScanPoints = 32;
// Rim points tried as contacts per cap: the nearest one and the rest evenly spaced from it.
constexpr int kRimContactPoints = 8;
// Sine of the angle between two cylinder axes below which they count as parallel; the rims then
// carry the side-by-side contact.
constexpr double kParallelAxisSine = 1e-6;

/// The rim contacts of one cap of `cylinder` (side -1 or +1).
void CapRimContacts(const PlacedPrimitive& cylinder, double side, const PlacedPrimitive& other,
                    bool cylinder_is_a, ContactSink* sink) {
  const double radius = cylinder.shape->radius;
  const Vec3 centre = cylinder.AxisEnd(side);
  const Vec3 e1 = cylinder.Axis(0);
  const Vec3 e2 = cylinder.Axis(1);
  const auto rim_point = [&](double angle) -> Vec3 {
    return centre + radius * (std::cos(angle) * e1 + std::sin(angle) * e2);
  };
  const auto distance_at = [&](double angle) {
    return QueryPoint(other, rim_point(angle)).distance;
  };

  // coarse scan for the rim sample nearest the other shape
  constexpr double kScanStep = 2.0 * kPi / kRimScanPoints;
  int best = 0;
  double best_distance = kInf;
  for (int i = 0; i < kRimScanPoints; ++i) {
    const double distance = distance_at(i * kScanStep);
    if (distance < best_distance) {
      best = i;
      best_distance = distance;
    }
  }
  // every rim point lies within a chord 2 r sin(step / 4) of a sample and distance changes no
  // faster than position: if even that cannot reach the boundary layer, the cap has no contact
  if (best_distance - 2.0 * radius * std::sin(0.25 * kScanStep) >= sink->tolerance()) return;

  // refine between the neighbouring samples, then try evenly spaced points from there (each
  // point's offset from the cylinder centre lies in the rim's cone of outward normals)
  const double nearest =
      MinimizeUnimodal(distance_at, (best - 1) * kScanStep, (best + 1) * kScanStep);
  for (int k = 0; k < kRimContactPoints; ++k) {
    const Vec3 point = rim_point(nearest + k * (2.0 * kPi / kRimContactPoints));
    sink->AddBall(cylinder_is_a, point, 0.0, QueryPoint(other, point, point - cylinder.Center()));
  }
}

/// The contact of two cylinder sides where their axes' common perpendicular meets both axes
/// strictly between the ends (crossing cylinders); nothing for parallel axes.
void SideContact(const PlacedPrimitive& a, const PlacedPrimitive& b, ContactSink* sink) {
  const Vec3 start_a = a.AxisEnd(-1.0);
  const Vec3 start_b = b.AxisEnd(-1.0);
  const Vec3 span_a = a.AxisEnd(1.0) - start_a;
  const Vec3 span_b = b.AxisEnd(1.0) - start_b;
  const Vec3 cross = span_a.cross(span_b);
  if (!(cross.norm() > kParallelAxisSine * span_a.norm() * span_b.norm())) return;
  // closest points of the two axis lines, as fractions of the axes
  const Vec3 offset = start_a - start_b;
  const double aa = span_a.squaredNorm();
  const double bb = span_b.squaredNorm();
  const double ab = span_a.dot(span_b);
  const double denominator = aa * bb - ab * ab;
  const double s = (ab * span_b.dot(offset) - bb * span_a.dot(offset)) / denominator;
  const double u = (aa * span_b.dot(offset) - ab * span_a.dot(offset)) / denominator;
  if (!(s > 0.0 && s < 1.0 && u > 0.0 && u < 1.0)) return;
  const Vec3 axis_a = start_a + s * span_a;
  const Vec3 axis_b = start_b + u * span_b;
  const double gap = (axis_a - axis_b).norm();
  // intersecting axes give no direction: use the common normal, pointing from b towards a
  const Vec3 normal = gap > 0.0
                          ? Vec3((axis_a - axis_b) / gap)
                          : Vec3(SignOf(cross.dot(a.Center() - b.Center())) * cross.normalized());
  const double radius_a = a.shape->radius;
  const double radius_b = b.shape->radius;
  sink->Add(axis_a - radius_a * normal, axis_b + radius_b * normal, normal,
            gap - radius_a - radius_b);
}

}  // namespace

void RimContacts(const PlacedPrimitive& cylinder, const PlacedPrimitive& other, bool cylinder_is_a,
                 ContactSink* sink) {
  CapRimContacts(cylinder, -1.0, other, cylinder_is_a, sink);
  CapRimContacts(cylinder, 1.0, other, cylinder_is_a, sink);
}

void BoxCylinderContacts(const PlacedPrimitive& box, const PlacedPrimitive& cylinder,
                         ContactSink* sink) {
  // box corners against the cylinder (point - box centre lies in a corner's normal cone)
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 point = box.BoxCorner(corner);
    sink->AddBall(true, point, 0.0, QueryPoint(cylinder, point, point - box.Center()));
  }
  // box edges crossing the cylinder: the nearest point of an edge, when nearer than its corners
  for (int edge = 0; edge < 12; ++edge) {
    Vec3 start;
    Vec3 end;
    box.BoxEdge(edge, &start, &end);
    // distance changes no faster than position: an edge whose middle is farther than the layer
    // plus half its length cannot reach the layer
    const double reach = 0.5 * (end - start).norm() + sink->tolerance();
    if (QueryPoint(cylinder, 0.5 * (start + end)).distance >= reach) continue;
    const SegmentNearest nearest = NearestOnSegment(start, end, cylinder);
    const double corner_distance =
        std::min(QueryPoint(cylinder, start).distance, QueryPoint(cylinder, end).distance);
    if (nearest.closest.distance < corner_distance - kLevelTolerance) {
      sink->AddBall(true, nearest.point, 0.0,
                    QueryPoint(cylinder, nearest.point, EdgeOutward(box, edge, nearest.point)));
    }
  }
  // the cylinder's rims against the box
  RimContacts(cylinder, box, false, sink);
}

void CylinderContacts(const PlacedPrimitive& cylinder, const PlacedPrimitive& other,
                      ContactSink* sink) {
  RimContacts(cylinder, other, true, sink);
  if (other.shape->type != PrimitiveType::kCylinder) return;
  RimContacts(other, cylinder, false, sink);
  SideContact(cylinder, other, sink);
}

}  // namespace lamina::core::primitive_detail
