// SPDX-License-Identifier: MIT
// Tessellated primitives must be closed, outward-facing and converge to the analytic volume.
#include "core/geometry/tessellate.h"

#include <cmath>
#include <map>
#include <utility>

#include <gtest/gtest.h>

#include "tests/common/test_support.h"

namespace lamina::core {
namespace {

using test::SignedVolume;

// For a convex shape around `centre`, every non-degenerate triangle's normal points away.
int InwardFacingTriangles(const TriangleMesh& mesh, const Vec3& centre) {
  int inward = 0;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    const Vec3& a = mesh.vertices[t[0]];
    const Vec3 normal = (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a);
    const Vec3 middle = (a + mesh.vertices[t[1]] + mesh.vertices[t[2]]) / 3.0;
    if (normal.norm() > 1e-14 && normal.dot(middle - centre) <= 0.0) ++inward;
  }
  return inward;
}

Pose SomePose() {
  Pose pose = Pose::Identity();
  pose.linear() = RotationFromRollPitchYaw(0.3, -0.7, 1.9);
  pose.translation() = Vec3(1.5, -2.0, 0.25);
  return pose;
}

class TessellatedPrimitive : public ::testing::TestWithParam<Primitive> {};

TEST_P(TessellatedPrimitive, ClosedOutwardAndPositiveVolume) {
  for (int segments : {4, 7, 16, 33}) {
    const TriangleMesh mesh = Tessellate(GetParam(), segments);
    SCOPED_TRACE(::testing::Message() << GetParam().TypeName() << " segments " << segments);
    EXPECT_TRUE(lamina::test::IsClosedAndConsistent(mesh));
    EXPECT_GT(SignedVolume(mesh), 0.0);
    EXPECT_EQ(InwardFacingTriangles(mesh, GetParam().pose.translation()), 0);
  }
}

TEST_P(TessellatedPrimitive, VolumeConvergesToAnalytic) {
  const double exact = GetParam().Volume();
  double previous_error = kInf;
  for (int segments : {8, 16, 32, 64, 128, 256}) {
    const double error = std::abs(SignedVolume(Tessellate(GetParam(), segments)) - exact);
    // inscribed polygons lose ~ (2π/n)²/6 of their area: the error at least halves per doubling
    // (it quarters asymptotically), unless the shape is exact (box)
    EXPECT_TRUE(error <= 0.5 * previous_error || error < 1e-12 * exact)
        << GetParam().TypeName() << " segments " << segments;
    previous_error = error;
  }
  // at n = 256: (2π/256)²/6 = 1.0e-4 per discretized direction; two directions for spheres
  EXPECT_LT(previous_error / exact, 3e-4) << GetParam().TypeName();
}

INSTANTIATE_TEST_SUITE_P(Shapes, TessellatedPrimitive,
                         ::testing::Values(Primitive::Sphere(0.7, Vec3(1, 2, 3)),
                                           Primitive::Box(Vec3(1, 2, 3), SomePose()),
                                           Primitive::Cylinder(0.4, 1.3, SomePose()),
                                           Primitive::Capsule(0.3, 0.8, SomePose())),
                         [](const ::testing::TestParamInfo<Primitive>& param_info) {
                           return std::string(param_info.param.TypeName());
                         });

TEST(Tessellate, CylinderVolumeIsThePrismFormula) {
  // the mesh is exactly a prism over a regular n-gon: V = n/2 r² sin(2π/n) h
  const double r = 0.4, h = 1.3;
  for (int n : {5, 12, 32}) {
    const double expected = n / 2.0 * r * r * std::sin(2.0 * kPi / n) * h;
    EXPECT_NEAR(SignedVolume(Tessellate(Primitive::Cylinder(r, h, SomePose()), n)), expected,
                1e-14);  // a sum of ~4n products of O(1) numbers
  }
}

TEST(Tessellate, BoxIsExact) {
  const TriangleMesh mesh = Tessellate(Primitive::Box(Vec3(1, 2, 3)));
  EXPECT_EQ(mesh.vertex_count(), 8);
  EXPECT_EQ(mesh.triangle_count(), 12);
  EXPECT_DOUBLE_EQ(SignedVolume(mesh), 6.0);
  EXPECT_TRUE(mesh.Bounds().min().isApprox(Vec3(-0.5, -1, -1.5)));
  EXPECT_TRUE(mesh.Bounds().max().isApprox(Vec3(0.5, 1, 1.5)));
}

TEST(Tessellate, PoseIsApplied) {
  Pose pose = Pose::Identity();
  pose.linear() = RotationFromRollPitchYaw(0, 0, kPi / 2);  // x -> y
  pose.translation() = Vec3(10, 0, 0);
  const Eigen::AlignedBox3d box = Tessellate(Primitive::Box(Vec3(4, 2, 6), pose)).Bounds();
  // 1e-12: the rotation holds cos(π/2) ≈ 6e-17, not an exact 0
  EXPECT_TRUE(box.min().isApprox(Vec3(9, -2, -3), 1e-12)) << box.min().transpose();
  EXPECT_TRUE(box.max().isApprox(Vec3(11, 2, 3), 1e-12)) << box.max().transpose();
}

TEST(Tessellate, SphereVerticesLieOnTheSphere) {
  const Primitive sphere = Primitive::Sphere(0.7, Vec3(1, 2, 3));
  const TriangleMesh mesh = Tessellate(sphere, 24);
  for (const Vec3& v : mesh.vertices) EXPECT_NEAR((v - Vec3(1, 2, 3)).norm(), 0.7, 1e-12);
}

TEST(Tessellate, PlaneIsEmpty) {
  const TriangleMesh mesh = Tessellate(Primitive::Plane(SomePose()));
  EXPECT_EQ(mesh.vertex_count(), 0);
  EXPECT_EQ(mesh.triangle_count(), 0);
}

}  // namespace
}  // namespace lamina::core
