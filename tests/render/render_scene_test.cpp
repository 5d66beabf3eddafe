// SPDX-License-Identifier: MIT
// Scene extraction without any GL: draw items per world, colours from display attributes and
// defaults, mesh caching across frames, overlays and the overlay list parser; the description
// drawn at poses that are not its own (WorldPoses), and where those poses come from; point
// clouds as octahedra, grouped by the file's colours.
#include <cmath>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

#include "core/render/display_color.h"
#include "core/render/overlay_options.h"
#include "core/render/picking.h"
#include "core/render/point_markers.h"
#include "core/render/scene_camera.h"
#include "core/render/scene_extract.h"
#include "core/render/world_poses.h"
#include "core/robot/kinematics.h"
#include "core/sim/simulator.h"
#include "tests/common/test_support.h"

namespace lamina::core {
namespace {

int CountFlag(const RenderScene& scene, DrawFlags flag) {
  int count = 0;
  for (const DrawItem& item : scene.items) count += item.has(flag) ? 1 : 0;
  return count;
}

void Extract(const std::string& path, const OverlayOptions& options, RenderScene* scene,
             RenderMeshCache* cache, const std::vector<ContactMarker>& contacts = {}) {
  test::LoadedWorld loaded;
  test::LoadWorld(path, &loaded);
  ASSERT_TRUE(loaded.ok) << loaded.diagnostics.FormatAll();
  ExtractScene(loaded.world, InitialPoses(loaded.world), options, contacts, cache, scene);
}

TEST(DisplayColorTest, ParsesRgbAndRgba) {
  EXPECT_EQ(ParseColor("1 0.5 0"), Rgba(1.0f, 0.5f, 0.0f, 1.0f));
  EXPECT_EQ(ParseColor(" 0.1 0.2 0.3 0.4 "), Rgba(0.1f, 0.2f, 0.3f, 0.4f));
  EXPECT_FALSE(ParseColor("1 0"));
  EXPECT_FALSE(ParseColor("1 0 0 1 1"));
  EXPECT_FALSE(ParseColor("red"));
  EXPECT_FALSE(ParseColor("2 0 0"));
  DisplayAttributes display{{"faceColor", "0 1 0"}, {"silhouette", "0.005"}};
  EXPECT_EQ(DisplayColor(display), Rgba(0, 1, 0, 1));
  display["color"] = "0 0 1 0.5";
  EXPECT_EQ(DisplayColor(display), Rgba(0, 0, 1, 0.5f));  // color wins over faceColor
}

TEST(RenderSceneTest, BoxStackHasTerrainAndTenBlocks) {
  RenderScene scene;
  RenderMeshCache cache;
  Extract(test::WorldsPath("klampt/simulation_test_worlds/stacktest.xml"), {}, &scene, &cache);
  ASSERT_EQ(scene.items.size(), 11u);
  EXPECT_EQ(CountFlag(scene, kDrawTerrain), 1);
  EXPECT_EQ(scene.items[0].color, DefaultTerrainColor());
  EXPECT_EQ(scene.items[1].color, DefaultObjectColor());
  EXPECT_EQ(cache.size(), 2);  // block.off and cube.off, shared by the ten blocks
  EXPECT_TRUE(scene.points.empty() && scene.lines.empty() && scene.arrows.empty());
  // terrain 4 x 4 m, top at z = 0; the stack reaches about 1 m
  EXPECT_NEAR(scene.bounds.min().x(), -2.0, 1e-6);
  EXPECT_NEAR(scene.bounds.max().z(), 1.0209, 1e-3);
  EXPECT_NEAR(scene.body_bounds.min().z(), 0.002, 1e-6);
}

TEST(RenderSceneTest, ColoursComeFromDisplayAttributes) {
  RenderScene scene;
  RenderMeshCache cache;
  Extract(std::string(LAMINA_RENDER_TEST_DATA) + "/padded_contacts.xml", {}, &scene, &cache);
  ASSERT_EQ(scene.items.size(), 3u);
  EXPECT_EQ(scene.items[0].color, Rgba(0.55f, 0.6f, 0.5f, 1.0f));   // terrain
  EXPECT_EQ(scene.items[1].color, Rgba(0.85f, 0.45f, 0.2f, 1.0f));  // box
  EXPECT_EQ(scene.items[2].color, DefaultObjectColor());            // ball: no <display>
}

TEST(RenderSceneTest, RobotLinksAreDrawnAndMeshesAreCachedAcrossFrames) {
  test::LoadedWorld loaded;
  test::LoadWorld(test::WorldsPath("klampt/athlete_fractal_1.xml"), &loaded);
  ASSERT_TRUE(loaded.ok) << loaded.diagnostics.FormatAll();
  int geometries = 0;
  for (const LinkDesc& link : loaded.world.robots[0].links) {
    for (const GeometryDesc& g : link.geometry) geometries += g.empty() ? 0 : 1;
  }
  RenderScene first, second;
  RenderMeshCache cache;
  const WorldPoses poses = InitialPoses(loaded.world);
  ExtractScene(loaded.world, poses, {}, {}, &cache, &first);
  const int cached = cache.size();
  ExtractScene(loaded.world, poses, {}, {}, &cache, &second);
  EXPECT_EQ(static_cast<int>(first.items.size()), 1 + geometries);
  EXPECT_EQ(cache.size(), cached);
  for (size_t i = 0; i < first.items.size(); ++i) {
    EXPECT_EQ(first.items[i].mesh, second.items[i].mesh);  // same mesh object, not rebuilt
  }
  EXPECT_EQ(first.items[1].color, DefaultRobotColor());
}

TEST(RenderSceneTest, OverlaysAddMarkersShellsAndBoxes) {
  OverlayOptions options;
  std::string error;
  ASSERT_TRUE(ParseOverlayList("all", &options, &error));
  options.selected_id = 1;  // the box
  const std::vector<ContactMarker> contacts = {
      {Vec3(0, 0, 0), Vec3::UnitZ(), Vec3(0, 0, 9.8), false},
      {Vec3(1, 0, 0), Vec3::UnitZ(), Vec3::Zero(), true}};
  RenderScene scene;
  RenderMeshCache cache;
  Extract(std::string(LAMINA_RENDER_TEST_DATA) + "/padded_contacts.xml", options, &scene, &cache,
          contacts);
  EXPECT_EQ(scene.items.size(), 6u);  // three bodies + three padding shells
  EXPECT_EQ(CountFlag(scene, kDrawTranslucent), 3);
  EXPECT_EQ(CountFlag(scene, kDrawSelected), 1);
  // 2 contact points + 2 centres of mass; 2 normals + 1 force (zero force has no arrow) + 2x3 axes
  EXPECT_EQ(scene.points.size(), 4u);
  EXPECT_EQ(scene.arrows.size(), 9u);
  EXPECT_EQ(scene.lines.size(), 3u * 12u);    // a box per body (the selected one highlighted)
  const DebugArrow& force = scene.arrows[7];  // after 6 frame axes and 1 normal
  EXPECT_NEAR(force.to.z() - force.from.z(), 9.8 * options.force_scale, 1e-6);
}

// largest entry of |a - b|
float MaxDifference(const Eigen::Matrix4f& a, const Eigen::Matrix4f& b) {
  return (a - b).cwiseAbs().maxCoeff();
}

Eigen::Matrix4f Drawn(const Pose& frame, const GeometryDesc& geometry) {
  return (frame * geometry.Matrix()).matrix().cast<float>();
}

test::LoadedWorld Load(const std::string& path) {
  test::LoadedWorld loaded;
  test::LoadWorld(path, &loaded);
  EXPECT_TRUE(loaded.ok) << loaded.diagnostics.FormatAll();
  return loaded;
}

std::string PaddedContactsPath() {
  return std::string(LAMINA_RENDER_TEST_DATA) + "/padded_contacts.xml";
}

// the box (object 0) turned 30 degrees about z and lifted to (1, 2, 3); the ball (object 1) at
// (-1, 0.5, 0.7); neither where the file puts them
WorldPoses MovedBoxAndBall(const WorldDesc& world) {
  WorldPoses poses = InitialPoses(world);
  poses.objects[0] = Eigen::Translation3d(1, 2, 3) * Eigen::AngleAxisd(M_PI / 6, Vec3::UnitZ());
  poses.objects[1] = Pose(Eigen::Translation3d(-1, 0.5, 0.7));
  return poses;
}

// a hinge through (1.5, 2, 0) about z on the box (object 0, at (1, 2, 1)), drawn level with the
// box: at (1.5, 2, 1); the box turned 90 degrees about its own vertical axis carries it to
// (1, 2.5, 1)
TEST(WorldPosesTest, WorldJointsAreDrawnWhereTheirBodiesTakeThem) {
  const test::LoadedWorld loaded = Load(PaddedContactsPath());
  WorldDesc world = loaded.world;
  world.objects[0].pose = Pose(Eigen::Translation3d(1, 2, 1));
  core::WorldJointDesc hinge;
  hinge.type = core::WorldJointType::kHinge;
  hinge.bodies = {{core::WorldId::Kind::kRigidObject, 0, -1}};
  hinge.point = Vec3(1.5, 2, 0);
  hinge.axis = Vec3::UnitZ();
  world.joints = {hinge};
  OverlayOptions options;
  options.joints = true;
  RenderScene scene;
  RenderMeshCache cache;
  ExtractScene(world, InitialPoses(world), options, {}, &cache, &scene);
  ASSERT_EQ(scene.arrows.size(), 1u);
  const auto middle = [](const core::DebugArrow& a) { return 0.5 * (a.from + a.to); };
  EXPECT_TRUE(middle(scene.arrows[0]).isApprox(Eigen::Vector3f(1.5f, 2, 1), 1e-5f));
  EXPECT_TRUE((scene.arrows[0].to - scene.arrows[0].from)
                  .normalized()
                  .isApprox(Eigen::Vector3f::UnitZ(), 1e-5f));
  WorldPoses turned = InitialPoses(world);
  turned.objects[0] = Eigen::Translation3d(1, 2, 1) * Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ());
  ExtractScene(world, turned, options, {}, &cache, &scene);
  ASSERT_EQ(scene.arrows.size(), 1u);
  EXPECT_TRUE(middle(scene.arrows[0]).isApprox(Eigen::Vector3f(1, 2.5f, 1), 1e-5f));
  options.joints = false;  // off: nothing drawn
  ExtractScene(world, turned, options, {}, &cache, &scene);
  EXPECT_TRUE(scene.arrows.empty());
}

TEST(WorldPosesTest, ObjectsAndTheirOverlaysAreDrawnAtTheGivenPoses) {
  const test::LoadedWorld loaded = Load(PaddedContactsPath());
  const WorldDesc& world = loaded.world;
  const WorldPoses poses = MovedBoxAndBall(world);
  OverlayOptions options;
  std::string error;
  ASSERT_TRUE(ParseOverlayList("padding,com,frames", &options, &error));
  RenderScene scene;
  RenderMeshCache cache;
  ExtractScene(world, poses, options, {}, &cache, &scene);
  // items: terrain, box, ball, then the three padding shells in the same order
  ASSERT_EQ(scene.items.size(), 6u);
  for (int i = 0; i < 2; ++i) {
    EXPECT_LE(MaxDifference(scene.items[1 + i].transform,
                            Drawn(poses.objects[i], world.objects[i].geometry)),
              1e-6f);
    EXPECT_LE(MaxDifference(scene.items[4 + i].transform, poses.objects[i].matrix().cast<float>()),
              1e-6f);
    // centre of mass and frame axes at the given frame (points: COMs; arrows: 3 axes per body)
    const Vec3 com = poses.objects[i] * world.objects[i].com;
    EXPECT_LE((scene.points[i].position.cast<double>() - com).norm(), 1e-6);
    const Vec3 origin = poses.objects[i].translation();
    EXPECT_LE((scene.arrows[3 * i].from.cast<double>() - origin).norm(), 1e-6);
    const Vec3 x_axis = (scene.arrows[3 * i].to - scene.arrows[3 * i].from).cast<double>();
    EXPECT_NEAR(x_axis.normalized().dot(poses.objects[i].linear().col(0)), 1.0, 1e-6);
  }
  // the body bounds hold the moved bodies only: the box (0.2 m cube turned 30 degrees, half
  // width 0.1 (cos 30 + sin 30) = 0.1366 m) and the ball (radius 0.1 m)
  EXPECT_NEAR(scene.body_bounds.max().x(), 1.0 + 0.1 * (std::cos(M_PI / 6) + 0.5), 1e-6);
  EXPECT_NEAR(scene.body_bounds.max().z(), 3.1, 1e-6);
  EXPECT_NEAR(scene.body_bounds.min().x(), -1.1, 2e-3);
  EXPECT_NEAR(scene.body_bounds.min().z(), 0.6, 2e-3);
}

TEST(WorldPosesTest, PickingAndFramingFollowTheGivenPoses) {
  const test::LoadedWorld loaded = Load(PaddedContactsPath());
  const WorldDesc& world = loaded.world;
  RenderScene scene;
  RenderMeshCache cache;
  ExtractScene(world, MovedBoxAndBall(world), {}, {}, &cache, &scene);
  const Ray down{Vec3(1, 2, 10), -Vec3::UnitZ()};
  const PickHit at_pose = PickBody(scene, down);
  EXPECT_EQ(at_pose.world_id, world.ObjectId(0));
  EXPECT_NEAR(at_pose.point.z(), 3.1, 1e-6);  // the top face of the lifted box
  // where the file puts the box there is only terrain now
  const Vec3 file_position = world.objects[0].pose.translation();
  const Ray at_file{file_position + Vec3(0, 0, 10), -Vec3::UnitZ()};
  EXPECT_EQ(PickBody(scene, at_file).world_id, world.TerrainId(0));
  // "bodies" frames the moved bodies: the target is the centre of their bounds
  OrbitCamera camera;
  std::string error;
  ASSERT_TRUE(CameraForScene("bodies", scene, 4.0 / 3.0, &camera, &error)) << error;
  EXPECT_LE((camera.target - scene.body_bounds.center()).norm(), 1e-9);
  EXPECT_GT(camera.target.z(), 1.5);  // the file's bodies are all below 0.3 m
}

TEST(WorldPosesTest, RobotLinksAreDrawnAtTheForwardKinematicsOfTheGivenConfiguration) {
  const test::LoadedWorld loaded = Load(test::WorldsPath("klampt/athlete_fractal_1.xml"));
  const RobotDesc& robot = loaded.world.robots[0];
  WorldPoses poses = InitialPoses(loaded.world);
  VecX& q = poses.robots[0];
  for (int l = 0; l < robot.dof(); ++l) q[l] += 0.05 * (l % 7) - 0.15;
  RenderScene scene;
  RenderMeshCache cache;
  ExtractScene(loaded.world, poses, {}, {}, &cache, &scene);
  const std::vector<Pose> frames = LinkTransforms(robot, q);
  const std::vector<Pose> file_frames = LinkTransforms(robot, DisplayConfiguration(robot));
  size_t item = 1;  // after the terrain
  double largest_move = 0.0;
  for (int l = 0; l < robot.dof(); ++l) {
    for (const GeometryDesc& geometry : robot.links[l].geometry) {
      if (geometry.empty()) continue;
      ASSERT_LT(item, scene.items.size());
      EXPECT_EQ(scene.items[item].world_id, loaded.world.RobotLinkId(0, l));
      EXPECT_LE(MaxDifference(scene.items[item].transform, Drawn(frames[l], geometry)), 1e-5f)
          << "link " << l;
      largest_move = std::max<double>(largest_move, MaxDifference(scene.items[item].transform,
                                                                  Drawn(file_frames[l], geometry)));
      ++item;
    }
  }
  EXPECT_EQ(item, scene.items.size());
  EXPECT_GT(largest_move, 0.05);  // the configuration drawn is not the file's
}

TEST(WorldPosesTest, MissingOrMisSizedPosesFallBackToTheDescription) {
  const test::LoadedWorld loaded = Load(test::WorldsPath("klampt/block.xml"));
  RenderScene initial, fallback;
  RenderMeshCache cache;
  ExtractScene(loaded.world, InitialPoses(loaded.world), {}, {}, &cache, &initial);
  WorldPoses odd;                                // no object entry ...
  odd.robots.push_back(VecX::Constant(2, 0.5));  // ... and a robot config of the wrong size
  ExtractScene(loaded.world, odd, {}, {}, &cache, &fallback);
  ASSERT_EQ(initial.items.size(), fallback.items.size());
  ASSERT_EQ(initial.items.size(), 3u);  // terrain, robot sphere, block
  for (size_t i = 0; i < initial.items.size(); ++i) {
    EXPECT_EQ(MaxDifference(initial.items[i].transform, fallback.items[i].transform), 0.0f);
  }
}

TEST(WorldPosesTest, InitialPosesAreTheFilesAndCurrentPosesTheSimulations) {
  const test::LoadedWorld loaded = Load(test::WorldsPath("klampt/block.xml"));
  const WorldDesc& world = loaded.world;
  const WorldPoses initial = InitialPoses(world);
  ASSERT_EQ(initial.objects.size(), 1u);
  ASSERT_EQ(initial.robots.size(), 1u);
  EXPECT_TRUE(initial.objects[0].matrix() == world.objects[0].pose.matrix());
  EXPECT_TRUE(initial.robots[0] == world.robots[0].config);  // "3  0 -0.065 0.05"
  Simulator simulator(world);
  simulator.Simulate(0.2);
  const WorldPoses current = CurrentPoses(simulator);
  ASSERT_EQ(current.objects.size(), 1u);
  ASSERT_EQ(current.robots.size(), 1u);
  EXPECT_TRUE(current.objects[0].matrix() == simulator.GetObjectPose(0).matrix());
  EXPECT_TRUE(current.robots[0] == simulator.GetRobotConfig(0));
  // the block fell from 0.11 m onto the terrain
  EXPECT_LT(current.objects[0].translation().z(), 0.11 - 0.05);
}

TEST(WorldPosesTest, DrawnBodyFrameNamesObjectAndLinkFramesOnly) {
  const test::LoadedWorld loaded = Load(test::WorldsPath("klampt/block.xml"));
  const WorldDesc& world = loaded.world;
  WorldPoses poses = InitialPoses(world);
  poses.objects[0] = Pose(Eigen::Translation3d(0.3, -0.2, 0.5));
  poses.robots[0] = Vec3(0.1, 0.2, 0.3);  // three prismatic joints along x, y, z
  const std::optional<Pose> block = DrawnBodyFrame(world, poses, world.ObjectId(0));
  ASSERT_TRUE(block);
  EXPECT_TRUE(block->matrix() == poses.objects[0].matrix());
  const std::optional<Pose> sphere = DrawnBodyFrame(world, poses, world.RobotLinkId(0, 2));
  ASSERT_TRUE(sphere);
  EXPECT_LE((sphere->translation() - Vec3(0.1, 0.2, 0.3)).norm(), 1e-12);
  EXPECT_FALSE(DrawnBodyFrame(world, poses, world.TerrainId(0)));
  EXPECT_FALSE(DrawnBodyFrame(world, poses, world.RobotId(0)));
  EXPECT_FALSE(DrawnBodyFrame(world, poses, world.IdCount()));
  EXPECT_FALSE(DrawnBodyFrame(world, poses, -1));
}

TEST(OverlayOptionsTest, ParsesListsAndNamesUnknownEntries) {
  OverlayOptions options;
  std::string error;
  ASSERT_TRUE(ParseOverlayList("contacts,padding", &options, &error));
  EXPECT_TRUE(options.contacts && options.padding);
  EXPECT_FALSE(options.normals || options.forces || options.com || options.frames || options.bbox);
  EXPECT_FALSE(ParseOverlayList("contacts,shadows", &options, &error));
  EXPECT_NE(error.find("unknown overlay 'shadows'"), std::string::npos) << error;
  OverlayOptions none;
  EXPECT_TRUE(ParseOverlayList("none", &none, &error));
  EXPECT_EQ(none, OverlayOptions());
  EXPECT_NE(error.find("contacts,normals,forces,padding,com,frames,bbox"), std::string::npos);
}

// each toggle's name turns on its own flag and no other; "all" is every toggle and every flag
TEST(OverlayOptionsTest, EveryToggleNamesItsOwnFlag) {
  constexpr int kFlags = 9;  // the bool members of OverlayOptions
  ASSERT_EQ(std::size(core::kOverlayToggles), static_cast<size_t>(kFlags));
  std::string error;
  OverlayOptions all;
  ASSERT_TRUE(ParseOverlayList("all", &all, &error));
  OverlayOptions each;
  for (const core::OverlayToggle& toggle : core::kOverlayToggles) {
    OverlayOptions one;
    ASSERT_TRUE(ParseOverlayList(toggle.name, &one, &error)) << error;
    EXPECT_TRUE(one.*toggle.flag) << toggle.name;
    one.*toggle.flag = false;
    EXPECT_EQ(one, OverlayOptions()) << toggle.name << " turned on another flag";
    EXPECT_FALSE(each.*toggle.flag) << toggle.name << " shares its flag";
    each.*toggle.flag = true;
  }
  EXPECT_EQ(each, all);
  EXPECT_TRUE(all.contacts && all.normals && all.forces && all.padding && all.com && all.frames &&
              all.bbox && all.joints);
}

TEST(RenderMeshTest, CreasesStaySharpAndOffsetsGrow) {
  TriangleMesh box = BakedMesh([] {
    GeometryDesc g;
    g.kind = GeometryKind::kPrimitive;
    g.primitive = Primitive::Box(Vec3(1, 1, 1));
    return g;
  }());
  const RenderMesh mesh = BuildRenderMesh(box);
  ASSERT_EQ(mesh.corner_count(), box.triangle_count() * 3);
  for (const Eigen::Vector3f& n : mesh.normals) {
    EXPECT_NEAR(n.cwiseAbs().maxCoeff(), 1.0f, 1e-6f);  // face normals: axis aligned
  }
  const TriangleMesh grown = OffsetMesh(box, 0.1);
  EXPECT_GT(grown.Bounds().sizes().x(), 1.1);
}

TEST(PointMarkersTest, AnOctahedronPerPointFacingOutward) {
  const TriangleMesh mesh = PointMarkers({Vec3(0, 0, 0), Vec3(1, 2, 3)}, 0.01);
  ASSERT_EQ(mesh.vertex_count(), 12);
  ASSERT_EQ(mesh.triangle_count(), 16);
  EXPECT_TRUE(test::IsClosedAndConsistent(mesh));
  EXPECT_EQ(mesh.Bounds().max(), Vec3(1.01, 2.01, 3.01));
  for (int t = 0; t < 8; ++t) {  // every face normal points away from its point
    const Eigen::Vector3i& f = mesh.triangles[t];
    const Vec3 n = (mesh.vertices[f[1]] - mesh.vertices[f[0]])
                       .cross(mesh.vertices[f[2]] - mesh.vertices[f[0]]);
    EXPECT_GT(n.dot(mesh.vertices[f[0]] + mesh.vertices[f[1]] + mesh.vertices[f[2]]), 0.0);
  }
  // 1016 points over a 0.346 m diagonal: half the spacing, 0.5 * 0.346 / sqrt(1016) = 5.4 mm
  PointCloud cube;
  for (int i = 0; i < 1016; ++i) cube.points.push_back(Vec3(i % 2, (i / 2) % 2, (i / 4) % 2) * 0.2);
  EXPECT_NEAR(PointMarkerRadius(cube), 0.5 * std::sqrt(0.12) / std::sqrt(1016.0), 1e-15);
}

TEST(PointMarkersTest, ColoursGroupExactlyOrBinned) {
  PointCloud cloud;
  for (int i = 0; i < 6; ++i) {
    cloud.points.push_back(Vec3(i, 0, 0));
    cloud.colors.push_back(i % 2 == 0 ? 0xFF0000u : 0x0000FFu);
  }
  std::vector<PointColorGroup> groups = GroupPointsByColor(cloud);
  ASSERT_EQ(groups.size(), 2u);
  EXPECT_EQ(groups[0].color, Rgba(1, 0, 0, 1));
  EXPECT_EQ(groups[1].points, (std::vector<Vec3>{Vec3(1, 0, 0), Vec3(3, 0, 0), Vec3(5, 0, 0)}));
  // 4096 distinct colours: binned to 8 levels a channel, each group its members' mean colour
  cloud = PointCloud();
  for (std::uint32_t i = 0; i < 4096; ++i) {
    cloud.points.push_back(Vec3(i, 0, 0));
    cloud.colors.push_back(((i & 0xF) << 20) | (((i >> 4) & 0xF) << 12) | ((i >> 8) << 4));
  }
  groups = GroupPointsByColor(cloud);
  EXPECT_EQ(groups.size(), 512u);
  // the first bin holds red 0x00 and 0x10, green and blue likewise: means 0x08 / 255
  EXPECT_NEAR(groups[0].color.x(), 8.0f / 255.0f, 1e-6f);
  EXPECT_TRUE(GroupPointsByColor(PointCloud{{Vec3::Zero()}, {}}).empty());
}

TEST(RenderSceneTest, PointCloudsAreDrawnInTheirFilesColours) {
  test::LoadedWorld loaded;
  test::LoadWorld(test::WorldsPath("examples/point_clouds.xml"), &loaded);
  ASSERT_TRUE(loaded.ok) << loaded.diagnostics.FormatAll();
  RenderScene scene;
  RenderMeshCache cache;
  OverlayOptions options;
  options.padding = true;
  ExtractScene(loaded.world, InitialPoses(loaded.world), options, {}, &cache, &scene);
  // the floor, the cube cloud's colour groups (1016 colours: binned), the ball's six bands, the
  // block; then the padding shells of the three bodies (the floor has none)
  int cube_items = 0, ball_items = 0;
  const double cube_marker = PointMarkerRadius(*loaded.world.objects[0].geometry.point_cloud);
  for (const DrawItem& item : scene.items) {
    if (item.has(kDrawTranslucent)) continue;
    ball_items += item.world_id == 2 ? 1 : 0;
    if (item.world_id != 1) continue;
    ++cube_items;
    // each group's bounds are the whole cloud's: the cube's 0.2 m plus its markers
    EXPECT_NEAR(item.mesh->bounds.sizes().x(), 0.2 + 2 * cube_marker, 1e-6);
  }
  EXPECT_GT(cube_items, 6);
  EXPECT_LE(cube_items, 512);
  EXPECT_EQ(ball_items, 6);
  EXPECT_EQ(CountFlag(scene, kDrawTranslucent), 3);
}

}  // namespace
}  // namespace lamina::core
