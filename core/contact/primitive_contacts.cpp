// SPDX-License-Identifier: MIT
// Primitive-primitive dispatch: places both shapes in the world, puts the pair in its canonical
// order (by shape kind, then by placement for two shapes of one kind, so that swapping a and b
// only negates the normals), runs the pair routine and turns the contacts back if it swapped.
#include "core/contact/primitive_contacts.h"

#include <array>
#include <cmath>
#include <cstddef>

#include "core/contact/primitive_pairs.h"

namespace lamina::core {
namespace {

using primitive_detail::ContactSink;
using primitive_detail::PlacedPrimitive;
using primitive_detail::QueryPoint;

/// Position of a kind in the canonical order; a pair runs with the lower rank as shape a.
int Rank(PrimitiveType type) {
  switch (type) {
    case PrimitiveType::kSphere:
      return 0;
    case PrimitiveType::kCapsule:
      return 1;
    case PrimitiveType::kBox:
      return 2;
    case PrimitiveType::kCylinder:
      return 3;
    case PrimitiveType::kPlane:
      return 4;
  }
  return 5;
}

/// The numbers that place and size a shape, for ordering two shapes of one kind.
std::array<double, 17> PlacementKey(const PlacedPrimitive& placed) {
  std::array<double, 17> key{};
  const Vec3 centre = placed.Center();
  const Mat3 rotation = placed.X_WS.linear();
  for (int i = 0; i < 3; ++i) key[i] = centre[i];
  for (int i = 0; i < 9; ++i) key[3 + i] = rotation(i / 3, i % 3);
  const Primitive& shape = *placed.shape;
  key[12] = shape.radius;
  key[13] = shape.length;
  for (int i = 0; i < 3; ++i) key[14 + i] = shape.size[i];
  return key;
}

/// True when the pair must run as (b, a).
bool RunsSwapped(const PlacedPrimitive& a, const PlacedPrimitive& b) {
  const int rank_a = Rank(a.shape->type);
  const int rank_b = Rank(b.shape->type);
  if (rank_a != rank_b) return rank_a > rank_b;
  return PlacementKey(b) < PlacementKey(a);
}

/// Radius of the ball around the shape's centre that holds it (m); unused for a plane.
double BoundingRadius(const Primitive& shape) {
  switch (shape.type) {
    case PrimitiveType::kSphere:
      return shape.radius;
    case PrimitiveType::kBox:
      return 0.5 * shape.size.norm();
    case PrimitiveType::kCapsule:
      return 0.5 * shape.length + shape.radius;
    case PrimitiveType::kCylinder:
      return std::hypot(shape.radius, 0.5 * shape.length);
    case PrimitiveType::kPlane:
      break;
  }
  return kInf;
}

/// True when the bounding balls of a and b (or a's ball and the plane b) are at least
/// `tolerance` apart, so the shapes cannot be in contact.
bool FarApart(const PlacedPrimitive& a, const PlacedPrimitive& b, double tolerance) {
  const double radius_a = BoundingRadius(*a.shape);
  if (b.shape->type == PrimitiveType::kPlane) {
    return QueryPoint(b, a.Center()).distance - radius_a >= tolerance;
  }
  return (a.Center() - b.Center()).norm() - radius_a - BoundingRadius(*b.shape) >= tolerance;
}

/// Runs the routine for a canonically ordered pair (rank of a <= rank of b, not plane-plane).
void Dispatch(const PlacedPrimitive& a, const PlacedPrimitive& b, ContactSink* sink) {
  if (FarApart(a, b, sink->tolerance())) return;
  switch (a.shape->type) {
    case PrimitiveType::kSphere:
      primitive_detail::SphereContacts(a, b, sink);
      return;
    case PrimitiveType::kCapsule:
      primitive_detail::CapsuleContacts(a, b, sink);
      return;
    case PrimitiveType::kBox:
      if (b.shape->type == PrimitiveType::kBox) {
        primitive_detail::BoxBoxContacts(a, b, sink);
      } else if (b.shape->type == PrimitiveType::kCylinder) {
        primitive_detail::BoxCylinderContacts(a, b, sink);
      } else {
        primitive_detail::BoxPlaneContacts(a, b, sink);
      }
      return;
    case PrimitiveType::kCylinder:
      primitive_detail::CylinderContacts(a, b, sink);
      return;
    case PrimitiveType::kPlane:
      return;
  }
}

}  // namespace

namespace primitive_detail {

bool ContactSink::Add(const Vec3& p_a, const Vec3& p_b, const Vec3& normal, double distance) {
  // written so that a NaN distance is never added
  if (!(distance < tolerance())) return false;
  Contact contact;
  contact.position = 0.5 * ((p_a - pad_a_ * normal) + (p_b + pad_b_ * normal));
  contact.normal = normal;
  contact.depth = tolerance() - distance;
  contact.penetrating = distance < 0.0;
  out_->push_back(contact);
  return true;
}

bool ContactSink::AddBall(bool ball_on_a, const Vec3& centre, double radius,
                          const SurfacePoint& closest) {
  const Vec3 ball_point = centre - radius * closest.normal;
  const double distance = closest.distance - radius;
  if (ball_on_a) return Add(ball_point, closest.point, closest.normal, distance);
  return Add(closest.point, ball_point, -closest.normal, distance);
}

}  // namespace primitive_detail

bool PrimitiveContacts(const Primitive& a, const Pose& X_Wa, double pad_a, const Primitive& b,
                       const Pose& X_Wb, double pad_b, ContactList* out) {
  if (a.type == PrimitiveType::kPlane && b.type == PrimitiveType::kPlane) return false;
  const PlacedPrimitive placed_a{&a, X_Wa * a.pose};
  const PlacedPrimitive placed_b{&b, X_Wb * b.pose};
  if (!RunsSwapped(placed_a, placed_b)) {
    ContactSink sink(pad_a, pad_b, out);
    Dispatch(placed_a, placed_b, &sink);
    return true;
  }
  // run as (b, a), then turn the normals around so they point from b into a again
  const std::size_t first = out->size();
  ContactSink sink(pad_b, pad_a, out);
  Dispatch(placed_b, placed_a, &sink);
  for (std::size_t i = first; i < out->size(); ++i) (*out)[i].normal = -(*out)[i].normal;
  return true;
}

}  // namespace lamina::core
