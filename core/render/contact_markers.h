// SPDX-License-Identifier: MIT
// Contact markers: the contacts of a simulation reduced to what the contact overlays draw.
#pragma once

#include <vector>

#include "core/math_types.h"

namespace lamina::core {

class Simulator;

struct ContactMarker {
  Vec3 position = Vec3::Zero();  ///< world, m
  Vec3 normal = Vec3::UnitZ();   ///< unit, into body a of the pair
  Vec3 force = Vec3::Zero();     ///< on body a, N (zero without contact feedback)
  bool penetrating = false;
};

/// Every contact of the simulator's current state. Where contact feedback is on for a pair
/// (Simulator::EnableContactFeedbackAll) the markers are the last sub-step's contacts with their
/// forces; otherwise the current contacts with zero force.
std::vector<ContactMarker> ContactMarkersFromSimulator(const Simulator& simulator);

}  // namespace lamina::core
