// SPDX-License-Identifier: MIT
// Shared pieces of the render commands: option parsing, loading, the off-screen view.
#include "app/headless_render.h"

#include <iostream>

#include "core/io/world_file.h"
#include "core/render/contact_markers.h"
#include "core/render/scene_camera.h"
#include "core/render/scene_extract.h"
#include "core/render/sensor_overlay.h"
#include "core/sim/simulator.h"
#include "ui/platform/osmesa_context.h"
#include "ui/render/renderer.h"

namespace lamina::app {

bool LoadWorldForRendering(const std::string& path, core::WorldDesc* world) {
  core::Diagnostics diagnostics;
  core::MeshCache meshes;
  core::LoadContext context{diagnostics, meshes};
  const bool ok = core::LoadWorldFile(path, context, world);
  std::cerr << diagnostics.FormatAll();
  return ok && !diagnostics.HasErrors();
}

std::unique_ptr<core::Simulator> MakeRenderSimulator(const core::WorldDesc& world) {
  auto simulator = std::make_unique<core::Simulator>(world);
  simulator->EnableContactFeedbackAll();
  return simulator;
}

struct OffscreenView::State {
  ViewOptions options;
  ui::OsmesaContext context;
  ui::Renderer renderer;
  core::RenderMeshCache meshes;
  core::RenderScene scene;
  core::OrbitCamera camera;
  bool camera_chosen = false;
};

OffscreenView::OffscreenView() : state_(std::make_unique<State>()) {}
OffscreenView::~OffscreenView() = default;

bool OffscreenView::Open(const ViewOptions& options, std::string* error) {
  state_->options = options;
  if (!state_->context.Create(options.width, options.height, error)) return false;
  state_->renderer.settings().samples = options.samples;
  return state_->renderer.Initialize(error);
}

std::vector<std::uint8_t> OffscreenView::Render(const core::WorldDesc& world,
                                                const core::WorldPoses& poses,
                                                const core::Simulator* simulator) {
  State& s = *state_;
  s.context.MakeCurrent();  // another view may have been drawn since
  const std::vector<core::ContactMarker> contacts =
      simulator ? core::ContactMarkersFromSimulator(*simulator)
                : std::vector<core::ContactMarker>();
  core::ExtractScene(world, poses, s.options.overlays, contacts, &s.meshes, &s.scene);
  if (simulator) core::AddSensorOverlays(*simulator, s.options.overlays, &s.scene);
  if (!s.camera_chosen) {
    std::string ignored;  // the spec was validated by core::ParseViewOptions
    core::CameraForScene(s.options.camera, s.scene,
                         static_cast<double>(s.options.width) / s.options.height, &s.camera,
                         &ignored);
    s.camera_chosen = true;
  }
  s.renderer.Render(s.scene, s.camera, s.options.width, s.options.height);
  s.context.SwapOrFinish();
  return s.renderer.ReadPixels(s.options.width, s.options.height);
}

const core::OrbitCamera& OffscreenView::camera() const {
  return state_->camera;
}

std::string OffscreenView::GlDescription() const {
  return state_->renderer.gl_version() + " / " + state_->renderer.gl_renderer();
}

}  // namespace lamina::app
