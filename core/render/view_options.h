// SPDX-License-Identifier: MIT
// The picture options every front end takes — image size, camera and overlays — checked once:
// `lamina --size/--camera/--overlay`, `lamina-headless shot` and `record`, and Python's
// lamina.render and lamina.vis.run.
#pragma once

#include <string>

#include "core/render/overlay_options.h"

namespace lamina::core {

struct ViewOptions {
  int width = 1280;  ///< pixels
  int height = 720;
  std::string camera;  ///< "world", "bodies" or a camera description (camera.h); "" = world
  OverlayOptions overlays;
};

/// Parses `size` (WIDTHxHEIGHT), `camera` and `overlay` (a comma list, overlay_options.h) into
/// `options`; false with a message naming the option as `prefix` + its name ("--size expects
/// ..." on a command line, "size expects ..." with prefix "" for keyword arguments).
bool ParseViewOptions(const std::string& size, const std::string& camera,
                      const std::string& overlay, ViewOptions* options, std::string* error,
                      const std::string& prefix = "--");

}  // namespace lamina::core
