// SPDX-License-Identifier: MIT
#include "ui/render/sensor_camera.h"

#include <utility>

namespace lamina::ui {

SceneCamera::SceneCamera(Renderer* renderer, SceneSource source, std::function<void()> make_current)
    : renderer_(renderer), source_(std::move(source)), make_current_(std::move(make_current)) {}

bool SceneCamera::Render(const core::CameraRequest& request, core::CameraImage* image) {
  if (make_current_) make_current_();
  source_(&scene_);
  if (!renderer_->RenderCamera(scene_, request, image)) return false;
  ++pictures_;
  return true;
}

}  // namespace lamina::ui
