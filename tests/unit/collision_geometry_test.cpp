// SPDX-License-Identifier: MIT
// Collision geometry: meshes with scale and placement baked in, primitives kept analytic when
// their scale allows it, the mesh topology built with the hierarchy, the hierarchy queries,
// and the cache that builds each (mesh, placement) once.
#include "core/contact/collision_geometry.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "core/contact/mesh_query.h"
#include "core/io/mesh_file.h"
#include "tests/common/test_support.h"

namespace lamina {
namespace {

using core::CollisionGeometry;
using core::GeometryDesc;
using core::GeometryKind;
using core::Pose;
using core::Primitive;
using core::PrimitiveType;
using core::Vec3;

std::shared_ptr<const core::TriangleMesh> LoadMesh(const std::string& relative) {
  core::Diagnostics diagnostics;
  std::optional<core::TriangleMesh> mesh =
      core::ReadMeshFile(test::WorldsPath(relative), {}, diagnostics);
  EXPECT_TRUE(mesh.has_value()) << diagnostics.FormatAll();
  return std::make_shared<const core::TriangleMesh>(mesh.value_or(core::TriangleMesh()));
}

GeometryDesc MeshDesc(std::shared_ptr<const core::TriangleMesh> mesh,
                      const Vec3& scale = Vec3::Ones()) {
  GeometryDesc desc;
  desc.kind = GeometryKind::kMesh;
  desc.mesh = std::move(mesh);
  desc.scale = scale;
  return desc;
}

GeometryDesc PrimitiveDesc(const Primitive& primitive, const Vec3& scale = Vec3::Ones()) {
  GeometryDesc desc;
  desc.kind = GeometryKind::kPrimitive;
  desc.primitive = primitive;
  desc.scale = scale;
  return desc;
}

// exact arithmetic on small integers and unit vectors: rounding only
constexpr double kExact = 1e-12;

TEST(CollisionGeometryTest, MeshHasScaledVerticesOutwardNormalsAndBounds) {
  GeometryDesc desc = MeshDesc(LoadMesh("klampt/objects/cube.off"), Vec3(2, 3, 4));
  desc.transform.translation() = Vec3(1, 0, 0);
  desc.margin = 0.01;
  const auto geometry = CollisionGeometry::Build(desc);
  ASSERT_NE(geometry, nullptr);
  EXPECT_EQ(geometry->kind(), CollisionGeometry::Kind::kMesh);
  EXPECT_EQ(geometry->mesh().triangle_count(), 12);
  EXPECT_DOUBLE_EQ(geometry->margin(), 0.01);
  EXPECT_TRUE(geometry->local_bounds().min().isApprox(Vec3(1, 0, 0), kExact));
  EXPECT_TRUE(geometry->local_bounds().max().isApprox(Vec3(3, 3, 4), kExact));
  // every face normal is a unit axis pointing away from the box centre
  const Vec3 centre(2, 1.5, 2);
  for (int t = 0; t < 12; ++t) {
    const Vec3& n = geometry->triangle_normals()[t];
    EXPECT_NEAR(n.norm(), 1.0, kExact);
    EXPECT_NEAR(n.cwiseAbs().maxCoeff(), 1.0, kExact);
    const Vec3 on_face = geometry->mesh().vertices[geometry->mesh().triangles[t][0]];
    EXPECT_GT(n.dot(on_face - centre), 0.0) << "triangle " << t;
  }
}

TEST(CollisionGeometryTest, MirroringScaleKeepsNormalsOutward) {
  const auto geometry =
      CollisionGeometry::Build(MeshDesc(LoadMesh("klampt/objects/cube.off"), Vec3(-1, 1, 1)));
  ASSERT_NE(geometry, nullptr);
  const Vec3 centre(-0.5, 0.5, 0.5);
  for (int t = 0; t < 12; ++t) {
    const Vec3 on_face = geometry->mesh().vertices[geometry->mesh().triangles[t][0]];
    EXPECT_GT(geometry->triangle_normals()[t].dot(on_face - centre), 0.0) << "triangle " << t;
  }
}

TEST(CollisionGeometryTest, EmptyGeometryGivesNull) {
  EXPECT_EQ(CollisionGeometry::Build(GeometryDesc()), nullptr);
  GeometryDesc no_mesh;
  no_mesh.kind = GeometryKind::kMesh;
  EXPECT_EQ(CollisionGeometry::Build(no_mesh), nullptr);
}

TEST(CollisionGeometryTest, UniformScaleKeepsSphereAnalytic) {
  GeometryDesc desc = PrimitiveDesc(Primitive::Sphere(0.5, Vec3(1, 0, 0)), Vec3::Constant(2));
  desc.transform.translation() = Vec3(0, 0, 3);
  const auto geometry = CollisionGeometry::Build(desc);
  ASSERT_NE(geometry, nullptr);
  ASSERT_EQ(geometry->kind(), CollisionGeometry::Kind::kPrimitive);
  EXPECT_EQ(geometry->primitive().type, PrimitiveType::kSphere);
  EXPECT_NEAR(geometry->primitive().radius, 1.0, kExact);
  EXPECT_TRUE(geometry->primitive().pose.translation().isApprox(Vec3(2, 0, 3), kExact));
  EXPECT_TRUE(geometry->local_bounds().min().isApprox(Vec3(1, -1, 2), kExact));
  EXPECT_TRUE(geometry->local_bounds().max().isApprox(Vec3(3, 1, 4), kExact));
}

TEST(CollisionGeometryTest, AxisScaleOfBoxAndCylinderStaysAnalytic) {
  const auto box =
      CollisionGeometry::Build(PrimitiveDesc(Primitive::Box(Vec3(1, 1, 1)), Vec3(1, 2, 3)));
  ASSERT_EQ(box->kind(), CollisionGeometry::Kind::kPrimitive);
  EXPECT_TRUE(box->primitive().size.isApprox(Vec3(1, 2, 3), kExact));
  // a cylinder scaled equally across its axis stays a cylinder: radius x2, length x3
  const auto cylinder =
      CollisionGeometry::Build(PrimitiveDesc(Primitive::Cylinder(0.5, 1.0), Vec3(2, 2, 3)));
  ASSERT_EQ(cylinder->kind(), CollisionGeometry::Kind::kPrimitive);
  EXPECT_NEAR(cylinder->primitive().radius, 1.0, kExact);
  EXPECT_NEAR(cylinder->primitive().length, 3.0, kExact);
  EXPECT_TRUE(cylinder->local_bounds().max().isApprox(Vec3(1, 1, 1.5), kExact));
}

TEST(CollisionGeometryTest, OtherScaledPrimitivesBecomeMeshes) {
  // a rotated box scaled along world axes is sheared; a sphere scaled unevenly is an ellipsoid
  Pose rotated = Pose::Identity();
  rotated.linear() = core::RotationFromRollPitchYaw(0, 0, 0.5);
  const auto box = CollisionGeometry::Build(
      PrimitiveDesc(Primitive::Box(Vec3(1, 1, 1), rotated), Vec3(1, 2, 1)));
  ASSERT_NE(box, nullptr);
  EXPECT_EQ(box->kind(), CollisionGeometry::Kind::kMesh);
  EXPECT_EQ(box->mesh().triangle_count(), 12);
  const auto ellipsoid =
      CollisionGeometry::Build(PrimitiveDesc(Primitive::Sphere(1.0), Vec3(1, 1, 2)));
  ASSERT_NE(ellipsoid, nullptr);
  EXPECT_EQ(ellipsoid->kind(), CollisionGeometry::Kind::kMesh);
  // the tessellation spans the scaled extents exactly at the poles
  EXPECT_NEAR(ellipsoid->local_bounds().max().z(), 2.0, kExact);
}

TEST(CollisionGeometryTest, PlaneFollowsTransform) {
  GeometryDesc desc = PrimitiveDesc(Primitive::Plane());
  desc.transform.linear() = core::RotationFromRollPitchYaw(0.5 * core::kPi, 0, 0);
  desc.transform.translation() = Vec3(0, 0, 1);
  const auto plane = CollisionGeometry::Build(desc);
  ASSERT_EQ(plane->kind(), CollisionGeometry::Kind::kPrimitive);
  // roll by 90 degrees turns +z into -y
  EXPECT_TRUE(plane->primitive().pose.linear().col(2).isApprox(Vec3(0, -1, 0), kExact));
  EXPECT_TRUE(plane->primitive().pose.translation().isApprox(Vec3(0, 0, 1), kExact));
  EXPECT_TRUE(std::isinf(plane->local_bounds().max().x()));
}

TEST(CollisionGeometryTest, CubeTopologyIsClosedWithCornerNormals) {
  const auto geometry = CollisionGeometry::Build(MeshDesc(LoadMesh("klampt/objects/cube.off")));
  const core::mesh_detail::MeshTopology& topology = core::mesh_detail::Topology(geometry->bvh());
  for (int t = 0; t < 12; ++t) {
    for (int k = 0; k < 3; ++k) EXPECT_GE(topology.neighbors[t][k], 0) << t << " " << k;
  }
  // triangles 0 ("0 1 3") and 1 ("0 3 2") share edge 0-3, opposite corner 1 of triangle 0
  EXPECT_EQ(topology.neighbors[0][1], 1);
  // vertex 0 sits at the corner (0, 0, 0): the mean of the three faces' normals
  EXPECT_TRUE(topology.vertex_normals[0].isApprox(Vec3(-1, -1, -1).normalized(), kExact));
  // the edge 0-3 lies inside the face x = 0: its normal is that face's
  EXPECT_TRUE(core::mesh_detail::EdgeNormal(*geometry, 0, 1).isApprox(Vec3(-1, 0, 0), kExact));
}

TEST(CollisionGeometryTest, DuplicatedVerticesAreWelded) {
  // two triangles of a square with the shared edge's vertices written twice
  auto mesh = std::make_shared<core::TriangleMesh>();
  mesh->vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  mesh->triangles = {{0, 1, 2}, {3, 4, 5}};
  const auto geometry = CollisionGeometry::Build(MeshDesc(mesh));
  const core::mesh_detail::MeshTopology& topology = core::mesh_detail::Topology(geometry->bvh());
  EXPECT_EQ(topology.welded[3], 0);
  EXPECT_EQ(topology.welded[4], 2);
  EXPECT_EQ(topology.neighbors[0][1], 1);   // the diagonal 2-0 is opposite corner 1 of triangle 0
  EXPECT_EQ(topology.neighbors[1][2], 0);   // and 3-4 is opposite corner 2 of triangle 1
  EXPECT_EQ(topology.neighbors[0][0], -1);  // a border edge
}

TEST(CollisionGeometryTest, BoxQueryFindsTheTrianglesItTouches) {
  const auto geometry = CollisionGeometry::Build(MeshDesc(LoadMesh("klampt/objects/cube.off")));
  std::vector<int> triangles;
  Pose box = Pose::Identity();
  box.translation() = Vec3(0.5, 0.5, 2.0);
  // a slab well above the top face (oriented bounding volumes of single triangles may stick
  // out of the cube by up to half an edge) finds nothing; one reaching below z = 1 does
  core::mesh_detail::TrianglesNearBox(geometry->bvh(), box, Vec3(0.1, 0.1, 0.1), &triangles);
  EXPECT_TRUE(triangles.empty());
  core::mesh_detail::TrianglesNearBox(geometry->bvh(), box, Vec3(0.1, 0.1, 1.05), &triangles);
  std::sort(triangles.begin(), triangles.end());
  // the top face z = 1 is triangles 10 and 11; bounding volumes may add neighbours, never drop
  EXPECT_TRUE(std::binary_search(triangles.begin(), triangles.end(), 10));
  EXPECT_TRUE(std::binary_search(triangles.begin(), triangles.end(), 11));
}

TEST(CollisionGeometryCacheTest, SharesGeometryPerMeshAndScale) {
  const auto mesh = LoadMesh("klampt/objects/cube.off");
  core::CollisionGeometryCache cache;
  const auto first = cache.Get(MeshDesc(mesh));
  const auto second = cache.Get(MeshDesc(mesh));
  const auto scaled = cache.Get(MeshDesc(mesh, Vec3::Constant(2)));
  ASSERT_NE(first, nullptr);
  EXPECT_EQ(first, second);
  EXPECT_EQ(&first->bvh(), &second->bvh());
  EXPECT_NE(first, scaled);
  EXPECT_EQ(cache.size(), 2);
  EXPECT_NEAR(scaled->local_bounds().max().x(), 2.0, kExact);
  const auto sphere = cache.Get(PrimitiveDesc(Primitive::Sphere(1.0)));
  EXPECT_EQ(sphere, cache.Get(PrimitiveDesc(Primitive::Sphere(1.0))));
  EXPECT_NE(sphere, cache.Get(PrimitiveDesc(Primitive::Sphere(2.0))));
  EXPECT_EQ(cache.size(), 4);
}

}  // namespace
}  // namespace lamina
