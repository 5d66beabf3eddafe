// SPDX-License-Identifier: MIT
// Mesh contacts with known answers: unit cube meshes resting, turned, separated, touching at
// faces, edges and corners, and overlapping; mesh vertices on planes; the cube mesh against
// analytic boxes, spheres, capsules and cylinders; determinism, also across calls that reuse
// the working memory; and the per-call time of a cube on a 32768-triangle terrain (printed,
// not asserted).
#include "core/contact/mesh_contacts.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>

#include <gtest/gtest.h>

#include "core/contact/mesh_query.h"
#include "core/contact/triangle_queries.h"
#include "core/io/mesh_file.h"
#include "tests/common/test_support.h"

namespace lamina {
namespace {

using core::CollisionGeometry;
using core::Contact;
using core::ContactList;
using core::GeometryDesc;
using core::Mat3;
using core::Pose;
using core::Primitive;
using core::Vec3;

// 2.5 mm of padding on each side: contacts appear below 5 mm and are 4 mm deep at 1 mm
constexpr double kPad = 0.0025;
constexpr double kTolerance = 2 * kPad;
// the distances are differences of small exact numbers: only rounding is allowed
constexpr double kDepthTolerance = 1e-9;
constexpr double kNormalTolerance = 1e-9;

std::shared_ptr<const CollisionGeometry> MeshGeometry(const std::string& relative,
                                                      double scale = 1.0) {
  core::Diagnostics diagnostics;
  std::optional<core::TriangleMesh> mesh =
      core::ReadMeshFile(test::WorldsPath(relative), {}, diagnostics);
  EXPECT_TRUE(mesh.has_value()) << diagnostics.FormatAll();
  GeometryDesc desc;
  desc.kind = core::GeometryKind::kMesh;
  desc.mesh = std::make_shared<const core::TriangleMesh>(mesh.value_or(core::TriangleMesh()));
  desc.scale = Vec3::Constant(scale);
  return CollisionGeometry::Build(desc);
}

std::shared_ptr<const CollisionGeometry> PrimitiveGeometry(const Primitive& primitive) {
  GeometryDesc desc;
  desc.kind = core::GeometryKind::kPrimitive;
  desc.primitive = primitive;
  return CollisionGeometry::Build(desc);
}

const CollisionGeometry& Cube() {
  static const std::shared_ptr<const CollisionGeometry> cube =
      MeshGeometry("klampt/objects/cube.off");
  return *cube;
}

using test::PoseAt;

Mat3 AboutX(double angle) {
  return core::RotationFromRollPitchYaw(angle, 0, 0);
}
Mat3 AboutY(double angle) {
  return core::RotationFromRollPitchYaw(0, angle, 0);
}
Mat3 AboutZ(double angle) {
  return core::RotationFromRollPitchYaw(0, 0, angle);
}

ContactList MeshMesh(const CollisionGeometry& a, const Pose& X_Wa, const CollisionGeometry& b,
                     const Pose& X_Wb) {
  ContactList contacts;
  core::MeshMeshContacts(a, X_Wa, kPad, b, X_Wb, kPad, &contacts);
  return contacts;
}

ContactList MeshPrimitive(const CollisionGeometry& a, const Pose& X_Wa, const Primitive& b,
                          const Pose& X_Wb = Pose::Identity()) {
  ContactList contacts;
  core::MeshPrimitiveContacts(a, X_Wa, kPad, *PrimitiveGeometry(b), X_Wb, kPad, &contacts);
  return contacts;
}

void ExpectAll(const ContactList& contacts, double depth, const Vec3& normal,
               bool penetrating = false) {
  ASSERT_FALSE(contacts.empty());
  for (size_t i = 0; i < contacts.size(); ++i) {
    EXPECT_NEAR(contacts[i].depth, depth, kDepthTolerance) << "contact " << i;
    EXPECT_NEAR((contacts[i].normal - normal).norm(), 0.0, kNormalTolerance) << "contact " << i;
    EXPECT_EQ(contacts[i].penetrating, penetrating) << "contact " << i;
  }
}

void ExpectIdentical(const ContactList& first, const ContactList& second) {
  ASSERT_EQ(first.size(), second.size());
  for (size_t i = 0; i < first.size(); ++i) {
    EXPECT_EQ(first[i].position, second[i].position);
    EXPECT_EQ(first[i].normal, second[i].normal);
    EXPECT_EQ(first[i].depth, second[i].depth);
    EXPECT_EQ(first[i].penetrating, second[i].penetrating);
  }
}

// ---- mesh-mesh ----

TEST(MeshMeshContactsTest, CubeRestingOnCubeHasBoundaryLayerDepth) {
  const ContactList contacts =
      MeshMesh(Cube(), PoseAt(Vec3(0, 0, 1.001)), Cube(), PoseAt(Vec3::Zero()));
  ExpectAll(contacts, 0.004, Vec3::UnitZ());
  for (const Contact& c : contacts) {
    // midway between the padded surfaces at z = 1.001 - 0.0025 and z = 1 + 0.0025
    EXPECT_NEAR(c.position.z(), 1.0005, kDepthTolerance);
    EXPECT_GE(c.position.x(), -kDepthTolerance);
    EXPECT_LE(c.position.x(), 1 + kDepthTolerance);
  }
}

TEST(MeshMeshContactsTest, WholeSceneTurnedKeepsTheNormalInTheSceneFrame) {
  for (const Mat3& R : {AboutX(0.25 * core::kPi), AboutZ(0.25 * core::kPi)}) {
    const Pose scene = PoseAt(Vec3(0.3, -0.2, 0.1), R);
    const ContactList contacts = MeshMesh(Cube(), scene * PoseAt(Vec3(0, 0, 1.001)), Cube(), scene);
    ExpectAll(contacts, 0.004, R * Vec3::UnitZ());
  }
}

TEST(MeshMeshContactsTest, TopCubeTurnedAboutTheVerticalStillPushesUp) {
  // turned 45 degrees about its own vertical axis, resting 1 mm above
  const Pose top = PoseAt(Vec3(0.5, 0.5, 1.001)) * PoseAt(Vec3::Zero(), AboutZ(0.25 * core::kPi)) *
                   PoseAt(Vec3(-0.5, -0.5, 0));
  ExpectAll(MeshMesh(Cube(), top, Cube(), PoseAt(Vec3::Zero())), 0.004, Vec3::UnitZ());
}

TEST(MeshMeshContactsTest, SeparatedBeyondThePaddingGivesNothing) {
  EXPECT_TRUE(MeshMesh(Cube(), PoseAt(Vec3(0, 0, 1.0051)), Cube(), PoseAt(Vec3::Zero())).empty());
  ExpectAll(MeshMesh(Cube(), PoseAt(Vec3(0, 0, 1.0049)), Cube(), PoseAt(Vec3::Zero())), 0.0001,
            Vec3::UnitZ());
}

TEST(MeshMeshContactsTest, OverlappingCubesArePenetrating) {
  const ContactList contacts =
      MeshMesh(Cube(), PoseAt(Vec3(0.3, 0.2, 0.9)), Cube(), PoseAt(Vec3::Zero()));
  ASSERT_FALSE(contacts.empty());
  int penetrating = 0;
  for (const Contact& c : contacts) {
    penetrating += c.penetrating;
    EXPECT_LE(c.depth, kTolerance);  // the boundary layer cannot express more
    EXPECT_NEAR(c.normal.norm(), 1.0, kNormalTolerance);
  }
  EXPECT_GT(penetrating, 0);
}

TEST(MeshMeshContactsTest, TouchingFacesTakeTheFaceNormal) {
  // exactly touching (distance 0): the normal comes from the features, not the points
  const ContactList contacts =
      MeshMesh(Cube(), PoseAt(Vec3(0.25, 0.25, 1.0)), Cube(), PoseAt(Vec3::Zero()));
  ExpectAll(contacts, kTolerance, Vec3::UnitZ());
}

TEST(MeshMeshContactsTest, CornerOnCornerTakesTheVertexNormals) {
  // a's corner (0,0,0) on b's corner (1,1,1): n_b - n_a = 2 (1,1,1)/sqrt(3)
  const ContactList contacts =
      MeshMesh(Cube(), PoseAt(Vec3(1, 1, 1)), Cube(), PoseAt(Vec3::Zero()));
  ExpectAll(contacts, kTolerance, Vec3(1, 1, 1).normalized());
}

TEST(MeshMeshContactsTest, CrossedEdgesTakeTheEdgeNormal) {
  // a turned 45 degrees about x (lowest feature: an edge along x), b turned about y (highest
  // feature: an edge along y), the edges crossing 1 micrometre apart
  const double half_diagonal = std::sqrt(0.5);
  const Pose centre_a = PoseAt(Vec3(0.5, 0.5, 0.5));  // cube centre in its own frame
  const Pose a =
      PoseAt(Vec3(0, 0, 2 * half_diagonal + 1e-6), AboutX(0.25 * core::kPi)) * centre_a.inverse();
  const Pose b = PoseAt(Vec3::Zero(), AboutY(0.25 * core::kPi)) * centre_a.inverse();
  const ContactList contacts = MeshMesh(Cube(), a, Cube(), b);
  ASSERT_FALSE(contacts.empty());
  for (const Contact& c : contacts) {
    EXPECT_NEAR((c.normal - Vec3::UnitZ()).norm(), 0.0, kNormalTolerance);
    // rounding in the rotated corners moves the distance by about 1e-16 m
    EXPECT_NEAR(c.depth, kTolerance - 1e-6, 1e-12);
    EXPECT_NEAR(c.position.head<2>().norm(), 0.0, 1e-9);
  }
}

TEST(MeshMeshContactsTest, CornerSunkOnAFaceDiagonalIsPushedStraightOut) {
  // a stands on its corner (body diagonal vertical), sunk 3 mm into b's top face exactly on the
  // face's diagonal, where b's two top triangles meet flat: the diagonal has no direction of
  // its own, so every contact must push along the face normal (closest points between a's
  // rising edges and the diagonal would point sideways)
  const Mat3 corner_down =
      AboutZ(0.3) * Eigen::Quaterniond::FromTwoVectors(Vec3(1, 1, 1).normalized(), -Vec3::UnitZ())
                        .toRotationMatrix();
  const Vec3 lowest_corner = corner_down * Vec3(1, 1, 1);
  const Pose a = PoseAt(Vec3(0.5, 0.5, 1 - 0.003) - lowest_corner, corner_down);
  const ContactList contacts = MeshMesh(Cube(), a, Cube(), PoseAt(Vec3::Zero()));
  ASSERT_FALSE(contacts.empty());
  double deepest = 0.0;
  for (const Contact& c : contacts) {
    EXPECT_NEAR((c.normal - Vec3::UnitZ()).norm(), 0.0, kNormalTolerance);
    EXPECT_GT(c.depth, 0.0);
    deepest = std::max(deepest, c.depth);
  }
  EXPECT_NEAR(deepest, kTolerance + 0.003, 1e-9);  // at the corner
}

TEST(MeshMeshContactsTest, SameCallTwiceGivesIdenticalContacts) {
  const Pose a = PoseAt(Vec3(0.1, 0.2, 1.002), core::RotationFromRollPitchYaw(0.001, -0.002, 0.3));
  const ContactList first = MeshMesh(Cube(), a, Cube(), PoseAt(Vec3::Zero()));
  const ContactList second = MeshMesh(Cube(), a, Cube(), PoseAt(Vec3::Zero()));
  ASSERT_FALSE(first.empty());
  ExpectIdentical(first, second);
  // and a tilted box sunk into the cube mesh's top corner
  const Primitive box = Primitive::Box(Vec3(0.3, 0.2, 0.1));
  const Pose box_pose =
      PoseAt(Vec3(0.95, 0.9, 1.03), core::RotationFromRollPitchYaw(0.3, 0.2, 0.1));
  const ContactList box_first = MeshPrimitive(Cube(), PoseAt(Vec3::Zero()), box, box_pose);
  ASSERT_FALSE(box_first.empty());
  ExpectIdentical(box_first, MeshPrimitive(Cube(), PoseAt(Vec3::Zero()), box, box_pose));
}

TEST(MeshMeshContactsTest, EarlierCallsOnOtherMeshesDoNotChangeTheContacts) {
  // calls reuse working memory sized by the meshes they see: a small pair, then large meshes in
  // both roles, then the small pair again
  const auto sphere = MeshGeometry("klampt/objects/sphere.off", 0.5);
  const Pose on_top =
      PoseAt(Vec3(0.1, 0.2, 1.002), core::RotationFromRollPitchYaw(0.01, -0.02, 0.3));
  const ContactList first = MeshMesh(Cube(), on_top, Cube(), PoseAt(Vec3::Zero()));
  ASSERT_FALSE(first.empty());
  const Pose sphere_on_cube = PoseAt(Vec3(0.5, 0.5, 1.501));
  const ContactList sphere_first = MeshMesh(*sphere, sphere_on_cube, Cube(), PoseAt(Vec3::Zero()));
  ASSERT_FALSE(sphere_first.empty());
  ASSERT_FALSE(MeshMesh(Cube(), PoseAt(Vec3::Zero()), *sphere, sphere_on_cube).empty());
  ExpectIdentical(first, MeshMesh(Cube(), on_top, Cube(), PoseAt(Vec3::Zero())));
  ExpectIdentical(sphere_first, MeshMesh(*sphere, sphere_on_cube, Cube(), PoseAt(Vec3::Zero())));
}

TEST(MeshMeshContactsTest, BallOverASlabTouchesOnceAtEachNearVertex) {
  // stiffness_test.xml's 960-triangle ball, radius 0.1 m, turned three ways, 1 mm over the 4 m
  // slab with 2 cm of padding each: every ball vertex within the 4 cm layer touches the slab's
  // top once, at its own place, straight up and tolerance - height deep. Each ball triangle's
  // closest points to the slab are its lowest corner and that corner's foot, which repeat the
  // vertex's contact: they add none.
  const auto ball = MeshGeometry("klampt/objects/sphere.off", 0.1);
  const auto slab = MeshGeometry("klampt/terrains/block.off");
  constexpr double kLayerPad = 0.02, kLayer = 2 * kLayerPad;
  for (const Mat3& R : {AboutX(0.3), Mat3(AboutY(-1.1) * AboutZ(0.4)), AboutZ(2.0)}) {
    const Pose X_Wball = PoseAt(Vec3(0.2, -0.3, 0.101), R);
    ContactList contacts;
    core::MeshMeshContacts(*ball, X_Wball, kLayerPad, *slab, PoseAt(Vec3::Zero()), kLayerPad,
                           &contacts);
    std::vector<Vec3> near;
    for (const Vec3& v : ball->mesh().vertices) {
      const Vec3 w = X_Wball * v;
      if (w.z() <= kLayer) near.push_back(w);
    }
    ASSERT_GT(near.size(), 60u);
    ASSERT_EQ(contacts.size(), near.size());
    for (const Vec3& w : near) {
      const auto at_w = std::find_if(contacts.begin(), contacts.end(), [&w](const Contact& c) {
        return (c.position.head<2>() - w.head<2>()).norm() < kDepthTolerance;
      });
      ASSERT_NE(at_w, contacts.end()) << "vertex at " << w.transpose();
      EXPECT_NEAR(at_w->position.z(), 0.5 * w.z(), kDepthTolerance);
      EXPECT_NEAR(at_w->depth, kLayer - w.z(), kDepthTolerance);
      EXPECT_NEAR((at_w->normal - Vec3::UnitZ()).norm(), 0.0, kNormalTolerance);
    }
  }
}

TEST(MeshMeshContactsTest, AFaceWithoutAreaHoldsNoVertexOverIt) {
  // HRP-2's foot (RLEG_LINK5.off) has 12 triangles of no area; one, 925, lies along the sole's
  // edge: three collinear corners at y = 0.019, z = -0.105, whose barycentric map is rounding
  // (its determinant 2e-16 of its scale, not zero). With no normal, the face "held" a ground
  // vertex near it at distance 0: a contact the whole layer deep where the ground is 4 mm away
  // (the 18 rollbacks in 5 s of hrp2_rough.xml). A ground triangle 4.14 mm under the sole, with
  // a corner where that map reads inside the face: no contact is deeper than the 0.86 mm the
  // layers overlap (the sole's face over the ground's; its edges give shallower ones).
  const auto foot = MeshGeometry("klampt/robots/hrp2/RLEG_LINK5.off");
  const Vec3 corner(-0.07353103097149746, 0.01016496340216167, -0.10914277686853904);
  auto ground = std::make_shared<core::TriangleMesh>();
  ground->vertices = {corner, corner + Vec3(0.02, 0.02, 0), corner + Vec3(-0.02, 0.02, 0)};
  ground->triangles = {Eigen::Vector3i(0, 1, 2)};
  GeometryDesc desc;
  desc.kind = core::GeometryKind::kMesh;
  desc.mesh = ground;
  const auto ground_geometry = CollisionGeometry::Build(desc);
  const ContactList contacts =
      MeshMesh(*foot, PoseAt(Vec3::Zero()), *ground_geometry, PoseAt(Vec3::Zero()));
  ASSERT_FALSE(contacts.empty());
  for (size_t i = 0; i < contacts.size(); ++i) {
    EXPECT_LE(contacts[i].depth, kTolerance - (-0.105 - corner.z()) + 1e-9) << "contact " << i;
    EXPECT_NEAR(contacts[i].normal.norm(), 1.0, kNormalTolerance) << "contact " << i;
  }
}

TEST(BarycentricMapTest, MatchesBarycentricCoordinatesBitwise) {
  const core::mesh_detail::Triangle3 triangle = {Vec3(0.1, 0.2, 0.3), Vec3(1.3, -0.2, 0.1),
                                                 Vec3(0.2, 0.9, -0.4)};
  const core::mesh_detail::BarycentricMap map(triangle);
  for (const Vec3& p : {Vec3(0.3, 0.3, 0.0), Vec3(-2.0, 1.0, 0.5), Vec3(0.1, 0.2, 0.3)}) {
    EXPECT_EQ(map(p), core::mesh_detail::BarycentricCoordinates(p, triangle));
  }
  // a degenerate triangle maps everything to its first corner
  const core::mesh_detail::Triangle3 line = {Vec3::Zero(), Vec3::UnitX(), Vec3(2, 0, 0)};
  EXPECT_EQ(core::mesh_detail::BarycentricMap(line)(Vec3(0.5, 1, 0)), Vec3(1, 0, 0));
}

// ---- mesh-plane ----

TEST(MeshPlaneContactsTest, SphereMeshRestingOnAPlaneTouchesWithItsLowestVertex) {
  const auto sphere = MeshGeometry("klampt/objects/sphere.off");  // unit sphere, pole at -z
  const ContactList contacts =
      MeshPrimitive(*sphere, PoseAt(Vec3(0, 0, 1.001)), Primitive::Plane());
  ASSERT_EQ(contacts.size(), 1u);
  ExpectAll(contacts, 0.004, Vec3::UnitZ());
  EXPECT_NEAR((contacts[0].position - Vec3(0, 0, 0.0005)).norm(), 0.0, kDepthTolerance);
}

TEST(MeshPlaneContactsTest, TiltedPlaneThroughAMeshMatchesEveryVertex) {
  const auto sphere = MeshGeometry("klampt/objects/sphere.off");
  const Pose plane = PoseAt(Vec3(0.2, 0.1, 0.3), core::RotationFromRollPitchYaw(0.4, -0.3, 0.2));
  const Pose X_Wa = PoseAt(Vec3(0.1, 0, 0.5));
  const ContactList contacts = MeshPrimitive(*sphere, X_Wa, Primitive::Plane(), plane);
  // brute force over every vertex, in the same (vertex) order
  const Vec3 n = plane.linear().col(2);
  size_t k = 0;
  for (const Vec3& v : sphere->mesh().vertices) {
    const double height = n.dot(X_Wa * v - plane.translation());
    if (height >= kTolerance) continue;
    ASSERT_LT(k, contacts.size());
    EXPECT_NEAR(contacts[k].depth, kTolerance - height, kDepthTolerance);
    EXPECT_EQ(contacts[k].penetrating, height < 0);
    EXPECT_NEAR((contacts[k].normal - n).norm(), 0.0, kNormalTolerance);
    ++k;
  }
  EXPECT_EQ(k, contacts.size());
  EXPECT_GT(k, 100u);  // the plane cuts the sphere well below its centre
}

TEST(MeshPlaneContactsTest, PlaneFacingDownPushesTheMeshDown) {
  // the plane turned upside down at z = 1.001 above the cube: its half-space is z >= 1.001
  const Pose plane = PoseAt(Vec3(0, 0, 1.001), AboutX(core::kPi));
  const ContactList contacts =
      MeshPrimitive(Cube(), PoseAt(Vec3::Zero()), Primitive::Plane(), plane);
  EXPECT_EQ(contacts.size(), 4u);  // the four top corners
  ExpectAll(contacts, 0.004, -Vec3::UnitZ());
}

TEST(MeshPlaneContactsTest, SwappedOrderGivesTheSameContactsTurnedAround) {
  const auto plane = PrimitiveGeometry(Primitive::Plane());
  const Pose X_cube = PoseAt(Vec3(0, 0, 0.002), AboutZ(0.3));
  ContactList mesh_first, plane_first;
  core::Collide(Cube(), X_cube, kPad, *plane, Pose::Identity(), kPad, &mesh_first);
  core::Collide(*plane, Pose::Identity(), kPad, Cube(), X_cube, kPad, &plane_first);
  ASSERT_EQ(mesh_first.size(), 4u);
  ASSERT_EQ(plane_first.size(), mesh_first.size());
  for (size_t i = 0; i < mesh_first.size(); ++i) {
    EXPECT_EQ(mesh_first[i].normal, Vec3::UnitZ());
    EXPECT_EQ(plane_first[i].normal, -mesh_first[i].normal);
    EXPECT_EQ(plane_first[i].position, mesh_first[i].position);
    EXPECT_NEAR(mesh_first[i].depth, 0.003 + core::kLayerEdgeSlack, kDepthTolerance);
  }
}

// ---- mesh-primitive: the unit cube mesh below, the primitive above its top face ----

TEST(MeshPrimitiveContactsTest, BoxAboveTheTopFaceRestsOnItsFourCorners) {
  const ContactList contacts =
      MeshPrimitive(Cube(), PoseAt(Vec3::Zero()), Primitive::Box(Vec3::Constant(0.5)),
                    PoseAt(Vec3(0.5, 0.5, 1.251)));
  ASSERT_EQ(contacts.size(), 4u);
  // normal from the box into the mesh below: down
  ExpectAll(contacts, 0.004, -Vec3::UnitZ());
  for (const Contact& c : contacts) {
    EXPECT_NEAR(c.position.z(), 1.0005, kDepthTolerance);
    EXPECT_NEAR(std::abs(c.position.x() - 0.5), 0.25, kDepthTolerance);
    EXPECT_NEAR(std::abs(c.position.y() - 0.5), 0.25, kDepthTolerance);
  }
}

TEST(MeshPrimitiveContactsTest, BoxSunkIntoTheFacePushesOutAlongIt) {
  // 2 mm into the top face: corners behind the face are dropped, the crossing gives the depth
  const ContactList contacts =
      MeshPrimitive(Cube(), PoseAt(Vec3::Zero()), Primitive::Box(Vec3::Constant(0.5)),
                    PoseAt(Vec3(0.5, 0.5, 1.248)));
  ExpectAll(contacts, kTolerance + 0.002, -Vec3::UnitZ(), true);
}

TEST(MeshPrimitiveContactsTest, BoxAcrossARidgeTouchesAtTheRidge) {
  // the cube mesh turned 45 degrees about y: its top is the edge along y at height sqrt(2)/2
  const Pose cube = PoseAt(Vec3::Zero(), AboutY(0.25 * core::kPi)) * PoseAt(Vec3(-0.5, -0.5, -0.5));
  const double ridge = std::sqrt(0.5);
  const ContactList contacts = MeshPrimitive(Cube(), cube, Primitive::Box(Vec3(2, 2, 0.2)),
                                             PoseAt(Vec3(0, 0, ridge + 0.1 + 0.001)));
  ExpectAll(contacts, 0.004, -Vec3::UnitZ());
  for (const Contact& c : contacts) EXPECT_NEAR(c.position.x(), 0.0, kDepthTolerance);
}

TEST(MeshPrimitiveContactsTest, SphereAboveTheFaceAndBesideTheEdge) {
  const ContactList above = MeshPrimitive(Cube(), PoseAt(Vec3::Zero()), Primitive::Sphere(0.3),
                                          PoseAt(Vec3(0.5, 0.3, 1.302)));
  ASSERT_EQ(above.size(), 1u);
  ExpectAll(above, 0.003, -Vec3::UnitZ());
  // beside the top edge x = 1 at 45 degrees: the normal points from the sphere to the edge
  const Vec3 out = Vec3(1, 0, 1).normalized();
  const ContactList beside = MeshPrimitive(Cube(), PoseAt(Vec3::Zero()), Primitive::Sphere(0.2),
                                           PoseAt(Vec3(1, 0.5, 1) + 0.201 * out));
  ASSERT_EQ(beside.size(), 1u);  // two triangles meet at the edge: one contact survives
  ExpectAll(beside, 0.004, -out);
}

TEST(MeshPrimitiveContactsTest, SphereSunkBelowTheFaceStillPushesOut) {
  // centre 1 cm below the top face: distance -(0.01 + 0.1), normal from the face
  const ContactList contacts = MeshPrimitive(Cube(), PoseAt(Vec3::Zero()), Primitive::Sphere(0.1),
                                             PoseAt(Vec3(0.5, 0.4, 0.99)));
  ASSERT_FALSE(contacts.empty());
  const Contact& deepest =
      *std::max_element(contacts.begin(), contacts.end(),
                        [](const Contact& x, const Contact& y) { return x.depth < y.depth; });
  EXPECT_NEAR(deepest.depth, kTolerance + 0.09, kDepthTolerance);
  EXPECT_TRUE(deepest.penetrating);
  EXPECT_NEAR((deepest.normal + Vec3::UnitZ()).norm(), 0.0, kNormalTolerance);
}

TEST(MeshPrimitiveContactsTest, CapsuleLyingOnTheFaceRestsOnBothEnds) {
  const ContactList contacts =
      MeshPrimitive(Cube(), PoseAt(Vec3::Zero()), Primitive::Capsule(0.1, 0.6),
                    PoseAt(Vec3(0.5, 0.5, 1.101), AboutY(0.5 * core::kPi)));
  ASSERT_EQ(contacts.size(), 2u);
  ExpectAll(contacts, 0.004, -Vec3::UnitZ());
  EXPECT_NEAR(std::abs(contacts[0].position.x() - contacts[1].position.x()), 0.6, kDepthTolerance);
}

TEST(MeshPrimitiveContactsTest, CylinderStandingOrLyingRestsOnItsRims) {
  const ContactList standing = MeshPrimitive(
      Cube(), PoseAt(Vec3::Zero()), Primitive::Cylinder(0.2, 0.4), PoseAt(Vec3(0.5, 0.5, 1.201)));
  ASSERT_EQ(standing.size(), 4u);
  ExpectAll(standing, 0.004, -Vec3::UnitZ());
  const ContactList lying =
      MeshPrimitive(Cube(), PoseAt(Vec3::Zero()), Primitive::Cylinder(0.2, 0.6),
                    PoseAt(Vec3(0.5, 0.5, 1.201), AboutY(0.5 * core::kPi)));
  ASSERT_EQ(lying.size(), 2u);
  ExpectAll(lying, 0.004, -Vec3::UnitZ());
  // tilted about y: the rim point lowest along +x touches alone
  const double tilt = 0.1;
  const double lift = 0.2 * std::cos(tilt) + 0.2 * std::sin(tilt);
  const ContactList tilted =
      MeshPrimitive(Cube(), PoseAt(Vec3::Zero()), Primitive::Cylinder(0.2, 0.4),
                    PoseAt(Vec3(0.5, 0.3, 1.001 + lift), AboutY(tilt)));
  ASSERT_EQ(tilted.size(), 1u);
  ExpectAll(tilted, 0.004, -Vec3::UnitZ());
  EXPECT_NEAR(tilted[0].position.x(), 0.5 - 0.2 * std::sin(tilt) + 0.2 * std::cos(tilt),
              kDepthTolerance);
}

TEST(MeshPrimitiveContactsTest, MeshOnABoxFloorStandsOnItsCorners) {
  // the cube mesh 1 mm above a 4 m box: its four bottom vertices, not one point per triangle
  const ContactList contacts = MeshPrimitive(
      Cube(), PoseAt(Vec3(0, 0, 0.001)), Primitive::Box(Vec3(4, 4, 1)), PoseAt(Vec3(0, 0, -0.5)));
  ASSERT_EQ(contacts.size(), 4u);
  ExpectAll(contacts, 0.004, Vec3::UnitZ());
  for (const Contact& c : contacts) {
    EXPECT_NEAR(std::abs(c.position.x() - 0.5), 0.5, kDepthTolerance);
    EXPECT_NEAR(std::abs(c.position.y() - 0.5), 0.5, kDepthTolerance);
    EXPECT_NEAR(c.position.z(), 0.0005, kDepthTolerance);
  }
}

TEST(MeshPrimitiveContactsTest, SeparatedPrimitivesGiveNothing) {
  const Pose mesh = PoseAt(Vec3::Zero());
  EXPECT_TRUE(MeshPrimitive(Cube(), mesh, Primitive::Box(Vec3::Constant(0.5)),
                            PoseAt(Vec3(0.5, 0.5, 1.2551)))
                  .empty());
  EXPECT_TRUE(
      MeshPrimitive(Cube(), mesh, Primitive::Sphere(0.3), PoseAt(Vec3(0.5, 0.5, 1.3051))).empty());
  EXPECT_TRUE(
      MeshPrimitive(Cube(), mesh, Primitive::Capsule(0.1, 0.4), PoseAt(Vec3(0.5, 0.5, 1.3051)))
          .empty());
  EXPECT_TRUE(
      MeshPrimitive(Cube(), mesh, Primitive::Cylinder(0.1, 0.4), PoseAt(Vec3(0.5, 0.5, 1.2051)))
          .empty());
}

// ---- time per call on a large terrain ----

TEST(MeshContactsTimingTest, CubeOnFractalTerrain) {
  auto start = std::chrono::steady_clock::now();
  const auto terrain = MeshGeometry("klampt/terrains/fractal_terrain_1.off");
  const double build_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  ASSERT_EQ(terrain->mesh().triangle_count(), 32768);
  // lower the unit cube from above the terrain under it in 1 mm steps until it touches
  const Vec3 corner(10, 10, 0);
  double top = -core::kInf;
  for (const Vec3& v : terrain->mesh().vertices) {
    if ((v - corner).head<2>().cwiseAbs().maxCoeff() <= 2.0) top = std::max(top, v.z());
  }
  Pose cube = PoseAt(Vec3(corner.x(), corner.y(), top + 0.001));
  ContactList contacts, box_contacts;
  while (contacts.empty() && cube.translation().z() > top - 2.0) {
    cube.translation().z() -= 0.001;
    core::MeshMeshContacts(Cube(), cube, kPad, *terrain, Pose::Identity(), kPad, &contacts);
  }
  const auto box = PrimitiveGeometry(Primitive::Box(Vec3::Ones()));
  const Pose box_pose = cube * PoseAt(Vec3::Constant(0.5));
  constexpr int kCalls = 200;
  start = std::chrono::steady_clock::now();
  for (int i = 0; i < kCalls; ++i) {
    contacts.clear();
    core::MeshMeshContacts(Cube(), cube, kPad, *terrain, Pose::Identity(), kPad, &contacts);
  }
  const double mesh_us =
      std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count() /
      kCalls;
  start = std::chrono::steady_clock::now();
  for (int i = 0; i < kCalls; ++i) {
    box_contacts.clear();
    core::MeshPrimitiveContacts(*terrain, Pose::Identity(), kPad, *box, box_pose, kPad,
                                &box_contacts);
  }
  const double box_us =
      std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count() /
      kCalls;
  std::cout << "[ timing ] fractal_terrain_1.off: load + BVH build " << build_ms << " ms; "
            << "cube mesh resting on it " << mesh_us << " us/call (" << contacts.size()
            << " contacts); box primitive " << box_us << " us/call (" << box_contacts.size()
            << " contacts)\n";
  EXPECT_FALSE(contacts.empty());
  EXPECT_FALSE(box_contacts.empty());
}

}  // namespace
}  // namespace lamina
