// SPDX-License-Identifier: MIT
// Collision geometry: meshes with scale and placement baked in, primitives kept analytic when
// their scale allows it, the mesh topology built with the hierarchy, the hierarchy queries
// (every way of finding near triangle pairs gives the same pairs), the sparse scratch arrays,
// and the cache that builds each (mesh, placement) once.
#include "core/contact/collision_geometry.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <tuple>

#include <gtest/gtest.h>

#include "core/contact/mesh_query.h"
#include "core/contact/near_pair_cache.h"
#include "core/contact/triangle_queries.h"
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

// a triangle without area has no normal, whether its corners are exactly collinear or only to
// rounding: HRP-2's right arm (RARM_LINK4.off) has one through an edge's midpoint, whose cross
// product is 9.5e-16 of its edges' and pointed anywhere
TEST(CollisionGeometryTest, ATriangleWithoutAreaHasNoNormal) {
  auto mesh = std::make_shared<core::TriangleMesh>();
  mesh->vertices = {{-0.027557, 0.037887, 0.037395},
                    {-0.028611, 0.035777, 0.039791},
                    {-0.028084, 0.036832, 0.038593},
                    {0, 0, 0},
                    {0.1, 0, 0},
                    {0, 1e-7, 0}};
  mesh->triangles = {{0, 1, 2}, {3, 4, 4}, {3, 4, 5}};
  const auto geometry = CollisionGeometry::Build(MeshDesc(mesh));
  EXPECT_EQ(geometry->triangle_normals()[0], Vec3::Zero());
  EXPECT_EQ(geometry->triangle_normals()[1], Vec3::Zero());
  // a thin triangle that has area (sine 1e-6) keeps its normal
  EXPECT_TRUE(geometry->triangle_normals()[2].isApprox(Vec3::UnitZ(), 1e-12));
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

// ---- near triangle pairs ----

using core::mesh_detail::PairSearch;
using core::mesh_detail::TrianglePairHit;

std::shared_ptr<const CollisionGeometry> MeshGeometry(
    std::shared_ptr<const core::TriangleMesh> mesh, const Vec3& scale = Vec3::Ones()) {
  return CollisionGeometry::Build(MeshDesc(std::move(mesh), scale));
}

// A bumpy n x n grid of squares (2 n^2 triangles) over [0, 1]^2, heights up to 0.1.
std::shared_ptr<const core::TriangleMesh> BumpyGrid(int n) {
  auto mesh = std::make_shared<core::TriangleMesh>();
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) {
      const double x = static_cast<double>(i) / n, y = static_cast<double>(j) / n;
      mesh->vertices.emplace_back(x, y, 0.05 * (std::sin(7 * x) * std::cos(5 * y) + 1));
    }
  }
  const auto at = [n](int i, int j) { return i * (n + 1) + j; };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      mesh->triangles.emplace_back(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      mesh->triangles.emplace_back(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  }
  return mesh;
}

// Turned by up to `angle` about each axis, moved by up to `spread` along each from `centre`.
Pose RandomPose(std::mt19937& random, const Vec3& centre, double spread, double angle) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Pose pose = Pose::Identity();
  pose.linear() =
      core::RotationFromRollPitchYaw(angle * u(random), angle * u(random), angle * u(random));
  pose.translation() = centre + spread * Vec3(u(random), u(random), u(random));
  return pose;
}

std::vector<TrianglePairHit> NearPairs(const CollisionGeometry& a, const CollisionGeometry& b,
                                       const Pose& X_ab, double tolerance, PairSearch search) {
  std::vector<TrianglePairHit> hits;
  core::mesh_detail::NearTrianglePairs(a.bvh(), b.bvh(), X_ab, tolerance, &hits, search);
  return hits;
}

void ExpectSameHits(const std::vector<TrianglePairHit>& expected,
                    const std::vector<TrianglePairHit>& actual, const std::string& what) {
  ASSERT_EQ(expected.size(), actual.size()) << what;
  for (size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(expected[i].triangle_a, actual[i].triangle_a) << what << " hit " << i;
    EXPECT_EQ(expected[i].triangle_b, actual[i].triangle_b) << what << " hit " << i;
    EXPECT_EQ(expected[i].distance, actual[i].distance) << what << " hit " << i;
    EXPECT_EQ(expected[i].point_a, actual[i].point_a) << what << " hit " << i;
    EXPECT_EQ(expected[i].point_b, actual[i].point_b) << what << " hit " << i;
    EXPECT_EQ(expected[i].foot, actual[i].foot) << what << " hit " << i;
    EXPECT_EQ(expected[i].corner, actual[i].corner) << what << " hit " << i;
  }
}

// Each triangle's corners placed by X.
std::vector<core::mesh_detail::Triangle3> PlacedTriangles(const CollisionGeometry& mesh,
                                                          const Pose& X) {
  std::vector<core::mesh_detail::Triangle3> triangles;
  for (const Eigen::Vector3i& c : mesh.mesh().triangles) {
    const std::vector<Vec3>& v = mesh.mesh().vertices;
    triangles.push_back({X * v[c[0]], X * v[c[1]], X * v[c[2]]});
  }
  return triangles;
}

// True when the triangles' boxes are at least `gap` apart along some axis.
bool BoxesApart(const core::mesh_detail::Triangle3& s, const core::mesh_detail::Triangle3& t,
                double gap) {
  for (int axis = 0; axis < 3; ++axis) {
    const double s_low = std::min({s[0][axis], s[1][axis], s[2][axis]});
    const double s_high = std::max({s[0][axis], s[1][axis], s[2][axis]});
    const double t_low = std::min({t[0][axis], t[1][axis], t[2][axis]});
    const double t_high = std::max({t[0][axis], t[1][axis], t[2][axis]});
    if (s_low - t_high >= gap || t_low - s_high >= gap) return true;
  }
  return false;
}

// Every pair whose distance is surely below the tolerance is reported (the closest points of
// edges and vertices bound the distance from above, the triangles' boxes from below), and
// every reported pair is within it.
void ExpectComplete(const CollisionGeometry& a, const CollisionGeometry& b, const Pose& X_ab,
                    double tolerance, const std::vector<TrianglePairHit>& hits) {
  std::vector<std::pair<int, int>> reported;
  for (const TrianglePairHit& hit : hits) {
    EXPECT_LE(hit.distance, tolerance);
    reported.emplace_back(hit.triangle_a, hit.triangle_b);
  }
  std::sort(reported.begin(), reported.end());
  const std::vector<core::mesh_detail::Triangle3> triangles_a =
      PlacedTriangles(a, Pose::Identity());
  const std::vector<core::mesh_detail::Triangle3> triangles_b = PlacedTriangles(b, X_ab);
  for (int ta = 0; ta < a.mesh().triangle_count(); ++ta) {
    for (int tb = 0; tb < b.mesh().triangle_count(); ++tb) {
      if (BoxesApart(triangles_a[ta], triangles_b[tb], tolerance)) continue;
      const double bound =
          core::mesh_detail::ClosestPointsOfTriangles(triangles_a[ta], triangles_b[tb]).distance;
      if (bound >= tolerance - 1e-9) continue;
      EXPECT_TRUE(std::binary_search(reported.begin(), reported.end(), std::make_pair(ta, tb)))
          << "pair " << ta << ", " << tb << " at most " << bound << " apart is missing";
    }
  }
}

// b at `poses` random poses (a's frame, from `random_pose`): every search reports bitwise the
// same pairs as the exact distance of every pair with nothing pruned, in (triangle_a, triangle_b)
// order, and no near pair is missed. Returns how many poses had pairs.
template <typename RandomPose>
int CompareSearches(const CollisionGeometry& a, const CollisionGeometry& b, int poses,
                    const RandomPose& random_pose, double tolerance = 0.005) {
  std::mt19937 random(7);
  int with_hits = 0;
  for (int i = 0; i < poses; ++i) {
    const Pose X_ab = random_pose(random);
    const std::vector<TrianglePairHit> every =
        NearPairs(a, b, X_ab, tolerance, PairSearch::kReference);
    EXPECT_TRUE(std::is_sorted(every.begin(), every.end(), [](const auto& x, const auto& y) {
      return std::tie(x.triangle_a, x.triangle_b) < std::tie(y.triangle_a, y.triangle_b);
    }));
    const std::string pose = "pose " + std::to_string(i);
    for (const PairSearch search : {PairSearch::kAuto, PairSearch::kEveryPair,
                                    PairSearch::kSmallerInLarger, PairSearch::kBothHierarchies}) {
      ExpectSameHits(every, NearPairs(a, b, X_ab, tolerance, search),
                     pose + " search " + std::to_string(static_cast<int>(search)));
    }
    ExpectComplete(a, b, X_ab, tolerance, every);
    with_hits += !every.empty();
  }
  return with_hits;
}

TEST(NearTrianglePairsTest, SmallMeshesGiveTheSamePairsEveryWay) {
  // two 10 cm cubes near touching, b turned every way
  const auto cube = MeshGeometry(LoadMesh("klampt/objects/cube.off"), Vec3::Constant(0.1));
  const int with_hits = CompareSearches(*cube, *cube, 300, [](std::mt19937& random) {
    return RandomPose(random, Vec3(0.05, 0.05, 0.15), 0.06, core::kPi);
  });
  EXPECT_GT(with_hits, 100);
}

TEST(NearTrianglePairsTest, SmallMeshOnALargeOneGivesTheSamePairsEveryWay) {
  const auto cube = MeshGeometry(LoadMesh("klampt/objects/cube.off"), Vec3::Constant(0.1));
  const auto grid = MeshGeometry(BumpyGrid(16));  // 512 triangles
  const auto cube_on_grid = [](std::mt19937& random) {
    return RandomPose(random, Vec3(0.5, 0.5, 0.08), 0.2, core::kPi);
  };
  EXPECT_GT(CompareSearches(*grid, *cube, 40, cube_on_grid), 10);
  // the same with the roles swapped: the grid placed in the cube's frame
  EXPECT_GT(CompareSearches(*cube, *grid, 40,
                            [&cube_on_grid](std::mt19937& random) {
                              return Pose(cube_on_grid(random).inverse());
                            }),
            10);
}

TEST(NearTrianglePairsTest, SmallMeshSpanningALargeOneGivesTheSamePairs) {
  // a 2 m cube under which the whole grid lies: bounding the cube as a whole finds every
  // triangle of the grid (2048 x 12 pairs), so the automatic search falls back to both
  // hierarchies
  const auto big_cube = MeshGeometry(LoadMesh("klampt/objects/cube.off"), Vec3::Constant(2.0));
  const auto grid = MeshGeometry(BumpyGrid(32));
  const int with_hits = CompareSearches(*grid, *big_cube, 10, [](std::mt19937& random) {
    return RandomPose(random, Vec3(-0.5, -0.5, -1.92), 0.02, 0.02);
  });
  EXPECT_GT(with_hits, 5);
}

TEST(NearTrianglePairsTest, LargeMeshesGiveTheSamePairsEveryWay) {
  // 128 triangles each: the automatic search traverses both hierarchies
  const auto cylinder = MeshGeometry(LoadMesh("klampt/objects/cylinder.off"));
  ASSERT_EQ(cylinder->mesh().triangle_count(), 128);
  const Vec3 size = cylinder->local_bounds().sizes();
  const int with_hits = CompareSearches(*cylinder, *cylinder, 20, [&size](std::mt19937& random) {
    return RandomPose(random, Vec3(0, 0, size.z()), 0.5 * size.x(), core::kPi);
  });
  EXPECT_GT(with_hits, 5);
}

TEST(NearTrianglePairsTest, BallSunkIntoASlabGivesTheSamePairsEveryWay) {
  // stiffness_test.xml's 960-triangle ball (radius 0.1 m) within its 8 cm paddings of the 4 m
  // slab, on either side of the diagonal of the slab's top face, turned every way: the searches
  // prune by boxes, planes and edge planes, FCL measures what is left
  const auto ball = MeshGeometry(LoadMesh("klampt/objects/sphere.off"), Vec3::Constant(0.1));
  const auto slab = MeshGeometry(LoadMesh("klampt/terrains/block.off"));
  ASSERT_EQ(ball->mesh().triangle_count(), 960);
  const auto ball_on_slab = [](std::mt19937& random) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const Pose X_slab_ball = RandomPose(random, Vec3(0, 0, 0.1), 0.3, core::kPi);
    Pose X = X_slab_ball;
    X.translation().z() = 0.11 + 0.09 * u(random);  // 1 cm clear of the layer to 8 cm sunk
    return Pose(X.inverse());                       // the slab in the ball's frame
  };
  EXPECT_GT(CompareSearches(*ball, *slab, 60, ball_on_slab, 0.08), 40);
}

// A single triangle of corners random within `spread` of `centre`.
std::shared_ptr<const core::TriangleMesh> RandomTriangle(std::mt19937& random, const Vec3& centre,
                                                         double spread) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto mesh = std::make_shared<core::TriangleMesh>();
  for (int k = 0; k < 3; ++k) {
    mesh->vertices.push_back(centre + spread * Vec3(u(random), u(random), u(random)));
  }
  mesh->triangles.emplace_back(0, 1, 2);
  return mesh;
}

TEST(NearTrianglePairsTest, CornerOverAFaceGivesTheExactDistanceAndPoints) {
  // 4000 random triangle pairs, b 0..0.4 above a and turned every way: a pair settled by a
  // corner over the other face reports the distance of the independent closest-point routine,
  // the corner itself and its foot inside the other triangle
  std::mt19937 random(11);
  int corner_hits = 0, general_hits = 0;
  for (int i = 0; i < 4000; ++i) {
    const auto a = MeshGeometry(RandomTriangle(random, Vec3::Zero(), 1.0));
    const auto b = MeshGeometry(RandomTriangle(random, Vec3::Zero(), 0.3));
    const Pose X_ab = RandomPose(random, Vec3(0, 0, 0.2), 0.2, core::kPi);
    const std::vector<TrianglePairHit> hits = NearPairs(*a, *b, X_ab, 10.0, PairSearch::kAuto);
    ASSERT_EQ(hits.size(), 1u);
    const TrianglePairHit& hit = hits[0];
    const core::mesh_detail::Triangle3 ta = PlacedTriangles(*a, Pose::Identity())[0];
    const core::mesh_detail::Triangle3 tb = PlacedTriangles(*b, X_ab)[0];
    Vec3 crossing;
    if (core::mesh_detail::TrianglesCross(ta, tb, &crossing)) continue;
    const double exact = core::mesh_detail::ClosestPointsOfTriangles(ta, tb).distance;
    EXPECT_NEAR(hit.distance, exact, kExact) << "pair " << i;
    EXPECT_NEAR((hit.point_a - hit.point_b).norm(), hit.distance, kExact) << "pair " << i;
    using Foot = TrianglePairHit::Foot;
    if (hit.foot == Foot::kGeneral) {
      ++general_hits;
      continue;
    }
    ++corner_hits;
    const bool of_b = hit.foot == Foot::kCornerOfBOverA;
    const Vec3& corner = of_b ? hit.point_b : hit.point_a;
    const Vec3& foot = of_b ? hit.point_a : hit.point_b;
    EXPECT_LT((corner - (of_b ? tb : ta)[hit.corner]).norm(), kExact) << "pair " << i;
    const Vec3 barycentric = core::mesh_detail::BarycentricCoordinates(foot, of_b ? ta : tb);
    EXPECT_GE(barycentric.minCoeff(), -kExact) << "pair " << i;
  }
  EXPECT_GT(corner_hits, 1000);
  EXPECT_GT(general_hits, 500);
}

TEST(NearTrianglePairsTest, FarMeshesGiveNoPairs) {
  const auto cube = MeshGeometry(LoadMesh("klampt/objects/cube.off"));
  Pose X_ab = Pose::Identity();
  X_ab.translation() = Vec3(0, 0, 1.0051);  // 5.1 mm above: beyond a 5 mm tolerance
  for (const PairSearch search : {PairSearch::kAuto, PairSearch::kReference, PairSearch::kEveryPair,
                                  PairSearch::kSmallerInLarger, PairSearch::kBothHierarchies}) {
    EXPECT_TRUE(NearPairs(*cube, *cube, X_ab, 0.005, search).empty());
  }
  X_ab.translation().z() = 1.0049;
  EXPECT_FALSE(NearPairs(*cube, *cube, X_ab, 0.005, PairSearch::kAuto).empty());
}

// b walks from `start` by random steps of up to `step` (m, and rad about each axis), with a jump
// of up to 20 steps now and then: at every pose the search from the kept candidates reports
// bitwise what a fresh search reports, whether the cache measures its candidates directly or
// after the plane tests, and the candidates are reused and collected again. `direct` counts the
// queries after which the cache chose to measure directly (most pairs near enough were hits).
struct WalkCounts {
  int with_hits = 0;
  int direct = 0;
  long long collections = 0, reuses = 0;
};
WalkCounts CompareWithKeptCandidates(const CollisionGeometry& a, const CollisionGeometry& b,
                                     const Pose& start, int poses, double step, double tolerance) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  core::NearPairCache cache;
  Pose X_ab = start;
  WalkCounts counts;
  for (int i = 0; i < poses; ++i) {
    const double size = i % 25 == 24 ? 20.0 * step : step;
    Pose move = Pose::Identity();
    move.linear() =
        core::RotationFromRollPitchYaw(size * u(random), size * u(random), size * u(random));
    move.translation() = size * Vec3(u(random), u(random), u(random));
    X_ab = X_ab * move;
    const std::vector<TrianglePairHit> fresh = NearPairs(a, b, X_ab, tolerance, PairSearch::kAuto);
    // the walk's own query (the cache's choice), then the other way at the same pose: a reuse
    // that the counts leave out, so that they say what the walk alone reused and collected
    const bool chosen = cache.measure_directly;
    for (const bool directly : {chosen, !chosen}) {
      const long long collections = cache.collections, reuses = cache.reuses;
      cache.measure_directly = directly;
      std::vector<TrianglePairHit> kept;
      core::mesh_detail::NearTrianglePairs(a.bvh(), b.bvh(), X_ab, tolerance, &kept,
                                           PairSearch::kAuto, &cache);
      ExpectSameHits(fresh, kept,
                     "pose " + std::to_string(i) + (directly ? " measured directly" : " planes"));
      if (directly != chosen) continue;
      counts.direct += cache.measure_directly;
      counts.collections += cache.collections - collections;
      counts.reuses += cache.reuses - reuses;
    }
    counts.with_hits += !fresh.empty();
  }
  return counts;
}

TEST(NearTrianglePairsTest, KeptCandidatesGiveTheSamePairsAsAFreshSearch) {
  // the 960-triangle ball within its 8 cm paddings on the slab (the smaller mesh through
  // the larger's hierarchy), walking by up to 2 mm and 2 mrad a step
  const auto ball = MeshGeometry(LoadMesh("klampt/objects/sphere.off"), Vec3::Constant(0.1));
  const auto slab = MeshGeometry(LoadMesh("klampt/terrains/block.off"));
  Pose slab_in_ball = Pose::Identity();
  slab_in_ball.translation() = Vec3(0.3, -0.2, -0.15);
  const WalkCounts ball_on_slab =
      CompareWithKeptCandidates(*ball, *slab, slab_in_ball, 150, 2e-3, 0.08);
  EXPECT_GT(ball_on_slab.with_hits, 100);
  EXPECT_GT(ball_on_slab.reuses, 75);
  EXPECT_GT(ball_on_slab.collections, 3);
  // the ball's pairs near enough are hits about half the time: the cache changes its way both
  // ways (78 of the 150 queries chose to measure directly)
  EXPECT_GT(ball_on_slab.direct, 25);
  EXPECT_LT(ball_on_slab.direct, 125);
  // a cube over a 2048-triangle bumpy grid (both hierarchies), walking by up to 0.2 mm a step
  const auto cube = MeshGeometry(LoadMesh("klampt/objects/cube.off"), Vec3::Constant(0.1));
  const auto grid = MeshGeometry(BumpyGrid(32));
  Pose cube_on_grid = Pose::Identity();
  cube_on_grid.translation() = Vec3(0.45, 0.45, 0.085);  // over bumps 5 to 8 cm high
  const WalkCounts on_grid = CompareWithKeptCandidates(*grid, *cube, cube_on_grid, 150, 2e-4, 0.01);
  EXPECT_GT(on_grid.with_hits, 100);
  EXPECT_GT(on_grid.reuses, 75);
  EXPECT_GT(on_grid.collections, 3);
  EXPECT_GT(on_grid.direct, 75);  // (128 of 150)
}

TEST(NearTrianglePairsTest, KeptCandidatesFollowAChangeOfMeshOrTolerance) {
  const auto cube = MeshGeometry(LoadMesh("klampt/objects/cube.off"), Vec3::Constant(0.1));
  const auto other = MeshGeometry(LoadMesh("klampt/objects/cube.off"), Vec3::Constant(0.2));
  const auto grid = MeshGeometry(BumpyGrid(16));
  Pose X = Pose::Identity();
  X.translation() = Vec3(0.45, 0.45, 0.085);  // the grid is 5 to 8 cm high under the cube
  core::NearPairCache cache;
  const auto kept = [&](const CollisionGeometry& b, double tolerance) {
    std::vector<TrianglePairHit> hits;
    core::mesh_detail::NearTrianglePairs(grid->bvh(), b.bvh(), X, tolerance, &hits,
                                         PairSearch::kAuto, &cache);
    ExpectSameHits(NearPairs(*grid, b, X, tolerance, PairSearch::kAuto), hits, "kept");
    return hits.size();
  };
  const size_t first = kept(*cube, 0.01);
  EXPECT_GT(first, 0u);
  EXPECT_EQ(kept(*cube, 0.01), first);  // the same query: answered from the candidates
  EXPECT_GT(kept(*cube, 0.05), first);  // a wider padding: collected again
  EXPECT_GT(kept(*other, 0.01), 0u);    // another mesh in the pair: collected again
  EXPECT_EQ(cache.collections, 3);
  EXPECT_EQ(cache.reuses, 1);
}

// ---- sparse scratch arrays ----

TEST(SparseArrayTest, ClearForgetsEverySetValueAndGrows) {
  core::mesh_detail::SparseArray<int> values;
  values.Clear(4);
  EXPECT_FALSE(values.Has(2));
  values.Set(2) = 7;
  EXPECT_TRUE(values.Has(2));
  EXPECT_EQ(values[2], 7);
  EXPECT_FALSE(values.Has(3));
  values.Clear(10);  // grows, and forgets index 2
  EXPECT_FALSE(values.Has(2));
  values.Set(9) = 1;
  EXPECT_TRUE(values.Has(9));
  values.Clear(3);  // a smaller size keeps the room
  EXPECT_FALSE(values.Has(9));
  for (int i = 0; i < 1000; ++i) values.Clear(10);
  EXPECT_FALSE(values.Has(9));
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
