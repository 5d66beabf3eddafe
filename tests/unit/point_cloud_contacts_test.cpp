// SPDX-License-Identifier: MIT
// Point-cloud contacts with known answers: points as balls of the cloud's padding against a
// sphere (analytic depth, normal and position), a plane, a box, a mesh's faces and edges (signed
// behind a face) and another cloud; swapped pairs; scale and placement; the leaves; and a
// 10,000-point cloud on the 32768-triangle fractal terrain (every point found; the time per call
// printed, not asserted).
#include "core/contact/point_cloud_contacts.h"

#include <algorithm>
#include <chrono>
#include <iostream>
#include <random>

#include <gtest/gtest.h>

#include "core/io/mesh_file.h"
#include "tests/common/test_support.h"

namespace lamina {
namespace {

using core::CollisionGeometry;
using core::Contact;
using core::ContactList;
using core::GeometryDesc;
using core::Pose;
using core::Primitive;
using core::Vec3;

// rounding of sums of a few metres-scale numbers
constexpr double kCloudExact = 1e-12;

std::shared_ptr<const CollisionGeometry> Cloud(
    std::vector<Vec3> points, const Vec3& scale = Vec3::Ones(),
    const core::Affine& transform = core::Affine::Identity()) {
  auto cloud = std::make_shared<core::PointCloud>();
  cloud->points = std::move(points);
  GeometryDesc desc;
  desc.kind = core::GeometryKind::kPointCloud;
  desc.point_cloud = cloud;
  desc.scale = scale;
  desc.transform = transform;
  return CollisionGeometry::Build(desc);
}

std::shared_ptr<const CollisionGeometry> Shape(const Primitive& primitive) {
  GeometryDesc desc;
  desc.kind = core::GeometryKind::kPrimitive;
  desc.primitive = primitive;
  return CollisionGeometry::Build(desc);
}

std::shared_ptr<const CollisionGeometry> Mesh(const std::string& relative) {
  core::Diagnostics diagnostics;
  std::optional<core::TriangleMesh> mesh =
      core::ReadMeshFile(test::WorldsPath(relative), {}, diagnostics);
  EXPECT_TRUE(mesh) << diagnostics.FormatAll();
  GeometryDesc desc;
  desc.kind = core::GeometryKind::kMesh;
  desc.mesh = std::make_shared<const core::TriangleMesh>(mesh.value_or(core::TriangleMesh()));
  return CollisionGeometry::Build(desc);
}

using test::PoseAt;

// the contact whose position is nearest `near` (contacts come in leaf order)
const Contact& Near(const ContactList& contacts, const Vec3& near) {
  return *std::min_element(contacts.begin(), contacts.end(),
                           [&](const Contact& x, const Contact& y) {
                             return (x.position - near).norm() < (y.position - near).norm();
                           });
}

// The contact of a point p of body a at signed distance d from b's surface along the unit
// normal n (from b into a): depth tol - d (Collide adds the layer-edge nanometre), midway between
// p's ball and b's padded surface.
void ExpectBallContact(const Contact& c, const Vec3& p, double d, const Vec3& n, double pad_a,
                       double pad_b) {
  const Vec3 on_b = p - d * n;  // b's surface point
  EXPECT_NEAR(c.depth, pad_a + pad_b + core::kLayerEdgeSlack - d, kCloudExact);
  EXPECT_LT((c.normal - n).norm(), kCloudExact) << c.normal.transpose();
  EXPECT_LT((c.position - 0.5 * ((p - pad_a * n) + (on_b + pad_b * n))).norm(), kCloudExact);
  EXPECT_EQ(c.penetrating, d < 0.0);
}

TEST(PointCloudContactsTest, PointsAgainstASphereHaveTheAnalyticDepth) {
  const double pad_a = 0.0025, pad_b = 0.001, radius = 0.5;
  // cloud frame 1 m along x: world points (0.502, 0, 0), (0, 0.503, 0), (0, 0, -0.6) and
  // (0, 0.3, 0.3) inside the sphere
  const auto cloud =
      Cloud({Vec3(-0.498, 0, 0), Vec3(-1, 0.503, 0), Vec3(-1, 0, -0.6), Vec3(-1, 0.3, 0.3)});
  const auto sphere = Shape(Primitive::Sphere(radius));
  ContactList contacts;
  core::Collide(*cloud, PoseAt(Vec3(1, 0, 0)), pad_a, *sphere, Pose::Identity(), pad_b, &contacts);
  ASSERT_EQ(contacts.size(), 3u);  // (0, 0, -0.6) is 0.1 m away
  for (const Vec3& p : {Vec3(0.502, 0, 0), Vec3(0, 0.503, 0), Vec3(0, 0.3, 0.3)}) {
    SCOPED_TRACE(p.transpose());
    ExpectBallContact(Near(contacts, p), p, p.norm() - radius, p.normalized(), pad_a, pad_b);
  }
  // the depths: 3.5 - 2 = 1.5 mm, 3.5 - 3 = 0.5 mm, and 3.5 mm + 0.5 - 0.3 sqrt(2) inside
  EXPECT_NEAR(Near(contacts, Vec3(0.502, 0, 0)).depth, 0.0015 + core::kLayerEdgeSlack, kCloudExact);
  EXPECT_NEAR(Near(contacts, Vec3(0, 0.3, 0.3)).depth,
              0.0035 + core::kLayerEdgeSlack + 0.5 - 0.3 * std::sqrt(2.0), kCloudExact);
}

TEST(PointCloudContactsTest, ASwappedPairGivesTheSameContactsWithNormalsTurned) {
  // world points 1.5 mm, 0 and 3.3 mm from the sphere
  const auto cloud = Cloud({Vec3(0, 0, 0.501), Vec3(0.29, 0.02, 0.4), Vec3(0, 0.2, 0.47)});
  const auto sphere = Shape(Primitive::Sphere(0.5));
  const Pose X_cloud = PoseAt(Vec3(0.01, -0.02, 0.0));
  ContactList forward, swapped;
  core::Collide(*cloud, X_cloud, 0.002, *sphere, Pose::Identity(), 0.003, &forward);
  core::Collide(*sphere, Pose::Identity(), 0.003, *cloud, X_cloud, 0.002, &swapped);
  ASSERT_EQ(forward.size(), 3u);
  ASSERT_EQ(swapped.size(), forward.size());
  for (size_t i = 0; i < forward.size(); ++i) {
    EXPECT_EQ(swapped[i].normal, -forward[i].normal);
    EXPECT_EQ(swapped[i].position, forward[i].position);
    EXPECT_EQ(swapped[i].depth, forward[i].depth);
  }
}

TEST(PointCloudContactsTest, PointsOnAPlaneAndInABoxUseTheirSignedDistance) {
  const auto cloud = Cloud({Vec3(0, 0, 0.001), Vec3(1, 0, 0.003), Vec3(2, 0, -0.001)});
  const auto plane = Shape(Primitive::Plane());
  ContactList contacts;
  core::Collide(*cloud, Pose::Identity(), 0.0025, *plane, Pose::Identity(), 0.0, &contacts);
  ASSERT_EQ(contacts.size(), 2u);  // 3 mm is beyond the 2.5 mm layer
  ExpectBallContact(Near(contacts, Vec3(0, 0, 0)), Vec3(0, 0, 0.001), 0.001, Vec3::UnitZ(), 0.0025,
                    0.0);
  ExpectBallContact(Near(contacts, Vec3(2, 0, 0)), Vec3(2, 0, -0.001), -0.001, Vec3::UnitZ(),
                    0.0025, 0.0);
  // a box 1 m wide: a point 4 mm inside its +x face is pushed out through that face
  contacts.clear();
  core::Collide(*Cloud({Vec3(0.496, 0.1, 0.2)}), Pose::Identity(), 0.002,
                *Shape(Primitive::Box(Vec3::Ones())), Pose::Identity(), 0.001, &contacts);
  ASSERT_EQ(contacts.size(), 1u);
  ExpectBallContact(contacts[0], Vec3(0.496, 0.1, 0.2), -0.004, Vec3::UnitX(), 0.002, 0.001);
}

TEST(PointCloudContactsTest, PointsAgainstAMeshAreSignedAlongTheFaceAndTurnedAtEdges) {
  const auto cube = Mesh("klampt/objects/cube.off");  // the unit cube [0, 1]^3
  const double pad = 0.0025;
  const Vec3 above(0.5, 0.4, 1.001), behind(0.3, 0.6, 0.999), edge(1.001, 0.5, 1.001);
  const auto cloud = Cloud({above, behind, edge, Vec3(0.5, 0.5, 1.01)});
  ContactList contacts;
  core::Collide(*cloud, Pose::Identity(), pad, *cube, Pose::Identity(), pad, &contacts);
  ASSERT_EQ(contacts.size(), 3u);  // 10 mm above the top is out of reach
  ExpectBallContact(Near(contacts, above), above, 0.001, Vec3::UnitZ(), pad, pad);
  // 1 mm below the top face (its nearest triangle): pushed back up, the layer plus 1 mm deep
  ExpectBallContact(Near(contacts, behind), behind, -0.001, Vec3::UnitZ(), pad, pad);
  ExpectBallContact(Near(contacts, edge), edge, 0.001 * std::sqrt(2.0), Vec3(1, 0, 1).normalized(),
                    pad, pad);
}

TEST(PointCloudContactsTest, TwoCloudsTouchAsBallsAtTheirNearestPoints) {
  const auto a = Cloud({Vec3(0, 0, 0), Vec3(1, 0, 0)});
  const auto b = Cloud({Vec3(0, 0, 0.004), Vec3(0, 0, 0.0045), Vec3(5, 5, 5)});
  ContactList contacts;
  core::Collide(*a, Pose::Identity(), 0.0025, *b, Pose::Identity(), 0.0025, &contacts);
  ASSERT_EQ(contacts.size(), 1u);  // a's origin and b's nearest point, 4 mm apart
  ExpectBallContact(contacts[0], Vec3::Zero(), 0.004, -Vec3::UnitZ(), 0.0025, 0.0025);
  EXPECT_LT((contacts[0].position - Vec3(0, 0, 0.002)).norm(), kCloudExact);
}

TEST(PointCloudContactsTest, ScaleAndPlacementAreBakedIn) {
  core::Affine transform = core::Affine::Identity();
  transform.translate(Vec3(0.1, 0, 0)).rotate(Eigen::AngleAxisd(core::kPi / 2, Vec3::UnitZ()));
  const auto cloud = Cloud({Vec3(1, 0, 0), Vec3(0, 1, 1)}, Vec3(2, 3, 4), transform);
  ASSERT_EQ(cloud->kind(), CollisionGeometry::Kind::kPointCloud);
  std::vector<Vec3> points = cloud->points();
  std::sort(points.begin(), points.end(),
            [](const Vec3& x, const Vec3& y) { return x.x() < y.x(); });
  // (2, 0, 0) turned to (0, 2, 0) then moved; (0, 3, 4) turned to (-3, 0, 4) then moved
  EXPECT_LT((points[0] - Vec3(-2.9, 0, 4)).norm(), kCloudExact);
  EXPECT_LT((points[1] - Vec3(0.1, 2, 0)).norm(), kCloudExact);
  EXPECT_LT((cloud->local_bounds().min() - Vec3(-2.9, 0, 0)).norm(), kCloudExact);
}

TEST(PointCloudContactsTest, LeavesHoldEveryPointOnceWithTheirBounds) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::vector<Vec3> points(1000);
  for (Vec3& p : points) p = Vec3(uniform(random), uniform(random), 0.1 * uniform(random));
  std::vector<Vec3> partitioned = points;
  const auto leaves = core::point_cloud_detail::PartitionPoints(16, &partitioned);
  int next = 0;
  for (const CollisionGeometry::PointLeaf& leaf : leaves) {
    EXPECT_EQ(leaf.begin, next);
    EXPECT_LE(leaf.end - leaf.begin, 16);
    EXPECT_GE(leaf.end - leaf.begin, 8);  // halving at the median keeps leaves balanced
    for (int i = leaf.begin; i < leaf.end; ++i) EXPECT_TRUE(leaf.bounds.contains(partitioned[i]));
    next = leaf.end;
  }
  EXPECT_EQ(next, 1000);
  const auto order = [](const Vec3& x, const Vec3& y) {
    return std::lexicographical_compare(x.data(), x.data() + 3, y.data(), y.data() + 3);
  };
  std::sort(points.begin(), points.end(), order);
  std::sort(partitioned.begin(), partitioned.end(), order);
  EXPECT_EQ(points, partitioned);
}

// Points 1 mm above the middle of 10,000 of the terrain's triangles: each is within the layer
// of its own triangle, so each must give a contact at least 1.5 mm deep (tol 2.5 mm). The leaf
// queries of the terrain's hierarchy keep this far from 10,000 x 32768 triangle tests.
TEST(PointCloudContactsTest, TenThousandPointsOnTheFractalTerrainAreAllFound) {
  const auto terrain = Mesh("klampt/terrains/fractal_terrain_1.off");
  ASSERT_EQ(terrain->mesh().triangle_count(), 32768);
  std::vector<Vec3> points;
  for (int t = 0; t < 32768 && points.size() < 10000; t += 3) {
    const Eigen::Vector3i& index = terrain->mesh().triangles[t];
    Vec3 centre = Vec3::Zero();
    for (int k = 0; k < 3; ++k) centre += terrain->mesh().vertices[index[k]] / 3.0;
    points.push_back(centre + 0.001 * terrain->triangle_normals()[t]);
  }
  const auto cloud = Cloud(points);
  ContactList contacts;
  double fastest_ms = core::kInf;
  for (int call = 0; call < 5; ++call) {
    contacts.clear();
    const auto start = std::chrono::steady_clock::now();
    core::Collide(*cloud, Pose::Identity(), 0.0025, *terrain, Pose::Identity(), 0.0, &contacts);
    fastest_ms =
        std::min(fastest_ms,
                 std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                     .count());
  }
  std::cout << "10000 points on 32768 triangles: " << fastest_ms << " ms per call (fastest of 5)\n";
  ASSERT_EQ(contacts.size(), points.size());
  for (const Contact& c : contacts) {
    EXPECT_GE(c.depth, 0.0015 - 1e-9);
    EXPECT_LE(c.depth, 0.0025 + 1e-9);
  }
}

}  // namespace
}  // namespace lamina
