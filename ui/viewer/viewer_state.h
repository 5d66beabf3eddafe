// SPDX-License-Identifier: MIT
// What the panels and the keyboard edit and the viewer loop acts on: immediate-mode panels write
// requests and settings here, the loop carries them out once per frame. Plain data.
#pragma once

#include <string>
#include <vector>

#include "core/render/overlay_options.h"
#include "core/sim/simulator.h"

namespace lamina::ui {

/// Speeds the speed control offers (simulated seconds per wall second).
inline constexpr double kMinSpeed = 0.1;
inline constexpr double kMaxSpeed = 4.0;

struct ViewerRequests {
  bool step = false;        ///< one physics step (while paused)
  bool step_frame = false;  ///< one frame's worth of steps, 1/60 s (while paused)
  bool reset = false;
  bool reframe = false;  ///< back to the default view of the world
  bool screenshot = false;
  std::string open_path;  ///< a world to load; "" for none
};

struct ViewerState {
  bool playing = true;
  double speed = 1.0;
  core::SolverType solver = core::SolverType::kStep;
  bool sleep = false;  ///< idle objects sleep (core::Simulator::SetSleeping)
  core::OverlayOptions overlays;
  bool show_panels = true;
  int hovered_id = -1;   ///< world id of the body under the mouse, -1 for none
  int selected_id = -1;  ///< world id of the selected body, -1 for none

  // measured, shown by the panels
  double real_time_factor = 0.0;
  double frame_milliseconds = 0.0;
  std::string message;  ///< last event for the status line ("wrote shot.png", ...)

  // File > Open
  std::string open_path_input;
  std::vector<std::string> world_files;  ///< .xml files offered by the Open panel
  std::string worlds_dir;                ///< where they were found (shown relative to it)
  bool expand_open_panel = false;        ///< open the panel on the next frame (a load failed)

  ViewerRequests requests;
};

}  // namespace lamina::ui
