// SPDX-License-Identifier: MIT
// lamina: the desktop viewer/editor. Argument parsing and wiring only; the window, the loop and
// the panels live in ui/viewer and ui/panels.
#include <filesystem>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "app/worlds_dir.h"
#include "core/render/view_options.h"
#include "ui/viewer/viewer_app.h"

namespace {

// checks --size, --camera and --overlay into `options`; false with a message naming the option
bool CheckViewOptions(const std::string& size, const std::string& overlay,
                      lamina::ui::ViewerOptions* options, std::string* error) {
  lamina::core::ViewOptions view;
  if (!lamina::core::ParseViewOptions(size, options->camera, overlay, &view, error)) return false;
  options->width = view.width;
  options->height = view.height;
  options->overlays = view.overlays;
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"lamina: the Lamina world viewer and editor"};
  lamina::ui::ViewerOptions options;
  options.worlds_dir = lamina::app::WorldsDir();
  options.world_path = options.worlds_dir + "/" + LAMINA_DEFAULT_WORLD;
  std::string size = "1280x720", overlay;
  bool no_ui = false;
  app.add_option("world", options.world_path, "world file to open")->capture_default_str();
  app.add_option("--worlds", options.worlds_dir, "folder the Open world panel lists")
      ->check(CLI::ExistingDirectory)
      ->capture_default_str();
  app.add_option("--frames", options.frames, "quit after this many frames (0 = run until closed)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--screenshot", options.screenshot,
                 "PNG written after the last frame (with --frames) and by F12/P");
  app.add_option("--time", options.start_time, "simulate this long before the first frame, s")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--camera", options.camera,
                 "world (default), bodies, or 'target=x,y,z;yaw=deg;pitch=deg;dist=m;fov=deg'");
  app.add_option("--overlay", overlay,
                 "comma list of " + lamina::core::OverlayNames() + " (or all)");
  app.add_option("--size", size, "window size WIDTHxHEIGHT (default 1280x720)");
  app.add_flag("--no-ui", no_ui, "hide the panels (H toggles them)");
  app.add_option("--select", options.selected_id, "world id of the body to select at start")
      ->check(CLI::NonNegativeNumber);
  app.add_flag("--paused", options.paused, "start paused (Space plays)");
  app.add_flag("--sleep", options.sleep,
               "let idle objects sleep (a toggle in the Simulation panel)");
  app.add_option("--msaa", options.samples,
                 "antialiasing samples per pixel: 1, 2 or 4 (default: 4 on a GPU, 1 on "
                 "software GL)")
      ->check(CLI::IsMember({1, 2, 4}));
  app.add_flag("--fxaa", options.fxaa,
               "FXAA instead of multisampling (about 20 ms a frame at 1280x720 on software GL)");
  app.add_option("--set", options.sets,
                 "PATH=VALUE: set what an access path names in the world before it opens, e.g. "
                 "'objects[box].kFriction=0.1' (repeatable; docs/access-paths.md)")
      ->allow_extra_args(false);
  app.add_option("--bench-frames", options.bench_frames,
                 "time this many frames (vsync off) and print the median frame times")
      ->check(CLI::NonNegativeNumber);
  app.add_flag("--lockstep", options.lockstep,
               "physics on the window's thread, exactly 1/60 s of simulated time per frame "
               "(reproducible runs for scripted tests; default: its own thread, real time)");
  std::string panels;
  app.add_option("--panels", panels,
                 "the panels shown at start, e.g. 'inspector,plots' (or all, none): simulation, "
                 "world, inspector, robot, settings, plots, overlays, help, open");
  bool no_solver_choice = false;
  app.add_flag("--no-solver-choice", no_solver_choice,
               "always run the world's own solver, even when the exact one cannot keep real "
               "time (default: the Newton solver in its place then, QuickStep in a world with "
               "robots, and the Simulation panel says so)");
  app.add_option("--trace", options.trace_path,
                 "write one JSON line per frame (selection, drag, positions) to this file");
  CLI11_PARSE(app, argc, argv);

  std::string error;
  if (!CheckViewOptions(size, overlay, &options, &error)) {
    std::cerr << "lamina: " << error << "\n";
    return 2;
  }
  options.show_panels = !no_ui;
  options.solver_choice = !no_solver_choice;
  if (!panels.empty()) {
    lamina::ui::PanelVisibility shown;
    if (!lamina::ui::ParsePanelList(panels, &shown, &error)) {
      std::cerr << "lamina: " << error << "\n";
      return 2;
    }
    options.panels = shown;
  }
  return lamina::ui::RunViewer(options);
}
