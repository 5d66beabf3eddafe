// SPDX-License-Identifier: MIT
// `lamina-headless shot WORLD -o out.png [--time T] [--size WxH] [--camera SPEC] [--overlay LIST]`
#include <chrono>
#include <iostream>
#include <memory>

#include "app/headless_render.h"
#include "app/headless_render_commands.h"
#include "core/render/camera.h"
#include "core/render/overlay_options.h"
#include "core/sim/simulator.h"
#include "ui/platform/image_file.h"

namespace lamina::app {

namespace {

struct ShotOptions {
  std::string world;
  std::string output;
  double time = 0.0;
  std::string size = "1280x720";
  std::string camera;
  std::string overlay;
  int samples = 4;
};

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

int RunShot(const ShotOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  ViewOptions view;
  std::string error;
  if (!core::ParseViewOptions(options.size, options.camera, options.overlay, &view, &error)) {
    std::cerr << "lamina-headless shot: " << error << "\n";
    return 2;
  }
  view.samples = options.samples;
  core::WorldDesc world;
  if (!LoadWorldForRendering(options.world, &world)) {
    std::cerr << "lamina-headless shot: cannot load world '" << options.world << "'\n";
    return 1;
  }
  std::unique_ptr<core::Simulator> simulator;
  const bool needs_contacts =
      view.overlays.contacts || view.overlays.normals || view.overlays.forces;
  if (options.time > 0.0 || needs_contacts) {
    simulator = MakeRenderSimulator(world);
    if (options.time > 0.0) simulator->Simulate(options.time);
  }
  // the simulation's state when there is one, else the file's initial conditions
  const core::WorldPoses poses =
      simulator ? core::CurrentPoses(*simulator) : core::InitialPoses(world);
  OffscreenView renderer;
  if (!renderer.Open(view, &error)) {
    std::cerr << "lamina-headless shot: " << error << "\n";
    return 1;
  }
  const std::vector<std::uint8_t> pixels = renderer.Render(world, poses, simulator.get());
  if (!ui::WritePngBottomUp(options.output, view.width, view.height, pixels)) {
    std::cerr << "lamina-headless shot: cannot write " << options.output << "\n";
    return 1;
  }
  std::cout << "wrote " << options.output << " (" << view.width << "x" << view.height
            << ", t=" << (simulator ? simulator->time() : 0.0) << " s, camera "
            << core::FormatCamera(renderer.camera()) << ", " << SecondsSince(start) << " s)\n";
  return 0;
}

}  // namespace

Subcommand AddShotCommand(CLI::App& app) {
  auto options = std::make_shared<ShotOptions>();
  CLI::App* shot = app.add_subcommand("shot", "render a world to a PNG (off screen, OSMesa)");
  shot->add_option("world", options->world, "world file")->required();
  shot->add_option("-o,--output", options->output, "PNG file to write")->required();
  shot->add_option("--time", options->time, "simulate this long first, s (default 0)")
      ->check(CLI::NonNegativeNumber);
  shot->add_option("--size", options->size, "image size WIDTHxHEIGHT (default 1280x720)");
  shot->add_option("--camera", options->camera,
                   "world (default), bodies, or 'target=x,y,z;yaw=deg;pitch=deg;dist=m;fov=deg'");
  shot->add_option("--overlay", options->overlay,
                   "comma list of " + core::OverlayNames() + " (or all)");
  shot->add_option("--msaa", options->samples,
                   "antialiasing samples per pixel: 1 (off) or 4 (default)")
      ->check(CLI::IsMember({1, 4}));
  return {shot, [options] { return RunShot(*options); }};
}

}  // namespace lamina::app
