// SPDX-License-Identifier: MIT
#include "core/sim/contact_set.h"

#include "core/contact/contact_clustering.h"
#include "core/contact/contact_reduction.h"
#include "core/sim/contact_rows.h"

namespace lamina::core {

bool FindPairContacts(int first, int second, const NarrowBody& body_first,
                      const NarrowBody& body_second, int max_contacts, ContactList* scratch,
                      ContactPair* pair, SimTimeSplit* timing, NearPairCache* cache) {
  // a is a body that moves (ODE attaches contact joints to it); normals point into a
  const bool swap = !body_first.moves;
  const NarrowBody& a = swap ? body_second : body_first;
  const NarrowBody& b = swap ? body_first : body_second;
  Stopwatch watch;
  scratch->clear();
  Collide(*a.geometry, a.pose, a.padding, *b.geometry, b.pose, b.padding, scratch, cache);
  timing->contact_generation += watch.Lap();
  if (scratch->empty()) return false;
  *pair = ContactPair{};
  pair->a = swap ? second : first;
  pair->b = swap ? first : second;
  pair->tolerance = a.padding + a.geometry->margin() + b.padding + b.geometry->margin();
  for (const Contact& contact : *scratch) {
    pair->max_depth = std::max(pair->max_depth, contact.depth);
    pair->penetrating = pair->penetrating || contact.penetrating;
  }
  MergeCoincidentContacts(std::max(kMergeFraction * pair->tolerance, kMinimumMergeRadius), scratch);
  ReduceFlatPatch(ContactWeightDepth(0.0, pair->tolerance), scratch);
  ClusterContacts(max_contacts, kDefaultClusterNormalScale, scratch);
  pair->contacts = *scratch;
  timing->clustering += watch.Lap();
  return true;
}

void ContactSet::Clear() {
  kept_pairs_.clear();
  broad_.Clear();
  before_candidates_.clear();
  pairs_.clear();
  before_.clear();
  current_ = false;
}

void ContactSet::KeepForRollback() {
  std::swap(pairs_, before_);
  broad_.Swap(&before_candidates_);
  current_ = false;
}

void ContactSet::Rollback() {
  std::swap(pairs_, before_);
  broad_.Swap(&before_candidates_);
  current_ = true;
}

void ContactSet::SetReusePairs(bool reuse) {
  reuse_pairs_ = reuse;
  if (!reuse) {
    ++detection_;  // no pair was met in this "detection": every one is forgotten
    SweepPairCaches();
  }
}

NearPairCache* ContactSet::PairCacheFor(int first, int second, const NarrowBody& body_first,
                                        const NarrowBody& body_second) {
  using Kind = CollisionGeometry::Kind;
  if (!reuse_pairs_ || body_first.geometry->kind() != Kind::kMesh ||
      body_second.geometry->kind() != Kind::kMesh) {
    return nullptr;
  }
  KeptPairs& kept = kept_pairs_[{first, second}];
  kept.detection = detection_;
  return &kept.cache;
}

void ContactSet::SweepPairCaches() {
  for (auto it = kept_pairs_.begin(); it != kept_pairs_.end();) {
    if (it->second.detection == detection_) {
      ++it;
      continue;
    }
    forgotten_collections_ += it->second.cache.collections;
    forgotten_reuses_ += it->second.cache.reuses;
    it = kept_pairs_.erase(it);
  }
}

long long ContactSet::PairCollections() const {
  long long sum = forgotten_collections_;
  for (const auto& [key, kept] : kept_pairs_) sum += kept.cache.collections;
  return sum;
}

long long ContactSet::PairReuses() const {
  long long sum = forgotten_reuses_;
  for (const auto& [key, kept] : kept_pairs_) sum += kept.cache.reuses;
  return sum;
}

}  // namespace lamina::core
