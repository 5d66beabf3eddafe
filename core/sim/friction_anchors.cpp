// SPDX-License-Identifier: MIT
#include "core/sim/friction_anchors.h"

#include <algorithm>

namespace lamina::core {

void FrictionAnchors::Update(std::vector<ContactPair>* pairs, const CandidatePairs& candidates,
                             const BodyTable& bodies, double step, double gain, double slip) {
  next_.clear();
  velocities_.clear();
  for (ContactPair& pair : *pairs) {
    pair.anchor_speed = 0.0;
    if (!pair.contacts.empty()) UpdatePair(&pair, bodies, step, gain, slip);
  }
  KeepNearbyAnchors(candidates);
  std::swap(anchors_, next_);
}

// the pair's anchor and its contacts' correction velocities; false when it re-anchored
void FrictionAnchors::UpdatePair(ContactPair* pair, const BodyTable& bodies, double step,
                                 double gain, double slip) {
  const BodyFrame frame_a = bodies.FrameOf(pair->a);
  const BodyFrame frame_b = bodies.FrameOf(pair->b);
  const size_t first = velocities_.size();
  const FrictionAnchor* anchor = FindAnchor(anchors_, pair->a, pair->b);
  bool sticks =
      anchor != nullptr && AnchorRotation(*anchor, frame_a, frame_b) <= kAnchorMaxRotation;
  for (const Contact& contact : pair->contacts) {
    const Vec3 drift =
        sticks ? AnchorDrift(*anchor, frame_a, frame_b, contact.position, contact.normal)
               : Vec3::Zero();
    sticks = sticks && drift.norm() <= slip;
    velocities_.push_back(AnchorCorrectionVelocity(drift, step, gain));
  }
  if (!sticks) {
    next_.push_back(MakeAnchor(pair->a, pair->b, frame_a, frame_b));
    std::fill(velocities_.begin() + first, velocities_.end(), Vec3::Zero());
    return;
  }
  next_.push_back(*anchor);
  for (size_t i = first; i < velocities_.size(); ++i) {
    pair->anchor_speed = std::max(pair->anchor_speed, velocities_[i].norm());
  }
}

// a pair that has no contact in this step but is still close keeps its anchor
void FrictionAnchors::KeepNearbyAnchors(const CandidatePairs& candidates) {
  const size_t in_contact = next_.size();
  SortAnchors(&next_);
  for (const FrictionAnchor& anchor : anchors_) {
    const std::pair<int, int> ids(std::min(anchor.a, anchor.b), std::max(anchor.a, anchor.b));
    if (std::binary_search(candidates.begin(), candidates.end(), ids) &&
        FindAnchor(next_, anchor.a, anchor.b) == nullptr) {
      next_.push_back(anchor);
    }
  }
  if (next_.size() > in_contact) SortAnchors(&next_);
}

}  // namespace lamina::core
