// SPDX-License-Identifier: MIT
// The pair routines behind PrimitiveContacts (internal to core/contact) and the sink that turns
// pairs of closest surface points into boundary-layer contacts. Each routine handles one
// ordering of its pair (the dispatcher swaps the other) and appends its contacts in a fixed
// order, so the same input always gives the same list.
#pragma once

#include "core/contact/contact.h"
#include "core/contact/primitive_queries.h"

namespace lamina::core::primitive_detail {

/// Turns closest-point pairs of the routine's shapes a and b into contacts appended to a list.
class ContactSink {
 public:
  /// `pad_a`, `pad_b`: boundary layer thickness of a and b (m). `out` is not owned.
  ContactSink(double pad_a, double pad_b, ContactList* out)
      : pad_a_(pad_a), pad_b_(pad_b), out_(out) {}

  /// pad_a + pad_b: pairs closer than this are in contact (m).
  double tolerance() const { return pad_a_ + pad_b_; }

  /// Adds the contact between a's surface point `p_a` and b's surface point `p_b` with unit
  /// `normal` from b into a and signed distance `distance` = normal . (p_a - p_b) (< 0 when the
  /// shapes overlap) if distance < tolerance(). Returns whether it was added.
  bool Add(const Vec3& p_a, const Vec3& p_b, const Vec3& normal, double distance);

  /// Adds the contact of the ball (`centre`, `radius`) against the other shape, whose closest
  /// surface point to `centre` is `closest`; the ball belongs to a when `ball_on_a`, else to b.
  bool AddBall(bool ball_on_a, const Vec3& centre, double radius, const SurfacePoint& closest);

 private:
  double pad_a_;
  double pad_b_;
  ContactList* out_;
};

/// Below this gap (m) an interior minimum of distance along a segment or rim is taken as level
/// with the ends: the ends already represent it. Far above double rounding at robot scales.
inline constexpr double kLevelTolerance = 1e-10;

/// sphere a against any primitive b (one contact).
void SphereContacts(const PlacedPrimitive& sphere, const PlacedPrimitive& other, ContactSink* sink);
/// capsule a against a capsule, box, cylinder or plane b: the closest point of the capsule axis,
/// or the two ends of the stretch of axis lying along a flat or straight feature of b.
void CapsuleContacts(const PlacedPrimitive& capsule, const PlacedPrimitive& other,
                     ContactSink* sink);
/// box a against box b: separating axes, then the incident face clipped against the reference
/// face (up to 8 contacts) or one edge-edge contact.
void BoxBoxContacts(const PlacedPrimitive& box_a, const PlacedPrimitive& box_b, ContactSink* sink);
/// box a against plane b: every corner within the boundary layer.
void BoxPlaneContacts(const PlacedPrimitive& box, const PlacedPrimitive& plane, ContactSink* sink);
/// box a against cylinder b: box corners and edges against the cylinder, rim points against
/// the box.
void BoxCylinderContacts(const PlacedPrimitive& box, const PlacedPrimitive& cylinder,
                         ContactSink* sink);
/// cylinder a against a cylinder or plane b: rim points, and for two cylinders their sides.
void CylinderContacts(const PlacedPrimitive& cylinder, const PlacedPrimitive& other,
                      ContactSink* sink);
/// Contacts of the rim points of `cylinder` against `other`, for both caps: per cap the rim point
/// nearest `other` and 7 more evenly spaced around the rim from it, each added if within the
/// boundary layer. The cylinder is shape a of the sink when `cylinder_is_a`, else b.
void RimContacts(const PlacedPrimitive& cylinder, const PlacedPrimitive& other, bool cylinder_is_a,
                 ContactSink* sink);

}  // namespace lamina::core::primitive_detail
