// SPDX-License-Identifier: MIT
// Taking back the drift a step left in its joints (joint_stabilization.h): the least mass-weighted
// motion along the joints' rows at the start of the step, and the velocity that carries it. A rod
// pulled off its world hinge along itself slides back along itself without turning; two free
// bodies pulled apart meet where their mass centre was; a chain of random poses closes to
// rounding with its mass centre and momentum kept; a body that does not move is not moved; a
// slider's child goes back across its line and keeps its travel and rotation.
#include "core/sim/joint_stabilization.h"

#include <cmath>
#include <random>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

namespace lamina::core {
namespace {

constexpr double kClosed = 1e-12;  // m: the tolerance asked for
// what a correction may leave of the drift: JointStabilizer::kReduction of it (each round leaves
// 1e-6 of it here, the penalty's 1/w, or as much as the joints turned)
constexpr double kLeft = JointStabilizer::kReduction;
// the rounding of a correction's solve relative to the correction: up to 2.4e-10 measured here
// (the penalty weight 1e6 of joint_stabilization.h: M + w·JᵀJ spans six decades and more)
constexpr double kRounding = 1e-9;

Eigen::Quaterniond Turn(double angle, const Vec3& axis) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis.normalized()));
}

// a 1 m rod of `mass` along its body x axis
StabilizedBody Rod(double mass, const Eigen::Quaterniond& orientation, const Vec3& centre) {
  StabilizedBody rod;
  rod.mass = mass;
  rod.inertia = Vec3(1e-4, mass / 12.0, mass / 12.0).asDiagonal();
  rod.start.orientation = orientation;
  rod.start.com_position = centre;
  rod.state = rod.start;
  return rod;
}

StabilizedJoint Hinge(const std::vector<StabilizedBody>& bodies, int parent, int child,
                      const Vec3& axis, const Vec3& point) {
  StabilizedJoint joint;
  joint.parent = parent;
  joint.child = child;
  const BodyState world;
  joint.placement = MakeJointPlacement(parent < 0 ? world : bodies[parent].start,
                                       bodies[child].start, false, axis, point);
  return joint;
}

double Gap(const std::vector<StabilizedBody>& bodies, const StabilizedJoint& joint) {
  const BodyState world;
  return JointGap(joint.placement, joint.parent < 0 ? world : bodies[joint.parent].state,
                  bodies[joint.child].state);
}

constexpr double kStep = 1e-3;  // s
constexpr double kErp = 0.95;   // the world's default

Vec3 Momentum(const std::vector<StabilizedBody>& bodies) {
  Vec3 sum = Vec3::Zero();
  for (const StabilizedBody& body : bodies) sum += body.mass * body.state.linear_velocity;
  return sum;
}

Vec3 MassCentre(const std::vector<StabilizedBody>& bodies) {
  Vec3 sum = Vec3::Zero();
  double mass = 0.0;
  for (const StabilizedBody& body : bodies) {
    sum += body.mass * body.state.com_position;
    mass += body.mass;
  }
  return sum / mass;
}

TEST(JointStabilizationTest, ARodPulledAlongItselfSlidesBackWithoutTurning) {
  // hung from a world hinge about y at the origin, 30° from straight down
  const Eigen::Quaterniond pose = Turn(-M_PI / 2 + M_PI / 6, Vec3::UnitY());
  const Vec3 along = pose * Vec3::UnitX();  // from the pivot to the far end
  std::vector<StabilizedBody> bodies = {Rod(1.0, pose, 0.5 * along)};
  const std::vector<StabilizedJoint> joints = {Hinge(bodies, -1, 0, Vec3::UnitY(), Vec3::Zero())};
  constexpr double kPulled = 1e-3;  // m, the ½(ωh)²·d a step leaves, magnified
  bodies[0].state.com_position += kPulled * along;
  JointStabilizer stabilizer;
  const JointStabilizer::Result result =
      stabilizer.Stabilize(&bodies, joints, kStep, kErp, kClosed);
  EXPECT_NEAR(result.gap_before, kPulled, 1e-15);
  EXPECT_LE(result.gap_after, kLeft * kPulled);
  EXPECT_TRUE(result.applied);
  EXPECT_LE((bodies[0].state.com_position - 0.5 * along).norm(), kLeft * kPulled);
  EXPECT_LE(bodies[0].state.orientation.angularDistance(pose), kLeft * kPulled);
  // and the velocity that brings it back over the step
  EXPECT_LE((bodies[0].state.linear_velocity + kPulled / kStep * along).norm(),
            kLeft * kPulled / kStep);
  EXPECT_LE(bodies[0].state.angular_velocity.norm(), kLeft * kPulled / kStep);
}

TEST(JointStabilizationTest, ArcOffsetMovesTheChordsEndToTheTurnsAboutThePoint) {
  // any arm and any turning (not only about an axis across the arm), 3 ms at up to 40 rad/s
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  constexpr double kStepLong = 3e-3;  // s
  for (int trial = 0; trial < 20; ++trial) {
    const Vec3 arm(unit(random), unit(random), unit(random));  // c₀ − p₀, m
    const Vec3 omega = 40.0 * Vec3(unit(random), unit(random), unit(random));
    const Vec3 velocity = omega.cross(arm);  // the centre's, turning about the point at rest
    Vec3 velocity_change;
    const Vec3 offset = ArcOffset(arm, omega, kStepLong, &velocity_change);
    const Eigen::Quaterniond turn = Turn(kStepLong * omega.norm(), omega);
    // the chord's end c₀ + h·v, moved, is the turned centre p₀ + exp(h·ω̂)(c₀ − p₀)
    EXPECT_LE((arm + kStepLong * velocity + offset - turn * arm).norm(), 1e-15);
    // and the centre's velocity is the turn's about the point there, of the same length
    const Vec3 turned_velocity = velocity + velocity_change;
    EXPECT_LE((turned_velocity - omega.cross(turn * arm)).norm(), 1e-13);
    EXPECT_NEAR(turned_velocity.norm(), velocity.norm(), 1e-13);
  }
  Vec3 velocity_change = Vec3::Ones();
  EXPECT_EQ(ArcOffset(Vec3(0.5, 0, 0), Vec3::Zero(), kStep, &velocity_change), Vec3::Zero());
  EXPECT_EQ(velocity_change, Vec3::Zero());
}

TEST(JointStabilizationTest, ARodTurningOnAWorldHingeFollowsTheArcWithNoDriftLeft) {
  // a rod on a world hinge about y at (0, 0, 2), 30° from straight down, turning at 4 rad/s; the
  // step as ODE takes it (finite rotation: the centre along h·v, the rod turned by exp(h·ω̂))
  // leaves the hinge's point ½(ωh)²·d = 0.1 mm off the axis at 5 ms
  constexpr double kStepLong = 5e-3, kOmega = 4.0;
  const Vec3 pivot(0, 0, 2);
  const Eigen::Quaterniond pose = Turn(-M_PI / 2 + M_PI / 6, Vec3::UnitY());
  const Vec3 arm = 0.5 * (pose * Vec3::UnitX());  // the centre from the pivot
  std::vector<StabilizedBody> bodies = {Rod(1.0, pose, pivot + arm)};
  const std::vector<StabilizedJoint> joints = {Hinge(bodies, -1, 0, Vec3::UnitY(), pivot)};
  const Vec3 omega = kOmega * Vec3::UnitY();
  bodies[0].start.angular_velocity = omega;
  bodies[0].start.linear_velocity = omega.cross(arm);
  bodies[0].state = bodies[0].start;
  const Eigen::Quaterniond turn = Turn(kStepLong * kOmega, Vec3::UnitY());
  bodies[0].state.com_position += kStepLong * bodies[0].start.linear_velocity;
  bodies[0].state.orientation = turn * pose;
  EXPECT_NEAR(Gap(bodies, joints[0]), 0.5 * std::pow(kOmega * kStepLong, 2) * 0.5, 1e-8);
  JointStabilizer stabilizer;
  const JointStabilizer::Result result =
      stabilizer.Stabilize(&bodies, joints, kStepLong, kErp, kClosed);
  // nothing left for the correction's rounds: the rod is where the turn about its pivot puts it
  EXPECT_LE(result.gap_before, 1e-15);
  EXPECT_EQ(result.rounds, 0);
  EXPECT_LE((bodies[0].state.com_position - (pivot + turn * arm)).norm(), 1e-15);
  EXPECT_LE((bodies[0].state.linear_velocity - omega.cross(turn * arm)).norm(), 1e-14);
  EXPECT_EQ(bodies[0].state.angular_velocity, omega);
  EXPECT_EQ(bodies[0].state.orientation.coeffs(), (turn * pose).coeffs());
}

TEST(JointStabilizationTest, TwoFreeBodiesPulledApartMeetAtTheirMassCentre) {
  // rods end to end along x, hinged about z at x = 0; the heavy one moved 1 mm further out
  std::vector<StabilizedBody> bodies = {Rod(1.0, Eigen::Quaterniond::Identity(), Vec3(-0.5, 0, 0)),
                                        Rod(3.0, Eigen::Quaterniond::Identity(), Vec3(0.5, 0, 0))};
  const std::vector<StabilizedJoint> joints = {Hinge(bodies, 0, 1, Vec3::UnitZ(), Vec3::Zero())};
  constexpr double kPulled = 1e-3;
  bodies[1].state.com_position.x() += kPulled;
  const Vec3 centre = MassCentre(bodies);
  JointStabilizer stabilizer;
  EXPECT_LE(stabilizer.Stabilize(&bodies, joints, kStep, kErp, kClosed).gap_after, kLeft * kPulled);
  // the light one goes ¾ of the way, the heavy one ¼; neither turns
  EXPECT_NEAR(bodies[0].state.com_position.x(), -0.5 + 0.75 * kPulled, kLeft * kPulled);
  EXPECT_NEAR(bodies[1].state.com_position.x(), 0.5 + 0.75 * kPulled, kLeft * kPulled);
  EXPECT_LE((MassCentre(bodies) - centre).norm(), kRounding * kPulled);
  EXPECT_LE(Momentum(bodies).norm(), kRounding * kPulled / kStep);
  for (const StabilizedBody& body : bodies) {
    EXPECT_LE(body.state.orientation.angularDistance(Eigen::Quaterniond::Identity()), 1e-12);
  }
}

// ten links hinged end to end about random axes, each then moved and turned at random by up to
// 1 cm and 0.01 rad (ten times a whipping chain's gap at 1 ms)
struct RandomChain {
  std::vector<StabilizedBody> bodies;
  std::vector<StabilizedJoint> joints;
  explicit RandomChain(bool to_world) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const auto vector = [&] { return Vec3(unit(random), unit(random), unit(random)); };
    Vec3 end = Vec3::Zero();
    for (int l = 0; l < 10; ++l) {
      const Eigen::Quaterniond pose = Turn(3.0 * unit(random), vector());
      const Vec3 along = pose * Vec3::UnitX();
      bodies.push_back(Rod(0.5 + unit(random) * 0.4, pose, end + 0.5 * along));
      if (l > 0 || to_world) joints.push_back(Hinge(bodies, l - 1, l, vector(), end));
      end += along;
    }
    for (StabilizedBody& body : bodies) {
      body.state.linear_velocity = vector();
      body.state.com_position += 0.01 * vector();
      body.state.orientation = Turn(0.01 * unit(random), vector()) * body.state.orientation;
    }
  }
};

TEST(JointStabilizationTest, AFreeChainOfRandomPosesClosesAndKeepsItsMassCentre) {
  RandomChain chain(false);
  const Vec3 centre = MassCentre(chain.bodies);
  const Vec3 momentum = Momentum(chain.bodies);
  JointStabilizer stabilizer;
  const JointStabilizer::Result result =
      stabilizer.Stabilize(&chain.bodies, chain.joints, kStep, kErp, kClosed);
  EXPECT_GT(result.gap_before, 1e-3);
  EXPECT_LE(result.gap_after, kLeft * result.gap_before);
  // the rows of the start against the poses of the end (turned by up to 0.01 rad): each round
  // leaves about 1e-2 of the drift, so two rounds reach kLeft
  EXPECT_LE(result.rounds, 2);
  for (const StabilizedJoint& joint : chain.joints)
    EXPECT_LE(Gap(chain.bodies, joint), kLeft * result.gap_before);
  // every row pushes its two bodies equally and oppositely: Σ m·Δx = 0 and Σ m·Δv = 0 (the
  // bodies were moved by up to 1 cm)
  EXPECT_LE((MassCentre(chain.bodies) - centre).norm(), kRounding * 1e-2);
  EXPECT_LE((Momentum(chain.bodies) - momentum).norm(), kRounding * 1e-2 / kStep);
}

TEST(JointStabilizationTest, ABodyThatDoesNotMoveStaysBitForBit) {
  // the last link of a free chain (a held body inside a loop, as between the world and another
  // held body, may leave gaps no motion along the rows closes when its pose is random)
  RandomChain chain(false);
  chain.bodies[9].moves = false;
  const BodyState held = chain.bodies[9].state;
  JointStabilizer stabilizer;
  EXPECT_TRUE(stabilizer.Stabilize(&chain.bodies, chain.joints, kStep, kErp, kClosed).applied);
  EXPECT_EQ(chain.bodies[9].state, held);
}

TEST(JointStabilizationTest, ASlidersChildGoesBackAcrossItsLineAndKeepsItsTravel) {
  // a body on a world slider along (1, 1, 0), pushed 2 mm across and 5 cm along the line
  std::vector<StabilizedBody> bodies = {Rod(2.0, Turn(0.3, Vec3(0, 0, 1)), Vec3(0.2, 0.1, 1.0))};
  const Vec3 axis = Vec3(1, 1, 0).normalized();
  StabilizedJoint joint;
  joint.child = 0;
  joint.placement = MakeJointPlacement(BodyState{}, bodies[0].start, true, axis, Vec3::Zero());
  const Vec3 across = Vec3(1, -1, 0.5).normalized().cross(axis).normalized();
  bodies[0].state.com_position += 0.05 * axis + 0.002 * across;
  const Eigen::Quaterniond turned = bodies[0].state.orientation;
  JointStabilizer stabilizer;
  EXPECT_LE(stabilizer.Stabilize(&bodies, {joint}, kStep, kErp, kClosed).gap_after, kLeft * 0.002);
  EXPECT_NEAR(JointCoordinate(joint.placement, BodyState{}, bodies[0].state), 0.05, kLeft * 0.002);
  EXPECT_LE(bodies[0].state.orientation.angularDistance(turned), kRounding * 0.05);
}

TEST(JointStabilizationTest, AGapTheJointHadBeforeTheStepIsTheErpsToClose) {
  // a rod 0.3 m off its world hinge at the start (teleported); with ERP 0.002 the step aimed at
  // 0.2994 m and left 0.2995 m: only the 0.1 mm the step added is taken back
  const Eigen::Quaterniond pose = Turn(-M_PI / 2, Vec3::UnitY());  // hanging straight down
  const Vec3 along = pose * Vec3::UnitX();
  std::vector<StabilizedBody> bodies = {Rod(1.0, pose, 0.5 * along)};
  const std::vector<StabilizedJoint> joints = {Hinge(bodies, -1, 0, Vec3::UnitY(), Vec3::Zero())};
  constexpr double kTeleported = 0.3, kErpSlow = 0.002, kAdded = 1e-4;
  bodies[0].start.com_position += kTeleported * along;
  bodies[0].state = bodies[0].start;
  bodies[0].state.com_position += ((1.0 - kErpSlow) * kTeleported - kTeleported + kAdded) * along;
  JointStabilizer stabilizer;
  const JointStabilizer::Result result =
      stabilizer.Stabilize(&bodies, joints, kStep, kErpSlow, kClosed);
  EXPECT_NEAR(result.gap_before, kAdded, 1e-15);
  EXPECT_TRUE(result.applied);
  EXPECT_NEAR(Gap(bodies, joints[0]), (1.0 - kErpSlow) * kTeleported, kLeft * kAdded);
  EXPECT_NEAR(bodies[0].state.linear_velocity.dot(along), -kAdded / kStep, kLeft * kAdded / kStep);
}

TEST(JointStabilizationTest, AStraightBridgeSaggedIsLeftAsTheStepLeftIt) {
  // two 1 m links pinned to the world at x = 0 and x = 2 and to each other at x = 1, straight at
  // the start; the step turned them down by 1 mrad about their pins, which stretches the middle
  // hinge by 2·(1 − cos θ) = 1e-6 m along x: the rows of the straight pose (all along x or about
  // y) cannot shorten it, so nothing closes and nothing moves
  std::vector<StabilizedBody> bodies = {Rod(5.0, Eigen::Quaterniond::Identity(), Vec3(0.5, 0, 0)),
                                        Rod(5.0, Eigen::Quaterniond::Identity(), Vec3(1.5, 0, 0))};
  const std::vector<StabilizedJoint> joints = {Hinge(bodies, -1, 0, Vec3::UnitY(), Vec3::Zero()),
                                               Hinge(bodies, 0, 1, Vec3::UnitY(), Vec3(1, 0, 0)),
                                               Hinge(bodies, -1, 1, Vec3::UnitY(), Vec3(2, 0, 0))};
  constexpr double kSag = 1e-3;                               // rad
  const Eigen::Quaterniond down = Turn(kSag, Vec3::UnitY());  // about +y: x goes down
  bodies[0].state.orientation = down;
  bodies[0].state.com_position = down * Vec3(0.5, 0, 0);
  bodies[1].state.orientation = down.conjugate();
  bodies[1].state.com_position = Vec3(2, 0, 0) + down.conjugate() * Vec3(-0.5, 0, 0);
  const std::vector<StabilizedBody> stepped = bodies;
  JointStabilizer stabilizer;
  const JointStabilizer::Result result =
      stabilizer.Stabilize(&bodies, joints, kStep, kErp, kClosed);
  EXPECT_NEAR(result.gap_before, 2.0 * (1.0 - std::cos(kSag)), 1e-15);
  EXPECT_FALSE(result.applied);
  EXPECT_EQ(result.gap_after, result.gap_before);
  for (size_t b = 0; b < bodies.size(); ++b) EXPECT_EQ(bodies[b].state, stepped[b].state);
}

}  // namespace
}  // namespace lamina::core
