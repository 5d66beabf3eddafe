// SPDX-License-Identifier: MIT
// What `shot` and `record` share: the view options (size, camera, overlays) parsed with messages
// naming the option, world loading, and an off-screen view (OSMesa + the renderer) that turns a
// world description drawn at given poses into pixels. Nothing here writes runtime state into the
// description.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/model/world_desc.h"
#include "core/render/camera.h"
#include "core/render/view_options.h"
#include "core/render/world_poses.h"

namespace lamina::core {
class Simulator;
}

namespace lamina::app {

/// The picture options with the multisampling of the off-screen context.
struct ViewOptions : core::ViewOptions {
  int samples = 4;  ///< multisampling (1 = off; llvmpipe offers 4)
};

/// Loads `path`, printing every diagnostic to stderr; false on any error.
bool LoadWorldForRendering(const std::string& path, core::WorldDesc* world);

/// A simulator for `world` with contact feedback on (for the contact overlays).
std::unique_ptr<core::Simulator> MakeRenderSimulator(const core::WorldDesc& world);

/// Renders world states off screen. The camera is resolved on the first frame and then kept.
class OffscreenView {
 public:
  OffscreenView();
  ~OffscreenView();

  /// Creates the OSMesa context and the renderer; false with a message otherwise.
  bool Open(const ViewOptions& options, std::string* error);
  /// Draws `world` at `poses` (contacts from `simulator` when given) and returns RGBA8 rows
  /// bottom-up.
  std::vector<std::uint8_t> Render(const core::WorldDesc& world, const core::WorldPoses& poses,
                                   const core::Simulator* simulator);
  const core::OrbitCamera& camera() const;
  /// GL_VERSION and GL_RENDERER, e.g. "4.5 (Core Profile) Mesa 22.3.6 / llvmpipe ...".
  std::string GlDescription() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace lamina::app
