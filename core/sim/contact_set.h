// SPDX-License-Identifier: MIT
// The contact set: every touching pair of bodies at the current state, after the narrow phase
// (exact contacts within the pair's padding), merging of coincident points and clustering to
// maxContacts; and the set of the state before a tentative step, kept for the rollback test.
//
// The set is the one cache of the simulator: it says itself whether it describes the current
// state (current()); whatever moves, reshapes, enables or re-filters a body calls Invalidate()
// (through the simulator's one BodyChanged rule), and the next step detects again.
// Pairs: `a` is a body with an ODE body (dynamic or kinematic), `b` the other (may be static);
// normals point from b into a; depths are boundary-layer overlaps (m).
#pragma once

#include <algorithm>
#include <map>
#include <utility>
#include <vector>

#include "core/contact/collision_geometry.h"
#include "core/contact/contact.h"
#include "core/contact/near_pair_cache.h"
#include "core/sim/broad_phase.h"
#include "core/sim/sim_timing.h"

namespace lamina::core {

/// The contacts between two bodies at the current state, after clustering.
struct ContactPair {
  int a = -1;  ///< world id of a body with an ODE body (dynamic or kinematic)
  int b = -1;  ///< world id of the other body (may be static); normals point from b into a
  ContactList contacts;
  double tolerance = 0.0;  ///< padding sum of the pair (m)
  double max_depth = 0.0;  ///< deepest boundary-layer overlap (m)
  bool penetrating = false;
  /// fastest tangential correction of the pair's friction anchor in a step from here (m/s)
  double anchor_speed = 0.0;
};

/// What the narrow phase needs of one body.
struct NarrowBody {
  const CollisionGeometry* geometry = nullptr;
  Pose pose = Pose::Identity();  ///< body frame in the world
  double padding = 0.0;          ///< m
  bool moves = false;            ///< has an ODE body (contact joints attach to it)
};

/// Contacts closer than this fraction of the pair's padding sum (or than kMinimumMergeRadius)
/// count as one point: the same corner reported by both meshes. Merging farther apart points
/// would move a pair's contacts by jumps as points enter and leave the layer, and a body resting
/// on them could pick up energy from that.
inline constexpr double kMergeFraction = 0.05;
inline constexpr double kMinimumMergeRadius = 1e-4;

/// The contacts of bodies `first` and `second` (a is the one that moves): collided within their
/// paddings, coincident points merged, a flat patch reduced to its outline's corners
/// (contact_reduction.h), clustered to `max_contacts`. False (and `pair` untouched)
/// when they do not touch. `scratch` is reused storage; times go to `timing`; `cache` (or null)
/// the pair's triangle pairs kept from its last call (near_pair_cache.h).
bool FindPairContacts(int first, int second, const NarrowBody& body_first,
                      const NarrowBody& body_second, int max_contacts, ContactList* scratch,
                      ContactPair* pair, SimTimeSplit* timing, NearPairCache* cache = nullptr);

class ContactSet {
 public:
  /// Pairs touching at the current state (sorted by (min id, max id) through the broad phase).
  const std::vector<ContactPair>& pairs() const { return pairs_; }
  /// The friction anchors record each pair's correction speed here.
  std::vector<ContactPair>& mutable_pairs() { return pairs_; }
  /// Pairs at the start of the tentative step (KeepForRollback).
  const std::vector<ContactPair>& before() const { return before_; }
  /// The broad phase of pairs().
  const CandidatePairs& candidates() const { return broad_.candidates(); }
  /// pairs() describes the current state.
  bool current() const { return current_; }
  void Invalidate() { current_ = false; }
  void Clear();

  /// Detects the pairs of the current state: `ids` are the collidable bodies, `bounds_of(id)`
  /// their padded bounds, `may_collide(a, b)` the pair filter, `narrow_of(id)` a NarrowBody.
  template <typename Bounds, typename Filter, typename Narrow>
  void Detect(const std::vector<int>& ids, const Bounds& bounds_of, const Filter& may_collide,
              const Narrow& narrow_of, int max_contacts, SimTimeSplit* timing);
  /// Before a tentative step: the current pairs become before(); the set is no longer current.
  void KeepForRollback();
  /// The tentative step was undone: before() is the current set again.
  void Rollback();
  /// Whether mesh–mesh pairs keep their candidate triangle pairs from step to step (on by
  /// default; the contacts are bitwise the same either way: near_pair_cache.h). Off forgets them.
  void SetReusePairs(bool reuse);
  /// Searches through the hierarchies, and queries answered from kept candidates, since the
  /// set was made.
  long long PairCollections() const;
  long long PairReuses() const;

 private:
  struct KeptPairs {
    NearPairCache cache;
    unsigned long long detection = 0;  ///< the last Detect that used it
  };
  /// The kept candidates of the pair (first, second), or null when pairs are not reused or
  /// either body is not a mesh (only mesh–mesh contact searches triangle pairs).
  NearPairCache* PairCacheFor(int first, int second, const NarrowBody& body_first,
                              const NarrowBody& body_second);
  /// Forgets the candidates of pairs this Detect did not meet (they no longer touch).
  void SweepPairCaches();

  BroadPhase broad_;
  CandidatePairs before_candidates_;
  std::vector<ContactPair> pairs_;
  std::vector<ContactPair> before_;
  ContactList scratch_;
  bool current_ = false;
  bool reuse_pairs_ = true;
  std::map<std::pair<int, int>, KeptPairs> kept_pairs_;
  unsigned long long detection_ = 0;
  long long forgotten_collections_ = 0, forgotten_reuses_ = 0;  ///< of pairs swept away
};

template <typename Bounds, typename Filter, typename Narrow>
void ContactSet::Detect(const std::vector<int>& ids, const Bounds& bounds_of,
                        const Filter& may_collide, const Narrow& narrow_of, int max_contacts,
                        SimTimeSplit* timing) {
  Stopwatch watch;
  pairs_.clear();
  broad_.Find(ids, bounds_of, may_collide);
  timing->broad_phase += watch.Lap();
  ContactPair pair;
  ++detection_;
  for (const auto& [first, second] : broad_.candidates()) {
    const NarrowBody body_first = narrow_of(first), body_second = narrow_of(second);
    if (FindPairContacts(first, second, body_first, body_second, max_contacts, &scratch_, &pair,
                         timing, PairCacheFor(first, second, body_first, body_second))) {
      pairs_.push_back(std::move(pair));
    }
  }
  SweepPairCaches();
  current_ = true;
}

}  // namespace lamina::core
