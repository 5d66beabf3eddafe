// SPDX-License-Identifier: MIT
// Each frame: input (s, Escape, the orbit camera) -> the caller's advance hook (while running)
// -> scene extraction from the caller's simulation -> 3D view -> status line -> swap.
#include "ui/viewer/script_window.h"

#include <algorithm>
#include <chrono>

#include <GLFW/glfw3.h>
#include <imgui.h>

#include "core/render/contact_markers.h"
#include "core/render/scene_camera.h"
#include "core/render/scene_extract.h"
#include "core/render/sensor_overlay.h"
#include "core/render/world_poses.h"
#include "core/sim/simulator.h"
#include "core/sim/step_observer.h"
#include "ui/panels/panels.h"
#include "ui/platform/glfw_window.h"
#include "ui/platform/image_file.h"
#include "ui/render/renderer.h"
#include "ui/viewer/viewer_input.h"

namespace lamina::ui {

namespace {

using Clock = std::chrono::steady_clock;

constexpr double kLongestFrameSeconds = 0.1;

class ScriptWindow {
 public:
  ScriptWindow(const ScriptWindowOptions& options, const ScriptWindowHooks& hooks)
      : options_(options), hooks_(hooks), running_(options.running) {}

  bool Start(std::string* error);
  /// One frame; false when the window should close.
  bool Frame();
  bool SaveScreenshot(std::string* error);
  void Swap() { window_.Swap(); }

 private:
  void DrawView(const core::Simulator& simulator, int width, int height);
  void DrawStatus(const core::Simulator& simulator);

  ScriptWindowOptions options_;
  ScriptWindowHooks hooks_;
  GlfwWindow window_;
  Renderer renderer_;
  ViewMouse mouse_;
  core::RenderMeshCache meshes_;
  core::RenderScene scene_;
  core::OrbitCamera camera_;
  bool camera_chosen_ = false;
  bool running_ = false;
  Clock::time_point last_frame_ = Clock::now();
  std::string camera_error_;
};

bool ScriptWindow::Start(std::string* error) {
  if (!window_.Open(options_.title, options_.width, options_.height, error)) return false;
  if (!renderer_.Initialize(error)) return false;
  if (IsSoftwareRenderer(renderer_.gl_renderer())) {
    renderer_.settings().samples = 1;
    renderer_.settings().shadow_map_size = kSoftwareShadowMapSize;
  }
  return true;
}

void ScriptWindow::DrawView(const core::Simulator& simulator, int width, int height) {
  core::ExtractScene(simulator.world(), core::CurrentPoses(simulator), options_.overlays,
                     core::ContactMarkersFromSimulator(simulator), &meshes_, &scene_);
  core::AddSensorOverlays(simulator, options_.overlays, &scene_);
  if (!camera_chosen_) {
    core::CameraForScene(options_.camera, scene_, static_cast<double>(width) / height, &camera_,
                         &camera_error_);
    camera_chosen_ = true;
  }
  renderer_.Render(scene_, camera_, width, height, 0);
}

void ScriptWindow::DrawStatus(const core::Simulator& simulator) {
  if (BeginStatusStrip("##script-status")) {
    ImGui::Text("%s  t = %.3f s  %s   s: %s   Esc: close%s%s", running_ ? "running" : "paused",
                simulator.time(), core::StepStatusName(simulator.statistics().worst_status),
                running_ ? "stop" : "run", camera_error_.empty() ? "" : "   ",
                camera_error_.c_str());
  }
  ImGui::End();
}

bool ScriptWindow::Frame() {
  window_.BeginFrame();
  const auto now = Clock::now();
  const double seconds =
      std::min(kLongestFrameSeconds, std::chrono::duration<double>(now - last_frame_).count());
  last_frame_ = now;
  if (ImGui::IsKeyPressed(GLFW_KEY_S, false)) running_ = !running_;
  if (ImGui::IsKeyPressed(GLFW_KEY_ESCAPE, false)) return false;
  int width = 0, height = 0;
  window_.FramebufferSize(&width, &height);
  if (width > 0 && height > 0 && camera_chosen_) mouse_.Update(height, &camera_);
  if (running_ && !hooks_.advance(seconds)) return false;
  const core::Simulator& simulator = hooks_.simulator();
  if (width > 0 && height > 0) DrawView(simulator, width, height);
  DrawStatus(simulator);
  window_.DrawImGui();
  return !window_.ShouldClose();
}

bool ScriptWindow::SaveScreenshot(std::string* error) {
  int width = 0, height = 0;
  const std::vector<std::uint8_t> pixels = window_.ReadPixels(&width, &height);
  if (WritePngBottomUp(options_.screenshot, width, height, pixels)) return true;
  *error = "cannot write " + options_.screenshot;
  return false;
}

}  // namespace

bool RunScriptWindow(const ScriptWindowOptions& options, const ScriptWindowHooks& hooks,
                     std::string* error) {
  ScriptWindow window(options, hooks);
  if (!window.Start(error)) return false;
  for (int frame = 0; options.frames == 0 || frame < options.frames; ++frame) {
    const bool go_on = window.Frame();
    const bool last = !go_on || (options.frames > 0 && frame + 1 == options.frames);
    if (last && !options.screenshot.empty() && !window.SaveScreenshot(error)) return false;
    window.Swap();
    if (!go_on) break;
  }
  return true;
}

}  // namespace lamina::ui
