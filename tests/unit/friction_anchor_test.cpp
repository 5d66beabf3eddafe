// SPDX-License-Identifier: MIT
// Friction anchors: the drift they measure is the tangential displacement of a's material point
// relative to b (rigid motions that keep the contact point in place give none), and the
// correction velocity takes a fixed fraction of it back per step.
#include "core/sim/friction_anchor.h"

#include <cmath>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

namespace lamina::core {
namespace {

constexpr double kTight = 1e-14;

BodyFrame Frame(const Mat3& rotation, const Vec3& position) {
  return BodyFrame{rotation, position};
}

Mat3 Rotation(double angle, const Vec3& axis) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

TEST(FrictionAnchorTest, TranslationDriftsByItsTangentialPart) {
  const BodyFrame b;  // static: the world frame
  const BodyFrame a = Frame(Rotation(0.3, Vec3(1, 2, 3)), Vec3(0.1, -0.2, 0.5));
  const FrictionAnchor anchor = MakeAnchor(1, 0, a, b);
  const Vec3 moved(0.001, -0.002, 0.003);
  const BodyFrame a_now = Frame(a.rotation, a.position + moved);
  const Vec3 drift = AnchorDrift(anchor, a_now, b, Vec3(0.2, 0.1, 0.0), Vec3::UnitZ());
  EXPECT_NEAR((drift - Vec3(0.001, -0.002, 0.0)).norm(), 0.0, kTight);
  EXPECT_NEAR(AnchorRotation(anchor, a_now, b), 0.0, kTight);
}

TEST(FrictionAnchorTest, TurningAboutTheContactPointLeavesItInPlace) {
  const BodyFrame b;
  const BodyFrame a = Frame(Mat3::Identity(), Vec3(0, 0, 0.5));
  const FrictionAnchor anchor = MakeAnchor(1, 0, a, b);
  // a tips by 0.2 rad about a horizontal axis through the contact point (0.1, 0, 0)
  const Vec3 contact(0.1, 0, 0);
  const Mat3 tip = Rotation(0.2, Vec3::UnitY());
  const BodyFrame a_now = Frame(tip, contact + tip * (a.position - contact));
  EXPECT_NEAR(AnchorDrift(anchor, a_now, b, contact, Vec3::UnitZ()).norm(), 0.0, kTight);
  EXPECT_NEAR(AnchorRotation(anchor, a_now, b), 0.2, kTight);
  // a point 0.1 m further along x has moved 0.1 (1 - cos 0.2) back towards the pivot
  const Vec3 other = contact + tip * Vec3(0.1, 0, 0);
  EXPECT_NEAR(AnchorDrift(anchor, a_now, b, other, Vec3::UnitZ()).x(), -0.1 * (1 - std::cos(0.2)),
              kTight);
}

TEST(FrictionAnchorTest, DriftIsRelativeToTheOtherBody) {
  const BodyFrame a = Frame(Rotation(0.1, Vec3(0, 1, 1)), Vec3(0, 0, 1.1));
  const BodyFrame b = Frame(Rotation(-0.4, Vec3(1, 0, 0)), Vec3(0.3, 0, 1.0));
  const FrictionAnchor anchor = MakeAnchor(2, 1, a, b);
  // both bodies carried along by the same rigid motion: no drift
  const Mat3 turn = Rotation(0.7, Vec3(1, 1, 0));
  const Vec3 shift(0.5, -0.25, 2.0);
  const BodyFrame a_now = Frame(turn * a.rotation, turn * a.position + shift);
  const BodyFrame b_now = Frame(turn * b.rotation, turn * b.position + shift);
  const Vec3 normal = turn * Vec3::UnitZ();
  EXPECT_NEAR(AnchorDrift(anchor, a_now, b_now, Vec3(0.1, 0.2, 1.05), normal).norm(), 0.0, 1e-12);
  EXPECT_NEAR(AnchorRotation(anchor, a_now, b_now), 0.0, 1e-7);
  // b alone moving by -d is a's drift of +d relative to b
  const Vec3 d(0.002, 0.001, 0.0);
  const BodyFrame b_back = Frame(b.rotation, b.position - d);
  EXPECT_NEAR((AnchorDrift(anchor, a, b_back, Vec3(0, 0, 1), Vec3::UnitZ()) - d).norm(), 0.0,
              kTight);
}

TEST(FrictionAnchorTest, CorrectionTakesBackAFractionOfTheDriftPerStep) {
  const double step = 0.001;
  const Vec3 drift(3e-5, -4e-5, 0.0);  // 50 µm
  const double gain = 0.2;
  const Vec3 velocity = AnchorCorrectionVelocity(drift, step, gain);
  EXPECT_NEAR((velocity + gain * drift / step).norm(), 0.0, kTight);
  // a large drift is taken back no faster than the cap
  const Vec3 large(4e-4, 0.0, 0.0);
  EXPECT_NEAR(AnchorCorrectionVelocity(large, step, gain).x(), -kAnchorMaxCorrectionSpeed, kTight);
  // rounding-sized drift is left alone
  EXPECT_EQ(AnchorCorrectionVelocity(Vec3(1e-12, 0, 0), step, gain), Vec3::Zero());
}

TEST(FrictionAnchorTest, AnchorsAreFoundByPairAndForgottenByBody) {
  std::vector<FrictionAnchor> anchors;
  for (const auto& [a, b] : {std::pair(5, 0), std::pair(2, 7), std::pair(2, 1)}) {
    anchors.push_back(MakeAnchor(a, b, BodyFrame{}, BodyFrame{}));
  }
  SortAnchors(&anchors);
  ASSERT_NE(FindAnchor(anchors, 2, 7), nullptr);
  EXPECT_EQ(FindAnchor(anchors, 2, 7)->b, 7);
  EXPECT_EQ(FindAnchor(anchors, 7, 2), nullptr);  // pairs are ordered as the contacts name them
  ForgetAnchors(&anchors, 2);
  ASSERT_EQ(anchors.size(), 1u);
  EXPECT_EQ(anchors[0].a, 5);
}

}  // namespace
}  // namespace lamina::core
