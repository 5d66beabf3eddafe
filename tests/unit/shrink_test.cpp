// SPDX-License-Identifier: MIT
// Preshrinking: primitives offset exactly (with and without scale), meshes by Klamp't's
// ApproximateShrink (exact on a cube, within the tessellation's tilt on a sphere), the shared
// input mesh left alone, over-shrinking clamped with warnings, Klamp't's cube.off.
#include "core/geometry/shrink.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "core/geometry/geometry_desc.h"
#include "core/geometry/tessellate.h"
#include "core/io/mesh_file.h"
#include "tests/common/scene_builders.h"
#include "tests/common/test_support.h"

namespace lamina::core {
namespace {

// a geometry holding its own copy of `mesh`
GeometryDesc MeshGeometry(const TriangleMesh& mesh) {
  return test::MeshGeometry(std::make_shared<const TriangleMesh>(mesh));
}

using test::PrimitiveGeometry;

// The cube [0, 1]^3 as Klamp't's cube.off lists it: 8 corners, 12 outward triangles.
TriangleMesh UnitCube() {
  TriangleMesh mesh;
  for (int i = 0; i < 8; ++i) mesh.vertices.emplace_back(i >> 2 & 1, i >> 1 & 1, i & 1);
  const int triangles[12][3] = {{0, 1, 3}, {0, 3, 2}, {4, 6, 7}, {4, 7, 5}, {0, 4, 5}, {0, 5, 1},
                                {2, 3, 7}, {2, 7, 6}, {0, 2, 6}, {0, 6, 4}, {1, 5, 7}, {1, 7, 3}};
  for (const auto& t : triangles) mesh.triangles.emplace_back(t[0], t[1], t[2]);
  return mesh;
}

// The same cube with every face its own 4 vertices (24 in all), as a textured mesh has them:
// each corner appears 3 times, once per face.
TriangleMesh UnitCubeWithSeams() {
  const TriangleMesh cube = UnitCube();
  TriangleMesh mesh;
  for (int face = 0; face < 6; ++face) {
    const Eigen::Vector3i& a = cube.triangles[2 * face];
    const Eigen::Vector3i& b = cube.triangles[2 * face + 1];  // (a0, a2, b2)
    const int base = mesh.vertex_count();
    for (int corner : {a[0], a[1], a[2], b[2]}) mesh.vertices.push_back(cube.vertices[corner]);
    mesh.triangles.emplace_back(base, base + 1, base + 2);
    mesh.triangles.emplace_back(base, base + 2, base + 3);
  }
  return mesh;
}

// Every coordinate of every vertex is `low` or `high` (exactly, to 1e-12), with both present.
void ExpectCubeCorners(const std::vector<Vec3>& vertices, double low, double high) {
  for (const Vec3& v : vertices) {
    for (int k = 0; k < 3; ++k) {
      EXPECT_TRUE(std::abs(v[k] - low) < 1e-12 || std::abs(v[k] - high) < 1e-12)
          << v.transpose() << " not a corner of [" << low << ", " << high << "]^3";
    }
  }
}

using test::SignedVolume;

int WarningCount(const Diagnostics& diagnostics) {
  return static_cast<int>(diagnostics.Messages(Severity::kWarning).size());
}

TEST(ApproximateShrink, UnitCubeBecomesTheInnerCube) {
  // every corner has 3 face directions: the 3x3 solve moves it by (0.1, 0.1, 0.1) inward
  const ShrunkMesh shrunk = ApproximateShrink(UnitCube(), 0.1);
  EXPECT_EQ(shrunk.flipped_triangles, 0);
  ASSERT_EQ(shrunk.mesh.vertex_count(), 8);
  ExpectCubeCorners(shrunk.mesh.vertices, 0.1, 0.9);
  EXPECT_NEAR(SignedVolume(shrunk.mesh), 0.8 * 0.8 * 0.8, 1e-12);
}

TEST(ApproximateShrink, DuplicatedSeamVerticesMoveTogether) {
  // a seam copy sees only its own face: without merging it would move 0.1 along one normal and
  // the cube would come apart; merged, all 24 copies reach the inner cube's corners
  const ShrunkMesh shrunk = ApproximateShrink(UnitCubeWithSeams(), 0.1);
  EXPECT_EQ(shrunk.flipped_triangles, 0);
  ASSERT_EQ(shrunk.mesh.vertex_count(), 24);
  ExpectCubeCorners(shrunk.mesh.vertices, 0.1, 0.9);
}

// Each face plane at a vertex moves `amount` along its normal and the vertex goes where three
// of the moved planes meet. The normals are tilted from the vertex's radius by at most beta:
// with n segments a face spans 2 pi / n in longitude and latitude, so
// beta = atan(sqrt(2) tan(pi / n)) (0.138 rad for 32). The vertex therefore moves radially by
// between `amount` (a face across the radius) and amount / cos(beta) (1.0097 amount for 32;
// three faces tilted by beta, symmetrically); the sideways part of the move (< 0.5 % of amount
// for 32) changes the radius only to second order (~1e-9).
void ExpectSphereShrunkByAmount(int segments) {
  const double radius = 1.0, amount = 0.01;
  const ShrunkMesh shrunk =
      ApproximateShrink(Tessellate(Primitive::Sphere(radius), segments), amount);
  EXPECT_EQ(shrunk.flipped_triangles, 0);
  const double beta = std::atan(std::sqrt(2.0) * std::tan(kPi / segments));
  for (const Vec3& v : shrunk.mesh.vertices) {
    EXPECT_LE(v.norm(), radius - amount + 1e-12) << v.transpose();
    EXPECT_GE(v.norm(), radius - amount / std::cos(beta) - 1e-12) << v.transpose();
  }
}

TEST(ApproximateShrink, TessellatedSphereShrinksByTheAmount) {
  // the poles have 32 face directions: Klamp't's search over all triples
  ExpectSphereShrunkByAmount(32);
}

TEST(ApproximateShrink, ManyFacedVertexMovesAlongItsAxis) {
  // 128 face directions at each pole: too many triples, so the pole moves along the average
  // normal until every face has moved the amount (exact for this regular cone)
  ExpectSphereShrunkByAmount(128);
}

TEST(ShrinkGeometry, InputMeshIsNotModified) {
  const GeometryDesc cube = MeshGeometry(UnitCube());
  const TriangleMesh before = *cube.mesh;
  Diagnostics diagnostics;
  const GeometryDesc shrunk = ShrinkGeometry(cube, 0.1, &diagnostics);
  ASSERT_EQ(shrunk.kind, GeometryKind::kMesh);
  ASSERT_NE(shrunk.mesh, nullptr);
  EXPECT_NE(shrunk.mesh.get(), cube.mesh.get());
  EXPECT_EQ(cube.mesh->vertices, before.vertices);
  EXPECT_EQ(cube.mesh->triangles, before.triangles);
  EXPECT_EQ(diagnostics.entries().size(), 0u) << diagnostics.FormatAll();
  ExpectCubeCorners(shrunk.mesh->vertices, 0.1, 0.9);
}

TEST(ShrinkGeometry, ScaledMeshShrinksInBodyUnits) {
  // cube.off scaled 2 x 3 x 4 and moved: the amount is in body units, so every face moves
  // 0.1 whatever its axis' scale; the transform is kept and the scale baked in
  GeometryDesc box = MeshGeometry(UnitCube());
  box.scale = Vec3(2, 3, 4);
  box.transform = Affine(Eigen::Translation3d(1, 2, 3));
  const GeometryDesc shrunk = ShrinkGeometry(box, 0.1, nullptr);
  EXPECT_EQ(shrunk.scale, Vec3::Ones());
  EXPECT_TRUE(shrunk.transform.isApprox(box.transform));
  const Eigen::AlignedBox3d bounds = BakedMesh(shrunk).Bounds();
  EXPECT_TRUE(bounds.min().isApprox(Vec3(1.1, 2.1, 3.1), 1e-12)) << bounds.min().transpose();
  EXPECT_TRUE(bounds.max().isApprox(Vec3(2.9, 4.9, 6.9), 1e-12)) << bounds.max().transpose();
  EXPECT_NEAR(SignedVolume(BakedMesh(shrunk)), 1.8 * 2.8 * 3.8, 1e-9);
}

TEST(ShrinkGeometry, MirroredMeshStillShrinks) {
  // scale -1 turns the winding inside out; the shrink must still go inward
  GeometryDesc cube = MeshGeometry(UnitCube());
  cube.scale = Vec3(-1, 1, 1);
  const TriangleMesh baked = BakedMesh(ShrinkGeometry(cube, 0.1, nullptr));
  EXPECT_NEAR(SignedVolume(baked), 0.8 * 0.8 * 0.8, 1e-12);
  EXPECT_TRUE(baked.Bounds().min().isApprox(Vec3(-0.9, 0.1, 0.1), 1e-12));
}

TEST(ShrinkGeometry, NonRigidTransformIsBakedIn) {
  // a .rob geomtransform that scales by 2: the shrink is 0.1 in body units, not 0.2
  GeometryDesc cube = MeshGeometry(UnitCube());
  cube.transform = Affine(Eigen::Scaling(2.0));
  const GeometryDesc shrunk = ShrinkGeometry(cube, 0.1, nullptr);
  EXPECT_TRUE(shrunk.transform.isApprox(Affine::Identity()));
  ExpectCubeCorners(BakedMesh(shrunk).vertices, 0.1, 1.9);
}

TEST(ShrinkGeometry, KlamptCubeOffScaledTenCentimetres) {
  // heavyblocktest.xml's block: cube.off scaled 0.1, shifted by -0.05, padding 2.5 mm
  Diagnostics diagnostics;
  const std::optional<TriangleMesh> mesh =
      ReadMeshFile(test::WorldsPath("klampt/objects/cube.off"), SourceLocation{}, diagnostics);
  ASSERT_TRUE(mesh) << diagnostics.FormatAll();
  GeometryDesc block = MeshGeometry(*mesh);
  block.scale = Vec3::Constant(0.1);
  block.transform = Affine(Eigen::Translation3d(-0.05, -0.05, -0.05));
  const GeometryDesc shrunk = ShrinkGeometry(block, 0.0025, &diagnostics);
  EXPECT_EQ(diagnostics.entries().size(), 0u) << diagnostics.FormatAll();
  const TriangleMesh baked = BakedMesh(shrunk);
  ASSERT_EQ(baked.vertex_count(), mesh->vertex_count());
  ExpectCubeCorners(baked.vertices, -0.0475, 0.0475);
  EXPECT_NEAR(SignedVolume(baked), std::pow(0.095, 3), 1e-12);
}

TEST(ShrinkGeometry, OverShrunkMeshWarnsAboutFlippedTriangles) {
  // a 1 x 1 x 0.1 plate shrunk by 0.08: its top and bottom cross (z from [0, 0.1] to
  // [0.08, 0.02]), which turns the 8 side triangles around (the top and bottom keep their
  // normals: they swapped places instead)
  GeometryDesc plate = MeshGeometry(UnitCube());
  plate.scale = Vec3(1.0, 1.0, 0.1);
  Diagnostics diagnostics;
  const GeometryDesc shrunk = ShrinkGeometry(plate, 0.08, &diagnostics);
  ASSERT_EQ(WarningCount(diagnostics), 1) << diagnostics.FormatAll();
  EXPECT_NE(diagnostics.Messages(Severity::kWarning)[0].find("8 of 12 triangles"),
            std::string::npos)
      << diagnostics.FormatAll();
  // still a valid mesh of the same shape
  ASSERT_NE(shrunk.mesh, nullptr);
  EXPECT_EQ(shrunk.mesh->triangle_count(), 12);
  EXPECT_TRUE(BakedMesh(shrunk).Bounds().min().allFinite());
}

// --- primitives -------------------------------------------------------------------------------

TEST(ShrinkGeometry, SphereAndCapsuleLoseTheAmountOfRadius) {
  // a unit scale: radius - p; a capsule keeps its segment (length)
  const GeometryDesc sphere =
      ShrinkGeometry(PrimitiveGeometry(Primitive::Sphere(0.1)), 0.01, nullptr);
  EXPECT_NEAR(sphere.primitive.radius, 0.09, 1e-15);
  const GeometryDesc capsule =
      ShrinkGeometry(PrimitiveGeometry(Primitive::Capsule(0.1, 0.5)), 0.01, nullptr);
  EXPECT_NEAR(capsule.primitive.radius, 0.09, 1e-15);
  EXPECT_EQ(capsule.primitive.length, 0.5);
  // scale 2: body radius 0.2 - 0.01 = 0.19, i.e. 0.095 in the primitive's units
  GeometryDesc scaled = PrimitiveGeometry(Primitive::Capsule(0.1, 0.5));
  scaled.scale = Vec3::Constant(2.0);
  scaled = ShrinkGeometry(scaled, 0.01, nullptr);
  EXPECT_EQ(scaled.kind, GeometryKind::kPrimitive);
  EXPECT_NEAR(scaled.primitive.radius, 0.095, 1e-15);
  EXPECT_EQ(scaled.primitive.length, 0.5);
}

TEST(ShrinkGeometry, BoxLosesTwiceTheAmountPerAxisInBodyUnits) {
  const GeometryDesc box =
      ShrinkGeometry(PrimitiveGeometry(Primitive::Box(Vec3(0.2, 0.4, 0.6))), 0.01, nullptr);
  EXPECT_TRUE(box.primitive.size.isApprox(Vec3(0.18, 0.38, 0.58), 1e-14));
  // scale (2, 4, 5): body sizes 0.4, 1.6, 3.0 become 0.38, 1.58, 2.98
  GeometryDesc scaled = PrimitiveGeometry(Primitive::Box(Vec3(0.2, 0.4, 0.6)));
  scaled.scale = Vec3(2, 4, 5);
  scaled = ShrinkGeometry(scaled, 0.01, nullptr);
  EXPECT_TRUE(
      scaled.primitive.size.cwiseProduct(Vec3(2, 4, 5)).isApprox(Vec3(0.38, 1.58, 2.98), 1e-14))
      << scaled.primitive.size.transpose();
}

TEST(ShrinkGeometry, ShearedBoxFacesEachMoveTheAmount) {
  // a rotated box under non-uniform scale is a parallelepiped; every face plane of the shrunk
  // one lies exactly 0.01 inside the original's (same tessellation order, triangle by triangle)
  GeometryDesc box = PrimitiveGeometry(Primitive::Box(
      Vec3(0.3, 0.2, 0.1), Pose(Eigen::AngleAxisd(0.4, Vec3(1, 2, 3).normalized()))));
  box.scale = Vec3(1.0, 2.5, 0.7);
  const double amount = 0.01;
  Diagnostics diagnostics;
  const GeometryDesc shrunk = ShrinkGeometry(box, amount, &diagnostics);
  EXPECT_EQ(diagnostics.entries().size(), 0u) << diagnostics.FormatAll();
  ASSERT_EQ(shrunk.kind, GeometryKind::kPrimitive);
  const TriangleMesh before = BakedMesh(box), after = BakedMesh(shrunk);
  ASSERT_EQ(before.triangle_count(), after.triangle_count());
  for (int t = 0; t < before.triangle_count(); ++t) {
    const Eigen::Vector3i& tri = before.triangles[t];
    const Vec3 n = (before.vertices[tri[1]] - before.vertices[tri[0]])
                       .cross(before.vertices[tri[2]] - before.vertices[tri[0]])
                       .normalized();
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(n.dot(after.vertices[tri[k]] - before.vertices[tri[0]]), -amount, 1e-12);
    }
  }
}

TEST(ShrinkGeometry, CylinderLosesTheAmountAcrossAndTwiceAlong) {
  const GeometryDesc cylinder =
      ShrinkGeometry(PrimitiveGeometry(Primitive::Cylinder(0.1, 0.4)), 0.01, nullptr);
  EXPECT_NEAR(cylinder.primitive.radius, 0.09, 1e-15);
  EXPECT_NEAR(cylinder.primitive.length, 0.38, 1e-15);
  // scale (2, 2, 3): body radius 0.2 -> 0.19, body length 1.2 -> 1.18
  GeometryDesc scaled = PrimitiveGeometry(Primitive::Cylinder(0.1, 0.4));
  scaled.scale = Vec3(2, 2, 3);
  scaled = ShrinkGeometry(scaled, 0.01, nullptr);
  ASSERT_EQ(scaled.kind, GeometryKind::kPrimitive);
  EXPECT_NEAR(2 * scaled.primitive.radius, 0.19, 1e-15);
  EXPECT_NEAR(3 * scaled.primitive.length, 1.18, 1e-14);
}

TEST(ShrinkGeometry, PlaneMovesIntoItsHalfSpace) {
  // a tilted plane under scale: its boundary moves 0.01 (body units) along its body normal
  GeometryDesc plane =
      PrimitiveGeometry(Primitive::Plane(Pose(Eigen::AngleAxisd(0.3, Vec3::UnitX()))));
  plane.scale = Vec3(1.0, 3.0, 0.5);
  plane.transform = Affine(Eigen::Translation3d(0, 0, 1));
  const GeometryDesc shrunk = ShrinkGeometry(plane, 0.01, nullptr);
  const Affine before = plane.Matrix() * plane.primitive.pose;
  const Affine after = shrunk.Matrix() * shrunk.primitive.pose;
  const Vec3 normal = (before.linear().inverse().transpose() * Vec3::UnitZ()).normalized();
  EXPECT_NEAR(normal.dot(after.translation() - before.translation()), -0.01, 1e-15);
  // still the same plane direction
  EXPECT_TRUE(after.linear().isApprox(before.linear()));
}

TEST(ShrinkGeometry, NonUniformlyScaledSphereBecomesAShrunkMesh) {
  // an ellipsoid's inward offset is no ellipsoid: the tessellation is shrunk instead
  GeometryDesc ellipsoid = PrimitiveGeometry(Primitive::Sphere(0.1));
  ellipsoid.scale = Vec3(1.0, 2.0, 1.0);
  Diagnostics diagnostics;
  const GeometryDesc shrunk = ShrinkGeometry(ellipsoid, 0.01, &diagnostics);
  EXPECT_EQ(WarningCount(diagnostics), 1) << diagnostics.FormatAll();
  ASSERT_EQ(shrunk.kind, GeometryKind::kMesh);
  ASSERT_NE(shrunk.mesh, nullptr);
  const TriangleMesh before = BakedMesh(ellipsoid), after = BakedMesh(shrunk);
  ASSERT_EQ(before.vertex_count(), after.vertex_count());
  // every vertex moved inward by about the amount (the tessellation tilt allows ~5 %)
  for (int i = 0; i < before.vertex_count(); ++i) {
    EXPECT_NEAR((before.vertices[i] - after.vertices[i]).norm(), 0.01, 0.001) << i;
  }
  EXPECT_LT(SignedVolume(after), SignedVolume(before));
}

TEST(ShrinkGeometry, OverShrunkPrimitivesAreClampedWithAWarning) {
  Diagnostics diagnostics;
  const GeometryDesc sphere =
      ShrinkGeometry(PrimitiveGeometry(Primitive::Sphere(0.01)), 0.02, &diagnostics);
  EXPECT_EQ(WarningCount(diagnostics), 1) << diagnostics.FormatAll();
  EXPECT_GT(sphere.primitive.radius, 0.0);
  EXPECT_LT(sphere.primitive.radius, 0.01);
  // only the thin axis is clamped
  diagnostics.Clear();
  const GeometryDesc box =
      ShrinkGeometry(PrimitiveGeometry(Primitive::Box(Vec3(0.2, 0.2, 0.03))), 0.02, &diagnostics);
  EXPECT_EQ(WarningCount(diagnostics), 1) << diagnostics.FormatAll();
  EXPECT_NEAR(box.primitive.size.x(), 0.16, 1e-15);
  EXPECT_GT(box.primitive.size.z(), 0.0);
  EXPECT_LT(box.primitive.size.z(), 0.03);
  diagnostics.Clear();
  const GeometryDesc cylinder =
      ShrinkGeometry(PrimitiveGeometry(Primitive::Cylinder(0.01, 0.01)), 0.02, &diagnostics);
  EXPECT_EQ(WarningCount(diagnostics), 2) << diagnostics.FormatAll();
  EXPECT_GT(cylinder.primitive.radius, 0.0);
  EXPECT_GT(cylinder.primitive.length, 0.0);
}

TEST(ShrinkGeometry, ZeroNegativeAndEmptyAreLeftAlone) {
  const GeometryDesc cube = MeshGeometry(UnitCube());
  Diagnostics diagnostics;
  EXPECT_EQ(ShrinkGeometry(cube, 0.0, &diagnostics).mesh, cube.mesh);
  EXPECT_EQ(diagnostics.entries().size(), 0u);
  EXPECT_EQ(ShrinkGeometry(cube, -0.1, &diagnostics).mesh, cube.mesh);
  EXPECT_EQ(ShrinkGeometry(cube, std::nan(""), &diagnostics).mesh, cube.mesh);
  EXPECT_EQ(WarningCount(diagnostics), 2);
  EXPECT_TRUE(ShrinkGeometry(GeometryDesc(), 0.1, &diagnostics).empty());
}

TEST(ShrinkGeometry, WarningsNameTheGivenPlace) {
  Diagnostics diagnostics;
  ShrinkGeometry(PrimitiveGeometry(Primitive::Sphere(0.01)), 0.02, &diagnostics,
                 SourceLocation{"world.xml", 7, 0});
  ASSERT_EQ(WarningCount(diagnostics), 1);
  EXPECT_EQ(diagnostics.Messages(Severity::kWarning)[0].rfind("world.xml:7: warning: ", 0), 0u)
      << diagnostics.FormatAll();
}

}  // namespace
}  // namespace lamina::core
