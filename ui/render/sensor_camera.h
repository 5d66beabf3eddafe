// SPDX-License-Identifier: MIT
// SceneCamera: the renderer as a simulation's sensor cameras see through it
// (core::CameraRenderer). The caller says how to get the scene of the simulation's current
// state (core::ExtractScene of CurrentPoses, without overlays) and how to make the GL context
// current; the simulation asks it from within a step, on the thread that steps it, so that
// thread must own the context (lamina-headless, Python's OSMesa module).
#pragma once

#include <functional>

#include "core/render/render_scene.h"
#include "core/sensors/sensor.h"
#include "ui/render/renderer.h"

namespace lamina::ui {

class SceneCamera : public core::CameraRenderer {
 public:
  using SceneSource = std::function<void(core::RenderScene*)>;
  /// `renderer` (initialized, outliving this) draws what `source` gives; `make_current` (may be
  /// empty) runs before each picture.
  SceneCamera(Renderer* renderer, SceneSource source, std::function<void()> make_current = {});
  bool Render(const core::CameraRequest& request, core::CameraImage* image) override;
  /// Pictures taken so far.
  int pictures() const { return pictures_; }

 private:
  Renderer* renderer_;
  SceneSource source_;
  std::function<void()> make_current_;
  core::RenderScene scene_;
  int pictures_ = 0;
};

}  // namespace lamina::ui
