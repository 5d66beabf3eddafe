// SPDX-License-Identifier: MIT
// Contact feedback: forces that balance gravity, one sign convention (force on a, normal into a;
// swapping the pair negates), torques about the world origin, and the contact/separation flags.
#include <gtest/gtest.h>

#include "core/sim/simulator.h"
#include "tests/common/scene_builders.h"
#include "tests/common/test_support.h"

namespace lamina {
namespace {

using core::Vec3;

using test::kGravity;

core::WorldDesc BoxOnGround(const Vec3& position, double mass) {
  core::WorldDesc world;
  world.terrains.push_back(test::PlaneTerrain(0.5, 0.0));
  core::RigidObjectDesc box = test::BoxObject(0.2, mass, position);
  box.sim.surface.restitution = 0.0;
  world.objects.push_back(box);
  return world;
}

TEST(ContactFeedbackTest, RestingBoxIsHeldByItsWeightWithOneSignConvention) {
  const double mass = 2.0;
  const core::WorldDesc world = BoxOnGround(Vec3(1.0, 0.5, 0.1025), mass);
  core::Simulator simulator(world);
  const int ground = world.TerrainId(0), box = world.ObjectId(0);
  simulator.EnableContactFeedback(box, ground);
  simulator.Simulate(1.0);  // settle
  simulator.Simulate(0.1);
  const Vec3 weight(0, 0, mass * kGravity);
  // the bar: the resting box reports m g within 1 %
  const Vec3 mean = simulator.MeanContactForce(box, ground);
  EXPECT_NEAR(mean.z(), weight.z(), 0.01 * weight.z());
  EXPECT_NEAR(mean.head<2>().norm(), 0.0, 1e-6 * weight.z());
  const Vec3 last = simulator.ContactForce(box, ground);
  EXPECT_NEAR(last.z(), weight.z(), 0.01 * weight.z());
  // swapping the pair negates force, torque and normals exactly
  EXPECT_EQ(simulator.MeanContactForce(ground, box), -mean);
  EXPECT_EQ(simulator.ContactForce(ground, box), -last);
  EXPECT_EQ(simulator.ContactTorque(ground, box), -simulator.ContactTorque(box, ground));
  // b = -1: everything touching the box is the ground here
  EXPECT_EQ(simulator.ContactForce(box), last);
  // torque about the world origin of an upward force m g through (1, 0.5): (0.5 m g, -m g, 0)
  const Vec3 torque = simulator.ContactTorque(box, ground);
  EXPECT_NEAR(torque.x(), 0.5 * last.z(), 1e-6 * weight.z());
  EXPECT_NEAR(torque.y(), -1.0 * last.z(), 1e-6 * weight.z());
  // the contacts: normals into the first body asked for, forces that add up to ContactForce
  const std::vector<core::FeedbackContact> contacts = simulator.GetContacts(box, ground);
  ASSERT_GE(contacts.size(), 4u);
  Vec3 sum = Vec3::Zero();
  for (const core::FeedbackContact& contact : contacts) {
    EXPECT_NEAR(contact.normal.z(), 1.0, 1e-9);
    EXPECT_DOUBLE_EQ(contact.friction, 0.5);
    sum += contact.force;
  }
  EXPECT_NEAR((sum - last).norm(), 0.0, 1e-9);
  for (const core::FeedbackContact& contact : simulator.GetContacts(ground, box)) {
    EXPECT_NEAR(contact.normal.z(), -1.0, 1e-9);
  }
  EXPECT_EQ(simulator.GetContactForces(box, ground).size(), contacts.size());
  EXPECT_TRUE(simulator.InContact(box, ground));
  EXPECT_TRUE(simulator.HadContact(box, ground));
  EXPECT_FALSE(simulator.HadSeparation(box, ground));
  EXPECT_FALSE(simulator.HadPenetration(box, ground));
}

TEST(ContactFeedbackTest, BoxOnBoxCarriesTheUpperWeight) {
  core::WorldDesc world = BoxOnGround(Vec3(0, 0, 0.1025), 1.0);
  core::RigidObjectDesc top = test::BoxObject(0.2, 3.0, Vec3(0, 0, 0.3075));
  top.sim.surface.restitution = 0.0;
  world.objects.push_back(top);
  core::Simulator simulator(world);
  simulator.EnableContactFeedbackAll();
  const int ground = world.TerrainId(0), lower = world.ObjectId(0), upper = world.ObjectId(1);
  simulator.Simulate(1.0);
  simulator.Simulate(0.1);
  const double upper_weight = 3.0 * kGravity, total_weight = 4.0 * kGravity;
  EXPECT_NEAR(simulator.MeanContactForce(upper, lower).z(), upper_weight, 0.01 * upper_weight);
  EXPECT_NEAR(simulator.MeanContactForce(lower, upper).z(), -upper_weight, 0.01 * upper_weight);
  EXPECT_NEAR(simulator.MeanContactForce(lower, ground).z(), total_weight, 0.01 * total_weight);
  // everything on the lower box: the ground's push minus the upper box's weight
  EXPECT_NEAR(simulator.MeanContactForce(lower).z(), total_weight - upper_weight,
              0.01 * total_weight);
  EXPECT_FALSE(simulator.InContact(upper, ground));
}

TEST(ContactFeedbackTest, LandingIsSeenAsSeparationThenContact) {
  const core::WorldDesc world = BoxOnGround(Vec3(0, 0, 0.2), 1.0);
  core::Simulator simulator(world);
  const int ground = world.TerrainId(0), box = world.ObjectId(0);
  simulator.EnableContactFeedback(ground, box);
  simulator.Simulate(0.05);  // falls 12 mm of the 97.5 mm gap
  EXPECT_FALSE(simulator.InContact(box, ground));
  EXPECT_FALSE(simulator.HadContact(box, ground));
  EXPECT_TRUE(simulator.HadSeparation(box, ground));
  EXPECT_EQ(simulator.ContactForce(box, ground), Vec3::Zero());
  simulator.Simulate(0.2);  // lands after about 0.14 s
  EXPECT_TRUE(simulator.HadSeparation(box, ground));
  EXPECT_TRUE(simulator.HadContact(box, ground));
  EXPECT_TRUE(simulator.InContact(box, ground));
}

TEST(ContactFeedbackTest, UnregisteredPairsFallBackToGeometryForInContactOnly) {
  const core::WorldDesc world = BoxOnGround(Vec3(0, 0, 0.1025), 1.0);
  core::Simulator simulator(world);
  const int ground = world.TerrainId(0), box = world.ObjectId(0);
  simulator.Simulate(0.2);
  EXPECT_TRUE(simulator.InContact(box, ground));
  EXPECT_FALSE(simulator.HadContact(box, ground));
  EXPECT_EQ(simulator.ContactForce(box, ground), Vec3::Zero());
  EXPECT_TRUE(simulator.GetContacts(box, ground).empty());
}

}  // namespace
}  // namespace lamina
