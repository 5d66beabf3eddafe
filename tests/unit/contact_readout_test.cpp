// SPDX-License-Identifier: MIT
// "Its contacts now" (contact_readout.h): the blend a body's contacts use, the rules as text,
// counts, overlaps, the normal force and the soft-contact ERP/CFM, checked against the analytic
// blends and against what the contact joints were actually given.
#include "core/sim/contact_readout.h"

#include <cmath>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/model/params.h"
#include "core/number_text.h"
#include "tests/common/scene_builders.h"
#include "tests/common/test_support.h"

namespace lamina::core {
namespace {

using ::testing::HasSubstr;

constexpr double kBoxMass = 1.0;  // kg
using test::kBoxSide;

// a soft box (e 0.2, μ 0.5, k 2e5, c 2e3) resting on a soft ground (e 0.6, μ 1, k 6e5, c 6e3)
WorldDesc SoftBoxOnGround() {
  WorldDesc world;
  world.terrains.push_back(test::PlaneTerrain(1.0, 0.6));
  world.terrains[0].sim.surface.stiffness = 6e5;
  world.terrains[0].sim.surface.damping = 6e3;
  world.objects.push_back(test::BoxObject(kBoxSide, kBoxMass, Vec3(0, 0, kBoxSide / 2)));
  world.objects[0].sim.surface = {0.2, 0.5, 2e5, 2e3};
  return world;
}

constexpr int kGroundId = 0, kBoxId = 1;  // world ids

double Harmonic(double a, double b) {
  return 2 * a * b / (a + b);
}

TEST(ContactReadoutTest, ABoxOnGroundReadsTheAnalyticBlendAndItsWeight) {
  Simulator sim(SoftBoxOnGround());
  sim.EnableContactFeedback(kBoxId, kGroundId);
  sim.Simulate(1.0);  // settled: the overdamped layer (c = 1500 > 2 √(k m) = 775) rests in ms
  const std::vector<PairReadout> readouts = ReadContacts(sim, kBoxId);
  ASSERT_EQ(readouts.size(), 1u);
  const PairReadout& r = readouts[0];
  EXPECT_EQ(r.partner, kGroundId);
  EXPECT_EQ(r.partner_name, "ground");
  EXPECT_DOUBLE_EQ(r.friction.value, Harmonic(0.5, 1.0));  // 2/3
  EXPECT_DOUBLE_EQ(r.restitution.value, 0.4);
  EXPECT_DOUBLE_EQ(r.stiffness.value, 1.5e5);  // 1 / (1/2e5 + 1/6e5)
  EXPECT_DOUBLE_EQ(r.damping.value, 1.5e3);
  EXPECT_EQ(r.friction.own, 0.5);
  EXPECT_EQ(r.friction.partner, 1.0);
  EXPECT_EQ(r.friction.rule, "harmonic mean of 0.5 (box) and 1 (ground)");
  EXPECT_EQ(r.restitution.rule, "mean of 0.2 (box) and 0.6 (ground)");
  EXPECT_EQ(r.stiffness.rule, "series: 1/(1/ka + 1/kb) of " + FormatDouble(2e5) + " (box) and " +
                                  FormatDouble(6e5) + " (ground)");
  EXPECT_THAT(r.damping.rule, HasSubstr("1/(1/ca + 1/cb)"));
  // a box face on a plane: its four corners
  EXPECT_EQ(r.contact_count, 4);
  // the pair pushes with k times its deepest overlap: m g / k = 65 µm, within the 2.5 mm padding
  const double weight = kBoxMass * sim.world().settings.gravity.norm();
  EXPECT_LE(r.max_depth, r.padding_sum);
  EXPECT_DOUBLE_EQ(r.padding_sum, 0.0025);
  EXPECT_NEAR(r.max_depth, weight / 1.5e5, 0.01 * weight / 1.5e5);
  ASSERT_TRUE(r.normal_force_known);
  EXPECT_NEAR(r.normal_force, weight, 0.01 * weight);
  // the pair's soft contact: ERP = h k / (h k + c), CFM = 1 / (h k + c) at h = 1 ms
  const double h = sim.sim_step(), hk = h * 1.5e5;
  EXPECT_TRUE(r.soft);
  EXPECT_DOUBLE_EQ(r.erp, hk / (hk + 1.5e3));
  EXPECT_DOUBLE_EQ(r.cfm, 1.0 / (hk + 1.5e3));
  EXPECT_THAT(r.law, HasSubstr("soft: ERP "));
  // the ground sees the same pair from its side
  const std::vector<PairReadout> ground = ReadContacts(sim, kGroundId);
  ASSERT_EQ(ground.size(), 1u);
  EXPECT_EQ(ground[0].partner, kBoxId);
  EXPECT_EQ(ground[0].friction.value, r.friction.value);
  EXPECT_EQ(ground[0].friction.rule, "harmonic mean of 1 (ground) and 0.5 (box)");
  EXPECT_NEAR(ground[0].normal_force, weight, 0.01 * weight);  // along normals into the ground
}

TEST(ContactReadoutTest, WithoutFeedbackTheForceIsSaidToBeUnknown) {
  Simulator sim(SoftBoxOnGround());
  sim.Simulate(0.1);
  const std::vector<PairReadout> readouts = ReadContacts(sim, kBoxId);
  ASSERT_EQ(readouts.size(), 1u);
  EXPECT_FALSE(readouts[0].normal_force_known);
  EXPECT_EQ(readouts[0].normal_force, 0.0);
  EXPECT_THAT(readouts[0].normal_force_note, HasSubstr("feedback is not recorded"));
}

// two rigid boxes stacked on a rigid-cored ground, a sphere far above, all default surfaces
WorldDesc StackAndSphere() {
  WorldDesc world;
  world.terrains.push_back(test::PlaneTerrain(0.5, 0.0));
  world.objects.push_back(test::BoxObject(kBoxSide, kBoxMass, Vec3(0, 0, kBoxSide / 2)));
  world.objects.push_back(test::BoxObject(kBoxSide, kBoxMass, Vec3(0, 0, 1.5 * kBoxSide + 0.0025)));
  world.objects[1].name = "upper";
  world.objects.push_back(test::SphereObject(0.05, 1.0, Vec3(2, 0, 3)));
  return world;
}

TEST(ContactReadoutTest, AStackListsEachBoxsOwnPartners) {
  Simulator sim(StackAndSphere());
  sim.EnableContactFeedbackAll();
  sim.Simulate(0.5);
  const int lower = 1, upper = 2, sphere = 3;
  const std::vector<PairReadout> top = ReadContacts(sim, upper);
  ASSERT_EQ(top.size(), 1u);
  EXPECT_EQ(top[0].partner, lower);
  EXPECT_EQ(top[0].partner_name, "box");
  const double weight = kBoxMass * 9.8;
  EXPECT_NEAR(top[0].normal_force, weight, 0.01 * weight);
  // rigid on rigid: a hard contact, its stiffness inf by the rule that says so
  EXPECT_FALSE(top[0].soft);
  EXPECT_EQ(top[0].law, "hard");
  EXPECT_EQ(top[0].stiffness.value, kInf);
  EXPECT_EQ(top[0].stiffness.rule, "both sides rigid: inf (hard contact)");
  EXPECT_EQ(top[0].friction.rule, "harmonic mean of 0.5 (upper) and 0.5 (box)");
  const std::vector<PairReadout> bottom = ReadContacts(sim, lower);
  ASSERT_EQ(bottom.size(), 2u);
  EXPECT_TRUE((bottom[0].partner == 0 && bottom[1].partner == upper) ||
              (bottom[1].partner == 0 && bottom[0].partner == upper));
  for (const PairReadout& r : bottom) {
    // the ground carries both boxes, the upper box presses on the lower one: both push into it
    const double expected = r.partner == 0 ? 2 * weight : weight;
    EXPECT_NEAR(r.normal_force, expected, 0.01 * weight) << r.partner_name;
    EXPECT_LE(r.max_depth, r.padding_sum);
  }
  EXPECT_TRUE(ReadContacts(sim, sphere).empty());  // falling, 2 m above anything
}

TEST(ContactReadoutTest, AnIdThatIsNoBodyGivesNothing) {
  Simulator sim(StackAndSphere());
  sim.Simulate(0.01);
  EXPECT_TRUE(ReadContacts(sim, -1).empty());
  EXPECT_TRUE(ReadContacts(sim, 99).empty());
  EXPECT_EQ(BodyLabel(sim.world(), 99), "id 99");
  EXPECT_THROW(sim.PairSurface(1, 99), std::out_of_range);
}

TEST(ContactReadoutTest, AFrictionEditReachesTheReadoutAndTheJointsAtTheNextStep) {
  Simulator sim(SoftBoxOnGround());
  sim.EnableContactFeedback(kBoxId, kGroundId);
  sim.Simulate(0.1);
  const auto joint_friction = [&] {
    const std::vector<FeedbackContact> contacts = sim.GetContacts(kBoxId, kGroundId);
    EXPECT_FALSE(contacts.empty());
    for (const FeedbackContact& c : contacts) EXPECT_EQ(c.friction, contacts[0].friction);
    return contacts.empty() ? -1.0 : contacts[0].friction;  // what the ODE joints got (row.mu)
  };
  EXPECT_DOUBLE_EQ(joint_friction(), Harmonic(0.5, 1.0));
  std::string error;
  ASSERT_TRUE(sim.SetParam(ElementIndex::Object(0), *FindParam("kFriction", ElementKind::kObject),
                           {0.2}, &error))
      << error;
  EXPECT_DOUBLE_EQ(ReadContacts(sim, kBoxId)[0].friction.value, Harmonic(0.2, 1.0));
  EXPECT_EQ(ReadContacts(sim, kBoxId)[0].friction.rule,
            "harmonic mean of 0.2 (box) and 1 (ground)");
  sim.Simulate(sim.sim_step());
  EXPECT_DOUBLE_EQ(joint_friction(), Harmonic(0.2, 1.0));
  EXPECT_EQ(joint_friction(), ReadContacts(sim, kBoxId)[0].friction.value);
}

// rolling and spinning friction read as the contact rows use them: off while either side is 0
TEST(ContactReadoutTest, RollingAndSpinningFrictionReadTheirBlendAndRule) {
  WorldDesc world = SoftBoxOnGround();
  world.objects[0].sim.surface.rolling_friction = 0.002;
  world.terrains[0].sim.surface.rolling_friction = 0.006;
  world.terrains[0].sim.surface.spinning_friction = 0.001;
  Simulator sim(world);
  sim.Simulate(0.1);
  const std::vector<PairReadout> readouts = ReadContacts(sim, kBoxId);
  ASSERT_EQ(readouts.size(), 1u);
  EXPECT_DOUBLE_EQ(readouts[0].rolling.value, Harmonic(0.002, 0.006));  // 0.003
  EXPECT_EQ(readouts[0].rolling.own, 0.002);
  EXPECT_EQ(readouts[0].rolling.partner, 0.006);
  EXPECT_EQ(readouts[0].rolling.rule, "harmonic mean of 0.002 (box) and 0.006 (ground)");
  EXPECT_EQ(readouts[0].spinning.value, 0.0);
  EXPECT_EQ(readouts[0].spinning.rule, "off on one side (box): 0");
  EXPECT_EQ(readouts[0].rolling.value, sim.PairSurface(kBoxId, kGroundId).rolling);
  EXPECT_EQ(DescribeResistance(0.0, 0.0, "box", "ground"), "off on both sides: 0");
  EXPECT_EQ(DescribeResistance(0.01, 0.0, "box", "ground"), "off on one side (ground): 0");
}

TEST(BlendRuleTextTest, EachBranchOfTheBlendIsNamed) {
  EXPECT_EQ(DescribeFriction(kInf, 0.5, "box", "floor"),
            "one side infinite (box): twice 0.5 (floor)");
  EXPECT_EQ(DescribeFriction(0.5, kInf, "box", "floor"),
            "one side infinite (floor): twice 0.5 (box)");
  EXPECT_EQ(DescribeFriction(kInf, kInf, "box", "floor"), "both sides infinite: inf");
  EXPECT_EQ(DescribeFriction(0.0, 0.5, "box", "floor"), "one side frictionless (box): 0");
  EXPECT_EQ(DescribeLayer("k", kInf, 2e5, "box", "floor"),
            "one side rigid (box): the other side's " + FormatDouble(2e5) + " (floor)");
  EXPECT_EQ(DescribeLayer("c", 0.0, 10.0, "box", "floor"), "one side c = 0 (box): 0");
  // the texts match the values BlendSurfaces gives in those branches
  const BlendedSurface one_rigid = BlendSurfaces({0, kInf, kInf, 3.0}, {0, 0.5, 2e5, kInf});
  EXPECT_EQ(one_rigid.friction, 1.0);  // twice 0.5
  EXPECT_EQ(one_rigid.stiffness, 2e5);
  EXPECT_EQ(one_rigid.damping, 3.0);
  EXPECT_EQ(BlendSurfaces({0, 0.0, 1, 0.0}, {0, 0.5, 1, 10}).friction, 0.0);
}

}  // namespace
}  // namespace lamina::core
