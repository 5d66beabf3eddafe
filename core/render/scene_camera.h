// SPDX-License-Identifier: MIT
// Choosing the camera for a scene from a user's description: "world" (the default view that
// frames everything), "bodies" (frames the objects and robots, terrain left out) or an explicit
// camera description, whose missing keys keep the values of the "world" view.
#pragma once

#include <string>

#include "core/render/camera.h"
#include "core/render/render_scene.h"

namespace lamina::core {

/// The camera that `spec` asks for in `scene` for a viewport of `aspect` (width / height).
/// "" means "world". False with `error` when `spec` is not a preset or a valid description.
bool CameraForScene(const std::string& spec, const RenderScene& scene, double aspect,
                    OrbitCamera* camera, std::string* error);

/// True when `spec` would be accepted by CameraForScene (checks syntax and ranges only).
bool ValidCameraSpec(const std::string& spec, std::string* error);

}  // namespace lamina::core
