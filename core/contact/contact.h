// SPDX-License-Identifier: MIT
// Contacts between two bodies' padded geometries (Klamp't's boundary-layer design): a pair is in
// contact where the distance between the underlying geometries is below the sum of the
// paddings; each contact sits on the padded surfaces.
#pragma once

#include <vector>

#include "core/math_types.h"

namespace lamina::core {

/// How far beyond the sum of the paddings two geometries still count as in contact (m): Collide
/// grows each padding by half of it, so depths are the layers' overlap plus this. A body placed
/// exactly on the layer (a box stacked at padding distance, as worlds are written) has a distance
/// equal to the paddings' sum up to rounding; without the slack half of such pairs fall outside and
/// the body free-falls for a step (g h^2: 1 mm at 10 ms), and a stack of offset boxes set rattling
/// this way never settles. The depth keeps the slack rather than being clamped at 0: contacts at
/// depth exactly 0 between bodies falling together give ODE's Dantzig LCP rows with a zero
/// right-hand side, on which it lets a 4-box stack fall through its layers. Far below anything
/// physical, far above the rounding of positions up to 1e6 m.
inline constexpr double kLayerEdgeSlack = 1e-9;

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
