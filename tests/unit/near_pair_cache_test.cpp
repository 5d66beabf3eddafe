// SPDX-License-Identifier: MIT
// The motion bound and the validity rule of kept triangle-pair candidates
// (core/contact/near_pair_cache.h). The cached search itself is compared with a fresh one in
// collision_geometry_test.cpp.
#include "core/contact/near_pair_cache.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

namespace lamina {
namespace {

using core::Pose;
using core::Vec3;

Pose RandomPose(std::mt19937& random, double spread, double angle) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Pose pose = Pose::Identity();
  pose.linear() =
      core::RotationFromRollPitchYaw(angle * u(random), angle * u(random), angle * u(random));
  pose.translation() = spread * Vec3(u(random), u(random), u(random));
  return pose;
}

Vec3 RandomPointWithin(std::mt19937& random, double radius) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Vec3 p;
  do {
    p = Vec3(u(random), u(random), u(random));
  } while (p.norm() > 1.0);
  return radius * p;
}

TEST(NearPairCacheTest, MotionBoundHoldsEveryPointWithinTheRadius) {
  std::mt19937 random(3);
  for (int i = 0; i < 2000; ++i) {
    const double radius = 0.01 + 5.0 * (i % 7) / 7.0;
    const double angle = i % 2 == 0 ? 1e-4 : 1.0;
    const Pose before = RandomPose(random, 1.0, core::kPi);
    const Pose after = before * RandomPose(random, 0.01, angle);
    const double bound = core::MotionBound(before, after, radius);
    for (int k = 0; k < 20; ++k) {
      const Vec3 p = RandomPointWithin(random, radius);
      ASSERT_LE((after * p - before * p).norm(), bound * (1 + 1e-12) + 1e-15) << i;
    }
  }
}

TEST(NearPairCacheTest, MotionBoundIsTightForPureShiftsAndWithinRootTwoForTurns) {
  Pose before = Pose::Identity();
  Pose after = Pose::Identity();
  after.translation() = Vec3(0.003, -0.004, 0.0);
  EXPECT_NEAR(core::MotionBound(before, after, 2.0), 0.005, 1e-15);
  // a turn by θ about z moves a point at radius r by 2 r sin(θ/2); the Frobenius norm of the
  // rotation's change is √2 times the spectral one
  after = Pose::Identity();
  after.linear() = core::RotationFromRollPitchYaw(0.0, 0.0, 0.01);
  const double exact = 2.0 * 0.5 * std::sin(0.005);
  EXPECT_NEAR(core::MotionBound(before, after, 0.5), std::sqrt(2.0) * exact, 1e-12);
}

TEST(NearPairCacheTest, RelativeBoundUsesTheSmallerMeshsRadius) {
  // a 5 cm foot turned by 1 mrad about its own origin over a terrain whose vertices reach 5 m:
  // the terrain's points in the foot's frame sweep 7 mm, the foot's in the terrain's 71 µm
  Pose before = Pose::Identity();
  before.translation() = Vec3(2.0, 1.0, -0.1);  // the terrain in the foot's frame
  Pose turn = Pose::Identity();
  turn.linear() = core::RotationFromRollPitchYaw(0.0, 0.001, 0.0);
  const Pose after = turn * before;
  const double relative = core::RelativeMotionBound(before, after, 0.05, 5.0);
  EXPECT_NEAR(relative, core::MotionBound(before.inverse(), after.inverse(), 0.05), 1e-18);
  EXPECT_LT(relative, 1e-4);
  EXPECT_GT(core::MotionBound(before, after, 5.0), 5e-3);
}

TEST(NearPairCacheTest, CandidatesHoldOnlyForTheSameMeshesToleranceAndSmallMotion) {
  core::NearPairCache cache;
  const Pose X = Pose::Identity();
  EXPECT_FALSE(core::NearPairCacheHolds(cache, 1, 2, 0.01, X, 0.1, 0.1));  // nothing kept
  cache.mesh_a = 1;
  cache.mesh_b = 2;
  cache.tolerance = 0.01;
  cache.slack = core::NearPairSlack(0.01);
  EXPECT_DOUBLE_EQ(cache.slack, 0.005);
  EXPECT_DOUBLE_EQ(core::NearPairSlack(1e-4), core::kNearPairMinimumSlack);
  EXPECT_TRUE(core::NearPairCacheHolds(cache, 1, 2, 0.01, X, 0.1, 0.1));
  EXPECT_FALSE(core::NearPairCacheHolds(cache, 2, 1, 0.01, X, 0.1, 0.1));  // roles swapped
  EXPECT_FALSE(core::NearPairCacheHolds(cache, 1, 3, 0.01, X, 0.1, 0.1));  // another mesh
  EXPECT_FALSE(core::NearPairCacheHolds(cache, 1, 2, 0.02, X, 0.1, 0.1));  // padding edited
  Pose moved = X;
  moved.translation().z() = 0.0049;
  EXPECT_TRUE(core::NearPairCacheHolds(cache, 1, 2, 0.01, moved, 0.1, 0.1));
  moved.translation().z() = 0.005;
  EXPECT_FALSE(core::NearPairCacheHolds(cache, 1, 2, 0.01, moved, 0.1, 0.1));
  moved.translation().z() = std::nan("");
  EXPECT_FALSE(core::NearPairCacheHolds(cache, 1, 2, 0.01, moved, 0.1, 0.1));
}

}  // namespace
}  // namespace lamina
