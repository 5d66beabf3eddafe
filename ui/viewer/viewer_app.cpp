// SPDX-License-Identifier: MIT
// The editor loop. Each frame: the latest physics frame -> input (keys, mouse tools, camera) ->
// panels (edits posted to the physics) -> requests -> (lockstep only: the frame's physics steps)
// -> scene extraction -> 3D view -> tool overlay and panels drawn over it -> screenshot -> swap.
// The physics runs on its own thread (LiveSession) unless --lockstep. The 3D view uses the same
// extraction, camera choice and renderer as `lamina-headless shot`, so the two give the same
// picture.
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
#include "core/render/sensor_overlay.h"
#include "ui/panels/panels.h"
#include "ui/panels/plots_panel.h"
#include "ui/panels/sensors_panel.h"
#include "ui/platform/glfw_window.h"
#include "ui/platform/image_file.h"
#include "ui/render/renderer.h"
#include "ui/viewer/editor_actions.h"
#include "ui/viewer/frame_trace.h"
#include "ui/viewer/live_session.h"
#include "ui/viewer/mouse_tools.h"
#include "ui/viewer/viewer_input.h"
#include "ui/viewer/world_files.h"
#include "ui/widgets/item_registry.h"

namespace lamina::ui {

namespace {

using Clock = std::chrono::steady_clock;

constexpr int kBenchWarmupFrames = 5;
constexpr double kFrameStepSeconds = 1.0 / 60.0;

double MillisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

double Median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const size_t middle = values.size() / 2;
  return values.size() % 2 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
}

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
  std::vector<double> render, frame;
};

class Viewer {
 public:
  explicit Viewer(const ViewerOptions& options)
      : options_(options), session_(!options.lockstep), actions_(&session_) {}
  int Run();

 private:
  bool Start();
  void RunFrame();
  void DrawPanels();
  void ApplyRequests();
  void ApplyFileRequests();
  void OpenWorld(const std::string& path, const std::vector<std::string>& sets = {});
  void AskOrDo(PendingConfirmation::Action action, const std::string& path = "");
  void DrawView(int width, int height);
  void HandleMouse(int width, int height);
  void UpdateTitle();
  bool SaveScreenshot(const std::string& path);
  void PrintBenchmark() const;

  ViewerOptions options_;
  GlfwWindow window_;
  Renderer renderer_;
  LiveSession session_;
  EditorActions actions_;
  MouseTools tools_;
  PlotPanel plots_;
  SensorPanel sensor_panel_;
  std::shared_ptr<const SessionFrame> frame_ = std::make_shared<SessionFrame>();
  ViewerState state_;
  ViewMouse mouse_;
  core::RenderMeshCache meshes_;
  core::RenderScene scene_;
  core::OrbitCamera camera_;
  FrameTrace trace_;
  std::string title_;
  bool camera_chosen_ = false;
  bool mouse_moved_ = false;
  bool first_world_failed_ = false;
  bool quitting_ = false;
  int screenshot_counter_ = 0;
  FrameTimes times_;
  double last_render_ms_ = 0.0;
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
    renderer_.settings().shadow_map_size = kSoftwareShadowMapSize;
  }
  if (!options_.trace_path.empty() && !trace_.Open(options_.trace_path, &error)) {
    std::cerr << "lamina: " << error << "\n";
    return false;
  }
  state_.overlays = options_.overlays;
  state_.show_panels = options_.show_panels;
  if (options_.panels) state_.panels = *options_.panels;
  state_.playing = !options_.paused;
  state_.world_files = WorldFilesUnder(options_.worlds_dir);
  state_.worlds_dir = options_.worlds_dir;
  session_.SetPlaying(false);  // --time first, then play as asked
  session_.SetAutoSolver(options_.solver_choice);
  std::vector<std::string> sets = options_.sets;
  if (options_.sleep) sets.emplace_back("settings.sleeping=true");
  OpenWorld(options_.world_path, sets);
  first_world_failed_ = !frame_->loaded;
  if (frame_->loaded && options_.selected_id < frame_->world->IdCount()) {
    state_.selected_id = options_.selected_id;
  }
  if (options_.start_time > 0.0) {
    const double seconds = options_.start_time;
    session_.Post([seconds](core::LiveWorld& world) {
      world.simulator().Simulate(seconds);
      return std::string();
    });
  }
  session_.Flush();
  session_.SetPlaying(state_.playing);
  frame_ = session_.frame();
  return true;
}

void Viewer::OpenWorld(const std::string& path, const std::vector<std::string>& sets) {
  core::Diagnostics diagnostics;
  const bool ok = session_.Load(path, sets, diagnostics);
  std::cerr << diagnostics.FormatAll();
  state_.load_messages = diagnostics.FormatAll();
  state_.load_failed = !ok;
  if (!ok) {
    state_.message = "cannot open " + path;
    state_.panels.open = true;
    std::cerr << "lamina: " << state_.message << "\n";
    return;
  }
  frame_ = session_.frame();
  state_.open_path_input = path;
  state_.selected_id = state_.hovered_id = -1;
  state_.joint_targets.clear();
  state_.message = "opened " + frame_->path;
  camera_chosen_ = false;
}

// quitting, opening or reverting with unsaved edits asks first (dialogs.cpp)
void Viewer::AskOrDo(PendingConfirmation::Action action, const std::string& path) {
  if (frame_->dirty) {
    state_.confirm = {action, path};
    return;
  }
  switch (action) {
    case PendingConfirmation::Action::kQuit:
      quitting_ = true;
      window_.SetShouldClose(true);
      break;
    case PendingConfirmation::Action::kOpen:
      OpenWorld(path);
      break;
    case PendingConfirmation::Action::kRevert:
      OpenWorld(frame_->path);
      break;
    case PendingConfirmation::Action::kNone:
      break;
  }
}

void Viewer::ApplyFileRequests() {
  ViewerRequests& requests = state_.requests;
  using Action = PendingConfirmation::Action;
  for (const std::string& path : window_.TakeDroppedPaths()) requests.open_path = path;
  if (!requests.open_path.empty()) AskOrDo(Action::kOpen, requests.open_path);
  if (requests.revert && !frame_->path.empty()) AskOrDo(Action::kRevert);
  if (requests.quit) AskOrDo(Action::kQuit);
  if (!requests.open_confirmed.empty()) OpenWorld(requests.open_confirmed);
  if (requests.revert_confirmed) OpenWorld(frame_->path);
  if (requests.quit_confirmed) {
    quitting_ = true;
    window_.SetShouldClose(true);
  }
  if (requests.save && !actions_.Save(*frame_)) state_.requests.save_as = true;
}

void Viewer::ApplyRequests() {
  ApplyFileRequests();
  ViewerRequests& requests = state_.requests;
  if (requests.reset) actions_.Reset();
  if (requests.reframe) camera_chosen_ = false;
  if (requests.undo) actions_.Undo();
  if (requests.redo) actions_.Redo();
  if (requests.step) actions_.Step(1);
  if (requests.step_frame && frame_->step > 0.0) {
    actions_.Step(std::max(1, static_cast<int>(std::lround(kFrameStepSeconds / frame_->step))));
  }
  ViewerRequests kept;
  kept.screenshot = requests.screenshot;  // taken after the frame is drawn
  kept.save_as = requests.save_as;        // the dialog opens on the next frame
  requests = kept;
}

void Viewer::DrawView(int width, int height) {
  const auto start = Clock::now();
  core::OverlayOptions overlays = state_.overlays;
  overlays.selected_id = state_.selected_id;
  if (frame_->loaded) {
    core::ExtractScene(*frame_->world, frame_->poses, overlays, frame_->contacts, &meshes_,
                       &scene_);
    for (const RobotFrame& robot : frame_->robots) {
      if (overlays.sensors) core::AddSensorOverlay(robot.sensor_drawing, overlays, &scene_);
    }
  } else {
    scene_ = core::RenderScene();
  }
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
  const ToolInput input{event, scene_, camera_, width, height, *frame_, &state_, &actions_};
  if (event.pressed != core::MouseButton::kNone && tools_.Press(input)) mouse_.TakeDrag();
  if (tools_.active()) {
    tools_.Move(input);
    if (event.released) tools_.Release(input);
    return;
  }
  if (!event.over_view || event.dragging || !frame_->loaded) {
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

void Viewer::UpdateTitle() {
  std::string title = "Lamina";
  if (frame_->loaded) title += " - " + frame_->world->name + (frame_->dirty ? " *" : "");
  if (title != title_) window_.SetTitle(title);
  title_ = title;
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
  std::cout << "wrote " << path << " (" << width << "x" << height << ", t=" << frame_->time
            << " s, camera " << core::FormatCamera(camera_) << ")\n";
  return true;
}

void Viewer::DrawPanels() {
  const PanelContext context{*frame_, frame_->file_world.get(), &state_, &actions_};
  if (state_.show_panels) {
    DrawMainMenu(context);
    const PanelVisibility& panels = state_.panels;
    if (panels.simulation) DrawSimulationPanel(context);
    if (panels.world_tree) DrawWorldTree(context);
    if (panels.inspector) DrawInspector(context);
    if (panels.robot) DrawRobotPanel(context);
    if (panels.settings) DrawSettingsPanel(context);
    if (panels.plots) plots_.Draw(context);
    if (panels.sensors) sensor_panel_.Draw(context);
    if (panels.overlays) DrawOverlaysPanel(&state_);
    if (panels.open) DrawOpenWorldPanel(&state_);
    DrawStatusLine(context);
  }
  if (state_.panels.help) DrawHelpWindow(&state_);
  DrawDialogs(context);
}

void Viewer::RunFrame() {
  window_.BeginFrame();
  frame_ = session_.frame();
  actions_.Forget(*frame_);
  for (const std::string& message : session_.TakeMessages()) {
    std::cout << "lamina: " << message << "\n";
    state_.message = message;
  }
  state_.playing = session_.playing();
  const bool was_playing = state_.playing;
  int width = 0, height = 0;
  window_.FramebufferSize(&width, &height);
  HandleShortcuts(&state_);
  if (width > 0 && height > 0) HandleMouse(width, height);
  ClearRecordedItems();
  DrawPanels();
  actions_.EndIdleWidgetGroups(ImGui::IsAnyItemActive());
  ApplyRequests();
  if (state_.playing != was_playing) session_.SetPlaying(state_.playing);
  session_.SetSpeed(state_.speed);
  session_.SetSampledBody(state_.selected_id);
  if (!session_.threaded()) session_.Advance(kFrameStepSeconds);
  frame_ = session_.frame();
  const std::vector<SessionSample> samples = session_.TakeSamples();
  plots_.Add(samples, *frame_);
  sensor_panel_.Add(samples, *frame_);
  UpdateTitle();
  if (width > 0 && height > 0) {
    DrawView(width, height);
    tools_.DrawOverlay(*frame_, camera_, width, height);
  }
  window_.DrawImGui();
  trace_.Write(*frame_, state_);
}

void Viewer::PrintBenchmark() const {
  std::printf(
      "frames %zu at %dx%d, %d samples%s: median render %.2f ms, frame (render + panels + swap; "
      "physics on %s) %.2f ms, real-time factor %.2f, solver %s\n",
      times_.frame.size(), options_.width, options_.height, renderer_.samples_used(),
      renderer_.settings().fxaa ? " + FXAA" : "", Median(times_.render),
      session_.threaded() ? "its own thread" : "this thread", Median(times_.frame),
      frame_->real_time_factor, SolverText(*frame_).c_str());
}

int Viewer::Run() {
  if (!Start()) return 1;
  const int frames =
      options_.bench_frames > 0 ? options_.bench_frames + kBenchWarmupFrames : options_.frames;
  bool screenshot_failed = false;
  for (int frame = 0; frames == 0 || frame < frames; ++frame) {
    if (window_.ShouldClose()) {
      if (quitting_ || frames > 0 || !frame_->dirty) break;
      window_.SetShouldClose(false);  // the close button: ask about the unsaved edits first
      state_.confirm = {PendingConfirmation::Action::kQuit, ""};
    }
    const auto start = Clock::now();
    RunFrame();
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
