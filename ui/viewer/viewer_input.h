// SPDX-License-Identifier: MIT
// Keyboard shortcuts and the mouse over the 3D view, read from ImGui's input state after
// ImGui::NewFrame: nothing reaches the view while ImGui wants the mouse (a panel under it) or the
// keyboard (a text field). The bindings are described once, in KeyBindings() and
// MouseBindings(): HandleShortcuts runs the first, the F1 help window lists both.
#pragma once

#include <span>

#include "core/render/camera.h"
#include "core/render/camera_control.h"
#include "ui/viewer/viewer_state.h"

namespace lamina::ui {

/// Modifier requirements of a key binding.
enum KeyModifiers : unsigned { kNoMods = 0, kCtrl = 1, kShift = 2, kAnyShift = 4 };

struct KeyBinding {
  int key;             ///< GLFW key code
  unsigned mods;       ///< KeyModifiers: Ctrl / Shift required, or Shift either way (kAnyShift)
  bool repeat;         ///< held down repeats
  const char* keys;    ///< as the help shows it ("Ctrl+Z")
  const char* action;  ///< what it does
  void (*run)(ViewerState* state, bool shift);
};

struct MouseBinding {
  const char* gesture;  ///< "Ctrl + right drag on a body"
  const char* action;
};

std::span<const KeyBinding> KeyBindings();
std::span<const MouseBinding> MouseBindings();

/// Runs the key bindings pressed this frame (not while a text field has the keyboard).
void HandleShortcuts(ViewerState* state);

/// What the mouse did over the 3D view this frame.
struct ViewMouseEvent {
  bool over_view = false;  ///< the mouse is over the view, not over a panel
  bool dragging = false;   ///< a camera drag is in progress
  bool moved = false;      ///< the mouse moved this frame
  bool clicked = false;    ///< left button released without dragging
  bool double_clicked = false;
  /// a button went down over the view this frame (a tool may take the drag: TakeDrag)
  core::MouseButton pressed = core::MouseButton::kNone;
  bool released = false;  ///< the button of the drag in progress went up this frame
  bool control = false, shift = false, alt = false;  ///< modifiers held this frame
  double x = 0.0, y = 0.0;  ///< framebuffer pixels from the top-left corner
};

/// Turns drags and scrolling over the view into camera motion (core/render/camera_control).
class ViewMouse {
 public:
  /// Reads this frame's mouse input, moves `camera`, reports clicks for picking.
  ViewMouseEvent Update(int viewport_height, core::OrbitCamera* camera);
  /// The drag that began this frame belongs to a tool: the camera ignores it until release.
  void TakeDrag() { tool_drag_ = true; }
  /// A tool owns the drag in progress (until its button is released).
  bool tool_dragging() const { return tool_drag_; }

 private:
  core::MouseButton button_ = core::MouseButton::kNone;  ///< the button that started the drag
  double travelled_ = 0.0;                               ///< pixels moved since the press
  bool tool_drag_ = false;
};

}  // namespace lamina::ui
