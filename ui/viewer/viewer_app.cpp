// SPDX-License-Identifier: MIT
// The viewer loop. Each frame: input -> panels -> requests -> physics (whole fixed steps for the
// wall time that passed, times the speed, capped) -> scene extraction -> 3D view -> panels drawn
// over it -> screenshot -> swap. The 3D view uses the same extraction, camera choice and renderer
// as `lamina-headless shot`, so the two give the same picture.
#include "ui/viewer/viewer_app.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <vector>

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <imgui.h>

#include "core/render/contact_markers.h"
#include "core/render/picking.h"
#include "core/render/scene_camera.h"
#include "core/render/scene_extract.h"
#include "ui/panels/panels.h"
#include "ui/platform/glfw_window.h"
#include "ui/platform/image_file.h"
#include "ui/render/renderer.h"
#include "ui/viewer/sim_clock.h"
#include "ui/viewer/viewer_input.h"
#include "ui/viewer/world_files.h"
#include "ui/viewer/world_session.h"

namespace lamina::ui {

namespace {

// Mesa's software rasterizers, where multisampling costs more than the rest of a frame
bool IsSoftwareRenderer(const std::string& gl_renderer) {
  for (const char* name : {"llvmpipe", "softpipe", "swrast"}) {
    if (gl_renderer.find(name) != std::string::npos) return true;
  }
  return false;
}

using Clock = std::chrono::steady_clock;

constexpr int kBenchWarmupFrames = 5;
constexpr double kFrameStepSeconds = 1.0 / 60.0;
// physics stops for the frame after this much wall time, checked every few steps
constexpr double kPhysicsBudgetMilliseconds = 30.0;
constexpr int kStepsPerChunk = 2;

double MillisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

double Median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const size_t middle = values.size() / 2;
  return values.size() % 2 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
}

// every .xml file under `directory`, sorted
// the hovered body drawn a little lighter
void HighlightHovered(int hovered_id, core::RenderScene* scene) {
  if (hovered_id < 0) return;
  for (core::DrawItem& item : scene->items) {
    if (item.world_id != hovered_id || item.has(core::kDrawUnlit)) continue;
    item.color.head<3>() = item.color.head<3>() * 0.7f + Eigen::Vector3f::Constant(0.3f);
  }
}

// a name that is not taken yet: lamina-screenshot-<n>.png in the working directory
std::string NextScreenshotName(int* counter) {
  std::string name;
  do {
    name = "lamina-screenshot-" + std::to_string(++*counter) + ".png";
  } while (std::filesystem::exists(name));
  return name;
}

struct FrameTimes {
  std::vector<double> render, frame, physics;
};

class Viewer {
 public:
  explicit Viewer(const ViewerOptions& options) : options_(options) {}
  int Run();

 private:
  bool Start();
  void RunFrame(double wall_seconds);
  void ApplyRequests();
  void OpenWorld(const std::string& path, const std::vector<std::string>& sets = {});
  double AdvanceSimulation(double wall_seconds);
  void DrawView(int width, int height);
  void HandleMouse(int width, int height);
  bool SaveScreenshot(const std::string& path);
  void PrintBenchmark() const;

  ViewerOptions options_;
  GlfwWindow window_;
  Renderer renderer_;
  WorldSession session_;
  ViewerState state_;
  ViewMouse mouse_;
  FixedStepClock clock_;
  RealTimeFactorMeter meter_;
  core::RenderMeshCache meshes_;
  core::RenderScene scene_;
  core::OrbitCamera camera_;
  bool camera_chosen_ = false;
  bool mouse_moved_ = false;
  bool first_world_failed_ = false;
  int screenshot_counter_ = 0;
  FrameTimes times_;
  double last_render_ms_ = 0.0, last_physics_ms_ = 0.0;
};

bool Viewer::Start() {
  std::string error;
  if (!window_.Open("Lamina", options_.width, options_.height, &error)) {
    std::cerr << "lamina: cannot open a window: " << error << "\n";
    return false;
  }
  window_.SetVsync(options_.bench_frames == 0);
  renderer_.settings().samples = options_.samples > 0 ? options_.samples : 4;
  renderer_.settings().fxaa = options_.fxaa;
  if (!renderer_.Initialize(&error)) {
    std::cerr << "lamina: cannot start the renderer: " << error << "\n";
    return false;
  }
  if (options_.samples == 0 && !options_.fxaa && IsSoftwareRenderer(renderer_.gl_renderer())) {
    renderer_.settings().samples = 1;
    renderer_.settings().fxaa = true;
  }
  state_.overlays = options_.overlays;
  state_.show_panels = options_.show_panels;
  state_.playing = !options_.paused;
  state_.sleep = options_.sleep;
  state_.world_files = WorldFilesUnder(options_.worlds_dir);
  state_.worlds_dir = options_.worlds_dir;
  OpenWorld(options_.world_path, options_.sets);
  first_world_failed_ = !session_.loaded();
  if (session_.loaded() && options_.selected_id < session_.description().IdCount()) {
    state_.selected_id = options_.selected_id;
  }
  session_.AdvanceTime(options_.start_time);
  return true;
}

void Viewer::OpenWorld(const std::string& path, const std::vector<std::string>& sets) {
  const bool ok = session_.Load(path, sets);
  std::cerr << session_.load_messages().FormatAll();
  if (!ok) {
    state_.message = "cannot open " + path;
    state_.expand_open_panel = true;
    std::cerr << "lamina: " << state_.message << "\n";
    return;
  }
  window_.SetTitle("Lamina - " + session_.description().name);
  // the panel shows the world's solver and sleeping (--sleep turns sleeping on for every world)
  state_.solver = session_.simulator()->solver().type;
  if (options_.sleep) session_.SetSleeping(true);
  state_.sleep = session_.simulator()->sleeping();
  state_.open_path_input = path;
  state_.selected_id = state_.hovered_id = -1;
  state_.message = "opened " + session_.path();
  camera_chosen_ = false;
  clock_.Clear();
  meter_.Clear();
}

void Viewer::ApplyRequests() {
  ViewerRequests& requests = state_.requests;
  for (const std::string& path : window_.TakeDroppedPaths()) requests.open_path = path;
  if (!requests.open_path.empty()) OpenWorld(requests.open_path);
  if (requests.reset) {
    session_.Reset();
    clock_.Clear();
    meter_.Clear();
  }
  if (requests.reframe) camera_chosen_ = false;
  const core::Simulator* simulator = session_.simulator();
  if (simulator && simulator->solver().type != state_.solver) session_.SetSolver(state_.solver);
  if (simulator && simulator->sleeping() != state_.sleep) session_.SetSleeping(state_.sleep);
  if (requests.step) session_.Advance(1);
  if (requests.step_frame && simulator) {
    session_.Advance(std::max(1, static_cast<int>(kFrameStepSeconds / simulator->sim_step())));
  }
  const bool screenshot = requests.screenshot;
  requests = ViewerRequests();
  requests.screenshot = screenshot;  // taken after the frame is drawn
}

double Viewer::AdvanceSimulation(double wall_seconds) {
  const core::Simulator* simulator = session_.simulator();
  if (!state_.playing || !simulator) {
    clock_.Clear();
    return 0.0;
  }
  const int steps = clock_.StepsForFrame(wall_seconds, state_.speed, simulator->sim_step());
  // in chunks, stopping at the wall-time budget so that the panels stay responsive when the
  // physics is slower than real time (the simulation then runs slower, shown by the factor)
  const auto start = Clock::now();
  double simulated = 0.0;
  for (int done = 0; done < steps;) {
    const int chunk = std::min(steps - done, kStepsPerChunk);
    simulated += session_.Advance(chunk);
    done += chunk;
    if (done < steps && MillisecondsSince(start) > kPhysicsBudgetMilliseconds) {
      clock_.Clear();
      break;
    }
  }
  return simulated;
}

void Viewer::DrawView(int width, int height) {
  const auto start = Clock::now();
  core::OverlayOptions overlays = state_.overlays;
  overlays.selected_id = state_.selected_id;
  const core::Simulator* simulator = session_.simulator();
  const std::vector<core::ContactMarker> contacts =
      simulator ? core::ContactMarkersFromSimulator(*simulator)
                : std::vector<core::ContactMarker>();
  core::ExtractScene(session_.description(), session_.poses(), overlays, contacts, &meshes_,
                     &scene_);
  HighlightHovered(state_.hovered_id, &scene_);
  if (!camera_chosen_) {
    std::string error;
    if (!core::CameraForScene(options_.camera, scene_, static_cast<double>(width) / height,
                              &camera_, &error)) {
      state_.message = error;
    }
    camera_chosen_ = true;
  }
  renderer_.Render(scene_, camera_, width, height, 0);
  if (options_.bench_frames > 0) glFinish();  // so that the render time is the GPU's too
  last_render_ms_ = MillisecondsSince(start);
}

void Viewer::HandleMouse(int width, int height) {
  const ViewMouseEvent event = mouse_.Update(height, &camera_);
  if (!event.over_view || event.dragging || !session_.loaded()) {
    if (!event.over_view) state_.hovered_id = -1;
    return;
  }
  // hovering starts with the first motion (a pointer resting on a fresh window, as under Xvfb,
  // must not change the picture) and skips terrains, which would light up the whole ground
  mouse_moved_ |= event.moved;
  const core::Ray ray = core::PixelRay(camera_, width, height, event.x, event.y);
  if (mouse_moved_) {
    core::PickFilter bodies_only;
    bodies_only.terrains = false;
    state_.hovered_id = core::PickBody(scene_, ray, bodies_only).world_id;
  }
  if (!event.clicked && !event.double_clicked) return;
  const core::PickHit hit = core::PickBody(scene_, ray);
  if (event.clicked) state_.selected_id = hit.world_id;
  if (event.double_clicked && hit.hit()) camera_.target = hit.point;  // orbit about that point
}

bool Viewer::SaveScreenshot(const std::string& path) {
  int width = 0, height = 0;
  const std::vector<std::uint8_t> pixels = window_.ReadPixels(&width, &height);
  if (!WritePngBottomUp(path, width, height, pixels)) {
    std::cerr << "lamina: cannot write " << path << "\n";
    state_.message = "cannot write " + path;
    return false;
  }
  state_.message = "wrote " + path;
  std::cout << "wrote " << path << " (" << width << "x" << height
            << ", t=" << (session_.simulator() ? session_.simulator()->time() : 0.0)
            << " s, camera " << core::FormatCamera(camera_) << ")\n";
  return true;
}

void Viewer::RunFrame(double wall_seconds) {
  window_.BeginFrame();
  int width = 0, height = 0;
  window_.FramebufferSize(&width, &height);
  HandleShortcuts(&state_);
  if (width > 0 && height > 0) HandleMouse(width, height);
  if (state_.show_panels) {
    DrawSimulationPanel(session_, &state_);
    DrawOverlaysPanel(&state_);
    DrawWorldPanel(session_, &state_);
    DrawOpenWorldPanel(&state_);
    DrawStatusLine(session_, state_);
  }
  ApplyRequests();
  const auto physics_start = Clock::now();
  const double simulated = AdvanceSimulation(wall_seconds);
  last_physics_ms_ = MillisecondsSince(physics_start);
  meter_.AddFrame(wall_seconds, simulated);
  state_.real_time_factor = meter_.factor();
  if (width > 0 && height > 0) DrawView(width, height);
  window_.DrawImGui();
}

void Viewer::PrintBenchmark() const {
  std::printf(
      "frames %zu at %dx%d, %d samples%s: median render %.2f ms, physics %.2f ms, "
      "frame (physics + render + panels + swap) %.2f ms, real-time factor %.2f\n",
      times_.frame.size(), options_.width, options_.height, renderer_.samples_used(),
      renderer_.settings().fxaa ? " + FXAA" : "", Median(times_.render), Median(times_.physics),
      Median(times_.frame), meter_.factor());
}

int Viewer::Run() {
  if (!Start()) return 1;
  const int frames =
      options_.bench_frames > 0 ? options_.bench_frames + kBenchWarmupFrames : options_.frames;
  auto previous = Clock::now();
  bool screenshot_failed = false;
  for (int frame = 0; !window_.ShouldClose() && (frames == 0 || frame < frames); ++frame) {
    const auto start = Clock::now();
    const double wall_seconds = frame == 0 ? 0.0 : MillisecondsSince(previous) / 1000.0;
    previous = start;
    RunFrame(wall_seconds);
    const bool last = frames > 0 && frame + 1 == frames;
    if (state_.requests.screenshot) {
      const std::string name = options_.screenshot.empty()
                                   ? NextScreenshotName(&screenshot_counter_)
                                   : options_.screenshot;
      SaveScreenshot(name);
      state_.requests.screenshot = false;
    }
    if (last && !options_.screenshot.empty())
      screenshot_failed = !SaveScreenshot(options_.screenshot);
    window_.Swap();
    state_.frame_milliseconds = MillisecondsSince(start);
    if (options_.bench_frames > 0 && frame >= kBenchWarmupFrames) {
      times_.render.push_back(last_render_ms_);
      times_.physics.push_back(last_physics_ms_);
      times_.frame.push_back(state_.frame_milliseconds);
    }
  }
  if (options_.bench_frames > 0) PrintBenchmark();
  return (first_world_failed_ || screenshot_failed) ? 1 : 0;
}

}  // namespace

int RunViewer(const ViewerOptions& options) {
  Viewer viewer(options);
  return viewer.Run();
}

}  // namespace lamina::ui
