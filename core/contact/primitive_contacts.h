// SPDX-License-Identifier: MIT
// Contacts between analytic primitives (sphere, box, capsule, cylinder, plane), including
// multi-point face contact: a box resting on a plane or on another box touches at 4 points.
#pragma once

#include "core/contact/contact.h"
#include "core/geometry/primitive.h"

namespace lamina::core {

/// Contacts between primitive a (its pose in world = X_Wa * a.pose) padded by pad_a and
/// primitive b padded by pad_b, appended to `out` (normal from b into a). Supports every pair
/// of sphere, box, capsule, cylinder and plane except plane-plane. Returns false for an
/// unsupported pair.
bool PrimitiveContacts(const Primitive& a, const Pose& X_Wa, double pad_a, const Primitive& b,
                       const Pose& X_Wb, double pad_b, ContactList* out);

}  // namespace lamina::core
