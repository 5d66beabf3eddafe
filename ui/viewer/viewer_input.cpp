// SPDX-License-Identifier: MIT
#include "ui/viewer/viewer_input.h"

#include <algorithm>
#include <cmath>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

namespace lamina::ui {

namespace {

// a press that moved less than this is a click, not a drag (pixels)
constexpr double kClickSlop = 3.0;

bool Pressed(int glfw_key) {
  return ImGui::IsKeyPressed(glfw_key, false);
}

void HandleOverlayKeys(core::OverlayOptions* overlays) {
  bool* toggles[] = {&overlays->contacts, &overlays->normals, &overlays->forces, &overlays->padding,
                     &overlays->com,      &overlays->frames,  &overlays->bbox};
  for (int i = 0; i < 7; ++i) {
    if (Pressed(GLFW_KEY_1 + i)) *toggles[i] = !*toggles[i];
  }
}

core::MouseButton PressedButton(const ImGuiIO& io) {
  if (io.MouseClicked[0]) return core::MouseButton::kLeft;
  if (io.MouseClicked[1]) return core::MouseButton::kRight;
  if (io.MouseClicked[2]) return core::MouseButton::kMiddle;
  return core::MouseButton::kNone;
}

bool ButtonDown(const ImGuiIO& io, core::MouseButton button) {
  switch (button) {
    case core::MouseButton::kLeft:
      return io.MouseDown[0];
    case core::MouseButton::kRight:
      return io.MouseDown[1];
    case core::MouseButton::kMiddle:
      return io.MouseDown[2];
    case core::MouseButton::kNone:
      break;
  }
  return false;
}

}  // namespace

void HandleShortcuts(ViewerState* state) {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantCaptureKeyboard || io.WantTextInput) return;
  if (Pressed(GLFW_KEY_SPACE)) state->playing = !state->playing;
  if (Pressed(GLFW_KEY_S) || ImGui::IsKeyPressed(GLFW_KEY_RIGHT, true)) {
    (io.KeyShift ? state->requests.step_frame : state->requests.step) = true;
  }
  if (Pressed(GLFW_KEY_R) || Pressed(GLFW_KEY_BACKSPACE)) state->requests.reset = true;
  if (Pressed(GLFW_KEY_F12) || Pressed(GLFW_KEY_P)) state->requests.screenshot = true;
  if (Pressed(GLFW_KEY_F) || Pressed(GLFW_KEY_HOME)) state->requests.reframe = true;
  if (Pressed(GLFW_KEY_H)) state->show_panels = !state->show_panels;
  if (Pressed(GLFW_KEY_LEFT_BRACKET)) state->speed = std::max(kMinSpeed, state->speed / 2.0);
  if (Pressed(GLFW_KEY_RIGHT_BRACKET)) state->speed = std::min(kMaxSpeed, state->speed * 2.0);
  HandleOverlayKeys(&state->overlays);
}

ViewMouseEvent ViewMouse::Update(int viewport_height, core::OrbitCamera* camera) {
  const ImGuiIO& io = ImGui::GetIO();
  ViewMouseEvent event;
  event.x = io.MousePos.x * io.DisplayFramebufferScale.x;
  event.y = io.MousePos.y * io.DisplayFramebufferScale.y;
  event.over_view = !io.WantCaptureMouse && ImGui::IsMousePosValid();
  event.moved = io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f;
  if (button_ == core::MouseButton::kNone && event.over_view) {
    button_ = PressedButton(io);
    travelled_ = 0.0;
    event.double_clicked = io.MouseDoubleClicked[0];
    if (io.MouseWheel != 0.0f) *camera = core::ApplyScroll(*camera, io.MouseWheel);
  }
  if (button_ == core::MouseButton::kNone) return event;
  core::MouseDrag drag;
  drag.button = button_;
  drag.shift = io.KeyShift;
  drag.control = io.KeyCtrl;
  drag.alt = io.KeyAlt;
  drag.dx = io.MouseDelta.x * io.DisplayFramebufferScale.x;
  drag.dy = io.MouseDelta.y * io.DisplayFramebufferScale.y;
  travelled_ += std::hypot(drag.dx, drag.dy);
  if (travelled_ > kClickSlop && (drag.dx != 0.0 || drag.dy != 0.0)) {
    *camera = core::ApplyMouseDrag(*camera, drag, viewport_height);
  }
  event.dragging = travelled_ > kClickSlop;
  if (!ButtonDown(io, button_)) {
    event.clicked = button_ == core::MouseButton::kLeft && travelled_ <= kClickSlop;
    button_ = core::MouseButton::kNone;
    event.dragging = false;
  }
  return event;
}

}  // namespace lamina::ui
