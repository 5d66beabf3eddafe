// SPDX-License-Identifier: MIT
// The friction anchors of a simulation (the law is in friction_anchor.h): one per pair that
// sticks, sorted by (a, b), and the anchor correction velocity of every contact of the step.
//
// Each step, a pair keeps its anchor while it sticks (the relative rotation stays under
// kAnchorMaxRotation and every contact's drift under the settings' frictionAnchorSlip) and gets a
// new one where it is when it starts touching, slides or rolls; a pair with no contact in this
// step that is still a broad-phase candidate keeps its anchor (contacts at the edge of the layer
// come and go while a body stands). Anchors are part of the simulation state (SimState).
#pragma once

#include <vector>

#include "core/sim/body_table.h"
#include "core/sim/contact_set.h"
#include "core/sim/friction_anchor.h"

namespace lamina::core {

class FrictionAnchors {
 public:
  const std::vector<FrictionAnchor>& anchors() const { return anchors_; }
  void Restore(const std::vector<FrictionAnchor>& anchors) { anchors_ = anchors; }
  void Clear() { anchors_.clear(); }
  /// Drops every anchor of body `id` (it was moved by hand: its drift means nothing).
  void Forget(int id) { ForgetAnchors(&anchors_, id); }

  /// The anchors of `pairs` (current contacts; each pair's anchor_speed is set) for a step of
  /// `step` s with gain and re-anchor slip from the settings; velocities() then holds one
  /// correction velocity (a minus b, world) per contact of `pairs`, in order.
  void Update(std::vector<ContactPair>* pairs, const CandidatePairs& candidates,
              const BodyTable& bodies, double step, double gain, double slip);
  const std::vector<Vec3>& velocities() const { return velocities_; }

 private:
  void UpdatePair(ContactPair* pair, const BodyTable& bodies, double step, double gain,
                  double slip);
  void KeepNearbyAnchors(const CandidatePairs& candidates);

  std::vector<FrictionAnchor> anchors_;  ///< sorted by (a, b)
  std::vector<FrictionAnchor> next_;     ///< scratch
  std::vector<Vec3> velocities_;         ///< per contact of the step
};

}  // namespace lamina::core
