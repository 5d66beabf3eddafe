// SPDX-License-Identifier: MIT
// Golden-image tests: worlds rendered through OSMesa (llvmpipe) at 320x240 compared with the
// references in tests/render/golden/. Tolerance: a pixel differs when a colour channel differs by
// more than 16 levels; a test fails when more than 0.5 % of the pixels differ (software rendering
// is deterministic on one machine; the slack absorbs Mesa/LLVM version differences).
// On failure <name>_actual.png and <name>_diff.png are written to the working directory.
// LAMINA_UPDATE_GOLDEN=1 rewrites the references instead of comparing. One test needs no golden:
// a point cloud is found in the picture where its outline projects.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>

#include <gtest/gtest.h>

#include "core/render/scene_camera.h"
#include "core/render/scene_extract.h"
#include "core/sim/simulator.h"
#include "tests/common/test_support.h"
#include "tests/render/golden_image.h"
#include "ui/platform/osmesa_context.h"
#include "ui/render/renderer.h"

namespace lamina::test {
namespace {

constexpr int kWidth = 320;
constexpr int kHeight = 240;
constexpr int kChannelThreshold = 16;
constexpr double kMaxDifferingFraction = 0.005;

struct GoldenCase {
  std::string name;
  std::string world;  ///< absolute path
  double time = 0.0;  ///< simulated before rendering, s
  std::string overlays;
  std::string camera;  ///< preset or description
  int selected_id = -1;
};

class RenderGoldenTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    context_ = std::make_unique<ui::OsmesaContext>();
    renderer_ = std::make_unique<ui::Renderer>();
    std::string error;
    ASSERT_TRUE(context_->Create(kWidth, kHeight, &error)) << error;
    ASSERT_TRUE(renderer_->Initialize(&error)) << error;
    std::cout << "GL: " << renderer_->gl_version() << " / " << renderer_->gl_renderer() << "\n";
  }
  static void TearDownTestSuite() {
    renderer_.reset();
    context_.reset();
  }

  // loads, simulates and renders a case; RGBA rows top first
  static Image Render(const GoldenCase& c) {
    LoadedWorld loaded;
    LoadWorld(c.world, &loaded);
    EXPECT_TRUE(loaded.ok) << loaded.diagnostics.FormatAll();
    core::OverlayOptions overlays;
    std::string error;
    EXPECT_TRUE(core::ParseOverlayList(c.overlays, &overlays, &error)) << error;
    overlays.selected_id = c.selected_id;
    std::vector<core::ContactMarker> contacts;
    core::WorldPoses poses = core::InitialPoses(loaded.world);
    if (c.time > 0.0) {
      core::Simulator simulator(loaded.world);
      simulator.EnableContactFeedbackAll();
      simulator.Simulate(c.time);
      poses = core::CurrentPoses(simulator);
      contacts = core::ContactMarkersFromSimulator(simulator);
    }
    core::RenderMeshCache meshes;
    core::RenderScene scene;
    core::ExtractScene(loaded.world, poses, overlays, contacts, &meshes, &scene);
    core::OrbitCamera camera;
    EXPECT_TRUE(core::CameraForScene(c.camera, scene, double(kWidth) / kHeight, &camera, &error))
        << error;
    renderer_->Render(scene, camera, kWidth, kHeight);
    context_->SwapOrFinish();
    return FromBottomUp(kWidth, kHeight, renderer_->ReadPixels(kWidth, kHeight));
  }

  // `world` at its initial poses from the camera `description`, no overlays; RGBA rows top first
  static Image RenderWorld(const core::WorldDesc& world, const std::string& description,
                           core::OrbitCamera* camera) {
    core::RenderMeshCache meshes;
    core::RenderScene scene;
    core::ExtractScene(world, core::InitialPoses(world), {}, {}, &meshes, &scene);
    std::string error;
    EXPECT_TRUE(core::CameraForScene(description, scene, double(kWidth) / kHeight, camera, &error))
        << error;
    renderer_->Render(scene, *camera, kWidth, kHeight);
    context_->SwapOrFinish();
    return FromBottomUp(kWidth, kHeight, renderer_->ReadPixels(kWidth, kHeight));
  }

  static void ExpectMatchesGolden(const GoldenCase& c) {
    const Image actual = Render(c);
    const std::string golden = std::string(LAMINA_GOLDEN_DIR) + "/" + c.name + ".png";
    const char* update = std::getenv("LAMINA_UPDATE_GOLDEN");
    if (update != nullptr && std::string(update) == "1") {
      ASSERT_TRUE(WritePng(golden, actual)) << "cannot write " << golden;
      std::cout << "updated " << golden << "\n";
      return;
    }
    Image expected;
    ASSERT_TRUE(ReadPng(golden, &expected))
        << "missing reference " << golden << " (LAMINA_UPDATE_GOLDEN=1 creates it)";
    ASSERT_EQ(expected.width, actual.width);
    ASSERT_EQ(expected.height, actual.height);
    const ImageDifference difference = CompareImages(expected, actual, kChannelThreshold);
    if (difference.differing_fraction <= kMaxDifferingFraction) return;
    const std::string dir = std::filesystem::current_path().string();
    const std::string actual_path = dir + "/" + c.name + "_actual.png";
    const std::string diff_path = dir + "/" + c.name + "_diff.png";
    WritePng(actual_path, actual);
    WritePng(diff_path, difference.diff);
    ADD_FAILURE() << c.name << ": " << difference.differing_pixels << " pixels ("
                  << 100.0 * difference.differing_fraction << " %) differ by more than "
                  << kChannelThreshold << " levels (largest " << difference.max_channel_difference
                  << "), allowed " << 100.0 * kMaxDifferingFraction << " %\n  expected " << golden
                  << "\n  actual   " << actual_path << "\n  diff     " << diff_path;
  }

  static std::unique_ptr<ui::OsmesaContext> context_;
  static std::unique_ptr<ui::Renderer> renderer_;
};

std::unique_ptr<ui::OsmesaContext> RenderGoldenTest::context_;
std::unique_ptr<ui::Renderer> RenderGoldenTest::renderer_;

std::string TestWorld(const std::string& name) {
  return std::string(LAMINA_RENDER_TEST_DATA) + "/" + name;
}

TEST_F(RenderGoldenTest, BoxStack) {
  ExpectMatchesGolden(
      {"stacktest", WorldsPath("klampt/simulation_test_worlds/stacktest.xml"), 0.0, "", ""});
}

TEST_F(RenderGoldenTest, BouncingSpheres) {
  ExpectMatchesGolden(
      {"bounce_test", WorldsPath("klampt/simulation_test_worlds/bounce_test.xml"), 0.0, "", ""});
}

TEST_F(RenderGoldenTest, AthleteOnFractalTerrain) {
  ExpectMatchesGolden({"athlete_fractal", WorldsPath("klampt/athlete_fractal_1.xml"), 0.0, "", ""});
}

TEST_F(RenderGoldenTest, AthleteCloseUpWithFramesAndSelection) {
  // the robot (world id 2 = robot 0) selected, with link frames and centres of mass
  ExpectMatchesGolden({"athlete_closeup", WorldsPath("klampt/athlete_fractal_1.xml"), 0.0,
                       "frames,com", "bodies", 2});
}

TEST_F(RenderGoldenTest, ContactAndPaddingOverlays) {
  ExpectMatchesGolden({"padded_contacts", TestWorld("padded_contacts.xml"), 0.1,
                       "contacts,normals,forces,padding,bbox", "bodies", -1});
}

TEST_F(RenderGoldenTest, SameInputGivesIdenticalPixels) {
  const GoldenCase c{
      "repeat", WorldsPath("klampt/simulation_test_worlds/bounce_test.xml"), 0.0, "frames", "", -1};
  const Image first = Render(c);
  const Image second = Render(c);
  EXPECT_TRUE(first.rgba == second.rgba);
}

TEST_F(RenderGoldenTest, ShotCommandIsByteForByteRepeatable) {
  const std::string dir = ScratchDir();
  const std::string world = WorldsPath("klampt/simulation_test_worlds/stacktest.xml");
  for (const char* name : {"a.png", "b.png"}) {
    const CommandResult result =
        RunHeadless("shot " + world + " --size 160x120 --time 0.05 -o " + dir + "/" + name);
    ASSERT_EQ(result.exit_code, 0) << result.err;
  }
  std::ifstream a(dir + "/a.png", std::ios::binary), b(dir + "/b.png", std::ios::binary);
  const std::string bytes_a((std::istreambuf_iterator<char>(a)), std::istreambuf_iterator<char>());
  const std::string bytes_b((std::istreambuf_iterator<char>(b)), std::istreambuf_iterator<char>());
  EXPECT_GT(bytes_a.size(), 1000u);
  EXPECT_TRUE(bytes_a == bytes_b);
}

// The pixel of world point `p` (column, row from the top) for `camera`.
Eigen::Vector2d PixelOf(const core::OrbitCamera& camera, const core::Vec3& p) {
  const Eigen::Vector4d clip = camera.ProjectionMatrix(double(kWidth) / kHeight, 10.0) *
                               camera.ViewMatrix() * p.homogeneous();
  const Eigen::Vector2d ndc = clip.head<2>() / clip.w();
  return Eigen::Vector2d((ndc.x() + 1.0) / 2.0 * kWidth, (1.0 - ndc.y()) / 2.0 * kHeight);
}

// Golden-free: the 800-point ball of worlds/examples/point_clouds.xml (0.1 m, six colour bands)
// drawn by the GL renderer as it draws any mesh. Within 0.8 of the ball's projected radius most
// pixels differ from the picture without the ball, and its green and blue bands show.
TEST_F(RenderGoldenTest, PointCloudIsDrawnWhereItIsInItsColours) {
  LoadedWorld loaded;
  LoadWorld(WorldsPath("examples/point_clouds.xml"), &loaded);
  ASSERT_TRUE(loaded.ok) << loaded.diagnostics.FormatAll();
  core::WorldDesc without = loaded.world;
  without.objects.erase(without.objects.begin() + 1);  // the ball
  const std::string view = "target=0.35,0,0.3;yaw=20;pitch=15;dist=1;fov=45";
  core::OrbitCamera camera;
  const Image with_ball = RenderWorld(loaded.world, view, &camera);
  const Image no_ball = RenderWorld(without, view, &camera);
  const Eigen::Vector2d centre = PixelOf(camera, core::Vec3(0.35, 0, 0.3));
  const double radius = (PixelOf(camera, core::Vec3(0.35, 0, 0.4)) - centre).norm();
  EXPECT_GT(radius, 20.0);  // 0.1 m at 1 m with a 45 degree field of view: about 29 px
  int inside = 0, differ = 0, green = 0, blue = 0;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      if ((Eigen::Vector2d(x + 0.5, y + 0.5) - centre).norm() > 0.8 * radius) continue;
      const std::uint8_t* a = &with_ball.rgba[4 * (y * kWidth + x)];
      const std::uint8_t* b = &no_ball.rgba[4 * (y * kWidth + x)];
      ++inside;
      if (std::abs(a[0] - b[0]) <= kChannelThreshold &&
          std::abs(a[1] - b[1]) <= kChannelThreshold &&
          std::abs(a[2] - b[2]) <= kChannelThreshold) {
        continue;  // the same pixel as without the ball: a gap between its points
      }
      ++differ;
      green += (a[1] > a[0] + 20 && a[1] > a[2] + 20);
      blue += (a[2] > a[0] + 20 && a[2] > a[1] + 20);
    }
  }
  ASSERT_GT(inside, 1000);
  EXPECT_GT(differ, inside / 2) << differ << " of " << inside << " pixels differ";
  EXPECT_GT(green, 10);
  EXPECT_GT(blue, 10);
}

}  // namespace
}  // namespace lamina::test
