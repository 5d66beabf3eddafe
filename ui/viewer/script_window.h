// SPDX-License-Identifier: MIT
// The window a script drives (Python's lamina.vis.run, Klamp't's GLSimulationPlugin): a
// simulation the caller owns, drawn each frame with the editor's renderer, orbit camera and
// overlays. `s` starts and stops it (as Klamp't's), Escape closes the window. While it runs, the
// caller's `advance` hook moves the simulation on once per frame; the window never steps it
// itself and edits nothing. Everything happens on the calling thread (GLFW's rule).
#pragma once

#include <functional>
#include <string>

#include "core/render/overlay_options.h"

namespace lamina::core {
class Simulator;
}

namespace lamina::ui {

struct ScriptWindowOptions {
  int width = 1280;  ///< window size, pixels
  int height = 720;
  std::string camera;  ///< "world", "bodies" or a camera description (camera.h); "" = world
  core::OverlayOptions overlays;
  bool running = false;    ///< run from the first frame (otherwise press s)
  int frames = 0;          ///< close after this many frames (0 = when the window is closed)
  std::string screenshot;  ///< PNG of the last frame (with frames > 0)
  std::string title = "Lamina";
};

struct ScriptWindowHooks {
  /// The simulation to draw; called every frame, never null.
  std::function<const core::Simulator&()> simulator;
  /// Called once per frame while running with the wall-clock seconds since the previous frame
  /// (at most 0.1); moves the simulation on. Returning false closes the window. Exceptions
  /// propagate out of RunScriptWindow after the window is closed.
  std::function<bool(double frame_seconds)> advance;
};

/// Shows the simulation until the window is closed, `advance` returns false or `frames` frames
/// have been drawn. False with `error` set when the window or the renderer cannot start or the
/// screenshot cannot be written.
bool RunScriptWindow(const ScriptWindowOptions& options, const ScriptWindowHooks& hooks,
                     std::string* error);

}  // namespace lamina::ui
