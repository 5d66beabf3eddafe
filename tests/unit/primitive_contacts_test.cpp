// SPDX-License-Identifier: MIT
// Primitive-primitive boundary-layer contacts at configurations with known answers: counts,
// depths, normals and positions of single and multi-point contacts, swap symmetry, the
// boundary-layer threshold and the penetrating flag, for every supported pair.
#include "core/contact/primitive_contacts.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace lamina::core {
namespace {

// pads of 2.5 mm on each side: contact below a 5 mm gap
constexpr double kPad = 0.0025;
constexpr double kContactTol = 2.0 * kPad;
// Results computed in closed form from inputs of ~0.1-0.5 m: a few ulps of rounding.
constexpr double kPrimitiveExact = 1e-12;
// Points located by golden-section search on a smooth minimum (rim points, segment points on a
// curved surface), and normals taken from them, are resolved to ~sqrt(machine epsilon) * size;
// their distances, being at a minimum, remain exact to rounding.
constexpr double kSearched = 1e-7;
// random configurations per pair of shape kinds; the sanitizer build (make test-asan, -O0) runs
// the first quarter of them (the same code paths; its run took 115 s of CI's critical path), the
// optimized `make test` all of them
#if defined(__SANITIZE_ADDRESS__)
constexpr int kRandomTrials = 50;
#else
constexpr int kRandomTrials = 200;
#endif

Pose At(double x, double y, double z) {
  Pose pose = Pose::Identity();
  pose.translation() = Vec3(x, y, z);
  return pose;
}

Pose Rotated(const Vec3& axis, double angle, const Vec3& position) {
  Pose pose = Pose::Identity();
  pose.linear() = Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
  pose.translation() = position;
  return pose;
}

// local z (the axis of cylinders and capsules) turned onto world x or y
Pose AlongX(const Vec3& position) {
  return Rotated(Vec3::UnitY(), kPi / 2, position);
}
Pose AlongY(const Vec3& position) {
  return Rotated(Vec3::UnitX(), kPi / 2, position);
}

ContactList Contacts(const Primitive& a, const Pose& X_Wa, const Primitive& b, const Pose& X_Wb,
                     double pad_a = kPad, double pad_b = kPad) {
  ContactList out;
  EXPECT_TRUE(PrimitiveContacts(a, X_Wa, pad_a, b, X_Wb, pad_b, &out));
  return out;
}

void ExpectComponentsNear(const Vec3& actual, const Vec3& expected, double tolerance) {
  EXPECT_NEAR(actual.x(), expected.x(), tolerance);
  EXPECT_NEAR(actual.y(), expected.y(), tolerance);
  EXPECT_NEAR(actual.z(), expected.z(), tolerance);
}

// every contact has this normal and depth (the normal within `normal_tolerance`, if given)
void ExpectAllNormalDepth(const ContactList& contacts, const Vec3& normal, double depth,
                          double tolerance, double normal_tolerance = 0.0) {
  for (const Contact& contact : contacts) {
    ExpectComponentsNear(contact.normal, normal, std::max(tolerance, normal_tolerance));
    EXPECT_NEAR(contact.depth, depth, tolerance);
    EXPECT_FALSE(contact.penetrating);
  }
}

// some contact lies at `position` (within tolerance)
bool HasContactAt(const ContactList& contacts, const Vec3& position, double tolerance) {
  return std::any_of(contacts.begin(), contacts.end(), [&](const Contact& contact) {
    return (contact.position - position).cwiseAbs().maxCoeff() <= tolerance;
  });
}

// Box face contacts drop a vertex lying within 1e-3 of the overlap's diameter of the segment
// between two others: at least this for the 0.1-0.2 m faces below (m).
constexpr double kBetweenTolerance = 1e-4;

// Distance from `point` to the segment from `start` to `end`.
double DistanceToSegment(const Vec3& point, const Vec3& start, const Vec3& end) {
  const Vec3 chord = end - start;
  const double squared = chord.squaredNorm();
  const double t = squared > 0.0 ? std::clamp((point - start).dot(chord) / squared, 0.0, 1.0) : 0.0;
  return (point - (start + t * chord)).norm();
}

// some contact lies within `tolerance` of the segment between two others: it adds nothing to the
// support they give
bool SomeContactLiesBetweenTwoOthers(const ContactList& contacts, double tolerance) {
  const size_t count = contacts.size();
  for (size_t i = 0; i < count; ++i) {
    for (size_t j = 0; j < count; ++j) {
      for (size_t k = j + 1; k < count; ++k) {
        if (i == j || i == k) continue;
        const double distance =
            DistanceToSegment(contacts[i].position, contacts[j].position, contacts[k].position);
        if (distance <= tolerance) return true;
      }
    }
  }
  return false;
}

const Primitive kBox = Primitive::Box(Vec3(0.2, 0.2, 0.2));
const Primitive kPlane = Primitive::Plane();

// ---------------------------------------------------------------------------------------------
// spheres

TEST(PrimitiveContactsTest, SphereAbovePlane) {
  const ContactList contacts =
      Contacts(Primitive::Sphere(0.1), At(0, 0, 0.101), kPlane, At(0, 0, 0));
  ASSERT_EQ(contacts.size(), 1u);
  // gap 1 mm in a 5 mm layer
  EXPECT_NEAR(contacts[0].depth, 0.004, kPrimitiveExact);
  ExpectComponentsNear(contacts[0].normal, Vec3::UnitZ(), kPrimitiveExact);
  // padded surfaces at 0.001 - 0.0025 and 0 + 0.0025: midway at 0.0005
  ExpectComponentsNear(contacts[0].position, Vec3(0, 0, 0.0005), kPrimitiveExact);
  EXPECT_FALSE(contacts[0].penetrating);
}

TEST(PrimitiveContactsTest, UnequalPadsPlaceTheContactBetweenPaddedSurfaces) {
  const ContactList contacts =
      Contacts(Primitive::Sphere(0.1), At(0.3, -0.2, 0.101), kPlane, At(0, 0, 0), 0.001, 0.004);
  ASSERT_EQ(contacts.size(), 1u);
  EXPECT_NEAR(contacts[0].depth, 0.004, kPrimitiveExact);
  // padded surfaces at 0.001 - 0.001 = 0 and 0 + 0.004: midway at 0.002
  ExpectComponentsNear(contacts[0].position, Vec3(0.3, -0.2, 0.002), kPrimitiveExact);
}

TEST(PrimitiveContactsTest, PrimitivePoseIsInsideTheBodyFrame) {
  // the sphere sits 0.5 above its body frame, the body at z = -0.399: centre at 0.101
  const Primitive sphere = Primitive::Sphere(0.1, Vec3(0, 0, 0.5));
  const Primitive plane = Primitive::Plane(At(0, 0, 1.0));
  const ContactList contacts = Contacts(sphere, At(0, 0, -0.399), plane, At(0, 0, -1.0));
  ASSERT_EQ(contacts.size(), 1u);
  EXPECT_NEAR(contacts[0].depth, 0.004, kPrimitiveExact);
}

TEST(PrimitiveContactsTest, SphereSphere) {
  const ContactList contacts =
      Contacts(Primitive::Sphere(0.1), At(0, 0, 0), Primitive::Sphere(0.05), At(0.152, 0, 0));
  ASSERT_EQ(contacts.size(), 1u);
  EXPECT_NEAR(contacts[0].depth, 0.003, kPrimitiveExact);
  // from b (at +x) into a
  ExpectComponentsNear(contacts[0].normal, -Vec3::UnitX(), kPrimitiveExact);
  // a's padded surface at 0.1 + 0.0025, b's at 0.102 - 0.0025
  ExpectComponentsNear(contacts[0].position, Vec3(0.101, 0, 0), kPrimitiveExact);
}

TEST(PrimitiveContactsTest, SphereBoxFaceEdgeAndInside) {
  const Primitive sphere = Primitive::Sphere(0.05);
  // face: 2 mm from the +x face
  ContactList contacts = Contacts(sphere, At(0.152, 0, 0), kBox, At(0, 0, 0));
  ASSERT_EQ(contacts.size(), 1u);
  EXPECT_NEAR(contacts[0].depth, 0.003, kPrimitiveExact);
  ExpectComponentsNear(contacts[0].normal, Vec3::UnitX(), kPrimitiveExact);
  // edge: centre 0.0365 beyond both the x and y faces, 0.0365 sqrt(2) from the edge
  contacts = Contacts(sphere, At(0.1365, 0.1365, 0.03), kBox, At(0, 0, 0));
  ASSERT_EQ(contacts.size(), 1u);
  EXPECT_NEAR(contacts[0].depth, kContactTol - (0.0365 * std::sqrt(2.0) - 0.05), kPrimitiveExact);
  ExpectComponentsNear(contacts[0].normal, Vec3(1, 1, 0) / std::sqrt(2.0), kPrimitiveExact);
  // centre inside, 1 cm under the +x face: penetrates by 6 cm
  contacts = Contacts(sphere, At(0.09, 0, 0), kBox, At(0, 0, 0));
  ASSERT_EQ(contacts.size(), 1u);
  EXPECT_NEAR(contacts[0].depth, kContactTol + 0.06, kPrimitiveExact);
  ExpectComponentsNear(contacts[0].normal, Vec3::UnitX(), kPrimitiveExact);
  EXPECT_TRUE(contacts[0].penetrating);
}

TEST(PrimitiveContactsTest, SphereCapsuleSideAndEnd) {
  const Primitive sphere = Primitive::Sphere(0.1);
  const Primitive capsule = Primitive::Capsule(0.05, 0.4);
  // beside the straight part: 0.153 - 0.15 = 3 mm
  ContactList contacts = Contacts(sphere, At(0.153, 0, 0.1), capsule, At(0, 0, 0));
  ASSERT_EQ(contacts.size(), 1u);
  EXPECT_NEAR(contacts[0].depth, 0.002, kPrimitiveExact);
  ExpectComponentsNear(contacts[0].normal, Vec3::UnitX(), kPrimitiveExact);
  // over the end cap: 0.351 - (0.2 + 0.05 + 0.1) = 1 mm
  contacts = Contacts(sphere, At(0, 0, 0.351), capsule, At(0, 0, 0));
  ASSERT_EQ(contacts.size(), 1u);
  EXPECT_NEAR(contacts[0].depth, 0.004, kPrimitiveExact);
  ExpectComponentsNear(contacts[0].normal, Vec3::UnitZ(), kPrimitiveExact);
}

TEST(PrimitiveContactsTest, SphereCylinderSideCapRimAndInside) {
  const Primitive sphere = Primitive::Sphere(0.05);
  const Primitive cylinder = Primitive::Cylinder(0.1, 0.2);
  // side: 1 mm
  ContactList contacts = Contacts(sphere, At(0.151, 0, 0), cylinder, At(0, 0, 0));
  ASSERT_EQ(contacts.size(), 1u);
  EXPECT_NEAR(contacts[0].depth, 0.004, kPrimitiveExact);
  ExpectComponentsNear(contacts[0].normal, Vec3::UnitX(), kPrimitiveExact);
  // cap: 2 mm, off the axis
  contacts = Contacts(sphere, At(0.03, 0.02, 0.152), cylinder, At(0, 0, 0));
  ASSERT_EQ(contacts.size(), 1u);
  EXPECT_NEAR(contacts[0].depth, 0.003, kPrimitiveExact);
  ExpectComponentsNear(contacts[0].normal, Vec3::UnitZ(), kPrimitiveExact);
  // rim: 2 mm along the diagonal from the rim point (0.1, 0, 0.1)
  const Vec3 diagonal = Vec3(1, 0, 1) / std::sqrt(2.0);
  contacts = Contacts(sphere, At(0.1, 0, 0.1) * At(0.052 * diagonal.x(), 0, 0.052 * diagonal.z()),
                      cylinder, At(0, 0, 0));
  ASSERT_EQ(contacts.size(), 1u);
  EXPECT_NEAR(contacts[0].depth, 0.003, kPrimitiveExact);
  ExpectComponentsNear(contacts[0].normal, diagonal, kPrimitiveExact);
  // centre 1 cm inside the side: 6 cm deep
  contacts = Contacts(sphere, At(0.09, 0, 0), cylinder, At(0, 0, 0));
  ASSERT_EQ(contacts.size(), 1u);
  EXPECT_NEAR(contacts[0].depth, kContactTol + 0.06, kPrimitiveExact);
  ExpectComponentsNear(contacts[0].normal, Vec3::UnitX(), kPrimitiveExact);
  EXPECT_TRUE(contacts[0].penetrating);
}

// ---------------------------------------------------------------------------------------------
// boxes

TEST(PrimitiveContactsTest, BoxFlatOnPlaneGivesFourCorners) {
  const ContactList contacts = Contacts(kBox, At(0, 0, 0.101), kPlane, At(0, 0, 0));
  ASSERT_EQ(contacts.size(), 4u);
  ExpectAllNormalDepth(contacts, Vec3::UnitZ(), 0.004, kPrimitiveExact);
  for (const double x : {-0.1, 0.1}) {
    for (const double y : {-0.1, 0.1}) {
      EXPECT_TRUE(HasContactAt(contacts, Vec3(x, y, 0.0005), kPrimitiveExact)) << x << " " << y;
    }
  }
}

TEST(PrimitiveContactsTest, TiltedBoxOnPlaneGivesEachCornerItsOwnDepth) {
  // tilted about y: the corners at local x = +0.1 lie 0.2 sin(angle) above the others
  for (const double angle : {0.02, 0.03}) {
    const Pose X_WB = Rotated(Vec3::UnitY(), -angle, Vec3(0, 0, 0.2));
    double lowest = kInf;
    for (int i = 0; i < 8; ++i) {
      const Vec3 corner(i & 1 ? 0.1 : -0.1, i & 2 ? 0.1 : -0.1, i & 4 ? 0.1 : -0.1);
      lowest = std::min(lowest, (X_WB * corner).z());
    }
    // lower the box so that its lowest corners are 0.5 mm above the plane
    const Pose X_lowered = At(0, 0, 0.0005 - lowest) * X_WB;
    std::vector<double> expected_depths;
    for (int i = 0; i < 8; ++i) {
      const Vec3 corner(i & 1 ? 0.1 : -0.1, i & 2 ? 0.1 : -0.1, i & 4 ? 0.1 : -0.1);
      const double height = (X_lowered * corner).z();
      if (height < kContactTol) expected_depths.push_back(kContactTol - height);
    }
    // 0.2 sin(0.02) = 4.0 mm keeps all 4 bottom corners in the layer; 6.0 mm drops two
    ASSERT_EQ(expected_depths.size(), angle < 0.025 ? 4u : 2u);
    const ContactList contacts = Contacts(kBox, X_lowered, kPlane, At(0, 0, 0));
    ASSERT_EQ(contacts.size(), expected_depths.size());
    std::vector<double> depths;
    for (const Contact& contact : contacts) depths.push_back(contact.depth);
    std::sort(depths.begin(), depths.end());
    std::sort(expected_depths.begin(), expected_depths.end());
    for (size_t i = 0; i < depths.size(); ++i)
      EXPECT_NEAR(depths[i], expected_depths[i], kPrimitiveExact);
  }
}

TEST(PrimitiveContactsTest, BoxOnBoxOffsetByHalfASide) {
  const ContactList contacts = Contacts(kBox, At(0.1, 0, 0.201), kBox, At(0, 0, 0));
  ASSERT_EQ(contacts.size(), 4u);
  ExpectAllNormalDepth(contacts, Vec3::UnitZ(), 0.004, kPrimitiveExact);
  // the overlap rectangle x in [0, 0.1], y in [-0.1, 0.1], midway in the 1 mm gap
  for (const double x : {0.0, 0.1}) {
    for (const double y : {-0.1, 0.1}) {
      EXPECT_TRUE(HasContactAt(contacts, Vec3(x, y, 0.1005), kPrimitiveExact)) << x << " " << y;
    }
  }
}

TEST(PrimitiveContactsTest, BoxTurned45DegreesOnBoxGivesTheOctagon) {
  const ContactList contacts =
      Contacts(kBox, Rotated(Vec3::UnitZ(), kPi / 4, Vec3(0, 0, 0.201)), kBox, At(0, 0, 0));
  // the turned square reaches 0.1 sqrt(2) along x and y: it cuts the corners off the lower
  // square, leaving an octagon with vertices (+-0.1, +-(0.1 sqrt(2) - 0.1)) and swapped
  ASSERT_EQ(contacts.size(), 8u);
  ExpectAllNormalDepth(contacts, Vec3::UnitZ(), 0.004, kPrimitiveExact);
  const double cut = 0.1 * std::sqrt(2.0) - 0.1;
  for (const double u : {-0.1, 0.1}) {
    for (const double v : {-cut, cut}) {
      EXPECT_TRUE(HasContactAt(contacts, Vec3(u, v, 0.1005), kPrimitiveExact)) << u << " " << v;
      EXPECT_TRUE(HasContactAt(contacts, Vec3(v, u, 0.1005), kPrimitiveExact)) << v << " " << u;
    }
  }
  for (const Contact& contact : contacts) {
    // inside both squares (turned: |x| + |y| <= 0.1 sqrt(2))
    EXPECT_LE(contact.position.head<2>().cwiseAbs().maxCoeff(), 0.1 + kPrimitiveExact);
    EXPECT_LE(contact.position.head<2>().cwiseAbs().sum(), 0.1 * std::sqrt(2.0) + kPrimitiveExact);
  }
  // every vertex turns the outline by 45 degrees: none is dropped as lying between others
  EXPECT_FALSE(SomeContactLiesBetweenTwoOthers(contacts, kBetweenTolerance));
}

TEST(PrimitiveContactsTest, EqualBoxesExactlyAlignedGiveFourCorners) {
  const ContactList contacts = Contacts(kBox, At(0, 0, 0.201), kBox, At(0, 0, 0));
  ASSERT_EQ(contacts.size(), 4u);
  ExpectAllNormalDepth(contacts, Vec3::UnitZ(), 0.004, kPrimitiveExact);
  for (const double x : {-0.1, 0.1}) {
    for (const double y : {-0.1, 0.1}) {
      EXPECT_TRUE(HasContactAt(contacts, Vec3(x, y, 0.1005), kPrimitiveExact)) << x << " " << y;
    }
  }
}

TEST(PrimitiveContactsTest, SmallBoxTurnedOnALargerBoxGivesItsFourCorners) {
  const Primitive small = Primitive::Box(Vec3(0.1, 0.1, 0.1));
  const Pose X_Wa = Rotated(Vec3::UnitZ(), 0.01, Vec3(0.02, -0.03, 0.151));
  const ContactList contacts = Contacts(small, X_Wa, kBox, At(0, 0, 0));
  ASSERT_EQ(contacts.size(), 4u);
  ExpectAllNormalDepth(contacts, Vec3::UnitZ(), 0.004, kPrimitiveExact);
  for (const double x : {-0.05, 0.05}) {
    for (const double y : {-0.05, 0.05}) {
      const Vec3 corner = X_Wa * Vec3(x, y, -0.05);
      EXPECT_TRUE(HasContactAt(contacts, Vec3(corner.x(), corner.y(), 0.1005), kPrimitiveExact))
          << x << " " << y;
    }
  }
}

TEST(PrimitiveContactsTest, BoxTiltedOntoItsEdgeOnABoxGivesTheEdgeEnds) {
  // a, tilted 0.3 rad about y, rests its lowest edge (along y) 1 mm above b's top face; the rest
  // of its bottom face rises out of the layer
  const Primitive wide = Primitive::Box(Vec3(0.6, 0.6, 0.2));
  const Pose turn = Rotated(Vec3::UnitY(), 0.3, Vec3::Zero());
  const Vec3 lowest_edge = turn * Vec3(0.1, 0, -0.1);
  const Pose X_Wa = At(0, 0, 0.101 - lowest_edge.z()) * turn;
  const ContactList contacts = Contacts(kBox, X_Wa, wide, At(0, 0, 0));
  ASSERT_EQ(contacts.size(), 2u);
  ExpectAllNormalDepth(contacts, Vec3::UnitZ(), 0.004, kPrimitiveExact);
  for (const double y : {-0.1, 0.1}) {
    EXPECT_TRUE(HasContactAt(contacts, Vec3(lowest_edge.x(), y, 0.1005), kPrimitiveExact)) << y;
  }
}

TEST(PrimitiveContactsTest, CrossedEdgesGiveOneContact) {
  // a: turned 45 degrees about x, its lowest edge along x at z_a - 0.1 sqrt(2);
  // b: turned 45 degrees about y, its highest edge along y at 0.1 sqrt(2); 1 mm apart
  const double reach = 0.1 * std::sqrt(2.0);
  const Pose X_Wa = Rotated(Vec3::UnitX(), kPi / 4, Vec3(0, 0, 2 * reach + 0.001));
  const Pose X_Wb = Rotated(Vec3::UnitY(), kPi / 4, Vec3(0, 0, 0));
  const ContactList contacts = Contacts(kBox, X_Wa, kBox, X_Wb);
  ASSERT_EQ(contacts.size(), 1u);
  // the normal is the cross product of the edge directions x and y
  ExpectAllNormalDepth(contacts, Vec3::UnitZ(), 0.004, kPrimitiveExact);
  ExpectComponentsNear(contacts[0].position, Vec3(0, 0, reach + 0.0005), kPrimitiveExact);
}

TEST(PrimitiveContactsTest, CornerNearCornerOffTheFacesGivesOneContact) {
  // b's top corner (0.1, 0.1, 0.1) and a's bottom corner 1 mm away along (1, 1, 1) / sqrt(3):
  // off every face's prism, so the faces do not resolve it and the edge search does
  const double step = 0.001 / std::sqrt(3.0);
  const ContactList contacts =
      Contacts(kBox, At(0.2 + step, 0.2 + step, 0.2 + step), kBox, At(0, 0, 0));
  ASSERT_EQ(contacts.size(), 1u);
  EXPECT_NEAR(contacts[0].depth, 0.004, kSearched);
  ExpectComponentsNear(contacts[0].normal, Vec3(1, 1, 1) / std::sqrt(3.0), kSearched);
}

TEST(PrimitiveContactsTest, LowestEdgeOverhangingTheFaceBelowGivesTheNearestContact) {
  // a, tilted 0.3 rad about y, has its lowest edge (along y) 0.4 mm beyond b's top +x edge and
  // 3 mm above it, and its bottom face rises over b's top face. b's top face separates them
  // most (3 mm; a's bottom face: 0.4 sin 0.3 + 3 cos 0.3 = 2.98 mm), but the face clipped to it
  // starts 3 + 0.4 tan 0.3 = 3.12 mm up: the nearest points are the two edges, beside it
  const double beyond = 0.0004;
  const double above = 0.003;
  const Pose turn = Rotated(Vec3::UnitY(), 0.3, Vec3::Zero());
  const Vec3 lowest_edge = turn * Vec3(0.1, 0, -0.1);
  const Pose X_Wa = At(0.1 + beyond - lowest_edge.x(), 0, 0.1 + above - lowest_edge.z()) * turn;
  const ContactList contacts = Contacts(kBox, X_Wa, kBox, At(0, 0, 0));
  // the clipped face's contacts and the edges' one
  ASSERT_GE(contacts.size(), 2u);
  const Contact& deepest =
      *std::max_element(contacts.begin(), contacts.end(),
                        [](const Contact& x, const Contact& y) { return x.depth < y.depth; });
  const double gap = std::hypot(beyond, above);
  EXPECT_NEAR(deepest.depth, kContactTol - gap, kPrimitiveExact);
  ExpectComponentsNear(deepest.normal, Vec3(beyond, 0, above) / gap, kPrimitiveExact);
}

TEST(PrimitiveContactsTest, SunkCornerIsPushedOutThroughTheCapItSankInto) {
  // a box turned corner-down (its corner (-1, -1, -1) * 0.1 straight below its centre), the
  // corner sunk 1 mm into the top cap of a cylinder, 0.5 mm inside its side: the side is nearer,
  // but the corner points down into the cap, so the normal is up
  const Mat3 turn =
      Eigen::Quaterniond::FromTwoVectors(Vec3(-1, -1, -1), -Vec3::UnitZ()).toRotationMatrix();
  const Vec3 corner = turn * Vec3(-0.1, -0.1, -0.1);
  ASSERT_NEAR(corner.head<2>().norm(), 0.0, kPrimitiveExact);
  Pose X_Wa = Pose::Identity();
  X_Wa.linear() = turn;
  X_Wa.translation() = Vec3(0.0995, 0, 0.099) - corner;
  const ContactList contacts = Contacts(kBox, X_Wa, Primitive::Cylinder(0.1, 0.2), At(0, 0, 0));
  ASSERT_FALSE(contacts.empty());
  const Contact& deepest =
      *std::max_element(contacts.begin(), contacts.end(),
                        [](const Contact& x, const Contact& y) { return x.depth < y.depth; });
  EXPECT_NEAR(deepest.depth, kContactTol + 0.001, kPrimitiveExact);
  ExpectComponentsNear(deepest.normal, Vec3::UnitZ(), kPrimitiveExact);
  EXPECT_TRUE(deepest.penetrating);
}

// ---------------------------------------------------------------------------------------------
// capsules

TEST(PrimitiveContactsTest, CapsuleLyingOnBoxGivesBothEnds) {
  const Primitive box = Primitive::Box(Vec3(0.4, 0.4, 0.2));
  // short capsule: both axis ends over the face
  ContactList contacts =
      Contacts(Primitive::Capsule(0.05, 0.2), AlongX(Vec3(0, 0.05, 0.151)), box, At(0, 0, 0));
  ASSERT_EQ(contacts.size(), 2u);
  ExpectAllNormalDepth(contacts, Vec3::UnitZ(), 0.004, kPrimitiveExact);
  EXPECT_TRUE(HasContactAt(contacts, Vec3(-0.1, 0.05, 0.1005), kPrimitiveExact));
  EXPECT_TRUE(HasContactAt(contacts, Vec3(0.1, 0.05, 0.1005), kPrimitiveExact));
  // long capsule: the stretch over the face ends at the face's edges
  contacts =
      Contacts(Primitive::Capsule(0.05, 0.6), AlongX(Vec3(0, 0.05, 0.151)), box, At(0, 0, 0));
  ASSERT_EQ(contacts.size(), 2u);
  ExpectAllNormalDepth(contacts, Vec3::UnitZ(), 0.004, kPrimitiveExact);
  EXPECT_TRUE(HasContactAt(contacts, Vec3(-0.2, 0.05, 0.1005), kPrimitiveExact));
  EXPECT_TRUE(HasContactAt(contacts, Vec3(0.2, 0.05, 0.1005), kPrimitiveExact));
}

TEST(PrimitiveContactsTest, CapsuleOnPlaneLyingAndStanding) {
  const Primitive capsule = Primitive::Capsule(0.05, 0.3);
  ContactList contacts = Contacts(capsule, AlongY(Vec3(0, 0, 0.051)), kPlane, At(0, 0, 0));
  ASSERT_EQ(contacts.size(), 2u);
  ExpectAllNormalDepth(contacts, Vec3::UnitZ(), 0.004, kPrimitiveExact);
  EXPECT_TRUE(HasContactAt(contacts, Vec3(0, -0.15, 0.0005), kPrimitiveExact));
  EXPECT_TRUE(HasContactAt(contacts, Vec3(0, 0.15, 0.0005), kPrimitiveExact));
  contacts = Contacts(capsule, At(0, 0, 0.201), kPlane, At(0, 0, 0));
  ASSERT_EQ(contacts.size(), 1u);
  ExpectAllNormalDepth(contacts, Vec3::UnitZ(), 0.004, kPrimitiveExact);
}

TEST(PrimitiveContactsTest, CapsuleCapsuleCrossedAndParallel) {
  const Primitive capsule = Primitive::Capsule(0.05, 0.4);
  // crossed at right angles, axes 0.101 apart: one contact
  ContactList contacts =
      Contacts(capsule, AlongX(Vec3(0, 0, 0.101)), capsule, AlongY(Vec3::Zero()));
  ASSERT_EQ(contacts.size(), 1u);
  ExpectAllNormalDepth(contacts, Vec3::UnitZ(), 0.004, kPrimitiveExact, kSearched);
  ExpectComponentsNear(contacts[0].position, Vec3(0, 0, 0.0505), kSearched);
  // parallel, overlapping over x in [0.1, 0.2]: the ends of the overlap
  contacts = Contacts(capsule, AlongX(Vec3(0.3, 0, 0.101)), capsule, AlongX(Vec3::Zero()));
  ASSERT_EQ(contacts.size(), 2u);
  ExpectAllNormalDepth(contacts, Vec3::UnitZ(), 0.004, kPrimitiveExact);
  EXPECT_TRUE(HasContactAt(contacts, Vec3(0.1, 0, 0.0505), kPrimitiveExact));
  EXPECT_TRUE(HasContactAt(contacts, Vec3(0.2, 0, 0.0505), kPrimitiveExact));
}

TEST(PrimitiveContactsTest, CapsuleOnCylinderCapSideAndCrossing) {
  const Primitive capsule = Primitive::Capsule(0.05, 0.1);
  const Primitive cylinder = Primitive::Cylinder(0.1, 0.2);
  // lying on the cap of a standing cylinder: both axis ends over the disk
  ContactList contacts = Contacts(capsule, AlongX(Vec3(0, 0, 0.151)), cylinder, At(0, 0, 0));
  ASSERT_EQ(contacts.size(), 2u);
  ExpectAllNormalDepth(contacts, Vec3::UnitZ(), 0.004, kPrimitiveExact);
  EXPECT_TRUE(HasContactAt(contacts, Vec3(-0.05, 0, 0.1005), kPrimitiveExact));
  EXPECT_TRUE(HasContactAt(contacts, Vec3(0.05, 0, 0.1005), kPrimitiveExact));
  // long capsule over the cap: the stretch over the disk ends at the rim
  contacts =
      Contacts(Primitive::Capsule(0.05, 0.4), AlongX(Vec3(0, 0.06, 0.151)), cylinder, At(0, 0, 0));
  ASSERT_EQ(contacts.size(), 2u);
  ExpectAllNormalDepth(contacts, Vec3::UnitZ(), 0.004, kPrimitiveExact);
  EXPECT_TRUE(HasContactAt(contacts, Vec3(-0.08, 0.06, 0.1005), kPrimitiveExact));
  EXPECT_TRUE(HasContactAt(contacts, Vec3(0.08, 0.06, 0.1005), kPrimitiveExact));
  // alongside a lying cylinder, parallel: the ends of the capsule's axis
  contacts = Contacts(capsule, AlongX(Vec3(0, 0, 0.151)), cylinder, AlongX(Vec3::Zero()));
  ASSERT_EQ(contacts.size(), 2u);
  ExpectAllNormalDepth(contacts, Vec3::UnitZ(), 0.004, kPrimitiveExact);
  // crossing a lying cylinder at right angles: one contact on top
  contacts = Contacts(capsule, AlongY(Vec3(0, 0, 0.151)), cylinder, AlongX(Vec3::Zero()));
  ASSERT_EQ(contacts.size(), 1u);
  ExpectAllNormalDepth(contacts, Vec3::UnitZ(), 0.004, kPrimitiveExact, kSearched);
  ExpectComponentsNear(contacts[0].position, Vec3(0, 0, 0.1005), kSearched);
}

// ---------------------------------------------------------------------------------------------
// cylinders

TEST(PrimitiveContactsTest, CylinderLyingOnPlaneGivesTheLineEnds) {
  // turned a little about its own axis too, so no rim sample sits at the bottom by construction
  const Pose X_WC = AlongX(Vec3(0, 0, 0.101)) * Rotated(Vec3::UnitZ(), 0.3, Vec3::Zero());
  const ContactList contacts = Contacts(Primitive::Cylinder(0.1, 0.3), X_WC, kPlane, At(0, 0, 0));
  // rim points 45 degrees up from the bottom are 0.1 (1 - cos 45) = 29 mm high: out of the layer
  ASSERT_EQ(contacts.size(), 2u);
  ExpectAllNormalDepth(contacts, Vec3::UnitZ(), 0.004, kPrimitiveExact);
  EXPECT_TRUE(HasContactAt(contacts, Vec3(-0.15, 0, 0.0005), kSearched));
  EXPECT_TRUE(HasContactAt(contacts, Vec3(0.15, 0, 0.0005), kSearched));
}

TEST(PrimitiveContactsTest, CylinderStandingOnPlaneGivesRimPoints) {
  const ContactList contacts =
      Contacts(Primitive::Cylinder(0.1, 0.3), At(0.2, 0.1, 0.151), kPlane, At(0, 0, 0));
  ASSERT_EQ(contacts.size(), 8u);
  ExpectAllNormalDepth(contacts, Vec3::UnitZ(), 0.004, kPrimitiveExact);
  for (const Contact& contact : contacts) {
    EXPECT_NEAR((contact.position.head<2>() - Eigen::Vector2d(0.2, 0.1)).norm(), 0.1,
                kPrimitiveExact);
    EXPECT_NEAR(contact.position.z(), 0.0005, kPrimitiveExact);
  }
}

TEST(PrimitiveContactsTest, CylinderTiltedOnItsRimGivesTheLowestRimPoint) {
  // tilted 0.3 rad about y: the bottom rim's lowest point is its local +x point
  const Pose X_tilted = Rotated(Vec3::UnitY(), 0.3, Vec3::Zero());
  const Vec3 lowest = X_tilted * Vec3(0.1, 0, -0.15);
  ASSERT_LT(lowest.z(), (X_tilted * Vec3(-0.1, 0, -0.15)).z());
  const Pose X_WC = At(-lowest.x(), -lowest.y(), 0.001 - lowest.z()) * X_tilted;
  const ContactList contacts = Contacts(Primitive::Cylinder(0.1, 0.3), X_WC, kPlane, At(0, 0, 0));
  ASSERT_EQ(contacts.size(), 1u);
  ExpectAllNormalDepth(contacts, Vec3::UnitZ(), 0.004, kPrimitiveExact);
  ExpectComponentsNear(contacts[0].position, Vec3(0, 0, 0.0005), kSearched);
}

TEST(PrimitiveContactsTest, CylinderOnBoxStandingAndLying) {
  const Primitive box = Primitive::Box(Vec3(0.6, 0.6, 0.2));
  const Primitive cylinder = Primitive::Cylinder(0.1, 0.3);
  ContactList contacts = Contacts(cylinder, At(0, 0, 0.251), box, At(0, 0, 0));
  ASSERT_EQ(contacts.size(), 8u);
  ExpectAllNormalDepth(contacts, Vec3::UnitZ(), 0.004, kPrimitiveExact);
  contacts = Contacts(cylinder, AlongY(Vec3(0.05, 0, 0.201)), box, At(0, 0, 0));
  ASSERT_EQ(contacts.size(), 2u);
  ExpectAllNormalDepth(contacts, Vec3::UnitZ(), 0.004, kPrimitiveExact);
  EXPECT_TRUE(HasContactAt(contacts, Vec3(0.05, -0.15, 0.1005), kSearched));
  EXPECT_TRUE(HasContactAt(contacts, Vec3(0.05, 0.15, 0.1005), kSearched));
}

TEST(PrimitiveContactsTest, BoxOnLyingCylinderGivesItsCrossingEdges) {
  // the cylinder is longer than the box: the line contact runs across the whole bottom face,
  // whose edges across the axis carry it
  const ContactList contacts =
      Contacts(kBox, At(0, 0.03, 0.201), Primitive::Cylinder(0.1, 0.6), AlongX(Vec3::Zero()));
  ASSERT_EQ(contacts.size(), 2u);
  ExpectAllNormalDepth(contacts, Vec3::UnitZ(), 0.004, kPrimitiveExact, kSearched);
  EXPECT_TRUE(HasContactAt(contacts, Vec3(-0.1, 0, 0.1005), kSearched));
  EXPECT_TRUE(HasContactAt(contacts, Vec3(0.1, 0, 0.1005), kSearched));
}

TEST(PrimitiveContactsTest, CylindersCrossedAndStacked) {
  const Primitive cylinder = Primitive::Cylinder(0.1, 0.4);
  // crossed at right angles, lying on each other: the sides touch at one point
  ContactList contacts =
      Contacts(cylinder, AlongX(Vec3(0, 0, 0.201)), cylinder, AlongY(Vec3::Zero()));
  ASSERT_EQ(contacts.size(), 1u);
  ExpectAllNormalDepth(contacts, Vec3::UnitZ(), 0.004, kPrimitiveExact);
  ExpectComponentsNear(contacts[0].position, Vec3(0, 0, 0.1005), kPrimitiveExact);
  // stacked on the same axis: rim points of both rims facing each other
  contacts = Contacts(cylinder, At(0, 0, 0.401), cylinder, At(0, 0, 0));
  ASSERT_GE(contacts.size(), 8u);
  ExpectAllNormalDepth(contacts, Vec3::UnitZ(), 0.004, kPrimitiveExact);
  for (const Contact& contact : contacts) {
    EXPECT_NEAR(contact.position.head<2>().norm(), 0.1, kPrimitiveExact);
  }
}

TEST(PrimitiveContactsTest, StackedCylindersSunkIntoEachOtherArePushedApartAxially) {
  // equal radii sunk 1 cm: the rim points lie on the other's side surface, but they sank
  // through its cap, so the normal is axial
  const Primitive cylinder = Primitive::Cylinder(0.1, 0.4);
  const ContactList contacts = Contacts(cylinder, At(0, 0, 0.39), cylinder, At(0, 0, 0));
  ASSERT_GE(contacts.size(), 8u);
  for (const Contact& contact : contacts) {
    ExpectComponentsNear(contact.normal, Vec3::UnitZ(), kPrimitiveExact);
    EXPECT_NEAR(contact.depth, kContactTol + 0.01, kPrimitiveExact);
    EXPECT_TRUE(contact.penetrating);
  }
}

// ---------------------------------------------------------------------------------------------
// every pair: threshold, penetration, symmetry, determinism

struct PairCase {
  std::string name;
  Primitive a;
  Primitive b;
  double reach_a;  ///< how far a reaches below its centre (m)
  double reach_b;  ///< how far b reaches above its centre (m)
  Pose turn_a = Pose::Identity();
  Pose turn_b = Pose::Identity();
};

// b at the origin, a straight above with its lowest point `gap` above b's highest
void Place(const PairCase& pair, double gap, Pose* X_Wa, Pose* X_Wb) {
  *X_Wb = pair.turn_b;
  *X_Wa = At(0, 0, pair.reach_b + gap + pair.reach_a) * pair.turn_a;
}

std::vector<PairCase> AllPairs() {
  const Primitive sphere = Primitive::Sphere(0.1);
  const Primitive capsule = Primitive::Capsule(0.05, 0.3);
  const Primitive cylinder = Primitive::Cylinder(0.1, 0.3);
  const Pose along_x = AlongX(Vec3::Zero());
  const Pose along_y = AlongY(Vec3::Zero());
  return {
      {"sphere-sphere", sphere, sphere, 0.1, 0.1},
      {"sphere-box", sphere, kBox, 0.1, 0.1},
      {"sphere-capsule", sphere, capsule, 0.1, 0.05, Pose::Identity(), along_x},
      {"sphere-cylinder", sphere, cylinder, 0.1, 0.15},
      {"sphere-plane", sphere, kPlane, 0.1, 0.0},
      {"box-box", kBox, kBox, 0.1, 0.1, Rotated(Vec3::UnitZ(), 0.3, Vec3::Zero())},
      {"box-capsule", kBox, capsule, 0.1, 0.05, Pose::Identity(), along_y},
      {"box-cylinder", kBox, cylinder, 0.1, 0.15},
      {"box-plane", kBox, kPlane, 0.1, 0.0},
      {"capsule-capsule", capsule, capsule, 0.05, 0.05, along_x, along_y},
      {"capsule-cylinder", capsule, cylinder, 0.05, 0.1, along_x, along_y},
      {"capsule-plane", capsule, kPlane, 0.05, 0.0, along_x},
      {"cylinder-cylinder", cylinder, cylinder, 0.15, 0.15},
      {"cylinder-plane", cylinder, kPlane, 0.15, 0.0},
  };
}

TEST(PrimitiveContactsTest, EveryPairHasTheLayerAsThreshold) {
  for (const PairCase& pair : AllPairs()) {
    SCOPED_TRACE(pair.name);
    Pose X_Wa;
    Pose X_Wb;
    // just inside the layer: the shallowest possible contact
    Place(pair, kContactTol - 1e-6, &X_Wa, &X_Wb);
    ContactList contacts = Contacts(pair.a, X_Wa, pair.b, X_Wb);
    ASSERT_FALSE(contacts.empty());
    for (const Contact& contact : contacts) {
      // at least 1e-6 of depth; 1e-9 below for rounding
      EXPECT_GT(contact.depth, 1e-6 - 1e-9);
      ExpectComponentsNear(contact.normal, Vec3::UnitZ(), kSearched);
    }
    // just outside: nothing
    Place(pair, kContactTol + 1e-6, &X_Wa, &X_Wb);
    EXPECT_TRUE(Contacts(pair.a, X_Wa, pair.b, X_Wb).empty());
  }
}

TEST(PrimitiveContactsTest, EveryPairFlagsOverlap) {
  for (const PairCase& pair : AllPairs()) {
    SCOPED_TRACE(pair.name);
    Pose X_Wa;
    Pose X_Wb;
    // sunk 1 cm into each other
    Place(pair, -0.01, &X_Wa, &X_Wb);
    const ContactList contacts = Contacts(pair.a, X_Wa, pair.b, X_Wb);
    ASSERT_FALSE(contacts.empty());
    double deepest = 0.0;
    for (const Contact& contact : contacts) {
      deepest = std::max(deepest, contact.depth);
      EXPECT_EQ(contact.penetrating, contact.depth > kContactTol);
      EXPECT_GT(contact.normal.z(), 0.0);
    }
    // the deepest contact reports the full overlap
    EXPECT_NEAR(deepest, kContactTol + 0.01, kPrimitiveExact);
  }
}

TEST(PrimitiveContactsTest, SwappingTheShapesNegatesTheNormals) {
  for (const PairCase& pair : AllPairs()) {
    SCOPED_TRACE(pair.name);
    Pose X_Wa;
    Pose X_Wb;
    Place(pair, 0.002, &X_Wa, &X_Wb);
    const ContactList forward = Contacts(pair.a, X_Wa, pair.b, X_Wb, 0.001, 0.003);
    const ContactList backward = Contacts(pair.b, X_Wb, pair.a, X_Wa, 0.003, 0.001);
    ASSERT_FALSE(forward.empty());
    ASSERT_EQ(forward.size(), backward.size());
    for (size_t i = 0; i < forward.size(); ++i) {
      EXPECT_EQ(forward[i].depth, backward[i].depth);
      EXPECT_EQ(forward[i].position, backward[i].position);
      EXPECT_EQ(forward[i].normal, Vec3(-backward[i].normal));
    }
  }
}

TEST(PrimitiveContactsTest, SameInputGivesIdenticalOutputAndAppends) {
  for (const PairCase& pair : AllPairs()) {
    SCOPED_TRACE(pair.name);
    Pose X_Wa;
    Pose X_Wb;
    Place(pair, 0.001, &X_Wa, &X_Wb);
    ContactList first(1);  // an earlier pair's contact stays in front
    ContactList second(1);
    ASSERT_TRUE(PrimitiveContacts(pair.a, X_Wa, kPad, pair.b, X_Wb, kPad, &first));
    ASSERT_TRUE(PrimitiveContacts(pair.a, X_Wa, kPad, pair.b, X_Wb, kPad, &second));
    ASSERT_GT(first.size(), 1u);
    EXPECT_EQ(first[0].depth, 0.0);
    ASSERT_EQ(first.size(), second.size());
    for (size_t i = 0; i < first.size(); ++i) {
      EXPECT_EQ(first[i].position, second[i].position);
      EXPECT_EQ(first[i].normal, second[i].normal);
      EXPECT_EQ(first[i].depth, second[i].depth);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// random configurations against an independent distance: for convex shapes the signed distance
// is the largest separation over directions n of min_a n.a - max_b n.b, which needs only the
// shapes' support points

// the point of `shape` placed at X_WS farthest along world direction n
Vec3 Support(const Primitive& shape, const Pose& X_WS, const Vec3& n) {
  const Vec3 d = X_WS.linear().transpose() * n;
  const auto sign = [](double value) { return value < 0.0 ? -1.0 : 1.0; };
  Vec3 local = Vec3::Zero();
  switch (shape.type) {
    case PrimitiveType::kBox:
      for (int i = 0; i < 3; ++i) local[i] = sign(d[i]) * 0.5 * shape.size[i];
      break;
    case PrimitiveType::kCylinder: {
      const double radial = std::hypot(d.x(), d.y());
      if (radial > 0.0) local.head<2>() = shape.radius * d.head<2>() / radial;
      local.z() = sign(d.z()) * 0.5 * shape.length;
      break;
    }
    case PrimitiveType::kCapsule:
      local.z() = sign(d.z()) * 0.5 * shape.length;
      return X_WS * local + shape.radius * n;
    case PrimitiveType::kSphere:
      return X_WS * local + shape.radius * n;
    case PrimitiveType::kPlane:
      break;
  }
  return X_WS * local;
}

// separation of a from b along unit n (pointing from b to a)
double SeparationAlong(const Primitive& a, const Pose& X_Wa, const Primitive& b, const Pose& X_Wb,
                       const Vec3& n) {
  if (b.type == PrimitiveType::kPlane) {
    const Vec3 plane_normal = X_Wb.linear().col(2);
    return plane_normal.dot(Support(a, X_Wa, -plane_normal) - X_Wb.translation());
  }
  return n.dot(Support(a, X_Wa, -n)) - n.dot(Support(b, X_Wb, n));
}

// Maximises the separation over directions by a pattern search with shrinking steps in 16
// directions of the tangent plane, from `start`; returns the best value and updates `start`.
double MaximiseSeparation(const Primitive& a, const Pose& X_Wa, const Primitive& b,
                          const Pose& X_Wb, Vec3* start) {
  Vec3 best_n = start->normalized();
  double best = SeparationAlong(a, X_Wa, b, X_Wb, best_n);
  for (double step = 0.05; step > 1e-11; step *= 0.5) {
    // a few moves per step length; more would chase rounding noise at the smallest steps
    for (int round = 0, improved = 1; improved != 0 && round < 8; ++round) {
      improved = 0;
      const Vec3 t1 = best_n.unitOrthogonal();
      const Vec3 t2 = best_n.cross(t1);
      for (int k = 0; k < 16; ++k) {
        const Vec3 n = (best_n + step * (std::cos(k * kPi / 8) * t1 + std::sin(k * kPi / 8) * t2))
                           .normalized();
        const double value = SeparationAlong(a, X_Wa, b, X_Wb, n);
        if (value > best) {
          best = value;
          best_n = n;
          improved = 1;
        }
      }
    }
  }
  *start = best_n;
  return best;
}

// The signed distance as the largest separation found from the best direction of a coarse
// spherical grid and from `hint`. Any direction's separation is a lower bound of the distance,
// so a hint cannot make it too large: it only helps the search where the grid start stalls.
double OracleSignedDistance(const Primitive& a, const Pose& X_Wa, const Primitive& b,
                            const Pose& X_Wb, const Vec3& hint) {
  Vec3 grid_best = Vec3::UnitZ();
  double best = -kInf;
  constexpr int kGrid = 500;
  for (int i = 0; i < kGrid; ++i) {
    // Fibonacci sphere
    const double z = 1.0 - 2.0 * (i + 0.5) / kGrid;
    const double angle = i * kPi * (3.0 - std::sqrt(5.0));
    const Vec3 n(std::sqrt(1.0 - z * z) * std::cos(angle), std::sqrt(1.0 - z * z) * std::sin(angle),
                 z);
    const double value = SeparationAlong(a, X_Wa, b, X_Wb, n);
    if (value > best) {
      best = value;
      grid_best = n;
    }
  }
  Vec3 hinted = hint;
  return std::max(MaximiseSeparation(a, X_Wa, b, X_Wb, &grid_best),
                  MaximiseSeparation(a, X_Wa, b, X_Wb, &hinted));
}

// Portable random numbers: the standard distributions differ between standard libraries.
class Random {
 public:
  explicit Random(std::uint32_t seed) : engine_(seed) {}
  double Uniform(double lo, double hi) {
    return lo + (hi - lo) * (static_cast<double>(engine_()) + 0.5) / 4294967296.0;
  }
  // Box-Muller
  double Normal() {
    const double radius = std::sqrt(-2.0 * std::log(Uniform(0.0, 1.0)));
    return radius * std::cos(2.0 * kPi * Uniform(0.0, 1.0));
  }
  Vec3 Direction() { return Vec3(Normal(), Normal(), Normal()).normalized(); }
  Pose Orientation() {
    Pose pose = Pose::Identity();
    pose.linear() =
        Eigen::Quaterniond(Normal(), Normal(), Normal(), Normal()).normalized().toRotationMatrix();
    return pose;
  }

 private:
  std::mt19937 engine_;
};

const Contact* Deepest(const ContactList& contacts) {
  const auto deepest =
      std::max_element(contacts.begin(), contacts.end(),
                       [](const Contact& x, const Contact& y) { return x.depth < y.depth; });
  return deepest == contacts.end() ? nullptr : &*deepest;
}

// every contact well formed, and the swapped pair gives the same contacts turned around
void ExpectWellFormedAndSymmetric(const ContactList& contacts, const ContactList& swapped) {
  ASSERT_EQ(contacts.size(), swapped.size());
  for (size_t k = 0; k < contacts.size(); ++k) {
    const Contact& contact = contacts[k];
    ASSERT_TRUE(contact.position.allFinite());
    EXPECT_NEAR(contact.normal.norm(), 1.0, 1e-12);
    EXPECT_GT(contact.depth, 0.0);
    EXPECT_EQ(contact.penetrating, contact.depth > kContactTol);
    EXPECT_EQ(contact.depth, swapped[k].depth);
    EXPECT_EQ(contact.normal, Vec3(-swapped[k].normal));
  }
}

TEST(PrimitiveContactsTest, RandomPairsMatchTheSupportFunctionDistance) {
  const std::vector<Primitive> shapes = {
      Primitive::Sphere(0.1), Primitive::Box(Vec3(0.3, 0.2, 0.1)), Primitive::Capsule(0.05, 0.25),
      Primitive::Cylinder(0.08, 0.3), kPlane};
  Random random(7);
  // Every contact joins two surface points along its normal, so the contacts give an upper bound
  // of the distance and the oracle a lower bound. The oracle is started from the deepest normal
  // of a 10 cm layer too (any direction keeps it a lower bound), where the grid start can stall
  // on the kinks of box and rim support functions. Both resolve well below a micrometre.
  constexpr double kDistanceTolerance = 1e-7;
  constexpr double kWidePad = 0.05;
  for (size_t i = 0; i < shapes.size(); ++i) {
    for (size_t j = i; j < shapes.size(); ++j) {
      if (shapes[i].type == PrimitiveType::kPlane) continue;
      const bool plane = shapes[j].type == PrimitiveType::kPlane;
      for (int trial = 0; trial < kRandomTrials; ++trial) {
        SCOPED_TRACE(std::string(shapes[i].TypeName()) + "-" + shapes[j].TypeName() + " trial " +
                     std::to_string(trial));
        // b at the origin, a along a random direction, separated along it by a random gap
        const Pose X_Wb = plane ? Pose::Identity() : random.Orientation();
        const Vec3 direction = plane ? Vec3::UnitZ() : random.Direction();
        const Pose X_a0 = random.Orientation();
        const double gap = random.Uniform(-0.004, 0.008);
        const double reach = direction.dot(Support(shapes[j], X_Wb, direction)) -
                             direction.dot(Support(shapes[i], X_a0, -direction));
        const Pose X_Wa = Pose(Eigen::Translation3d((reach + gap) * direction)) * X_a0;

        const ContactList contacts = Contacts(shapes[i], X_Wa, shapes[j], X_Wb);
        ExpectWellFormedAndSymmetric(contacts, Contacts(shapes[j], X_Wb, shapes[i], X_Wa));
        const ContactList wide_contacts =
            Contacts(shapes[i], X_Wa, shapes[j], X_Wb, kWidePad, kWidePad);
        const Contact* wide = Deepest(wide_contacts);
        const double distance = OracleSignedDistance(shapes[i], X_Wa, shapes[j], X_Wb,
                                                     wide != nullptr ? wide->normal : direction);
        const Contact* deepest = Deepest(contacts);
        if (distance > kContactTol + kDistanceTolerance) {
          EXPECT_EQ(deepest, nullptr) << "distance " << distance;
        } else if (distance > 0.0 && distance < kContactTol - kDistanceTolerance) {
          // separated within the layer: the deepest contact is the nearest pair
          ASSERT_NE(deepest, nullptr) << "distance " << distance;
          EXPECT_NEAR(deepest->depth, kContactTol - distance, kDistanceTolerance);
        } else if (distance < -kDistanceTolerance) {
          ASSERT_NE(deepest, nullptr) << "distance " << distance;
          EXPECT_TRUE(deepest->penetrating) << "distance " << distance;
        }
      }
    }
  }
}

// A box of a stack placed over the one below it, at the origin.
struct StackedBox {
  Pose X_Wa = Pose::Identity();
  Vec3 shift = Vec3::Zero();  ///< its sideways offset from the box below (m)
};

// A box of side `side` over an equal one: turned by up to `yaw` (rad) about the vertical, shifted
// by up to `shift` (m) along x and y and tilted by up to `tilt` (rad), its bottom face from 1 mm
// into to 4 mm above the top face below (within the 5 mm layer).
StackedBox RandomStackedBox(double side, double yaw, double shift, double tilt, Random* random) {
  StackedBox stacked;
  stacked.shift = Vec3(random->Uniform(-shift, shift), random->Uniform(-shift, shift), 0.0);
  const Vec3 tilt_axis = Vec3(random->Normal(), random->Normal(), 0.0).normalized();
  const double gap = random->Uniform(-0.001, 0.004);
  stacked.X_Wa = At(stacked.shift.x(), stacked.shift.y(), side + gap) *
                 Rotated(tilt_axis, random->Uniform(0.0, tilt), Vec3::Zero()) *
                 Rotated(Vec3::UnitZ(), random->Uniform(-yaw, yaw), Vec3::Zero());
  return stacked;
}

TEST(PrimitiveContactsTest, NearlyAlignedStackedBoxesGiveJustTheOverlapCorners) {
  const double side = 0.1;
  const Primitive box = Primitive::Box(Vec3::Constant(side));
  // turning by the largest yaw moves a face corner this far sideways, tilting it even less (m)
  const double corner_tolerance = 1e-4;
  Random random(11);
  // perturbations at full size, at a micrometre scale, and at the rounding scale of a settled
  // stack (where the nearly parallel edges cross near their middles)
  for (const double scale : {1.0, 1e-3, 1e-12}) {
    for (int trial = 0; trial < kRandomTrials; ++trial) {
      SCOPED_TRACE(testing::Message() << "scale " << scale << " trial " << trial);
      const StackedBox stacked =
          RandomStackedBox(side, scale * 1e-3, scale * 1e-3, scale * 1e-4, &random);
      const ContactList contacts = Contacts(box, stacked.X_Wa, box, Pose::Identity());
      ExpectWellFormedAndSymmetric(contacts, Contacts(box, Pose::Identity(), box, stacked.X_Wa));
      ASSERT_EQ(contacts.size(), 4u);
      EXPECT_FALSE(SomeContactLiesBetweenTwoOthers(contacts, kBetweenTolerance));
      // the corners of the overlap of the two squares (taken unturned)
      for (const double x : {-1.0, 1.0}) {
        for (const double y : {-1.0, 1.0}) {
          const Vec3 corner(x * (0.5 * side - 0.5 * std::abs(stacked.shift.x())),
                            y * (0.5 * side - 0.5 * std::abs(stacked.shift.y())), 0.0);
          const Vec3 centred = corner + 0.5 * stacked.shift;
          const bool found =
              std::any_of(contacts.begin(), contacts.end(), [&](const Contact& contact) {
                return (contact.position - centred).head<2>().norm() <= corner_tolerance;
              });
          EXPECT_TRUE(found) << "no contact at " << centred.transpose();
        }
      }
    }
  }
}

TEST(PrimitiveContactsTest, OverhangingTiltedStackedBoxesFindTheTrueSeparation) {
  // a jostled stack (QuickStep's): the box above shifted past the edge of the one below by up to
  // 2 cm and tilted by up to 1e-2 rad, so that its lowest corner overhangs and the nearest points
  // lie on edges (the search over edges skips those its lower bound rules out: it must still find
  // the nearest)
  const double side = 0.1;
  const Primitive box = Primitive::Box(Vec3::Constant(side));
  Random random(13);
  constexpr double kDistanceTolerance = 1e-7;
  for (const double tilt : {1e-2, 1e-4}) {
    for (int trial = 0; trial < kRandomTrials; ++trial) {
      SCOPED_TRACE(testing::Message() << "tilt " << tilt << " trial " << trial);
      const StackedBox stacked = RandomStackedBox(side, 1e-2, 0.02, tilt, &random);
      const ContactList contacts = Contacts(box, stacked.X_Wa, box, Pose::Identity());
      ExpectWellFormedAndSymmetric(contacts, Contacts(box, Pose::Identity(), box, stacked.X_Wa));
      const Contact* deepest = Deepest(contacts);
      // the oracle (a lower bound of the distance) started from the deepest normal of a wide layer
      const ContactList wide_contacts =
          Contacts(box, stacked.X_Wa, box, Pose::Identity(), 0.05, 0.05);
      const Contact* wide = Deepest(wide_contacts);
      const double distance = OracleSignedDistance(box, stacked.X_Wa, box, Pose::Identity(),
                                                   wide != nullptr ? wide->normal : Vec3::UnitZ());
      if (distance > 0.0 && distance < kContactTol - kDistanceTolerance) {
        ASSERT_NE(deepest, nullptr) << "distance " << distance;
        EXPECT_NEAR(deepest->depth, kContactTol - distance, kDistanceTolerance);
      }
    }
  }
}

TEST(PrimitiveContactsTest, PlanePlaneIsUnsupported) {
  ContactList contacts;
  EXPECT_FALSE(
      PrimitiveContacts(kPlane, At(0, 0, 0), kPad, kPlane, At(0, 0, 0.001), kPad, &contacts));
  EXPECT_TRUE(contacts.empty());
}

}  // namespace
}  // namespace lamina::core
