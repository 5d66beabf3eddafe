// SPDX-License-Identifier: MIT
// The triangle pairs two meshes may bring within their padding sum, kept from one step to the
// next (a Verlet list for mesh–mesh contact): the search through the meshes' hierarchies runs
// once with the tolerance widened by a slack, and while mesh b has moved less than the slack
// relative to mesh a since then, every later query tests only those candidate pairs.
//
// Why the answer is bitwise the same as a fresh search: NearTrianglePairs reports a pair when the
// pair's own test (boxes, planes, edge planes, then FCL's triangle distance, mesh_query.h)
// accepts it, whatever narrowed the candidates down, in (triangle_a, triangle_b) order. The cheap
// tests only drop pairs farther apart than their reach. A pair within the tolerance now, after b
// moved at most d <= slack in a's frame, was within tolerance + slack when the candidates were
// collected (distance is 1-Lipschitz in a rigid displacement of one side), so it is among them;
// the candidates are kept sorted and each is tested as the fresh search would test it.
//
// The displacement bound (MotionBound): a point p of b, |p| <= r in b's frame, sits at R p + T in
// a's frame; it moves by |(R' − R) p + (T' − T)| <= ‖R' − R‖_F r + |T' − T| (the Frobenius norm
// bounds the spectral one). Distances do not change when both meshes move together, so a's
// points in b's frame give a second bound (with a's radius and the inverse poses); the smaller
// serves: a foot's radius, not a 5 m terrain's, multiplies the foot's turn.
//
// Differences from Klamp't: Klamp't searches the hierarchies every step (PQP/FCL distance with a
// tolerance). Units: m.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "core/math_types.h"

namespace lamina::core {

/// The slack the candidates are collected with: this fraction of the tolerance (padding sum), at
/// least kNearPairMinimumSlack. A resting or slowly moving pair collects once in many steps.
inline constexpr double kNearPairSlackFraction = 0.5;
inline constexpr double kNearPairMinimumSlack = 1e-3;

/// The candidate pairs of one pair of meshes (one pair of bodies of the contact set).
struct NearPairCache {
  std::uint64_t mesh_a = 0;  ///< the meshes' serial numbers (never reused; 0: nothing kept)
  std::uint64_t mesh_b = 0;
  double tolerance = -1.0;  ///< the tolerance the candidates serve (m)
  double slack = 0.0;       ///< how far b may move in a's frame before they are collected again
  Pose X_ab = Pose::Identity();                 ///< b's pose in a's frame when collected
  std::vector<std::pair<int, int>> candidates;  ///< (triangle_a, triangle_b), sorted
  long long collections = 0;                    ///< searches through the hierarchies
  long long reuses = 0;                         ///< queries answered from the candidates
  /// Measure the candidates whose boxes meet without the plane tests first: set after a query
  /// where at least kDirectMeasureHits of them were hits (a ball sunk in its layer), cleared
  /// after one where fewer were (wheels on rough ground). Only the time changes: the plane tests
  /// drop no pair the exact distance would keep.
  bool measure_directly = false;
};

/// The fraction of the pairs whose boxes meet that must be hits before a cache's next query
/// measures them directly (NearPairCache::measure_directly). The plane tests cost about as much
/// as measuring a pair whose corner lies over the other's face, and spare measuring far pairs:
/// stiffness_test.xml's resting balls (97 % hits) take 10 % fewer instructions measuring
/// directly and the bench's ball on its slab (60 %) 8 % less time; ATHLETE's wheels on fractal
/// terrain (14 %) 2 % more instructions, a scanned tray (2 %) 45 % more.
inline constexpr double kDirectMeasureHits = 0.5;

/// A bound on how far any point within `radius` of b's origin moves in a's frame when b's pose
/// there goes from `before` to `after` (m, >= the true largest displacement).
double MotionBound(const Pose& before, const Pose& after, double radius);

/// The slack for candidates of `tolerance` (kNearPairSlackFraction, kNearPairMinimumSlack).
double NearPairSlack(double tolerance);

/// How far the meshes have moved against each other between b's poses `before` and `after` in
/// a's frame: the smaller of b's points' bound (radius_b) and a's points' in b's frame (radius_a).
double RelativeMotionBound(const Pose& before, const Pose& after, double radius_a, double radius_b);

/// Whether `cache` answers a query of meshes `mesh_a`, `mesh_b` (serials) at `tolerance` with b
/// at `X_ab`, the meshes' vertices lying within `radius_a` and `radius_b` of their origins.
bool NearPairCacheHolds(const NearPairCache& cache, std::uint64_t mesh_a, std::uint64_t mesh_b,
                        double tolerance, const Pose& X_ab, double radius_a, double radius_b);

}  // namespace lamina::core
