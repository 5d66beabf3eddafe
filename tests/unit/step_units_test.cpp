// SPDX-License-Identifier: MIT
// The pure units of the simulator's step, each without a simulation: the broad phase (sorted,
// filtered candidates), the rollback rules, the contact-energy allowance, sleep islands and the
// one change rule (body_change.h).
#include <gtest/gtest.h>

#include "core/sim/body_change.h"
#include "core/sim/broad_phase.h"
#include "core/sim/sleep.h"
#include "core/sim/step_guard.h"

namespace lamina::core {
namespace {

Eigen::AlignedBox3d Box(double x0, double x1, double y0 = 0, double y1 = 1) {
  return Eigen::AlignedBox3d(Vec3(x0, y0, 0), Vec3(x1, y1, 1));
}

TEST(BroadPhaseTest, OverlappingPairsComeOutSortedWhateverTheirPositions) {
  // ids 0..4; 3 lies left of everything, 4 is far away in y
  const std::vector<Eigen::AlignedBox3d> bounds = {Box(0, 2), Box(1, 3), Box(2.5, 4), Box(-5, 0.5),
                                                   Box(0, 4, 10, 11)};
  BroadPhase broad;
  broad.Find(
      {0, 1, 2, 3, 4}, [&](int id) -> const auto& { return bounds[id]; },
      [](int, int) { return true; });
  const CandidatePairs expected = {{0, 1}, {0, 3}, {1, 2}};
  EXPECT_EQ(broad.candidates(), expected);
  // the filter removes pairs; ids not listed take no part
  broad.Find(
      {0, 1, 2}, [&](int id) -> const auto& { return bounds[id]; },
      [](int a, int b) { return a + b != 1; });
  EXPECT_EQ(broad.candidates(), (CandidatePairs{{1, 2}}));
}

TEST(BroadPhaseTest, TouchingBoundsOverlapAndAPlaneBoundsEverything) {
  const std::vector<Eigen::AlignedBox3d> bounds = {Box(0, 1), Box(1, 2)};
  BroadPhase broad;
  broad.Find(
      {1, 0}, [&](int id) -> const auto& { return bounds[id]; }, [](int, int) { return true; });
  EXPECT_EQ(broad.candidates(), (CandidatePairs{{0, 1}}));
  EXPECT_TRUE(BoundsOverlapInYZ(Box(0, 1, 0, 1), Box(5, 6, 1, 2)));
  EXPECT_FALSE(BoundsOverlapInYZ(Box(0, 1, 0, 1), Box(5, 6, 1.5, 2)));
}

ContactPair Pair(int a, int b, double depth, double tolerance, bool penetrating = false) {
  ContactPair pair;
  pair.a = a;
  pair.b = b;
  pair.max_depth = depth;
  pair.tolerance = tolerance;
  pair.penetrating = penetrating;
  pair.contacts.resize(1);
  return pair;
}

TEST(RollbackTest, UsingUpMoreThanHalfTheLayerAtOnceIsRetaken) {
  bool unreliable = false;
  // 0.2 of 1 cm used before, 0.7 after: more than half of the layer gone, more than half of what
  // remained, and far more than settling noise
  EXPECT_TRUE(NeedsRollback({Pair(1, 0, 0.002, 0.01)}, {Pair(1, 0, 0.007, 0.01)}, &unreliable));
  EXPECT_FALSE(unreliable);
  // a new pair entering deep at once
  EXPECT_TRUE(NeedsRollback({}, {Pair(1, 0, 0.006, 0.01)}, &unreliable));
  // settling noise at a pair already deep is no reason
  EXPECT_FALSE(NeedsRollback({Pair(1, 0, 0.0060, 0.01)}, {Pair(1, 0, 0.0065, 0.01)}, &unreliable));
  // nor using less than half of the layer
  EXPECT_FALSE(NeedsRollback({Pair(1, 0, 0.0, 0.01)}, {Pair(1, 0, 0.004, 0.01)}, &unreliable));
}

TEST(RollbackTest, NewInterpenetrationIsRetakenOldOrPressedThroughIsOnlyReported) {
  bool unreliable = false;
  EXPECT_TRUE(
      NeedsRollback({Pair(1, 0, 0.002, 0.01)}, {Pair(1, 0, 0.011, 0.01, true)}, &unreliable));
  EXPECT_TRUE(unreliable);
  unreliable = false;
  EXPECT_FALSE(
      NeedsRollback({Pair(1, 0, 0.011, 0.01, true)}, {Pair(1, 0, 0.012, 0.01, true)}, &unreliable));
  EXPECT_TRUE(unreliable);
  // a layer pressed through before (less than 1 % left) rests on its core
  EXPECT_FALSE(
      NeedsRollback({Pair(1, 0, 0.00995, 0.01)}, {Pair(1, 0, 0.0101, 0.01, true)}, &unreliable));
}

TEST(RollbackTest, PairsAreMatchedByTheirIdsInOneMerge) {
  bool unreliable = false;
  // pairs (0,1) and (0,3) before; after, (0,2) is new and shallow, (0,3) deepened a little
  const std::vector<ContactPair> before = {Pair(1, 0, 0.001, 0.01), Pair(3, 0, 0.005, 0.01)};
  const std::vector<ContactPair> after = {Pair(2, 0, 0.001, 0.01), Pair(3, 0, 0.0055, 0.01)};
  EXPECT_FALSE(NeedsRollback(before, after, &unreliable));
  // the same depth after without the pair before would be a jump
  EXPECT_TRUE(NeedsRollback({before[0]}, {Pair(3, 0, 0.0055, 0.01)}, &unreliable));
}

TEST(ContactEnergyAllowanceTest, CorrectionAnchorAndSpringEnergy) {
  ContactPair soft = Pair(4, 0, 0.002, 0.01);
  soft.anchor_speed = 0.05;
  const ContactPair other = Pair(5, 0, 0.003, 0.01);
  const auto stiffness = [](const ContactPair& pair) { return pair.a == 4 ? 1e4 : kInf; };
  const double h = 0.001, m = 2.0;
  const double expected =
      0.5 * m * (0.002 / h) * (0.002 / h) + 0.5 * m * 0.05 * 0.05 + 0.5 * 1e4 * 0.002 * 0.002;
  std::vector<double> masses(7, m), allowances;
  ContactEnergyAllowances({soft, other}, masses, stiffness, h, &allowances);
  ASSERT_EQ(allowances.size(), 7u);
  EXPECT_DOUBLE_EQ(allowances[4], expected);
  EXPECT_DOUBLE_EQ(allowances[5], 0.5 * m * (0.003 / h) * (0.003 / h));
  EXPECT_EQ(allowances[6], 0.0);
  // the other side of both pairs (id 0) has both, with its own mass
  masses[0] = 4.0;
  ContactEnergyAllowances({soft, other}, masses, stiffness, h, &allowances);
  // 0.5·4·(2² + 0.05²) + 0.5·1e4·0.002² + 0.5·4·3² = 8.005 + 0.02 + 18
  EXPECT_NEAR(allowances[0], 26.025, 1e-12);
}

TEST(SleepIslandsTest, AnIslandSleepsOnlyWhenAllItsMembersAreReady) {
  // islands {0, 1, 2} (a chain), {3, 4}, {5}
  std::vector<char> ready = {1, 1, 0, 1, 1, 1};
  std::vector<int> parent;
  IslandsReady(6, {{0, 1}, {2, 1}, {3, 4}}, &ready, &parent);
  EXPECT_EQ(ready, (std::vector<char>{0, 0, 0, 1, 1, 1}));
  ready = {1, 1, 1, 0, 1, 0};
  IslandsReady(6, {{0, 1}, {2, 1}, {3, 4}}, &ready, &parent);
  EXPECT_EQ(ready, (std::vector<char>{1, 1, 1, 0, 0, 0}));
}

TEST(BodyChangeTest, EachChangeInvalidatesAndWakesExactlyWhatTheTableSays) {
  using E = ChangeEffects;
  // {contacts stale, energy forgotten, anchors dropped, wake body, wake touching}
  EXPECT_EQ(BodyChangeEffects(kPoseChanged), (E{true, true, true, true, true}));
  EXPECT_EQ(BodyChangeEffects(kVelocityChanged), (E{false, true, false, true, false}));
  EXPECT_EQ(BodyChangeEffects(kShapeChanged), (E{true, false, false, true, true}));
  EXPECT_EQ(BodyChangeEffects(kSurfaceChanged), (E{false, false, false, true, true}));
  EXPECT_EQ(BodyChangeEffects(kEnabled), (E{true, true, false, true, false}));
  EXPECT_EQ(BodyChangeEffects(kDisabled), (E{true, true, false, false, true}));
  EXPECT_EQ(BodyChangeEffects(kKindChanged), (E{true, true, false, true, true}));
  EXPECT_EQ(BodyChangeEffects(kForceApplied), (E{false, false, false, true, false}));
  EXPECT_EQ(BodyChangeEffects(0), E{});
  // a teleport with a new velocity (FakeSimulate) is the union
  EXPECT_EQ(BodyChangeEffects(kPoseChanged | kVelocityChanged), BodyChangeEffects(kPoseChanged));
}

}  // namespace
}  // namespace lamina::core
