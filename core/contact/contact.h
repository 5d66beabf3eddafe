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
};

using ContactList = std::vector<Contact>;

}  // namespace lamina::core
