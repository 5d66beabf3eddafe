// SPDX-License-Identifier: MIT
// The simulator's units that hold ODE bodies, each on a bare ODE world of its own: the body
// table (frames at the centre of mass, held wrenches at a point), the friction anchors (kept
// while a pair sticks, re-anchored when it slides, kept near, dropped far) and the feedback
// recorder (sorted records, one sign convention, no allocation per query).
#include <gtest/gtest.h>
#include <ode/ode.h>

#include "core/sim/body_table.h"
#include "core/sim/contact_feedback.h"
#include "core/sim/friction_anchors.h"
#include "core/sim/ode_conversions.h"
#include "core/sim/ode_handle.h"

namespace lamina::core {
namespace {

constexpr double kUnitsTight = 1e-12;

// an ODE world with a static id 0 and a free unit-mass body at id 1
class OdeUnitTest : public ::testing::Test {
 protected:
  void SetUp() override {
    EnsureOdeInitialized();
    world_ = dWorldCreate();
    bodies_.Reset(2);
    bodies_[0].kind = WorldId::Kind::kTerrain;
    BodyRecord& box = bodies_[1];
    box.kind = WorldId::Kind::kRigidObject;
    box.index = 0;
    box.body = dBodyCreate(world_);
    dMass mass;
    dMassSetBoxTotal(&mass, 1.0, 0.1, 0.1, 0.1);
    dBodySetMass(box.body, &mass);
    box.mass = 1.0;
    bodies_.AddObject(1);
  }
  void TearDown() override { dWorldDestroy(world_); }

  dWorldID world_ = nullptr;
  BodyTable bodies_;
};

TEST_F(OdeUnitTest, TheBodyTablePlacesTheRecordFrameAroundTheCentreOfMass) {
  BodyRecord& box = bodies_[1];
  box.com = Vec3(0.1, 0.0, 0.0);
  box.rotation_in_body = Eigen::AngleAxisd(0.5, Vec3::UnitZ()).toRotationMatrix();
  Pose pose = Pose::Identity();
  pose.linear() = Eigen::AngleAxisd(0.3, Vec3::UnitX()).toRotationMatrix();
  pose.translation() = Vec3(1, 2, 3);
  bodies_.SetPose(box, pose);
  EXPECT_NEAR((bodies_.GetPose(box).matrix() - pose.matrix()).norm(), 0.0, 1e-12);
  EXPECT_NEAR((ToVec3(dBodyGetPosition(box.body)) - pose * box.com).norm(), 0.0, kUnitsTight);
  // the frame origin's velocity: v_com - ω × (com - origin)
  const Twist twist{Vec3(0.5, 0, 0), Vec3(0, 0, 2.0)};
  bodies_.SetVelocity(box, twist);
  const Twist back = bodies_.GetVelocity(box);
  EXPECT_NEAR((back.linear - twist.linear).norm(), 0.0, kUnitsTight);
  EXPECT_NEAR((back.angular - twist.angular).norm(), 0.0, kUnitsTight);
  // the static record stays where it was built
  bodies_[0].fixed_pose.translation() = Vec3(0, 0, -1);
  EXPECT_EQ(bodies_.GetPose(bodies_[0]).translation(), Vec3(0, 0, -1));
  EXPECT_EQ(bodies_.FrameOf(0).position, Vec3::Zero());
}

TEST_F(OdeUnitTest, AHeldForceAtAPointAddsItsMomentEveryStepAndOneCallForcesEnd) {
  BodyRecord& box = bodies_[1];
  bodies_.SetPose(box, Pose::Identity());
  box.held = HeldWrench{Vec3(0, 2, 0), Vec3(0, 0, 0.5), Vec3(0.05, 0, 0), true, true};
  box.force = Vec3(1, 0, 0);
  bodies_.ApplyForces();
  EXPECT_NEAR((ToVec3(dBodyGetForce(box.body)) - Vec3(1, 2, 0)).norm(), 0.0, kUnitsTight);
  // 0.5 N·m plus (0.05, 0, 0) × (0, 2, 0) = 0.1 N·m about z
  EXPECT_NEAR((ToVec3(dBodyGetTorque(box.body)) - Vec3(0, 0, 0.6)).norm(), 0.0, kUnitsTight);
  bodies_.ClearCallForces();
  EXPECT_EQ(box.force, Vec3::Zero());
  EXPECT_TRUE(box.held.active);
}

ContactPair Touching(const Vec3& point) {
  ContactPair pair;
  pair.a = 1;
  pair.b = 0;
  Contact contact;
  contact.position = point;
  contact.normal = Vec3::UnitZ();
  pair.contacts.push_back(contact);
  return pair;
}

TEST_F(OdeUnitTest, AnchorsAreKeptWhileAPairSticksAndRenewedWhenItSlides) {
  const double h = 0.001, gain = 0.2, slip = 5e-4;
  dBodySetPosition(bodies_[1].body, 0, 0, 0.05);
  std::vector<ContactPair> pairs = {Touching(Vec3(0, 0, 0))};
  const CandidatePairs candidates = {{0, 1}};
  FrictionAnchors anchors;
  anchors.Update(&pairs, candidates, bodies_, h, gain, slip);
  ASSERT_EQ(anchors.anchors().size(), 1u);  // first touch: anchored where it is
  EXPECT_EQ(anchors.velocities()[0], Vec3::Zero());
  // crept 0.1 mm along x: the rows ask for gain of it back in one step
  dBodySetPosition(bodies_[1].body, 1e-4, 0, 0.05);
  anchors.Update(&pairs, candidates, bodies_, h, gain, slip);
  EXPECT_NEAR((anchors.velocities()[0] - Vec3(-gain * 1e-4 / h, 0, 0)).norm(), 0.0, 1e-9);
  EXPECT_NEAR(pairs[0].anchor_speed, gain * 1e-4 / h, 1e-9);
  // slid 1 mm: re-anchored there, nothing asked
  dBodySetPosition(bodies_[1].body, 1.1e-3, 0, 0.05);
  anchors.Update(&pairs, candidates, bodies_, h, gain, slip);
  EXPECT_EQ(anchors.velocities()[0], Vec3::Zero());
  EXPECT_NEAR(anchors.anchors()[0].position.x(), 1.1e-3, kUnitsTight);
  // no contact this step but still a candidate: kept; out of the broad phase: dropped
  std::vector<ContactPair> none;
  anchors.Update(&none, candidates, bodies_, h, gain, slip);
  EXPECT_EQ(anchors.anchors().size(), 1u);
  anchors.Update(&none, {}, bodies_, h, gain, slip);
  EXPECT_TRUE(anchors.anchors().empty());
}

TEST(FeedbackRecorderTest, RecordsAreSortedUniqueAndQueriedWithOneSignConvention) {
  FeedbackRecorder recorder;
  recorder.Enable(5, 2);
  recorder.Enable(1, 3);
  recorder.Enable(2, 5);  // already recorded
  recorder.Enable(4, 4);  // not a pair
  ASSERT_EQ(recorder.records().size(), 2u);
  EXPECT_EQ(recorder.records()[0].first, 1);
  EXPECT_EQ(recorder.records()[1].first, 2);
  EXPECT_EQ(recorder.Find(5, 2), &recorder.records()[1]);
  EXPECT_EQ(recorder.Find(1, 2), nullptr);
  std::vector<std::pair<int, double>> seen;
  recorder.ForEach(5, -1, [&](const ContactFeedbackRecord& r, double sign) {
    seen.emplace_back(r.first, sign);
  });
  // 5 is the record's second body: its forces are the negatives of the record's
  EXPECT_EQ(seen, (std::vector<std::pair<int, double>>{{2, -1.0}}));
  seen.clear();
  recorder.ForEach(1, 3, [&](const ContactFeedbackRecord& r, double sign) {
    seen.emplace_back(r.second, sign);
  });
  EXPECT_EQ(seen, (std::vector<std::pair<int, double>>{{3, 1.0}}));
}

}  // namespace
}  // namespace lamina::core
