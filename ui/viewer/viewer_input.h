// SPDX-License-Identifier: MIT
// Keyboard shortcuts and the mouse over the 3D view, read from ImGui's input state after
// ImGui::NewFrame: nothing reaches the view while ImGui wants the mouse (a panel under it) or the
// keyboard (a text field).
#pragma once

#include "core/render/camera.h"
#include "core/render/camera_control.h"
#include "ui/viewer/viewer_state.h"

namespace lamina::ui {

/// Space play/pause, S or Right step (Shift: 1/60 s), R or Backspace reset, F12 or P screenshot,
/// F or Home re-frame, H hide/show panels, 1..7 toggle the overlays, [ and ] halve/double speed.
void HandleShortcuts(ViewerState* state);

/// What the mouse did over the 3D view this frame.
struct ViewMouseEvent {
  bool over_view = false;  ///< the mouse is over the view, not over a panel
  bool dragging = false;   ///< a camera drag is in progress
  bool moved = false;      ///< the mouse moved this frame
  bool clicked = false;    ///< left button released without dragging
  bool double_clicked = false;
  double x = 0.0, y = 0.0;  ///< framebuffer pixels from the top-left corner
};

/// Turns drags and scrolling over the view into camera motion (core/render/camera_control).
class ViewMouse {
 public:
  /// Reads this frame's mouse input, moves `camera`, reports clicks for picking.
  ViewMouseEvent Update(int viewport_height, core::OrbitCamera* camera);

 private:
  core::MouseButton button_ = core::MouseButton::kNone;  ///< the button that started the drag
  double travelled_ = 0.0;                               ///< pixels moved since the press
};

}  // namespace lamina::ui
