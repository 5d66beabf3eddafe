// SPDX-License-Identifier: MIT
// Ray casting against every kind of collision geometry, checked against distances worked out
// by hand: boxes along each axis and obliquely, spheres (hit, miss, tangent), capsule and
// cylinder sides and ends, the plane, a mesh cube against the box primitive, placed and posed
// geometry, the range limit, and rays that start inside a solid.
#include "core/contact/ray_cast.h"

#include <cmath>
#include <memory>
#include <random>

#include <gtest/gtest.h>

namespace lamina {
namespace {

using core::CollisionGeometry;
using core::GeometryDesc;
using core::GeometryKind;
using core::kInf;
using core::Pose;
using core::Primitive;
using core::RayCast;
using core::Vec3;

constexpr double kRayTolerance = 1e-9;
constexpr double kRange = 100.0;

std::shared_ptr<const CollisionGeometry> Build(
    const Primitive& primitive, const core::Affine& placement = core::Affine::Identity()) {
  GeometryDesc desc;
  desc.kind = GeometryKind::kPrimitive;
  desc.primitive = primitive;
  desc.transform = placement;
  auto geometry = CollisionGeometry::Build(desc);
  EXPECT_EQ(geometry->kind(), CollisionGeometry::Kind::kPrimitive);
  return geometry;
}

// A box of edge lengths `size` centred on the origin, each face counter-clockwise from outside.
std::shared_ptr<const CollisionGeometry> BuildMeshBox(const Vec3& size) {
  auto mesh = std::make_shared<core::TriangleMesh>();
  for (int i = 0; i < 8; ++i) {
    const Vec3 corner((i & 1) ? 1 : -1, (i & 2) ? 1 : -1, (i & 4) ? 1 : -1);
    mesh->vertices.push_back(0.5 * size.cwiseProduct(corner));
  }
  const int faces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto& f : faces) {
    mesh->triangles.emplace_back(f[0], f[1], f[2]);
    mesh->triangles.emplace_back(f[0], f[2], f[3]);
  }
  GeometryDesc desc;
  desc.kind = GeometryKind::kMesh;
  desc.mesh = std::move(mesh);
  auto geometry = CollisionGeometry::Build(desc);
  EXPECT_EQ(geometry->kind(), CollisionGeometry::Kind::kMesh);
  return geometry;
}

double Cast(const CollisionGeometry& geometry, const Vec3& origin, const Vec3& direction,
            double max_distance = kRange) {
  return RayCast(geometry, Pose::Identity(), origin, direction, max_distance);
}

Pose Placed(const Vec3& translation, const Eigen::AngleAxisd& rotation) {
  Pose pose = Pose::Identity();
  pose.translation() = translation;
  pose.linear() = rotation.toRotationMatrix();
  return pose;
}

TEST(RayCastTest, BoxAlongEachAxisFromBothSides) {
  const auto box = Build(Primitive::Box(Vec3(1, 2, 3)));
  for (int axis = 0; axis < 3; ++axis) {
    for (const double side : {-1.0, 1.0}) {
      const Vec3 origin = 5.0 * side * Vec3::Unit(axis);
      const double expected = 5.0 - 0.5 * (axis + 1);
      EXPECT_NEAR(Cast(*box, origin, -side * Vec3::Unit(axis)), expected, kRayTolerance)
          << "axis " << axis << " side " << side;
      EXPECT_EQ(Cast(*box, origin, side * Vec3::Unit(axis)), kInf) << "pointing away";
    }
  }
}

TEST(RayCastTest, BoxOblique) {
  const auto box = Build(Primitive::Box(Vec3::Ones()));
  // enters the face x = -0.5 at y = 0 after 2.5 along x and 2.5 along y
  EXPECT_NEAR(Cast(*box, Vec3(-3, -2.5, 0.2), Vec3(1, 1, 0).normalized()), 2.5 * std::sqrt(2.0),
              kRayTolerance);
  // through the corner (-0.5, -0.5, -0.5)
  EXPECT_NEAR(Cast(*box, Vec3(-2, -2, -2), Vec3(1, 1, 1).normalized()), 1.5 * std::sqrt(3.0),
              kRayTolerance);
  // passes beside the box
  EXPECT_EQ(Cast(*box, Vec3(-3, -1.5, 0), Vec3(1, 1, 0).normalized()), kInf);
}

TEST(RayCastTest, SphereHitMissAndTangent) {
  const auto sphere = Build(Primitive::Sphere(0.5, Vec3(1, 2, 3)));
  EXPECT_NEAR(Cast(*sphere, Vec3(1, 2, -3), Vec3::UnitZ()), 5.5, kRayTolerance);
  // 0.3 off the centre line: the chord's near end is 0.4 before the centre
  EXPECT_NEAR(Cast(*sphere, Vec3(1.3, 2, -3), Vec3::UnitZ()), 5.6, kRayTolerance);
  EXPECT_EQ(Cast(*sphere, Vec3(1.6, 2, -3), Vec3::UnitZ()), kInf);
  // grazing the sphere counts: the touching point is level with the centre
  EXPECT_NEAR(Cast(*sphere, Vec3(1.5, 2, -3), Vec3::UnitZ()), 6.0, kRayTolerance);
  EXPECT_EQ(Cast(*sphere, Vec3(1, 2, 4), Vec3::UnitZ()), kInf) << "behind";
}

TEST(RayCastTest, CapsuleSideAndCaps) {
  const auto capsule = Build(Primitive::Capsule(0.5, 2.0));
  EXPECT_NEAR(Cast(*capsule, Vec3(3, 0, 0.7), -Vec3::UnitX()), 2.5, kRayTolerance);
  EXPECT_NEAR(Cast(*capsule, Vec3(0, 0, 5), -Vec3::UnitZ()), 3.5, kRayTolerance);
  EXPECT_NEAR(Cast(*capsule, Vec3(0, 0, -5), Vec3::UnitZ()), 3.5, kRayTolerance);
  // 0.3 off the axis the cap's sphere (centre z = 1) is met at z = 1 + 0.4
  EXPECT_NEAR(Cast(*capsule, Vec3(0.3, 0, 5), -Vec3::UnitZ()), 3.6, kRayTolerance);
  // beside the cylinder part, over the round of the cap: misses the cylinder, hits the cap
  EXPECT_NEAR(Cast(*capsule, Vec3(3, 0.3, 1.3), -Vec3::UnitX()), 3.0 - std::sqrt(0.07),
              kRayTolerance);
  EXPECT_EQ(Cast(*capsule, Vec3(3, 0, 1.6), -Vec3::UnitX()), kInf);
}

TEST(RayCastTest, CylinderSideAndFlatCaps) {
  const auto cylinder = Build(Primitive::Cylinder(0.5, 2.0));
  EXPECT_NEAR(Cast(*cylinder, Vec3(3, 0, 0.7), -Vec3::UnitX()), 2.5, kRayTolerance);
  EXPECT_NEAR(Cast(*cylinder, Vec3(0, -3, -0.9), Vec3::UnitY()), 2.5, kRayTolerance);
  // the flat cap at z = 1, anywhere across it
  EXPECT_NEAR(Cast(*cylinder, Vec3(0.3, 0, 5), -Vec3::UnitZ()), 4.0, kRayTolerance);
  EXPECT_NEAR(Cast(*cylinder, Vec3(0.3, -0.3, -5), Vec3::UnitZ()), 4.0, kRayTolerance);
  // no round cap: just above the end, the side is missed
  EXPECT_EQ(Cast(*cylinder, Vec3(3, 0, 1.1), -Vec3::UnitX()), kInf);
  // oblique through the cap: from (0, 0, 3) down at 45 degrees, z = 1 after 2 along x
  EXPECT_NEAR(Cast(*cylinder, Vec3(-2.2, 0, 3), Vec3(1, 0, -1).normalized()), 2.0 * std::sqrt(2.0),
              kRayTolerance);
}

TEST(RayCastTest, PlaneFromAboveParallelAndBelow) {
  const auto plane = Build(Primitive::Plane());
  EXPECT_NEAR(Cast(*plane, Vec3(7, -4, 3), -Vec3::UnitZ()), 3.0, kRayTolerance);
  EXPECT_NEAR(Cast(*plane, Vec3(7, -4, 3), Vec3(0, 0.6, -0.8)), 3.75, kRayTolerance);
  EXPECT_EQ(Cast(*plane, Vec3(0, 0, 3), Vec3::UnitX()), kInf) << "parallel";
  EXPECT_EQ(Cast(*plane, Vec3(0, 0, 3), Vec3::UnitZ()), kInf) << "pointing away";
  EXPECT_EQ(Cast(*plane, Vec3(0, 0, -1), Vec3::UnitZ()), 0.0) << "below is inside";
  EXPECT_EQ(Cast(*plane, Vec3(0, 0, -1), Vec3::UnitX()), 0.0) << "inside, parallel";
}

TEST(RayCastTest, MeshBoxReadsAsTheBoxPrimitive) {
  const Vec3 size(1, 2, 3);
  const auto mesh = BuildMeshBox(size);
  const auto box = Build(Primitive::Box(size));
  EXPECT_NEAR(Cast(*mesh, Vec3(5, 0, 0), -Vec3::UnitX()), 4.5, kRayTolerance);
  EXPECT_NEAR(Cast(*mesh, Vec3(0, 0, -5), Vec3::UnitZ()), 3.5, kRayTolerance);
  const Pose X_W = Placed(Vec3(0.3, -1, 2), Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()));
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  int hits = 0;
  for (int i = 0; i < 200; ++i) {
    const Vec3 origin =
        X_W * (6.0 * Vec3(uniform(random), uniform(random), uniform(random)).normalized());
    const Vec3 target = X_W * Vec3(uniform(random), 1.5 * uniform(random), 2 * uniform(random));
    const Vec3 direction = (target - origin).normalized();
    const double expected = RayCast(*box, X_W, origin, direction, kRange);
    hits += expected < kInf;
    if (expected == kInf) {
      EXPECT_EQ(RayCast(*mesh, X_W, origin, direction, kRange), kInf) << "ray " << i;
    } else {
      EXPECT_NEAR(RayCast(*mesh, X_W, origin, direction, kRange), expected, kRayTolerance)
          << "ray " << i;
    }
  }
  EXPECT_GT(hits, 50);
  EXPECT_LT(hits, 200);
}

TEST(RayCastTest, MeshIsTwoSided) {
  const auto mesh = BuildMeshBox(Vec3::Ones());
  // from the centre the ray meets the inside of the wall: meshes have no inside
  EXPECT_NEAR(Cast(*mesh, Vec3::Zero(), Vec3::UnitY()), 0.5, kRayTolerance);
  EXPECT_NEAR(Cast(*mesh, Vec3(0.1, 0.2, 0.3), -Vec3::UnitZ()), 0.8, kRayTolerance);
  EXPECT_EQ(Cast(*mesh, Vec3(2, 0, 0), Vec3::UnitX()), kInf) << "behind";
}

TEST(RayCastTest, RotatedAndTranslatedPose) {
  const auto box = Build(Primitive::Box(Vec3(2, 1, 1)));
  // the long axis turned onto y, the centre moved to (10, 0, 0)
  const Pose X_W = Placed(Vec3(10, 0, 0), Eigen::AngleAxisd(core::kPi / 2, Vec3::UnitZ()));
  EXPECT_NEAR(RayCast(*box, X_W, Vec3(10, 5, 0), -Vec3::UnitY(), kRange), 4.0, kRayTolerance);
  EXPECT_NEAR(RayCast(*box, X_W, Vec3(5, 0, 0), Vec3::UnitX(), kRange), 4.5, kRayTolerance);
  EXPECT_EQ(RayCast(*box, X_W, Vec3(5, 0, 0.7), Vec3::UnitX(), kRange), kInf);
  const auto capsule = Build(Primitive::Capsule(0.5, 2.0));
  // the axis turned onto x: the cap's tip at x = 10 + 1.5
  const Pose X_W_capsule = Placed(Vec3(10, 0, 0), Eigen::AngleAxisd(core::kPi / 2, Vec3::UnitY()));
  EXPECT_NEAR(RayCast(*capsule, X_W_capsule, Vec3(20, 0, 0), -Vec3::UnitX(), kRange), 8.5,
              kRayTolerance);
}

TEST(RayCastTest, GeometryPlacementAndPrimitivePoseAreApplied) {
  // the cylinder's own pose lifts it 0.5 along its axis, the geometry placement turns that axis
  // onto y (about x by +90 degrees: z -> -y) and lifts it by 1, the body pose by 2 more: centre
  // (0, -0.5, 3), axis along y, ends at y = -1.5 and y = 0.5
  Pose own = Pose::Identity();
  own.translation() = Vec3(0, 0, 0.5);
  core::Affine placement = core::Affine::Identity();
  placement.linear() = Eigen::AngleAxisd(core::kPi / 2, Vec3::UnitX()).toRotationMatrix();
  placement.translation() = Vec3(0, 0, 1);
  const auto cylinder = Build(Primitive::Cylinder(0.5, 2.0, own), placement);
  const Pose X_W = Placed(Vec3(0, 0, 2), Eigen::AngleAxisd(0.0, Vec3::UnitZ()));
  EXPECT_NEAR(RayCast(*cylinder, X_W, Vec3(0, 5, 3.2), -Vec3::UnitY(), kRange), 4.5, kRayTolerance);
  EXPECT_NEAR(RayCast(*cylinder, X_W, Vec3(0, -5, 3.2), Vec3::UnitY(), kRange), 3.5, kRayTolerance);
  EXPECT_NEAR(RayCast(*cylinder, X_W, Vec3(0, -0.5, 10), -Vec3::UnitZ(), kRange), 6.5,
              kRayTolerance);
}

TEST(RayCastTest, MaxDistanceCutsOffAHit) {
  const auto box = Build(Primitive::Box(Vec3::Ones()));
  const auto mesh = BuildMeshBox(Vec3::Ones());
  for (const auto* geometry : {box.get(), mesh.get()}) {
    EXPECT_EQ(Cast(*geometry, Vec3(5, 0, 0), -Vec3::UnitX(), 4.4), kInf);
    EXPECT_NEAR(Cast(*geometry, Vec3(5, 0, 0), -Vec3::UnitX(), 4.6), 4.5, kRayTolerance);
    EXPECT_EQ(Cast(*geometry, Vec3(5, 0, 0), -Vec3::UnitX(), -1.0), kInf);
  }
  // the limit itself is in range
  EXPECT_EQ(Cast(*box, Vec3(5, 0, 0), -Vec3::UnitX(), 4.5), 4.5);
  const auto plane = Build(Primitive::Plane());
  EXPECT_EQ(Cast(*plane, Vec3(0, 0, 3), -Vec3::UnitZ(), 2.0), kInf);
}

TEST(RayCastTest, OriginInsideASolidReadsZero) {
  const Vec3 direction = Vec3(1, -2, 0.5).normalized();
  EXPECT_EQ(Cast(*Build(Primitive::Box(Vec3(1, 2, 3))), Vec3(0.2, 0.3, -1), direction), 0.0);
  EXPECT_EQ(Cast(*Build(Primitive::Sphere(1.0, Vec3(1, 1, 1))), Vec3(1.5, 1, 1), direction), 0.0);
  EXPECT_EQ(Cast(*Build(Primitive::Capsule(0.5, 2.0)), Vec3(0, 0.2, 1.3), direction), 0.0);
  EXPECT_EQ(Cast(*Build(Primitive::Cylinder(0.5, 2.0)), Vec3(0.3, 0, -0.9), direction), 0.0);
  EXPECT_EQ(Cast(*Build(Primitive::Plane()), Vec3(4, 5, -0.1), direction), 0.0);
  // on the surface counts as inside
  EXPECT_EQ(Cast(*Build(Primitive::Box(Vec3::Ones())), Vec3(0.5, 0, 0), Vec3::UnitX()), 0.0);
}

TEST(RayCastTest, IgnoresMarginAndDirectionLength) {
  GeometryDesc desc;
  desc.kind = GeometryKind::kPrimitive;
  desc.primitive = Primitive::Sphere(1.0);
  desc.margin = 0.25;
  const auto sphere = CollisionGeometry::Build(desc);
  EXPECT_NEAR(Cast(*sphere, Vec3(0, 0, 5), Vec3(0, 0, -3)), 4.0, kRayTolerance);
  EXPECT_EQ(Cast(*sphere, Vec3(0, 0, 5), Vec3::Zero()), kInf);
}

}  // namespace
}  // namespace lamina
