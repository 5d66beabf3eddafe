// SPDX-License-Identifier: MIT
#include "core/render/view_options.h"

#include "core/render/image_size.h"
#include "core/render/scene_camera.h"

namespace lamina::core {

bool ParseViewOptions(const std::string& size, const std::string& camera,
                      const std::string& overlay, ViewOptions* options, std::string* error,
                      const std::string& prefix) {
  if (!ParseImageSize(size, &options->width, &options->height)) {
    *error = prefix +
             "size expects WIDTHxHEIGHT with 1..16384 pixels per side (e.g. 1280x720), got '" +
             size + "'";
    return false;
  }
  std::string detail;
  if (!ValidCameraSpec(camera, &detail)) {
    *error = prefix + detail;  // "camera: ..."
    return false;
  }
  options->camera = camera;
  if (!ParseOverlayList(overlay, &options->overlays, &detail)) {
    *error = prefix + "overlay: " + detail;
    return false;
  }
  return true;
}

}  // namespace lamina::core
