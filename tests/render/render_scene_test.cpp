// SPDX-License-Identifier: MIT
// Scene extraction without any GL: draw items per world, colours from display attributes and
// defaults, mesh caching across frames, overlays and the overlay list parser.
#include <gtest/gtest.h>

#include "core/render/display_color.h"
#include "core/render/overlay_options.h"
#include "core/render/scene_extract.h"
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
  ExtractScene(loaded.world, options, contacts, cache, scene);
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
  ExtractScene(loaded.world, {}, {}, &cache, &first);
  const int cached = cache.size();
  ExtractScene(loaded.world, {}, {}, &cache, &second);
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

}  // namespace
}  // namespace lamina::core
