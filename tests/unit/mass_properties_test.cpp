// SPDX-License-Identifier: MIT
// Automass: centre of mass and inertia of solids, thin shells and blends, from meshes and
// from analytic primitives, checked against closed forms.
#include "core/geometry/mass_properties.h"

#include <cmath>
#include <limits>
#include <memory>
#include <utility>

#include <gtest/gtest.h>

#include "core/diagnostics.h"
#include "core/geometry/tessellate.h"
#include "core/io/mesh_file.h"
#include "tests/common/scene_builders.h"
#include "tests/common/test_support.h"

namespace lamina::core {
namespace {

// Exact cases (closed forms, meshes that are exactly the shape): only rounding differs.
constexpr double kExact = 1e-9;

std::shared_ptr<const TriangleMesh> LoadMesh(const std::string& relative) {
  Diagnostics diagnostics;
  auto mesh = ReadMeshFile(test::WorldsPath(relative), SourceLocation{}, diagnostics);
  EXPECT_TRUE(mesh.has_value()) << diagnostics.FormatAll();
  return std::make_shared<const TriangleMesh>(mesh ? std::move(*mesh) : TriangleMesh());
}

using test::MeshGeometry;
using test::PrimitiveGeometry;

// |a - b| <= tolerance * max(|b|, scale) entrywise, with `scale` the size of the matrix so
// that near-zero off-diagonal entries are compared in absolute terms.
void ExpectMatNear(const Mat3& a, const Mat3& b, double tolerance) {
  const double scale = b.cwiseAbs().maxCoeff();
  EXPECT_LE((a - b).cwiseAbs().maxCoeff(), tolerance * scale) << "actual\n"
                                                              << a << "\nexpected\n"
                                                              << b;
}

void ExpectVecNear(const Vec3& a, const Vec3& b, double tolerance) {
  EXPECT_LE((a - b).norm(), tolerance) << a.transpose() << " vs " << b.transpose();
}

Mat3 Diagonal(double x, double y, double z) {
  return Vec3(x, y, z).asDiagonal();
}

// Per-unit-mass second moment about the origin recovered from a result:
// C = tr(I)/(2m) 1 - I/m about the COM, plus com com^T.
Mat3 SecondMomentAboutOrigin(const MassProperties& p, double mass) {
  const Mat3 covariance = p.inertia.trace() / (2.0 * mass) * Mat3::Identity() - p.inertia / mass;
  return covariance + p.com * p.com.transpose();
}

// Thin box shell, faces as plates of uniform areal density: ∫x² over the surface.
double BoxShellIntegral(double a, double b, double c) {
  return a * a * b * c / 2.0 + a * a * a * (b + c) / 6.0;
}

// ---------------------------------------------------------------------------------------------
// Box 1 x 2 x 3 m, 6 kg

TEST(MassProperties, SolidBoxAnalytic) {
  const MassProperties p =
      ComputeMassProperties(PrimitiveGeometry(Primitive::Box(Vec3(1, 2, 3))), 6.0, 0.0);
  ASSERT_TRUE(p.valid);
  ExpectVecNear(p.com, Vec3::Zero(), kExact);
  // m(b²+c²)/12 = 6.5, m(a²+c²)/12 = 5, m(a²+b²)/12 = 2.5
  ExpectMatNear(p.inertia, Diagonal(6.5, 5.0, 2.5), kExact);
}

TEST(MassProperties, SolidBoxFromScaledCubeMesh) {
  // cube.off spans 0..1, so scaled (1,2,3) it is the same box with its COM at scale/2
  const GeometryDesc geometry = MeshGeometry(LoadMesh("klampt/objects/cube.off"), Vec3(1, 2, 3));
  const MassProperties p = ComputeMassProperties(geometry, 6.0, 0.0);
  ASSERT_TRUE(p.valid);
  ExpectVecNear(p.com, Vec3(0.5, 1.0, 1.5), kExact);
  ExpectMatNear(p.inertia, Diagonal(6.5, 5.0, 2.5), kExact);
}

TEST(MassProperties, ThinBoxShellAnalyticAndMeshAgreeWithClosedForm) {
  const double a = 1, b = 2, c = 3, m = 6;
  const double area = 2 * (a * b + b * c + c * a);
  const double xx = BoxShellIntegral(a, b, c) / area;
  const double yy = BoxShellIntegral(b, c, a) / area;
  const double zz = BoxShellIntegral(c, a, b) / area;
  const Mat3 expected = Diagonal(m * (yy + zz), m * (xx + zz), m * (xx + yy));
  const MassProperties analytic =
      ComputeMassProperties(PrimitiveGeometry(Primitive::Box(Vec3(a, b, c))), m, 1.0);
  ASSERT_TRUE(analytic.valid);
  ExpectMatNear(analytic.inertia, expected, kExact);
  const MassProperties mesh = ComputeMassProperties(
      MeshGeometry(LoadMesh("klampt/objects/cube.off"), Vec3(a, b, c)), m, 1.0);
  ASSERT_TRUE(mesh.valid);
  ExpectVecNear(mesh.com, Vec3(0.5, 1.0, 1.5), kExact);
  ExpectMatNear(mesh.inertia, expected, kExact);
}

// ---------------------------------------------------------------------------------------------
// Spheres

TEST(MassProperties, SphereSolidAndShellAnalytic) {
  const double r = 0.5, m = 3.0;
  const GeometryDesc geometry = PrimitiveGeometry(Primitive::Sphere(r, Vec3(1, 2, 3)));
  const MassProperties solid = ComputeMassProperties(geometry, m, 0.0);
  const MassProperties shell = ComputeMassProperties(geometry, m, 1.0);
  ASSERT_TRUE(solid.valid && shell.valid);
  ExpectVecNear(solid.com, Vec3(1, 2, 3), kExact);
  ExpectMatNear(solid.inertia, Mat3::Identity() * (2.0 / 5.0 * m * r * r), kExact);
  ExpectMatNear(shell.inertia, Mat3::Identity() * (2.0 / 3.0 * m * r * r), kExact);
}

TEST(MassProperties, TessellatedSphereMeshMatchesEqualVolumeSphere) {
  const auto mesh = LoadMesh("klampt/objects/sphere.off");
  double volume = 0.0;
  for (const Eigen::Vector3i& t : mesh->triangles) {
    volume += mesh->vertices[t[0]].dot(mesh->vertices[t[1]].cross(mesh->vertices[t[2]])) / 6.0;
  }
  const double r = std::cbrt(3.0 * volume / (4.0 * kPi));
  const double m = 2.0;
  const MassProperties p = ComputeMassProperties(*mesh, m, 0.0);
  ASSERT_TRUE(p.valid);
  // 960 triangles inscribed in the unit sphere (edges ~0.16): the body's radius varies between
  // ~0.99 at face centres and 1.0 at vertices, so its second moments differ from the
  // equal-volume ball's by O(0.5 %) of the radial spread (measured: 0.21 % solid, 0.15 % shell)
  const double tolerance = 5e-3;
  ExpectVecNear(p.com, Vec3::Zero(), 1e-6);  // symmetric up to the file's 6-digit rounding
  ExpectMatNear(p.inertia, Mat3::Identity() * (2.0 / 5.0 * m * r * r), tolerance);
  const MassProperties shell = ComputeMassProperties(*mesh, m, 1.0);
  ExpectMatNear(shell.inertia, Mat3::Identity() * (2.0 / 3.0 * m * r * r), tolerance);
}

// ---------------------------------------------------------------------------------------------
// Blends, transforms

TEST(MassProperties, BlendIsTheMeanOfSolidAndShellMoments) {
  // an asymmetric body, so the solid and shell COMs differ
  const auto mesh = LoadMesh("klampt/objects/cube.off");
  TriangleMesh wedge = *mesh;
  for (Vec3& v : wedge.vertices) v = Vec3(v.x() * (1.0 + v.z()), v.y() * 2.0, v.z() * 0.5);
  const double m = 4.0;
  const MassProperties solid = ComputeMassProperties(wedge, m, 0.0);
  const MassProperties shell = ComputeMassProperties(wedge, m, 1.0);
  const MassProperties half = ComputeMassProperties(wedge, m, 0.5);
  ASSERT_TRUE(solid.valid && shell.valid && half.valid);
  ASSERT_GT((solid.com - shell.com).norm(), 1e-3);
  ExpectVecNear(half.com, 0.5 * (solid.com + shell.com), kExact);
  ExpectMatNear(SecondMomentAboutOrigin(half, m),
                0.5 * (SecondMomentAboutOrigin(solid, m) + SecondMomentAboutOrigin(shell, m)),
                kExact);
}

TEST(MassProperties, TransformMovesComAndRotatesInertia) {
  Affine transform = Affine::Identity();
  const Mat3 rotation = RotationFromRollPitchYaw(0.4, -1.1, 2.3);
  transform.linear() = rotation;
  transform.translation() = Vec3(3, -1, 2);
  const double m = 6.0;
  const Mat3 body_inertia = Diagonal(6.5, 5.0, 2.5);
  // analytic box
  GeometryDesc box = PrimitiveGeometry(Primitive::Box(Vec3(1, 2, 3)));
  box.transform = transform;
  const MassProperties p = ComputeMassProperties(box, m, 0.0);
  ASSERT_TRUE(p.valid);
  ExpectVecNear(p.com, Vec3(3, -1, 2), kExact);
  ExpectMatNear(p.inertia, rotation * body_inertia * rotation.transpose(), kExact);
  // the same box as a mesh: scaled cube, COM at R * (0.5, 1, 1.5) + t
  GeometryDesc mesh = MeshGeometry(LoadMesh("klampt/objects/cube.off"), Vec3(1, 2, 3));
  mesh.transform = transform;
  const MassProperties q = ComputeMassProperties(mesh, m, 0.0);
  ASSERT_TRUE(q.valid);
  ExpectVecNear(q.com, rotation * Vec3(0.5, 1, 1.5) + Vec3(3, -1, 2), kExact);
  ExpectMatNear(q.inertia, rotation * body_inertia * rotation.transpose(), kExact);
}

TEST(MassProperties, InsideOutMeshGivesTheSameResult) {
  const auto mesh = LoadMesh("klampt/objects/cube.off");
  TriangleMesh flipped = *mesh;
  for (Eigen::Vector3i& t : flipped.triangles) std::swap(t[1], t[2]);
  for (double f : {0.0, 0.3, 1.0}) {
    const MassProperties a = ComputeMassProperties(*mesh, 2.0, f);
    const MassProperties b = ComputeMassProperties(flipped, 2.0, f);
    ASSERT_TRUE(a.valid && b.valid);
    ExpectVecNear(b.com, a.com, kExact);
    ExpectMatNear(b.inertia, a.inertia, kExact);
    // 2 kg unit cube: 2 (1 + 1) / 12 about each axis when solid
    if (f == 0.0) ExpectMatNear(a.inertia, Mat3::Identity() / 3.0, kExact);
  }
}

// ---------------------------------------------------------------------------------------------
// Cylinder and capsule closed forms against fine meshes

class RoundPrimitive : public ::testing::TestWithParam<double> {};

TEST_P(RoundPrimitive, AnalyticMatchesFineMesh) {
  const double f = GetParam();
  Pose pose = Pose::Identity();
  pose.linear() = RotationFromRollPitchYaw(0.2, 0.5, -0.3);
  pose.translation() = Vec3(0.1, 0.2, -0.3);
  for (const Primitive& primitive :
       {Primitive::Cylinder(0.3, 1.1, pose), Primitive::Capsule(0.3, 1.1, pose),
        Primitive::Sphere(0.4, Vec3(1, 0, 0))}) {
    const MassProperties analytic = ComputeMassProperties(PrimitiveGeometry(primitive), 5.0, f);
    const MassProperties mesh = ComputeMassProperties(Tessellate(primitive, 512), 5.0, f);
    ASSERT_TRUE(analytic.valid && mesh.valid);
    // 512 divisions: relative geometric error (2π/512)²/6 ≈ 2.5e-5, doubled for two directions
    ExpectVecNear(analytic.com, mesh.com, 1e-9);
    ExpectMatNear(analytic.inertia, mesh.inertia, 1e-4);
  }
}

INSTANTIATE_TEST_SUITE_P(SurfaceFractions, RoundPrimitive, ::testing::Values(0.0, 0.5, 1.0));

TEST(MassProperties, CylinderClosedForms) {
  const double r = 0.3, h = 1.1, m = 5.0;
  const MassProperties solid =
      ComputeMassProperties(PrimitiveGeometry(Primitive::Cylinder(r, h)), m, 0.0);
  ExpectMatNear(solid.inertia,
                Diagonal(m * (3 * r * r + h * h) / 12, m * (3 * r * r + h * h) / 12, m * r * r / 2),
                kExact);
}

// ---------------------------------------------------------------------------------------------
// Scale handling

TEST(MassProperties, UniformScaleKeepsPrimitivesAnalytic) {
  GeometryDesc geometry = PrimitiveGeometry(Primitive::Sphere(0.5, Vec3(1, 0, 0)));
  geometry.scale = Vec3::Constant(2.0);
  const MassProperties p = ComputeMassProperties(geometry, 1.0, 0.0);
  ASSERT_TRUE(p.valid);
  ExpectVecNear(p.com, Vec3(2, 0, 0), kExact);
  ExpectMatNear(p.inertia, Mat3::Identity() * 0.4, kExact);  // 2/5 · 1 kg · (1 m)²
}

TEST(MassProperties, AxisAlignedBoxUnderNonUniformScale) {
  // box axes permuted (rotation by 90° about z): its x size is scaled by the file's y scale
  Pose pose = Pose::Identity();
  pose.linear() << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  pose.translation() = Vec3(1, 1, 1);
  GeometryDesc geometry = PrimitiveGeometry(Primitive::Box(Vec3(1, 2, 3), pose));
  geometry.scale = Vec3(2, 3, 0.5);
  const MassProperties p = ComputeMassProperties(geometry, 6.0, 1.0);
  const MassProperties mesh = ComputeMassProperties(BakedMesh(geometry), 6.0, 1.0);
  ASSERT_TRUE(p.valid && mesh.valid);
  ExpectVecNear(p.com, Vec3(2, 3, 0.5), kExact);
  ExpectMatNear(p.inertia, mesh.inertia, kExact);  // the box mesh is exact
}

TEST(MassProperties, RotatedBoxUnderNonUniformScaleFallsBackToMesh) {
  // a box rotated 45° then stretched along x is a parallelepiped: the solid's covariance
  // transforms exactly as L C L^T, which the fallback mesh reproduces
  Pose pose = Pose::Identity();
  pose.linear() = RotationFromRollPitchYaw(0, 0, kPi / 4);
  GeometryDesc geometry = PrimitiveGeometry(Primitive::Box(Vec3(1, 2, 3), pose));
  geometry.scale = Vec3(2, 1, 1);
  const double m = 6.0;
  const MassProperties p = ComputeMassProperties(geometry, m, 0.0);
  ASSERT_TRUE(p.valid);
  const Mat3 linear = geometry.scale.asDiagonal() * pose.linear();
  const Mat3 covariance = linear * Diagonal(1.0 / 12, 4.0 / 12, 9.0 / 12) * linear.transpose();
  ExpectVecNear(p.com, Vec3::Zero(), kExact);
  ExpectMatNear(p.inertia, m * (covariance.trace() * Mat3::Identity() - covariance), kExact);
}

TEST(MassProperties, NonUniformlyScaledSphereIsAnEllipsoid) {
  GeometryDesc geometry = PrimitiveGeometry(Primitive::Sphere(1.0));
  geometry.scale = Vec3(1, 2, 3);
  const double m = 5.0;
  const MassProperties p = ComputeMassProperties(geometry, m, 0.0);
  ASSERT_TRUE(p.valid);
  // solid ellipsoid: I_xx = m (b² + c²) / 5; the 128-division fallback mesh is inscribed and
  // loses ~(2π/128)²/6 = 4e-4 per direction (measured 8e-4 on I_zz)
  ExpectMatNear(p.inertia, Diagonal(m * 13 / 5, m * 10 / 5, m * 5 / 5), 2e-3);
}

// ---------------------------------------------------------------------------------------------
// Degenerate input

TEST(MassProperties, DegenerateInputIsInvalid) {
  EXPECT_FALSE(ComputeMassProperties(TriangleMesh(), 1.0, 0.0).valid);
  EXPECT_FALSE(ComputeMassProperties(TriangleMesh(), 1.0, 1.0).valid);
  EXPECT_FALSE(ComputeMassProperties(GeometryDesc(), 1.0, 0.0).valid);
  EXPECT_FALSE(ComputeMassProperties(PrimitiveGeometry(Primitive::Plane()), 1.0, 0.0).valid);
  EXPECT_FALSE(ComputeMassProperties(PrimitiveGeometry(Primitive::Sphere(0.0)), 1.0, 1.0).valid);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(ComputeMassProperties(PrimitiveGeometry(Primitive::Sphere(1.0)), 1.0, nan).valid);
  GeometryDesc no_mesh;
  no_mesh.kind = GeometryKind::kMesh;
  EXPECT_FALSE(ComputeMassProperties(no_mesh, 1.0, 0.0).valid);
  // a flat square has area but no volume: a shell only
  TriangleMesh square;
  square.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
  square.triangles = {Eigen::Vector3i(0, 1, 2), Eigen::Vector3i(0, 2, 3)};
  EXPECT_FALSE(ComputeMassProperties(square, 1.0, 0.0).valid);
  EXPECT_FALSE(ComputeMassProperties(square, 1.0, 0.5).valid);
  const MassProperties plate = ComputeMassProperties(square, 12.0, 1.0);
  ASSERT_TRUE(plate.valid);
  ExpectVecNear(plate.com, Vec3(0.5, 0.5, 0), kExact);
  // thin square plate, 12 kg, side 1: I_xx = I_yy = m/12 = 1, I_zz = m/6 = 2
  ExpectMatNear(plate.inertia, Diagonal(1, 1, 2), kExact);
}

}  // namespace
}  // namespace lamina::core
