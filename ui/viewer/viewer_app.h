// SPDX-License-Identifier: MIT
// The viewer: a GLFW window that shows a world with the renderer, simulates it in real time with
// fixed physics steps decoupled from the frame rate, and draws the ImGui panels (ui/panels/).
// lamina's main parses the command line into ViewerOptions and calls RunViewer.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/render/overlay_options.h"
#include "ui/viewer/viewer_state.h"

namespace lamina::ui {

struct ViewerOptions {
  std::string world_path;
  std::string worlds_dir;  ///< where the Open panel looks for .xml files ("" = nowhere)
  int width = 1280;        ///< window size, pixels
  int height = 720;
  int frames = 0;           ///< quit after this many frames (0 = when the window is closed)
  std::string screenshot;   ///< PNG written after the last frame (with frames > 0) or on F12
  double start_time = 0.0;  ///< simulate this long before the first frame, s
  std::string camera;       ///< "world", "bodies" or a camera description (see camera.h)
  core::OverlayOptions overlays;
  int selected_id = -1;  ///< world id of the body selected at start (-1 = none)
  bool show_panels = true;
  bool paused = false;
  bool sleep = false;  ///< idle objects sleep (core::Simulator::SetSleeping)
  /// --set PATH=VALUE arguments applied to the first world's description (access paths)
  std::vector<std::string> sets;
  /// Multisampling of the 3D view (1, 2 or 4); 0 = automatic: none on software GL (llvmpipe,
  /// where 4x multisampling costs 40 ms a frame at 1280x720 and FXAA 20 ms), 4x on a GPU.
  int samples = 0;
  bool fxaa = false;     ///< FXAA instead of multisampling (cheaper on software GL)
  int bench_frames = 0;  ///< > 0: time this many frames without vsync and print the medians
  /// Physics on the window's thread, exactly 1/60 s of simulated time (times the speed) per
  /// frame, whatever the wall clock: reproducible runs for scripted tests and recordings.
  /// Otherwise the physics runs on its own thread in real time (LiveSession).
  bool lockstep = false;
  /// The panels shown at start (--panels; ParsePanelList), when set.
  std::optional<PanelVisibility> panels;
  /// The Newton solver in place of an exact solver too slow for real time (solver_choice.h); only
  /// with the physics on its own thread.
  bool solver_choice = true;
  /// When set: a JSON line per frame with the selection, the drag, the selected body's state and
  /// contacts, for scripted UI tests (docs/editor.md, "Scripted tests").
  std::string trace_path;
};

/// Runs the viewer until the window closes (or `frames` have been shown). Exit code: 0, or 1 when
/// the window or the renderer cannot start, the first world does not load, or a requested
/// screenshot cannot be written.
int RunViewer(const ViewerOptions& options);

}  // namespace lamina::ui
