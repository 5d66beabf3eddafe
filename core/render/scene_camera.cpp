// SPDX-License-Identifier: MIT
// Camera presets and descriptions resolved against a scene.
#include "core/render/scene_camera.h"

namespace lamina::core {

bool CameraForScene(const std::string& spec, const RenderScene& scene, double aspect,
                    OrbitCamera* camera, std::string* error) {
  const OrbitCamera world_view = FramingCamera(scene.bounds, aspect);
  if (spec.empty() || spec == "world") {
    *camera = world_view;
    return true;
  }
  if (spec == "bodies") {
    *camera = FramingCamera(scene.body_bounds.isEmpty() ? scene.bounds : scene.body_bounds, aspect);
    return true;
  }
  OrbitCamera parsed = world_view;
  if (!ParseCamera(spec, &parsed, error)) {
    *error += " (or a preset: world, bodies)";
    return false;
  }
  *camera = parsed;
  return true;
}

bool ValidCameraSpec(const std::string& spec, std::string* error) {
  OrbitCamera camera;
  return CameraForScene(spec, RenderScene(), 1.0, &camera, error);
}

}  // namespace lamina::core
