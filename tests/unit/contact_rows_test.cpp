// SPDX-License-Identifier: MIT
// The contact law as rows, without ODE (contact_rows.h): stiffness shares that add up to the
// pair's k·d_max whatever the clustering, soft and hard rows, bounce suppression, the friction
// direction and the anchor's correction on it, the core row under a pressed-through layer.
#include "core/sim/contact_rows.h"

#include <gtest/gtest.h>

namespace lamina::core {
namespace {

constexpr double kStep = 0.001;

Contact At(const Vec3& position, double depth) {
  Contact contact;
  contact.position = position;
  contact.normal = Vec3::UnitZ();
  contact.depth = depth;
  return contact;
}

ContactPair PairOf(std::vector<Contact> contacts, double tolerance) {
  ContactPair pair;
  pair.a = 1;
  pair.b = 0;
  pair.tolerance = tolerance;
  pair.contacts = std::move(contacts);
  for (const Contact& c : pair.contacts) pair.max_depth = std::max(pair.max_depth, c.depth);
  return pair;
}

// the spring force k_i·d_i of a soft row (ERP = h k / (h k + c) and CFM = 1 / (h k + c) give
// k = ERP / (h CFM))
double RowStiffness(const ContactRow& row) {
  return row.erp / (kStep * row.cfm);
}

TEST(ContactRowsTest, SoftSharesAddUpToThePairsSpringAtItsDeepestOverlap) {
  const double k = 1e4, c = 50.0;
  const ContactPair pair =
      PairOf({At(Vec3(0, 0, 0), 0.004), At(Vec3(1, 0, 0), 0.002), At(Vec3(0, 1, 0), 0.001)}, 0.01);
  const PairLaw law = MakePairLaw(pair, {0.0, 0.5, k, c}, kStep);
  ASSERT_TRUE(law.pushes);
  ASSERT_TRUE(law.soft.soft);
  double force = 0.0, damping = 0.0;
  for (const Contact& contact : pair.contacts) {
    const ContactRow row = MakeContactRow(contact, law, Vec3::Zero(), Vec3::Zero(), kStep, {});
    EXPECT_FALSE(row.bounce);  // soft layers never bounce on top of their spring
    EXPECT_FALSE(row.core);
    force += RowStiffness(row) * contact.depth;
    damping += 1.0 / row.cfm - kStep * RowStiffness(row);
  }
  EXPECT_NEAR(force, k * 0.004, 1e-9 * k);  // k times the deepest overlap, not 3 k d
  EXPECT_NEAR(damping, c, 1e-9 * c);
}

TEST(ContactRowsTest, ALayerWithNoStiffnessAndNoDampingMakesNoRows) {
  const ContactPair pair = PairOf({At(Vec3::Zero(), 0.001)}, 0.01);
  EXPECT_FALSE(MakePairLaw(pair, {0.0, 0.5, 0.0, 0.0}, kStep).pushes);
}

TEST(ContactRowsTest, HardRowsCorrectOverlapGentlyAndBounceOnlyAtImpact) {
  const ContactPair pair = PairOf({At(Vec3::Zero(), 0.005)}, 0.01);
  const PairLaw law = MakePairLaw(pair, {0.5, 0.5, kInf, kInf}, kStep);
  const RowSettings settings;  // ERP 0.95, push-out 0.01 m/s, bounce threshold 0.01 m/s
  // resting (closing at 1 mm/s): corrected at 0.01 m/s, i.e. ERP = 0.01·h/d
  const ContactRow resting =
      MakeContactRow(pair.contacts[0], law, Vec3(0, 0, -0.001), Vec3::Zero(), kStep, settings);
  EXPECT_TRUE(resting.bounce);
  EXPECT_DOUBLE_EQ(resting.erp, 0.01 * kStep / 0.005);
  EXPECT_EQ(resting.cfm, kHardContactCfm);  // below the world's 1e-6
  // an impact at 1 m/s: the restitution row sets the rebound and nothing else pushes
  const ContactRow impact =
      MakeContactRow(pair.contacts[0], law, Vec3(0, 0, -1.0), Vec3::Zero(), kStep, settings);
  EXPECT_EQ(impact.erp, 0.0);
  EXPECT_EQ(impact.restitution, 0.5);
  EXPECT_EQ(impact.bounce_velocity, settings.bounce_velocity_threshold);
  // a shallow overlap keeps the world's ERP
  EXPECT_EQ(HardContactErp(1e-7, kStep, settings), settings.erp);
}

// a bouncing row's CFM: the ceiling 1e-9 for 1 kg at 1 ms (1e-6·h/m is the same), 1e-6·h/m for a
// 10 kg ball at a 0.125 ms sub-step (its rebound then short of e·v by at most 1e-6·(1 + e)·v); a
// resting row keeps the ceiling, whatever the mass
TEST(ContactRowsTest, ABouncingRowsCfmIsBoundedByItsInverseMassAndStep) {
  const ContactPair pair = PairOf({At(Vec3::Zero(), 0.001)}, 0.01);
  const RowSettings settings;
  PairLaw law = MakePairLaw(pair, {1.0, 0.5, kInf, kInf}, kStep);
  law.inverse_mass = 1.0;
  const ContactRow light =
      MakeContactRow(pair.contacts[0], law, Vec3(0, 0, -5.0), Vec3::Zero(), kStep, settings);
  EXPECT_DOUBLE_EQ(light.cfm, kHardContactCfm);
  law.inverse_mass = 0.1;
  const double sub_step = kStep / 8;
  const ContactRow heavy =
      MakeContactRow(pair.contacts[0], law, Vec3(0, 0, -5.0), Vec3::Zero(), sub_step, settings);
  EXPECT_DOUBLE_EQ(heavy.cfm, 1e-6 * sub_step * 0.1);
  const ContactRow resting =
      MakeContactRow(pair.contacts[0], law, Vec3(0, 0, -0.001), Vec3::Zero(), sub_step, settings);
  EXPECT_EQ(resting.cfm, kHardContactCfm);
  law.inverse_mass = 0.0;  // not known: the ceiling
  EXPECT_EQ(
      MakeContactRow(pair.contacts[0], law, Vec3(0, 0, -5.0), Vec3::Zero(), sub_step, settings).cfm,
      kHardContactCfm);
}

TEST(ContactRowsTest, FrictionOpposesSlidingLessTheAnchorCorrection) {
  const ContactPair pair = PairOf({At(Vec3::Zero(), 0.001)}, 0.01);
  const PairLaw law = MakePairLaw(pair, {0.0, 0.5, kInf, kInf}, kStep);
  const ContactRow sliding =
      MakeContactRow(pair.contacts[0], law, Vec3(0.3, 0.4, -0.2), Vec3::Zero(), kStep, {});
  ASSERT_TRUE(sliding.has_direction);
  EXPECT_NEAR((sliding.fdir1 - Vec3(0.6, 0.8, 0)).norm(), 0.0, 1e-15);
  EXPECT_FALSE(sliding.has_motion);
  // sticking with an anchor correction: ODE's own axes, the correction asked along them
  const Vec3 anchor(0.002, -0.001, 0.0);
  const ContactRow held = MakeContactRow(pair.contacts[0], law, anchor, anchor, kStep, {});
  EXPECT_FALSE(held.has_direction);
  ASSERT_TRUE(held.has_motion);
  EXPECT_NEAR(std::hypot(held.motion1, held.motion2), anchor.norm(), 1e-15);
  EXPECT_EQ(held.mu, 0.5);
}

TEST(ContactRowsTest, APressedThroughSoftLayerGetsAHardCoreRowAtTheCoresDepth) {
  const ContactPair pair = PairOf({At(Vec3::Zero(), 0.012)}, 0.01);
  const PairLaw law = MakePairLaw(pair, {0.0, 0.5, 1e3, 10.0}, kStep);
  const ContactRow row =
      MakeContactRow(pair.contacts[0], law, Vec3::Zero(), Vec3::Zero(), kStep, {});
  ASSERT_TRUE(row.core);
  EXPECT_NEAR(row.core_depth, 0.002, 1e-15);
  EXPECT_DOUBLE_EQ(row.core_erp, 0.01 * kStep / 0.002);
  const dContact core = ToOdeContact(row, pair.contacts[0], true);
  EXPECT_NEAR(core.geom.depth, 0.002, 1e-15);
  EXPECT_EQ(core.surface.mode & dContactBounce, 0);
  const dContact soft = ToOdeContact(row, pair.contacts[0]);
  EXPECT_EQ(soft.geom.depth, 0.012);
  EXPECT_EQ(soft.surface.soft_erp, row.erp);
}

// Rolling and spinning friction become ODE's rolling rows: dContactRolling with dContactAxisDep
// (mu2 = mu, so the sliding friction is unchanged), rho = rho2 = rolling, rhoN = spinning, and -1
// for an axis that is off (ODE clamps it to 0 and counts no row for it). Off, the joint is
// exactly the joint without them.
TEST(ContactRowsTest, RollingAndSpinningFrictionBecomeOdesRollingRows) {
  const ContactPair pair = PairOf({At(Vec3::Zero(), 0.001)}, 0.01);
  auto joint = [&](double rolling, double spinning) {
    BlendedSurface surface{0.0, 0.5, kInf, kInf, rolling, spinning};
    const PairLaw law = MakePairLaw(pair, surface, kStep);
    const ContactRow row =
        MakeContactRow(pair.contacts[0], law, Vec3(0.3, 0, 0), Vec3::Zero(), kStep, {});
    EXPECT_EQ(row.rolling, rolling);
    EXPECT_EQ(row.spinning, spinning);
    return ToOdeContact(row, pair.contacts[0]);
  };
  const dContact off = joint(0.0, 0.0);
  EXPECT_EQ(off.surface.mode, dContactApprox1 | dContactSoftERP | dContactSoftCFM | dContactFDir1);
  EXPECT_EQ(off.surface.rho, 0.0);
  EXPECT_EQ(off.surface.rhoN, 0.0);

  const dContact both = joint(0.004, 0.002);
  EXPECT_EQ(both.surface.mode, off.surface.mode | dContactRolling | dContactAxisDep);
  EXPECT_EQ(both.surface.mu, 0.5);
  EXPECT_EQ(both.surface.mu2, 0.5);
  EXPECT_EQ(both.surface.rho, 0.004);
  EXPECT_EQ(both.surface.rho2, 0.004);
  EXPECT_EQ(both.surface.rhoN, 0.002);
  // the bounds are proportional to the normal force on all three axes
  EXPECT_EQ(both.surface.mode & dContactApprox1_N, dContactApprox1_N);

  const dContact rolling_only = joint(0.004, 0.0);
  EXPECT_EQ(rolling_only.surface.rho, 0.004);
  EXPECT_EQ(rolling_only.surface.rhoN, -1.0);
  const dContact spinning_only = joint(0.0, 0.002);
  EXPECT_EQ(spinning_only.surface.rho, -1.0);
  EXPECT_EQ(spinning_only.surface.rho2, -1.0);
  EXPECT_EQ(spinning_only.surface.rhoN, 0.002);
  // the hard core row under a pressed-through soft layer resists rolling too (its own N)
  const ContactPair pressed = PairOf({At(Vec3::Zero(), 0.012)}, 0.01);
  const PairLaw soft = MakePairLaw(pressed, {0.0, 0.5, 1e3, 10.0, 0.004, 0.0}, kStep);
  const ContactRow row =
      MakeContactRow(pressed.contacts[0], soft, Vec3::Zero(), Vec3::Zero(), kStep, {});
  ASSERT_TRUE(row.core);
  EXPECT_EQ(ToOdeContact(row, pressed.contacts[0], true).surface.rho, 0.004);
}

// ODE bounds each rolling axis separately, so the friction axes follow the rolling while the
// contact rolls rather than slides: n × fdir1 is the rolling axis and only that row resists it
TEST(ContactRowsTest, TheFrictionAxesFollowTheRollingWhileTheContactRolls) {
  const ContactPair pair = PairOf({At(Vec3::Zero(), 0.001)}, 0.01);
  const Vec3 spin(3.0, 4.0, 2.0);  // rad/s; the normal part (2) is spinning, not rolling
  auto row = [&](double rolling, const Vec3& sliding) {
    const PairLaw law = MakePairLaw(pair, {0.0, 0.5, kInf, kInf, rolling, 0.0}, kStep);
    return MakeContactRow(pair.contacts[0], law, sliding, Vec3::Zero(), kStep, {}, spin);
  };
  // rolling without slipping: t1 = axis × n, so that n × t1 is the rolling axis (0.6, 0.8, 0)
  const ContactRow rolls = row(0.005, Vec3::Zero());
  ASSERT_TRUE(rolls.has_direction);
  EXPECT_NEAR((rolls.fdir1 - Vec3(0.8, -0.6, 0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((Vec3::UnitZ().cross(rolls.fdir1) - Vec3(0.6, 0.8, 0)).norm(), 0.0, 1e-15);
  // a slow slide too: ρ |ω_t| = 0.025 dissipates more than μ |v| = 0.005
  EXPECT_NEAR((row(0.005, Vec3(0, 0.01, 0)).fdir1 - Vec3(0.8, -0.6, 0)).norm(), 0.0, 1e-15);
  // a real slide keeps the axes on the sliding (μ |v| = 0.25 > 0.025)
  EXPECT_NEAR((row(0.005, Vec3(0, 0.5, 0)).fdir1 - Vec3::UnitY()).norm(), 0.0, 1e-15);
  // without rolling friction the rotation is not read: ODE's own axes, as before
  EXPECT_FALSE(row(0.0, Vec3::Zero()).has_direction);
}

}  // namespace
}  // namespace lamina::core
