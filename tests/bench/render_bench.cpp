// SPDX-License-Identifier: MIT
// lamina_render_bench: rendering timings through OSMesa (llvmpipe, software). Frame time of
// athlete_fractal_1.xml at 1280x720 (target <= 33 ms) and the whole `shot` pipeline (load, context,
// renderer, extract, draw, read back, PNG; target <= 1 s). Wall-clock times: llvmpipe renders on
// its own threads, so the main thread's CPU time would understate a frame.
#include <algorithm>
#include <memory>
#include <string>

#include <benchmark/benchmark.h>

#include "core/io/world_file.h"
#include "core/render/scene_camera.h"
#include "core/render/scene_extract.h"
#include "ui/platform/image_file.h"
#include "ui/platform/osmesa_context.h"
#include "ui/render/renderer.h"

namespace lamina::bench {
namespace {

constexpr int kWidth = 1280;
constexpr int kHeight = 720;

std::string AthletePath() {
  return std::string(LAMINA_WORLDS_DIR) + "/klampt/athlete_fractal_1.xml";
}

bool LoadWorld(const std::string& path, core::WorldDesc* world) {
  core::Diagnostics diagnostics;
  core::MeshCache meshes;
  core::LoadContext context{diagnostics, meshes};
  return core::LoadWorldFile(path, context, world) && !diagnostics.HasErrors();
}

// one frame of a running viewer: extract the (unchanged) world at its initial poses, draw, wait
// for the pixels
// state.range(0): samples per pixel (0: one sample smoothed by FXAA), state.range(1): shadow
// map size (0 = no shadows)
void BM_AthleteFrame(benchmark::State& state, const char* camera_spec, bool read_back) {
  ui::OsmesaContext context;
  ui::Renderer renderer;
  renderer.settings().samples = std::max(1, static_cast<int>(state.range(0)));
  renderer.settings().fxaa = state.range(0) == 0;
  renderer.settings().shadows = state.range(1) > 0;
  renderer.settings().shadow_map_size = std::max(1, static_cast<int>(state.range(1)));
  std::string error;
  core::WorldDesc world;
  if (!context.Create(kWidth, kHeight, &error) || !renderer.Initialize(&error) ||
      !LoadWorld(AthletePath(), &world)) {
    state.SkipWithError(error.empty() ? "cannot load the world" : error.c_str());
    return;
  }
  core::RenderMeshCache meshes;
  core::RenderScene scene;
  const core::WorldPoses poses = core::InitialPoses(world);
  core::ExtractScene(world, poses, {}, {}, &meshes, &scene);
  core::OrbitCamera camera;
  core::CameraForScene(camera_spec, scene, double(kWidth) / kHeight, &camera, &error);
  renderer.Render(scene, camera, kWidth, kHeight);  // warm-up: uploads meshes, compiles shaders
  context.SwapOrFinish();
  for (auto _ : state) {
    core::ExtractScene(world, poses, {}, {}, &meshes, &scene);
    renderer.Render(scene, camera, kWidth, kHeight);
    if (read_back) {
      benchmark::DoNotOptimize(renderer.ReadPixels(kWidth, kHeight));
    } else {
      context.SwapOrFinish();
    }
  }
  state.SetLabel(renderer.gl_renderer() + ", " +
                 (renderer.settings().fxaa ? std::string("FXAA")
                                           : std::to_string(renderer.samples_used()) + "x MSAA"));
}
BENCHMARK_CAPTURE(BM_AthleteFrame, world_view, "world", false)
    ->Name("Render/athlete_fractal_1/1280x720/frame")
    ->ArgNames({"msaa", "shadow"})
    ->Args({4, 2048})
    ->Args({0, 2048})
    ->Args({1, 2048})
    ->Args({4, 1024})
    ->Args({1, 1024})
    ->Args({4, 0})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_AthleteFrame, world_view_readback, "world", true)
    ->Name("Render/athlete_fractal_1/1280x720/frame+readback")
    ->ArgNames({"msaa", "shadow"})
    ->Args({4, 2048})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_AthleteFrame, close_up, "bodies", false)
    ->Name("Render/athlete_fractal_1/1280x720/frame_closeup")
    ->ArgNames({"msaa", "shadow"})
    ->Args({4, 2048})
    ->Args({1, 2048})
    ->Args({1, 1024})
    ->Args({4, 0})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// everything `lamina-headless shot` does except process start-up
void BM_AthleteShot(benchmark::State& state) {
  const std::string output = "/tmp/lamina_render_bench_shot.png";
  for (auto _ : state) {
    core::WorldDesc world;
    if (!LoadWorld(AthletePath(), &world)) {
      state.SkipWithError("cannot load the world");
      return;
    }
    ui::OsmesaContext context;
    ui::Renderer renderer;
    std::string error;
    if (!context.Create(kWidth, kHeight, &error) || !renderer.Initialize(&error)) {
      state.SkipWithError(error.c_str());
      return;
    }
    core::RenderMeshCache meshes;
    core::RenderScene scene;
    core::ExtractScene(world, core::InitialPoses(world), {}, {}, &meshes, &scene);
    core::OrbitCamera camera;
    core::CameraForScene("", scene, double(kWidth) / kHeight, &camera, &error);
    renderer.Render(scene, camera, kWidth, kHeight);
    ui::WritePngBottomUp(output, kWidth, kHeight, renderer.ReadPixels(kWidth, kHeight));
  }
}
BENCHMARK(BM_AthleteShot)
    ->Name("Render/athlete_fractal_1/1280x720/shot")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace lamina::bench
