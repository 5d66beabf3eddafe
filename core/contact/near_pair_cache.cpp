// SPDX-License-Identifier: MIT
#include "core/contact/near_pair_cache.h"

#include <algorithm>
#include <cmath>

namespace lamina::core {

double MotionBound(const Pose& before, const Pose& after, double radius) {
  const double turn = (after.linear() - before.linear()).norm();  // Frobenius
  const double shift = (after.translation() - before.translation()).norm();
  return turn * radius + shift;
}

double NearPairSlack(double tolerance) {
  return std::max(kNearPairSlackFraction * tolerance, kNearPairMinimumSlack);
}

double RelativeMotionBound(const Pose& before, const Pose& after, double radius_a,
                           double radius_b) {
  return std::min(MotionBound(before, after, radius_b),
                  MotionBound(before.inverse(), after.inverse(), radius_a));
}

bool NearPairCacheHolds(const NearPairCache& cache, std::uint64_t mesh_a, std::uint64_t mesh_b,
                        double tolerance, const Pose& X_ab, double radius_a, double radius_b) {
  if (cache.mesh_a == 0 || cache.mesh_a != mesh_a || cache.mesh_b != mesh_b) return false;
  if (cache.tolerance != tolerance) return false;
  const double moved = RelativeMotionBound(cache.X_ab, X_ab, radius_a, radius_b);
  // (a margin far above the rounding of the bound itself; NaN fails)
  return moved <= cache.slack * (1.0 - 1e-6);
}

}  // namespace lamina::core
