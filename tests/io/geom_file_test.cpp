// SPDX-License-Identifier: MIT
// Klamp't `.geom` primitive files (KrisLibrary GeometricPrimitive3D text) mapped to our
// centred primitives, and LoadGeometryFile's dispatch between `.geom` and mesh files.
#include <map>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/geometry/tessellate.h"
#include "core/io/geometry_file.h"
#include "tests/common/test_support.h"

namespace lamina::core {
namespace {

using test::DataPath;
using test::WorldsPath;
using ::testing::ElementsAre;

// Values are decimal literals combined by a few additions and an exact rotation (0/±1
// entries) or a normalized axis: agreement to 1e-12 m is expected.
constexpr double kTolerance = 1e-12;

std::optional<Primitive> Parse(const std::string& text, Diagnostics* diagnostics) {
  return ParseGeomText(text, "/x/p.geom", *diagnostics);
}

void ExpectVec(const Vec3& actual, const Vec3& expected) {
  EXPECT_TRUE(actual.isApprox(expected, kTolerance) || (actual - expected).norm() < kTolerance)
      << actual.transpose() << " vs " << expected.transpose();
}

// Bounds of the tessellated primitive: checks where the shape really is, independent of how
// the pose is factored.
void ExpectMeshBounds(const Primitive& primitive, const Vec3& low, const Vec3& high) {
  const Eigen::AlignedBox3d box = Tessellate(primitive, 64).Bounds();
  ExpectVec(box.min(), low);
  ExpectVec(box.max(), high);
}

TEST(GeomText, KlamptSphereFileLoads) {
  // Klamp't itself fails to load this example; we must not
  GeometryDesc geometry;
  Diagnostics diagnostics;
  MeshCache meshes;
  LoadContext context{diagnostics, meshes};
  const std::string path = WorldsPath("klampt/objects/sphere.geom");
  ASSERT_TRUE(LoadGeometryFile(path, SourceLocation{"/w.xml", 3}, context, &geometry))
      << diagnostics.FormatAll();
  EXPECT_EQ(diagnostics.entries().size(), 0u);
  EXPECT_EQ(geometry.kind, GeometryKind::kPrimitive);
  EXPECT_EQ(geometry.path, path);
  EXPECT_EQ(geometry.mesh, nullptr);
  EXPECT_EQ(geometry.primitive.type, PrimitiveType::kSphere);
  EXPECT_EQ(geometry.primitive.radius, 1.0);
  EXPECT_TRUE(geometry.primitive.pose.isApprox(Pose::Identity()));
}

TEST(GeomText, SphereOnOneLineWithComment) {
  Diagnostics diagnostics;
  const auto p = Parse("Primitive Sphere 1 2 3 0.5  # centre, radius\n", &diagnostics);
  ASSERT_TRUE(p.has_value()) << diagnostics.FormatAll();
  EXPECT_EQ(p->type, PrimitiveType::kSphere);
  EXPECT_EQ(p->radius, 0.5);
  ExpectVec(p->pose.translation(), Vec3(1, 2, 3));
}

TEST(GeomText, BoxCornerAndAxesBecomeCentredPose) {
  // origin (1,2,3); x axis along +y, y axis along -x, z up; dims 2 4 6
  Diagnostics diagnostics;
  const auto p = Parse("Primitive\nBox\n1 2 3  0 1 0  -1 0 0  0 0 1  2 4 6\n", &diagnostics);
  ASSERT_TRUE(p.has_value()) << diagnostics.FormatAll();
  EXPECT_EQ(p->type, PrimitiveType::kBox);
  ExpectVec(p->size, Vec3(2, 4, 6));
  ExpectVec(p->pose.translation(), Vec3(1 - 2, 2 + 1, 3 + 3));  // origin + R * dims / 2
  EXPECT_TRUE(p->pose.linear().col(0).isApprox(Vec3(0, 1, 0)));
  EXPECT_TRUE(p->pose.linear().col(1).isApprox(Vec3(-1, 0, 0)));
  // x extent: origin.x - dims.y .. origin.x; y extent: origin.y .. origin.y + dims.x
  ExpectMeshBounds(*p, Vec3(-3, 2, 3), Vec3(1, 4, 9));
}

TEST(GeomText, LeftHandedBoxIsTheSameBox) {
  Diagnostics diagnostics;
  const auto p = Parse("Primitive Box 0 0 0  1 0 0  0 1 0  0 0 -1  1 1 2", &diagnostics);
  ASSERT_TRUE(p.has_value()) << diagnostics.FormatAll();
  EXPECT_NEAR(p->pose.linear().determinant(), 1.0, kTolerance);
  ExpectMeshBounds(*p, Vec3(0, 0, -2), Vec3(1, 1, 0));
}

TEST(GeomText, AabbBecomesCentredBox) {
  Diagnostics diagnostics;
  const auto p = Parse("Primitive\nAABB -1 -2 -3   1 2 5\n", &diagnostics);
  ASSERT_TRUE(p.has_value()) << diagnostics.FormatAll();
  EXPECT_EQ(p->type, PrimitiveType::kBox);
  ExpectVec(p->size, Vec3(2, 4, 8));
  ExpectVec(p->pose.translation(), Vec3(0, 0, 1));
  EXPECT_TRUE(p->pose.linear().isIdentity());
}

TEST(GeomText, CylinderFromBaseCentreAlongAxis) {
  Diagnostics diagnostics;
  const auto p = Parse("Primitive\nCylinder\n1 0 0  1 0 0  0.5  2\n", &diagnostics);
  ASSERT_TRUE(p.has_value()) << diagnostics.FormatAll();
  EXPECT_EQ(p->type, PrimitiveType::kCylinder);
  EXPECT_EQ(p->radius, 0.5);
  EXPECT_EQ(p->length, 2.0);
  ExpectVec(p->pose.translation(), Vec3(2, 0, 0));
  ExpectVec(p->pose.linear().col(2), Vec3(1, 0, 0));
  ExpectMeshBounds(*p, Vec3(1, -0.5, -0.5), Vec3(3, 0.5, 0.5));
}

TEST(GeomText, CapsuleUsesCylinderLayout) {
  Diagnostics diagnostics;
  const auto p = Parse("Primitive Capsule 1 0 0  1 0 0  0.5  2", &diagnostics);
  ASSERT_TRUE(p.has_value()) << diagnostics.FormatAll();
  EXPECT_EQ(p->type, PrimitiveType::kCapsule);
  ExpectVec(p->pose.translation(), Vec3(2, 0, 0));
  // caps reach one radius beyond the cylindrical part
  ExpectMeshBounds(*p, Vec3(0.5, -0.5, -0.5), Vec3(3.5, 0.5, 0.5));
}

TEST(GeomText, NonUnitAxisIsNormalizedWithWarning) {
  Diagnostics diagnostics;
  const auto p = Parse("Primitive\nCylinder 0 0 0  0 0 2  1 3\n", &diagnostics);
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(diagnostics.error_count(), 0);
  EXPECT_THAT(diagnostics.Messages(Severity::kWarning),
              ElementsAre("/x/p.geom:2: warning: normalizing 'Cylinder' axis of length 2"));
  ExpectVec(p->pose.translation(), Vec3(0, 0, 1.5));
}

TEST(GeomText, ExtraTextWarns) {
  Diagnostics diagnostics;
  const auto p = Parse("Primitive\nSphere 0 0 0 1\n7\n", &diagnostics);
  ASSERT_TRUE(p.has_value());
  EXPECT_THAT(diagnostics.Messages(Severity::kWarning),
              ElementsAre("/x/p.geom:3: warning: ignoring extra text after the primitive: '7'"));
}

TEST(GeomText, KeywordsAreCaseInsensitive) {
  Diagnostics diagnostics;
  const auto p = Parse("primitive\nSPHERE 0 0 0 2\n", &diagnostics);
  ASSERT_TRUE(p.has_value()) << diagnostics.FormatAll();
  EXPECT_EQ(p->radius, 2.0);
}

TEST(GeomText, MalformedFixtureFiles) {
  const std::map<std::string, std::string> cases = {
      {"bad_header.geom", ":1: error: expected 'Primitive', got 'Primitve'"},
      {"ellipsoid.geom", ":2: error: unsupported primitive type 'Ellipsoid'"},
      {"sphere_missing_radius.geom",
       ":2: error: 'Sphere' expects 4 values (center, radius), got 3"},
  };
  for (const auto& [file, message] : cases) {
    const std::string path = DataPath("bad/" + file);
    GeometryDesc geometry;
    Diagnostics diagnostics;
    MeshCache meshes;
    LoadContext context{diagnostics, meshes};
    EXPECT_FALSE(LoadGeometryFile(path, SourceLocation{"/w.xml", 2}, context, &geometry));
    EXPECT_EQ(geometry.kind, GeometryKind::kNone) << file;
    EXPECT_THAT(diagnostics.Messages(Severity::kError), ElementsAre(path + message));
  }
}

TEST(GeomText, MalformedText) {
  const std::map<std::string, std::string> cases = {
      {"", "1: error: empty geometry file, expected 'Primitive'"},
      {"Primitive\n", "1: error: expected a primitive type after 'Primitive'"},
      {"TriangleMesh\nOFF\n",
       "1: error: unsupported geometry type 'TriangleMesh', only 'Primitive' is supported in "
       "'.geom' files"},
      {"Primitive\nTorus 1 2\n",
       "2: error: unknown primitive type 'Torus', expected 'Sphere', 'Box', 'AABB', 'Cylinder' "
       "or 'Capsule'"},
      {"Primitive\nPlane 0 0 1 0\n", "2: error: unsupported primitive type 'Plane'"},
      {"Primitive\nSphere\n0 0 0 -1\n", "3: error: sphere radius must be > 0, got '-1'"},
      {"Primitive\nSphere\n0 nan 0 1\n", "3: error: 'nan' is not a number"},
      {"Primitive\nSphere 0 0\ninf 1\n", "3: error: 'inf' is not a finite number"},
      {"Primitive\nBox\n0 0 0 1 0 0 1 1 0 0 0 1 1 1 1\n",
       "2: error: 'Box' axes must be orthonormal"},
      {"Primitive\nBox 0 0 0 1 0 0 0 1 0 0 0 1 1 -2 1\n",
       "2: error: box dimension must be >= 0, got '-2'"},
      {"Primitive\nBox 0 0 0 1 0 0 0 1 0\n",
       "2: error: 'Box' expects 15 values (origin, x axis, y axis, z axis, dimensions), got 9"},
      {"Primitive\nAABB 1 0 0 0 1 1\n",
       "2: error: 'AABB' max must be >= min on every axis, got min '1 0 0' and max '0 1 1'"},
      {"Primitive\nCylinder 0 0 0 0 0 0 1 1\n", "2: error: 'Cylinder' axis must be non-zero"},
      {"Primitive\nCylinder 0 0 0 0 0 1 0 1\n", "2: error: radius must be > 0, got '0'"},
      {"Primitive\nCapsule 0 0 0 0 0 1 1\n",
       "2: error: 'Capsule' expects 8 values (base center, axis, radius, height), got 7"},
  };
  for (const auto& [text, message] : cases) {
    Diagnostics diagnostics;
    EXPECT_FALSE(Parse(text, &diagnostics).has_value()) << text;
    EXPECT_THAT(diagnostics.Messages(Severity::kError), ElementsAre("/x/p.geom:" + message))
        << text;
  }
}

// ---------------------------------------------------------------------------------------------
// LoadGeometryFile

TEST(LoadGeometryFile, MeshGoesThroughTheCacheAndKeepsPlacement) {
  Diagnostics diagnostics;
  MeshCache meshes;
  LoadContext context{diagnostics, meshes};
  GeometryDesc geometry;
  geometry.scale = Vec3(2, 2, 2);
  geometry.margin = 0.01;
  const std::string path = WorldsPath("klampt/objects/cube.off");
  ASSERT_TRUE(LoadGeometryFile(path, SourceLocation{"/w.xml", 1}, context, &geometry));
  EXPECT_EQ(geometry.kind, GeometryKind::kMesh);
  EXPECT_EQ(geometry.path, path);
  EXPECT_EQ(geometry.triangle_count(), 12);
  EXPECT_EQ(geometry.scale, Vec3(2, 2, 2));  // left alone
  EXPECT_EQ(geometry.margin, 0.01);
  EXPECT_EQ(geometry.mesh.get(), meshes.Get(path, SourceLocation{}, diagnostics).get());
  EXPECT_EQ(meshes.size(), 1);
}

TEST(LoadGeometryFile, FailuresAreReportedAtTheReferenceWithoutColumn) {
  const std::map<std::string, std::string> cases = {
      {"/x/a.xyz", "unsupported geometry file type '.xyz'"},
      {"/x/noext", "geometry file '/x/noext' has no extension"},
      {"/nonexistent/a.geom", "cannot open geometry file '/nonexistent/a.geom'"},
      {"/nonexistent/a.off", "cannot open mesh file '/nonexistent/a.off'"},
      {"/nonexistent/a.STL", "cannot open mesh file '/nonexistent/a.STL'"},
  };
  for (const auto& [path, message] : cases) {
    Diagnostics diagnostics;
    MeshCache meshes;
    LoadContext context{diagnostics, meshes};
    GeometryDesc geometry;
    EXPECT_FALSE(LoadGeometryFile(path, SourceLocation{"/r.rob", 4, 9}, context, &geometry));
    EXPECT_EQ(geometry.kind, GeometryKind::kNone);
    EXPECT_THAT(diagnostics.Messages(Severity::kError), ElementsAre("/r.rob:4: error: " + message));
  }
}

}  // namespace
}  // namespace lamina::core
