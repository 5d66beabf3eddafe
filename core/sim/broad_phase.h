// SPDX-License-Identifier: MIT
// The broad phase: which pairs of bodies may touch. Sweep and prune along x over the padded
// world bounds of every enabled body with geometry; candidate pairs come out sorted by (a, b)
// with a < b (world ids), so the order of contact joints never depends on where bodies are. Which
// kinds of bodies may collide at all (static with kinematic, robot self-collision, ...) is the
// caller's filter.
#pragma once

#include <algorithm>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "core/contact/collision_geometry.h"
#include "core/math_types.h"

namespace lamina::core {

using CandidatePairs = std::vector<std::pair<int, int>>;

/// Bounds of `geometry` at `pose`, grown by `padding` (and the geometry's margin and half of
/// kLayerEdgeSlack, as Collide pads) on every side;
/// empty for an empty geometry, everything for an unbounded one (a plane).
Eigen::AlignedBox3d WorldBounds(const CollisionGeometry& geometry, const Pose& pose,
                                double padding);

class BroadPhase {
 public:
  /// The pairs among `ids` (world ids whose padded bounds `bounds_of(id)` are not empty) whose
  /// bounds overlap and that `may_collide(a, b)` allows; replaces candidates(). Reuses its
  /// storage: no allocation once the sizes have been seen.
  template <typename Bounds, typename Filter>
  void Find(const std::vector<int>& ids, const Bounds& bounds_of, const Filter& may_collide);
  const CandidatePairs& candidates() const { return candidates_; }
  /// Keeps the current candidates aside (the state before a tentative step) and back.
  void Swap(CandidatePairs* other) { std::swap(candidates_, *other); }
  void Clear() { candidates_.clear(); }

 private:
  template <typename Bounds>
  void SortByMinX(const std::vector<int>& ids, const Bounds& bounds_of);
  std::vector<int> sorted_;
  CandidatePairs candidates_;
};

/// The bounds overlap in y and z (x is the sweep axis).
inline bool BoundsOverlapInYZ(const Eigen::AlignedBox3d& a, const Eigen::AlignedBox3d& b) {
  return a.min().y() <= b.max().y() && b.min().y() <= a.max().y() && a.min().z() <= b.max().z() &&
         b.min().z() <= a.max().z();
}

template <typename Bounds>
void BroadPhase::SortByMinX(const std::vector<int>& ids, const Bounds& bounds_of) {
  sorted_.assign(ids.begin(), ids.end());
  std::sort(sorted_.begin(), sorted_.end(), [&](int a, int b) {
    const double ax = bounds_of(a).min().x(), bx = bounds_of(b).min().x();
    return ax != bx ? ax < bx : a < b;
  });
}

template <typename Bounds, typename Filter>
void BroadPhase::Find(const std::vector<int>& ids, const Bounds& bounds_of,
                      const Filter& may_collide) {
  SortByMinX(ids, bounds_of);
  candidates_.clear();
  for (size_t i = 0; i < sorted_.size(); ++i) {
    const int a = sorted_[i];
    const Eigen::AlignedBox3d& box_a = bounds_of(a);
    for (size_t j = i + 1; j < sorted_.size(); ++j) {
      const int b = sorted_[j];
      const Eigen::AlignedBox3d& box_b = bounds_of(b);
      if (box_b.min().x() > box_a.max().x()) break;
      if (!BoundsOverlapInYZ(box_a, box_b) || !may_collide(a, b)) continue;
      candidates_.emplace_back(std::min(a, b), std::max(a, b));
    }
  }
  std::sort(candidates_.begin(), candidates_.end());
}

}  // namespace lamina::core
