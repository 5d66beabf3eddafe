// SPDX-License-Identifier: MIT
// What the panels and the keyboard edit and the editor loop acts on: immediate-mode panels write
// requests and settings here, the loop carries them out once per frame. Plain data. Edits of the
// world do not go through here: panels post them with EditorActions.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "core/math_types.h"
#include "core/render/overlay_options.h"

namespace lamina::ui {

/// Speeds the speed control offers (simulated seconds per wall second).
inline constexpr double kMinSpeed = 0.1;
inline constexpr double kMaxSpeed = 4.0;

/// What a left drag on a body does (a drag on empty space always turns the camera). The
/// modifier bindings work with any tool: Ctrl + right drag pulls (force), Ctrl + left drag turns
/// (torque), Ctrl + middle drag moves kinematically (docs/editor.md).
enum class MouseTool { kSelect, kForce, kTorque, kKinematic, kPose };

struct ViewerRequests {
  bool step = false;        ///< one physics step (while paused)
  bool step_frame = false;  ///< one frame's worth of steps, 1/60 s (while paused)
  bool reset = false;
  bool reframe = false;  ///< back to the default view of the world
  bool screenshot = false;
  bool undo = false, redo = false;
  bool save = false;      ///< Ctrl+S: to the document's file (Save As when it has none)
  bool save_as = false;   ///< open the Save As dialog
  bool revert = false;    ///< reload the file, dropping unsaved edits (asks first)
  bool quit = false;      ///< close the window (asks first when there are unsaved edits)
  std::string open_path;  ///< a world to load; "" for none (asks first when unsaved)
  // what the unsaved-changes question let through
  bool quit_confirmed = false, revert_confirmed = false;
  std::string open_confirmed;
};

/// Which windows are shown (the View menu).
struct PanelVisibility {
  bool simulation = true, world_tree = true, inspector = true, robot = true;
  bool settings = false, overlays = false, plots = false, help = false, open = false;
  bool sensors = false;
};

/// Every panel once: its name for `--panels`, its title in the View menu, its flag.
struct PanelEntry {
  const char* name;
  const char* title;
  bool PanelVisibility::*shown;
};
inline constexpr PanelEntry kPanels[] = {
    {"simulation", "Simulation", &PanelVisibility::simulation},
    {"world", "World tree", &PanelVisibility::world_tree},
    {"inspector", "Inspector", &PanelVisibility::inspector},
    {"robot", "Robot", &PanelVisibility::robot},
    {"settings", "Simulation settings", &PanelVisibility::settings},
    {"plots", "Plots", &PanelVisibility::plots},
    {"sensors", "Sensors", &PanelVisibility::sensors},
    {"overlays", "Overlays", &PanelVisibility::overlays},
    {"help", "Keys and mouse", &PanelVisibility::help},
    {"open", "Open world", &PanelVisibility::open},
};

/// "simulation,plots" (or "all", or "none"): exactly those panels shown. False with `error`
/// naming the unknown name and the known ones.
bool ParsePanelList(const std::string& text, PanelVisibility* panels, std::string* error);

/// A question the editor asks before it drops unsaved edits.
struct PendingConfirmation {
  enum class Action { kNone, kQuit, kOpen, kRevert } action = Action::kNone;
  std::string path;  ///< kOpen: the world to open
};

struct ViewerState {
  bool playing = true;
  double speed = 1.0;
  core::OverlayOptions overlays;
  bool show_panels = true;
  PanelVisibility panels;
  MouseTool tool = MouseTool::kSelect;
  int hovered_id = -1;      ///< world id of the body under the mouse, -1 for none
  int selected_id = -1;     ///< world id of the selected body, -1 for none
  std::string tree_filter;  ///< the World tree's filter text
  /// Where the Robot panel's joint sliders point, per robot index (link space): the commanded
  /// configuration until a slider moves; forgotten when a world opens or the time goes back.
  std::map<int, core::VecX> joint_targets;
  double joint_targets_time = -1.0;  ///< simulated time they were last shown at

  // measured, shown by the panels
  double frame_milliseconds = 0.0;
  std::string message;  ///< last event for the status line ("wrote shot.png", ...)

  // File > Open
  std::string open_path_input;
  std::string save_as_input;
  std::vector<std::string> world_files;  ///< .xml files offered by the Open panel
  std::string worlds_dir;                ///< where they were found (shown relative to it)
  std::string load_messages;             ///< diagnostics of the last load ("" when none)
  bool load_failed = false;              ///< the last load failed (shown in red)

  PendingConfirmation confirm;
  ViewerRequests requests;
};

}  // namespace lamina::ui
