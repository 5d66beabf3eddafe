// SPDX-License-Identifier: MIT
// Klamp't rigid-object `.obj` files (and Wavefront meshes with the same extension), bare meshes
// as objects, and `.env` / bare-mesh terrains.
#include "core/io/object_file.h"

#include <cmath>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/io/paths.h"
#include "tests/common/test_support.h"

namespace lamina::core {
namespace {

using ::lamina::test::DataPath;
using ::lamina::test::WorldsPath;
using ::lamina::test::WriteScratchFile;
using ::testing::ElementsAre;

// mass properties of meshes with exact arithmetic (boxes) are exact up to rounding
constexpr double kExactRelative = 1e-9;
// positions read from text or built from a few exact operations
constexpr double kRounding = 1e-12;

// The location that "referenced" the file, as a world file would.
const SourceLocation kWhere{"/worlds/scene.xml", 7, 0};

struct ObjectLoad {
  Diagnostics diagnostics;
  MeshCache meshes;
  RigidObjectDesc object;
  bool ok = false;

  explicit ObjectLoad(const std::string& path) {
    LoadContext context{diagnostics, meshes};
    ok = LoadRigidObjectFile(path, kWhere, context, &object);
  }
  std::vector<std::string> Errors() const { return diagnostics.Messages(Severity::kError); }
  std::vector<std::string> Warnings() const { return diagnostics.Messages(Severity::kWarning); }
};

struct TerrainLoad {
  Diagnostics diagnostics;
  MeshCache meshes;
  TerrainDesc terrain;
  bool ok = false;

  explicit TerrainLoad(const std::string& path) {
    LoadContext context{diagnostics, meshes};
    ok = LoadTerrainFile(path, kWhere, context, &terrain);
  }
  std::vector<std::string> Errors() const { return diagnostics.Messages(Severity::kError); }
};

// Thin-shell cube of edge a: each face a plate of mass m/6, I = 5/18 m a^2 about any axis.
double ShellCubeInertia(double mass, double edge) {
  return 5.0 / 18.0 * mass * edge * edge;
}

void ExpectDiagonal(const Mat3& inertia, const Vec3& diagonal, double relative) {
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(inertia(i, i), diagonal[i], relative * diagonal.maxCoeff()) << "axis " << i;
  }
  const Mat3 off_diagonal = inertia - Mat3(inertia.diagonal().asDiagonal());
  EXPECT_LE(off_diagonal.cwiseAbs().maxCoeff(), relative * diagonal.maxCoeff());
}

// [section] telling Klamp't object files from Wavefront meshes

TEST(LooksLikeKlamptObjectTest, DecidesOnTheFirstRecognisedKeyword) {
  EXPECT_TRUE(LooksLikeKlamptObject("# a block\nmesh \"cube.off\"\nmass 1\n"));
  EXPECT_TRUE(LooksLikeKlamptObject("Mass 2\nmesh cube.off\n"));
  EXPECT_TRUE(LooksLikeKlamptObject("T 1 0 0 0 1 0 0 0 1 0 0 0\n"));
  EXPECT_FALSE(LooksLikeKlamptObject("# Blender export\nmtllib a.mtl\no cube\nv 0 0 0\n"));
  EXPECT_FALSE(LooksLikeKlamptObject("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
  EXPECT_FALSE(LooksLikeKlamptObject("newthing 1\nvn 0 0 1\nmass 1\n"));
}

TEST(LooksLikeKlamptObjectTest, UnrecognisedOrEmptyTextReadsAsAnObjectFile) {
  // then the object reader's diagnostics (unknown key, missing 'mesh') explain the problem
  EXPECT_TRUE(LooksLikeKlamptObject(""));
  EXPECT_TRUE(LooksLikeKlamptObject("# only a comment\n"));
  EXPECT_TRUE(LooksLikeKlamptObject("colour red\n"));
}

TEST(LooksLikeKlamptObjectTest, ReadsOnlyTheTopOfLargeFiles) {
  std::string text = "v 0 0 0\n";
  while (text.size() < 200000) text += "v 1 2 3\n";
  text += "mesh cube.off\n";
  EXPECT_FALSE(LooksLikeKlamptObject(text));
}

// [section] the example objects

TEST(RigidObjectFileTest, EveryExampleObjectLoads) {
  const std::vector<std::pair<std::string, double>> objects = {
      {"block", 0.1},  {"block_small", 0.1}, {"flatblock", 0.05},
      {"sphere", 1.0}, {"sphere_10cm", 1.0}, {"sphere_5cm", 1.0}};
  for (const auto& [name, mass] : objects) {
    const ObjectLoad load(WorldsPath("klampt/objects/" + name + ".obj"));
    EXPECT_TRUE(load.ok) << name << "\n" << load.diagnostics.FormatAll();
    EXPECT_EQ(load.diagnostics.entries().size(), 0u) << load.diagnostics.FormatAll();
    EXPECT_EQ(load.object.name, name);
    EXPECT_EQ(load.object.mass, mass) << name;
    EXPECT_EQ(load.object.geometry.kind, GeometryKind::kMesh) << name;
    EXPECT_TRUE(load.object.inertia.allFinite()) << name;
    EXPECT_GT(load.object.inertia.trace(), 0.0) << name;
  }
}

TEST(RigidObjectFileTest, BlockIsAThinShellCubeWithItsSurface) {
  const ObjectLoad load(WorldsPath("klampt/objects/block.obj"));
  ASSERT_TRUE(load.ok) << load.diagnostics.FormatAll();
  const RigidObjectDesc& block = load.object;
  EXPECT_EQ(block.geometry.path, WorldsPath("klampt/objects/cube.off"));
  EXPECT_EQ(block.geometry.mesh->triangle_count(), 12);
  EXPECT_TRUE(block.geometry.scale.isApprox(Vec3::Constant(0.4), kRounding));
  EXPECT_TRUE(block.geometry.transform.translation().isApprox(Vec3::Constant(-0.2), kRounding));
  EXPECT_TRUE(block.geometry.transform.linear().isIdentity(0.0));
  EXPECT_TRUE(block.pose.linear().isIdentity(0.0));
  EXPECT_TRUE(block.pose.translation().isApprox(Vec3(1.0, 0.0, 0.3), kRounding));
  // autoMass without a value is Klamp't's thin shell: the 0.4 m cube centred on the origin
  EXPECT_LE(block.com.norm(), kRounding);
  ExpectDiagonal(block.inertia, Vec3::Constant(ShellCubeInertia(0.1, 0.4)), kExactRelative);
  EXPECT_EQ(block.sim.surface, (SurfaceDesc{0.0, 0.5, 10000.0, 3000.0}));
  EXPECT_EQ(block.sim.padding, DefaultObjectSimParams().padding);
  EXPECT_EQ(block.initial_velocity, Twist());
}

TEST(RigidObjectFileTest, SphereInertiaApproachesTheThinSphericalShell) {
  const ObjectLoad load(WorldsPath("klampt/objects/sphere.obj"));
  ASSERT_TRUE(load.ok) << load.diagnostics.FormatAll();
  const Mat3& inertia = load.object.inertia;
  const double radius = 0.1, mass = 1.0;
  EXPECT_LE(load.object.com.norm(), 1e-9);
  // sphere.off is a 960-triangle polyhedron inscribed in the unit sphere: every point of its
  // surface lies between 0.9904 r (the nearest face plane) and r (vertices, to 1e-6), so
  // trace(I) = 2 m E|x|^2 is bounded by 2 m (0.9904 r)^2 and 2 m r^2
  EXPECT_GE(inertia.trace(), 2.0 * mass * std::pow(0.9904 * radius, 2));
  EXPECT_LE(inertia.trace(), 2.0 * mass * radius * radius * (1.0 + 1e-5));
  // per axis it is close to the spherical shell's 2/3 m r^2: the 1.9 % radial bound plus the
  // small anisotropy of the tessellation
  ExpectDiagonal(inertia, Vec3::Constant(2.0 / 3.0 * mass * radius * radius), 0.02);
}

// [section] every key

TEST(RigidObjectFileTest, EveryKeyIsApplied) {
  const ObjectLoad load(DataPath("objects/box_all_keys.obj"));
  ASSERT_TRUE(load.ok) << load.diagnostics.FormatAll();
  EXPECT_EQ(load.diagnostics.entries().size(), 0u) << load.diagnostics.FormatAll();
  const RigidObjectDesc& box = load.object;
  EXPECT_EQ(box.name, "box_all_keys");
  EXPECT_EQ(box.geometry.scale, Vec3(1, 2, 3));
  EXPECT_EQ(box.geometry.transform.translation(), Vec3(-0.5, -1, -1.5));
  // the 4x4 rotation, with the translation replaced by 'position'
  Mat3 rotation;
  rotation << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  EXPECT_EQ(box.pose.linear(), rotation);
  EXPECT_EQ(box.pose.translation(), Vec3(1, 2, 3));
  EXPECT_EQ(box.initial_velocity.linear, Vec3(0.5, 0, 0));
  EXPECT_EQ(box.initial_velocity.angular, Vec3(0, 0, 2));
  EXPECT_EQ(box.mass, 6.0);
  // solid box 1 x 2 x 3 m, 6 kg: I = m (b² + c²) / 12 ... = (6.5, 5, 2.5) about its centre;
  // 'com' was given, so autoMass gives the inertia about (0.1, 0, 0): + m (0, 0.01, 0.01)
  EXPECT_EQ(box.com, Vec3(0.1, 0, 0));
  ExpectDiagonal(box.inertia, Vec3(6.5, 5.06, 2.56), kExactRelative);
  EXPECT_EQ(box.sim.surface, (SurfaceDesc{0.25, 0.8, 5e4, 100.0}));
}

TEST(RigidObjectFileTest, ExplicitInertiaAndTwelveNumberTransform) {
  const ObjectLoad load(DataPath("objects/explicit_inertia.obj"));
  ASSERT_TRUE(load.ok) << load.diagnostics.FormatAll();
  EXPECT_EQ(load.diagnostics.entries().size(), 0u) << load.diagnostics.FormatAll();
  const RigidObjectDesc& object = load.object;
  // 'T' is the rotation row by row (here 90 degrees about y), then the translation
  Mat3 rotation;
  rotation << 0, 0, 1, 0, 1, 0, -1, 0, 0;
  EXPECT_EQ(object.pose.linear(), rotation);
  EXPECT_EQ(object.pose.translation(), Vec3(0.5, 0, 2));
  // keys match case-insensitively ("Mass")
  EXPECT_EQ(object.mass, 2.5);
  EXPECT_EQ(object.com, Vec3(0.5, 0.5, 0.5));
  Mat3 inertia;
  inertia << 0.2, 0.01, 0, 0.01, 0.3, 0, 0, 0, 0.4;
  EXPECT_EQ(object.inertia, inertia);
}

TEST(RigidObjectFileTest, TwelveAndSixteenNumberTransformsAgree) {
  const std::string mesh = "mesh \"" + WorldsPath("klampt/objects/cube.off") + "\"\n";
  const std::string twelve =
      WriteScratchFile("twelve.obj", mesh + "T 0 -1 0  1 0 0  0 0 1   7 8 9\n");
  const std::string sixteen =
      WriteScratchFile("sixteen.obj", mesh + "T 0 -1 0 7  1 0 0 8  0 0 1 9  0 0 0 1\n");
  const ObjectLoad from_twelve(twelve), from_sixteen(sixteen);
  ASSERT_TRUE(from_twelve.ok) << from_twelve.diagnostics.FormatAll();
  ASSERT_TRUE(from_sixteen.ok) << from_sixteen.diagnostics.FormatAll();
  Mat3 rotation;
  rotation << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  for (const ObjectLoad* load : {&from_twelve, &from_sixteen}) {
    EXPECT_EQ(load->object.pose.linear(), rotation);
    EXPECT_EQ(load->object.pose.translation(), Vec3(7, 8, 9));
  }
}

// Lamina's rolling and spinning friction (m) are keys like the other surface rows, checked by the
// table with the same file:line diagnostics
TEST(RigidObjectFileTest, RollingAndSpinningFrictionKeys) {
  const std::string mesh = "mesh \"" + WorldsPath("klampt/objects/cube.off") + "\"\n";
  const ObjectLoad good(WriteScratchFile(
      "rolling.obj", mesh + "kFriction 0.6\nkRollingFriction 0.004\nkSpinningFriction 0.001\n"));
  ASSERT_TRUE(good.ok) << good.diagnostics.FormatAll();
  EXPECT_EQ(good.diagnostics.entries().size(), 0u) << good.diagnostics.FormatAll();
  EXPECT_EQ(good.object.sim.surface.friction, 0.6);
  EXPECT_EQ(good.object.sim.surface.rolling_friction, 0.004);
  EXPECT_EQ(good.object.sim.surface.spinning_friction, 0.001);
  const std::string bad_path =
      WriteScratchFile("bad_rolling.obj", mesh + "kRollingFriction -0.5\nkSpinningFriction inf\n");
  const ObjectLoad bad(bad_path);
  EXPECT_FALSE(bad.ok);
  EXPECT_THAT(bad.Errors(),
              ElementsAre(bad_path + ":2: error: 'kRollingFriction' must be >= 0, got '-0.5'",
                          bad_path + ":3: error: 'kSpinningFriction' must be >= 0, got 'inf'"));
  EXPECT_EQ(bad.object.sim.surface, DefaultObjectSimParams().surface);
}

TEST(RigidObjectFileTest, DefaultsAreKlamptsWithIdentityInertia) {
  const ObjectLoad load(DataPath("objects/no_automass.obj"));
  ASSERT_TRUE(load.ok) << load.diagnostics.FormatAll();
  EXPECT_EQ(load.object.mass, 1.0);
  EXPECT_EQ(load.object.com, Vec3::Zero());
  EXPECT_EQ(load.object.inertia, Mat3::Identity());
  EXPECT_TRUE(load.object.pose.isApprox(Pose::Identity(), 0.0));
  EXPECT_EQ(load.object.sim, DefaultObjectSimParams());
  EXPECT_EQ(load.object.geometry.scale, Vec3::Ones());
}

TEST(RigidObjectFileTest, PrimitiveGeometryGetsAnalyticAutoMass) {
  const ObjectLoad load(DataPath("objects/ball.obj"));
  ASSERT_TRUE(load.ok) << load.diagnostics.FormatAll();
  ASSERT_EQ(load.object.geometry.kind, GeometryKind::kPrimitive);
  EXPECT_EQ(load.object.geometry.primitive.type, PrimitiveType::kSphere);
  // autoMass 0: a solid sphere, 2/5 m r^2 = 0.4 * 2 * 0.25
  EXPECT_LE(load.object.com.norm(), kRounding);
  ExpectDiagonal(load.object.inertia, Vec3::Constant(0.2), kExactRelative);
}

// [section] bare meshes as objects

TEST(RigidObjectFileTest, BareMeshIsAUnitMassShell) {
  const ObjectLoad load(WorldsPath("klampt/objects/cube.off"));
  ASSERT_TRUE(load.ok) << load.diagnostics.FormatAll();
  const RigidObjectDesc& cube = load.object;
  EXPECT_EQ(cube.name, "cube");
  EXPECT_EQ(cube.geometry.kind, GeometryKind::kMesh);
  EXPECT_EQ(cube.mass, 1.0);
  // cube.off spans 0..1: COM at its centre, thin-shell inertia as Klamp't's bare-mesh default
  EXPECT_TRUE(cube.com.isApprox(Vec3::Constant(0.5), kRounding));
  ExpectDiagonal(cube.inertia, Vec3::Constant(ShellCubeInertia(1.0, 1.0)), kExactRelative);
  EXPECT_EQ(cube.sim.surface, (SurfaceDesc{0.5, 0.5, kInf, kInf}));
  EXPECT_TRUE(cube.pose.isApprox(Pose::Identity(), 0.0));
}

TEST(RigidObjectFileTest, WavefrontObjLoadsAsABareMesh) {
  const ObjectLoad load(DataPath("objects/wavefront_cube.obj"));
  ASSERT_TRUE(load.ok) << load.diagnostics.FormatAll();
  EXPECT_EQ(load.object.name, "wavefront_cube");
  ASSERT_EQ(load.object.geometry.kind, GeometryKind::kMesh);
  EXPECT_EQ(load.object.geometry.mesh->triangle_count(), 12);  // six quads
  EXPECT_LE(load.object.com.norm(), kRounding);
  ExpectDiagonal(load.object.inertia, Vec3::Constant(ShellCubeInertia(1.0, 1.0)), kExactRelative);
}

// [section] terrains

TEST(TerrainFileTest, PlaneEnvLoads) {
  const TerrainLoad load(WorldsPath("klampt/terrains/plane.env"));
  ASSERT_TRUE(load.ok) << load.diagnostics.FormatAll();
  EXPECT_EQ(load.diagnostics.entries().size(), 0u) << load.diagnostics.FormatAll();
  EXPECT_EQ(load.terrain.name, "plane");
  EXPECT_EQ(load.terrain.geometry.path, WorldsPath("klampt/terrains/plane.off"));
  EXPECT_EQ(load.terrain.geometry.triangle_count(), 2);
  EXPECT_EQ(load.terrain.sim, DefaultTerrainSimParams());
}

TEST(TerrainFileTest, FrictionFromTheFile) {
  const TerrainLoad rough(DataPath("objects/rough.env"));
  ASSERT_TRUE(rough.ok) << rough.diagnostics.FormatAll();
  EXPECT_EQ(rough.terrain.sim.surface.friction, 0.8);
  EXPECT_EQ(rough.terrain.sim.surface.restitution, DefaultTerrainSimParams().surface.restitution);
  EXPECT_EQ(rough.terrain.sim.padding, 0.0);
}

TEST(TerrainFileTest, FrictionAsKlamptSavesIt) {
  const std::string path = DataPath("objects/saved_by_klampt.env");
  const TerrainLoad load(path);
  ASSERT_TRUE(load.ok) << load.diagnostics.FormatAll();
  EXPECT_EQ(load.terrain.sim.surface.friction, 0.3);
  EXPECT_THAT(load.diagnostics.Messages(Severity::kNote),
              ElementsAre(path + ":2: note: 'friction' read as 'kFriction' (Klamp't writes it "
                                 "but ignores it)"));
}

TEST(TerrainFileTest, PerTriangleFrictionKeepsTheFirstValue) {
  const std::string mesh = WorldsPath("klampt/terrains/plane.off");  // 2 triangles
  const std::string same =
      WriteScratchFile("same.env", "mesh \"" + mesh + "\"\nkFriction 0.7 0.7\n");
  const TerrainLoad uniform(same);
  EXPECT_TRUE(uniform.ok) << uniform.diagnostics.FormatAll();
  EXPECT_EQ(uniform.diagnostics.entries().size(), 0u) << uniform.diagnostics.FormatAll();
  EXPECT_EQ(uniform.terrain.sim.surface.friction, 0.7);
  const std::string mixed =
      WriteScratchFile("mixed.env", "mesh \"" + mesh + "\"\nkFriction 0.7 0.2\n");
  const TerrainLoad varying(mixed);
  EXPECT_TRUE(varying.ok);
  EXPECT_EQ(varying.terrain.sim.surface.friction, 0.7);
  EXPECT_THAT(varying.diagnostics.Messages(Severity::kWarning),
              ElementsAre(mixed + ":2: warning: per-triangle 'kFriction' is not supported; using "
                                  "the first value '0.7'"));
}

TEST(TerrainFileTest, BareMeshTerrain) {
  const TerrainLoad load(WorldsPath("klampt/terrains/stair.off"));
  ASSERT_TRUE(load.ok) << load.diagnostics.FormatAll();
  EXPECT_EQ(load.terrain.name, "stair");
  EXPECT_EQ(load.terrain.geometry.kind, GeometryKind::kMesh);
  EXPECT_EQ(load.terrain.sim.surface.friction, 0.5);
  EXPECT_TRUE(load.terrain.geometry.transform.isApprox(Affine::Identity(), 0.0));
}

// [section] malformed input

TEST(RigidObjectFileErrorsTest, MissingFileIsReportedWhereItWasReferenced) {
  const std::string path = DataPath("objects/no_such_object.obj");
  const ObjectLoad load(path);
  EXPECT_FALSE(load.ok);
  EXPECT_THAT(load.Errors(),
              ElementsAre("/worlds/scene.xml:7: error: cannot open object file '" + path + "'"));
}

TEST(RigidObjectFileErrorsTest, MissingMeshKey) {
  const std::string path = DataPath("bad/obj_missing_mesh.obj");
  const ObjectLoad load(path);
  EXPECT_FALSE(load.ok);
  EXPECT_THAT(load.Errors(), ElementsAre(path + ": error: missing 'mesh' (the geometry file)"));
  EXPECT_EQ(load.object.mass, 1.0);  // the rest of the file is still read
}

TEST(RigidObjectFileErrorsTest, MissingMeshFileIsReportedAtTheMeshLine) {
  const std::string path = DataPath("bad/obj_missing_mesh_file.obj");
  const ObjectLoad load(path);
  EXPECT_FALSE(load.ok);
  EXPECT_THAT(load.Errors(), ElementsAre(path + ":1: error: cannot open mesh file '" +
                                         DataPath("bad/no_such_mesh.off") + "'"));
}

TEST(RigidObjectFileErrorsTest, EveryBadValueIsReportedInOneRun) {
  const std::string path = DataPath("bad/obj_bad_values.obj");
  const ObjectLoad load(path);
  EXPECT_FALSE(load.ok);
  EXPECT_THAT(load.Errors(),
              ElementsAre(path + ":2: error: 'geomscale' expects 1 or 3 values, got 2",
                          path + ":3: error: 'T' (transform) must be 12 finite numbers: a rotation "
                                 "(column-major) and a translation, got '1 0 0 0 1 0 0 0 2 0 0 0'",
                          path + ":13: error: 'velocity' must be finite, got 'inf'",
                          path + ":4: error: 'mass' must be >= 0, got '-2'",
                          path + ":5: error: 'nan' in 'com' is not a number",
                          path + ":6: error: 'inertia' expects 3 or 9 values, got 4",
                          path + ":8: error: 'kRestitution' must be in [0, 1], got '1.5'",
                          path + ":7: error: 'kFriction' must be >= 0 (inf allowed), got '-1'",
                          path + ":9: error: 'kStiffness' must be > 0 (inf allowed), got '0'",
                          path + ":10: error: 'kDamping' must be >= 0 (inf allowed), got '-3'",
                          path + ":11: error: 'autoMass' must be in [0, 1], got '2'"));
  EXPECT_THAT(load.Warnings(), ElementsAre(path + ":12: warning: unknown key 'colour' ignored"));
  // bad values leave the defaults in place
  EXPECT_EQ(load.object.mass, 1.0);
  EXPECT_EQ(load.object.sim.surface, DefaultObjectSimParams().surface);
}

TEST(RigidObjectFileErrorsTest, BadTransforms) {
  const std::string mesh = "mesh \"" + WorldsPath("klampt/objects/cube.off") + "\"\n";
  const std::string last_row =
      WriteScratchFile("last_row.obj", mesh + "T 1 0 0 0  0 1 0 0  0 0 1 0  0 0 1 1\n");
  EXPECT_THAT(ObjectLoad(last_row).Errors(),
              ElementsAre(last_row + ":2: error: 'T' 4x4 matrix must end with the row '0 0 0 1', "
                                     "got '0 0 1 1'"));
  const std::string short_t = WriteScratchFile("short.obj", mesh + "T 1 0 0\n");
  EXPECT_THAT(ObjectLoad(short_t).Errors(),
              ElementsAre(short_t + ":2: error: 'T' expects 12 or 16 values, got 3"));
}

TEST(RigidObjectFileErrorsTest, BadInertiaAndScale) {
  const std::string mesh = "mesh \"" + WorldsPath("klampt/objects/cube.off") + "\"\n";
  const std::string asymmetric =
      WriteScratchFile("asymmetric.obj", mesh + "inertia 1 0.5 0  0 1 0  0 0 1\n");
  EXPECT_THAT(ObjectLoad(asymmetric).Errors(),
              ElementsAre(asymmetric + ":2: error: 'inertia' must be a symmetric positive "
                                       "semi-definite 3x3 matrix, got '1 0.5 0 0 1 0 0 0 1'"));
  const std::string indefinite = WriteScratchFile("indefinite.obj", mesh + "inertia 1 -2 1\n");
  EXPECT_THAT(ObjectLoad(indefinite).Errors(),
              ElementsAre(indefinite + ":2: error: 'inertia' must be a symmetric positive "
                                       "semi-definite 3x3 matrix, got '1 -2 1'"));
  const std::string zero_scale = WriteScratchFile("zero_scale.obj", mesh + "geomscale 1 0 1\n");
  EXPECT_THAT(ObjectLoad(zero_scale).Errors(),
              ElementsAre(zero_scale + ":2: error: 'geomscale' must be > 0, got '0'"));
  const std::string two_meshes = WriteScratchFile("two_meshes.obj", "mesh a.off b.off\n");
  EXPECT_THAT(ObjectLoad(two_meshes).Errors(),
              ElementsAre(two_meshes + ":1: error: 'mesh' expects 1 file name, got 2"));
}

TEST(RigidObjectFileErrorsTest, UnknownAndRepeatedKeysWarn) {
  const std::string path =
      WriteScratchFile("keys.obj", "mesh \"" + WorldsPath("klampt/objects/cube.off") +
                                       "\"\nmass 2\nmas 3\nfriction 1\nmass 4\n");
  const ObjectLoad load(path);
  EXPECT_TRUE(load.ok) << load.diagnostics.FormatAll();
  EXPECT_THAT(load.Warnings(),
              ElementsAre(path + ":3: warning: unknown key 'mas' ignored (did you mean 'mass'?)",
                          path + ":4: warning: unknown key 'friction' ignored (did you mean "
                                 "'kFriction'?)",
                          path + ":5: warning: 'mass' given again (first at line 2); the last "
                                 "one is used"));
  EXPECT_EQ(load.object.mass, 4.0);
}

TEST(TerrainFileErrorsTest, BadEnvFiles) {
  const std::string counts = DataPath("bad/env_bad_friction.env");
  EXPECT_THAT(TerrainLoad(counts).Errors(),
              ElementsAre(counts + ":2: error: 'kFriction' expects 1 value, got 3"));
  const std::string no_mesh = DataPath("bad/env_missing_mesh.env");
  EXPECT_THAT(TerrainLoad(no_mesh).Errors(),
              ElementsAre(no_mesh + ": error: missing 'mesh' (the geometry file)"));
  const std::string missing = DataPath("objects/no_such_terrain.env");
  EXPECT_THAT(
      TerrainLoad(missing).Errors(),
      ElementsAre("/worlds/scene.xml:7: error: cannot open terrain file '" + missing + "'"));
}

TEST(TerrainFileErrorsTest, KlamptObjectFileIsNotATerrain) {
  const std::string path = WorldsPath("klampt/objects/block.obj");
  const TerrainLoad load(path);
  EXPECT_FALSE(load.ok);
  EXPECT_THAT(load.Errors(), ElementsAre("/worlds/scene.xml:7: error: '" + path +
                                         "' is a Klamp't rigid-object file, not a terrain mesh"));
}

}  // namespace
}  // namespace lamina::core
