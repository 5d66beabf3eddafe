// SPDX-License-Identifier: MIT
// Contacts between two bodies' padded geometries (Klamp't's boundary-layer design): a pair is in
// contact where the distance between the underlying geometries is below the sum of the
// paddings; each contact sits on the padded surfaces.
#pragma once

#include <vector>

#include "core/math_types.h"

namespace lamina::core {

/// One contact between body a and body b.
struct Contact {
  Vec3 position = Vec3::Zero();  ///< world, midway between the two padded surfaces (m)
  Vec3 normal = Vec3::UnitZ();   ///< world unit vector from b into a: moving a along it separates
  double depth = 0.0;            ///< overlap of the boundary layers, pad_a + pad_b - distance (m)
  /// The underlying (unpadded) geometries interpenetrate here: the penetration went beyond the
  /// boundary layer and `depth` understates it.
  bool penetrating = false;
  /// How much of the pair's pressure this contact stands for: 0 for a contact straight from the
  /// geometry (it counts as depth²), the members' sum for a cluster (see ClusterContacts).
  double weight = 0.0;
};

/// The pressure weight of a contact: its own `weight`, or depth² (floored at `floor`²) for a
/// contact straight from the geometry.
inline double PressureWeight(const Contact& contact, double floor) {
  if (contact.weight > 0.0) return contact.weight;
  const double depth = contact.depth > floor ? contact.depth : floor;
  return depth * depth;
}

using ContactList = std::vector<Contact>;

}  // namespace lamina::core
