// SPDX-License-Identifier: MIT
#include "ui/viewer/viewer_input.h"

#include <algorithm>
#include <cmath>
#include <string>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include "core/render/overlay_options.h"

namespace lamina::ui {

namespace {

// a press that moved less than this is a click, not a drag (pixels)
constexpr double kClickSlop = 3.0;

// key 1 + i toggles the i-th overlay of core::kOverlayToggles
static_assert(std::size(core::kOverlayToggles) == 9, "keys 1 ... 9 toggle every overlay");
template <int kIndex>
void Overlay(ViewerState* state, bool) {
  bool& flag = state->overlays.*core::kOverlayToggles[kIndex].flag;
  flag = !flag;
}

// the actions two keys share
void Step(ViewerState* s, bool shift) {
  (shift ? s->requests.step_frame : s->requests.step) = true;
}
void Reset(ViewerState* s, bool) {
  s->requests.reset = true;
}
void Redo(ViewerState* s, bool) {
  s->requests.redo = true;
}
void Screenshot(ViewerState* s, bool) {
  s->requests.screenshot = true;
}
void Reframe(ViewerState* s, bool) {
  s->requests.reframe = true;
}

const std::string kOverlayHelp = "toggle the overlays in this order: " + core::OverlayNames();

template <MouseTool kTool>
void Tool(ViewerState* state, bool) {
  state->tool = kTool;
}

const KeyBinding kKeys[] = {
    {GLFW_KEY_SPACE, kNoMods, false, "Space", "play / pause",
     [](ViewerState* s, bool) { s->playing = !s->playing; }},
    {GLFW_KEY_S, kAnyShift, true, "S or Right", "one step (Shift: 1/60 s)", Step},
    {GLFW_KEY_RIGHT, kAnyShift, true, "", "", Step},
    {GLFW_KEY_R, kNoMods, false, "R or Backspace", "reset to the initial state", Reset},
    {GLFW_KEY_BACKSPACE, kNoMods, false, "", "", Reset},
    {GLFW_KEY_LEFT_BRACKET, kNoMods, false, "[", "half speed",
     [](ViewerState* s, bool) { s->speed = std::max(kMinSpeed, s->speed / 2.0); }},
    {GLFW_KEY_RIGHT_BRACKET, kNoMods, false, "]", "double speed",
     [](ViewerState* s, bool) { s->speed = std::min(kMaxSpeed, s->speed * 2.0); }},
    {GLFW_KEY_Z, kCtrl, false, "Ctrl+Z", "undo",
     [](ViewerState* s, bool) { s->requests.undo = true; }},
    {GLFW_KEY_Z, kCtrl | kShift, false, "Ctrl+Shift+Z or Ctrl+Y", "redo", Redo},
    {GLFW_KEY_Y, kCtrl, false, "", "", Redo},
    {GLFW_KEY_S, kCtrl, false, "Ctrl+S", "save",
     [](ViewerState* s, bool) { s->requests.save = true; }},
    {GLFW_KEY_S, kCtrl | kShift, false, "Ctrl+Shift+S", "save as",
     [](ViewerState* s, bool) { s->requests.save_as = true; }},
    {GLFW_KEY_O, kCtrl, false, "Ctrl+O", "open a world",
     [](ViewerState* s, bool) { s->panels.open = true; }},
    {GLFW_KEY_Q, kCtrl, false, "Ctrl+Q", "quit",
     [](ViewerState* s, bool) { s->requests.quit = true; }},
    {GLFW_KEY_Q, kNoMods, false, "Q", "select tool", Tool<MouseTool::kSelect>},
    {GLFW_KEY_W, kNoMods, false, "W", "force tool (pull)", Tool<MouseTool::kForce>},
    {GLFW_KEY_E, kNoMods, false, "E", "torque tool (turn)", Tool<MouseTool::kTorque>},
    {GLFW_KEY_T, kNoMods, false, "T", "kinematic drag tool", Tool<MouseTool::kKinematic>},
    {GLFW_KEY_G, kNoMods, false, "G", "pose tool (paused)", Tool<MouseTool::kPose>},
    {GLFW_KEY_F12, kNoMods, false, "F12 or P", "screenshot", Screenshot},
    {GLFW_KEY_P, kNoMods, false, "", "", Screenshot},
    {GLFW_KEY_F, kNoMods, false, "F or Home", "frame the world", Reframe},
    {GLFW_KEY_HOME, kNoMods, false, "", "", Reframe},
    {GLFW_KEY_H, kNoMods, false, "H", "hide / show the panels",
     [](ViewerState* s, bool) { s->show_panels = !s->show_panels; }},
    {GLFW_KEY_F1, kNoMods, false, "F1", "this help",
     [](ViewerState* s, bool) { s->panels.help = !s->panels.help; }},
    {GLFW_KEY_ESCAPE, kNoMods, false, "Esc", "clear the selection",
     [](ViewerState* s, bool) { s->selected_id = -1; }},
    {GLFW_KEY_1, kNoMods, false, "1 ... 9", kOverlayHelp.c_str(), Overlay<0>},
    {GLFW_KEY_2, kNoMods, false, "", "", Overlay<1>},
    {GLFW_KEY_3, kNoMods, false, "", "", Overlay<2>},
    {GLFW_KEY_4, kNoMods, false, "", "", Overlay<3>},
    {GLFW_KEY_5, kNoMods, false, "", "", Overlay<4>},
    {GLFW_KEY_6, kNoMods, false, "", "", Overlay<5>},
    {GLFW_KEY_7, kNoMods, false, "", "", Overlay<6>},
    {GLFW_KEY_8, kNoMods, false, "", "", Overlay<7>},
    {GLFW_KEY_9, kNoMods, false, "", "", Overlay<8>},
};

const MouseBinding kMouse[] = {
    {"left drag", "orbit the camera (on a body: the current tool)"},
    {"right drag, Shift + left drag", "pan"},
    {"middle drag, Alt + left drag, wheel", "zoom"},
    {"click", "select the body under the mouse (empty space: none)"},
    {"double click", "orbit about the point under the mouse"},
    {"Ctrl + right drag on a body",
     "force: a spring pulls the grabbed point toward the cursor "
     "(Shift: in the horizontal plane)"},
    {"Ctrl + left drag on a body", "torque: a spring turns the body with the mouse"},
    {"Ctrl + middle drag on a body", "kinematic drag: the body follows the cursor; release throws"},
    {"pose tool, left drag (paused)",
     "move an object's initial pose, or a robot by its floating base; hold X, Y or Z "
     "to move along that axis only, Ctrl to turn about it"},
};

bool ModifiersMatch(const KeyBinding& binding, const ImGuiIO& io) {
  if (io.KeyCtrl != ((binding.mods & kCtrl) != 0)) return false;
  if (binding.mods & kAnyShift) return true;
  return io.KeyShift == ((binding.mods & kShift) != 0);
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

std::span<const KeyBinding> KeyBindings() {
  return kKeys;
}

std::span<const MouseBinding> MouseBindings() {
  return kMouse;
}

void HandleShortcuts(ViewerState* state) {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantTextInput) return;
  for (const KeyBinding& binding : kKeys) {
    // Ctrl bindings work over panels too; plain keys only when no widget wants the keyboard
    if (io.WantCaptureKeyboard && !(binding.mods & kCtrl) && binding.key != GLFW_KEY_F1) continue;
    if (ImGui::IsKeyPressed(binding.key, binding.repeat) && ModifiersMatch(binding, io)) {
      binding.run(state, io.KeyShift);
    }
  }
}

ViewMouseEvent ViewMouse::Update(int viewport_height, core::OrbitCamera* camera) {
  const ImGuiIO& io = ImGui::GetIO();
  ViewMouseEvent event;
  event.x = io.MousePos.x * io.DisplayFramebufferScale.x;
  event.y = io.MousePos.y * io.DisplayFramebufferScale.y;
  event.control = io.KeyCtrl;
  event.shift = io.KeyShift;
  event.alt = io.KeyAlt;
  event.over_view = !io.WantCaptureMouse && ImGui::IsMousePosValid();
  event.moved = io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f;
  if (button_ == core::MouseButton::kNone && event.over_view) {
    button_ = PressedButton(io);
    event.pressed = button_;
    travelled_ = 0.0;
    tool_drag_ = false;
    event.double_clicked = io.MouseDoubleClicked[0];
    if (io.MouseWheel != 0.0f) *camera = core::ApplyScroll(*camera, io.MouseWheel);
  }
  if (button_ == core::MouseButton::kNone) return event;
  core::MouseDrag drag;
  drag.button = button_;
  drag.shift = io.KeyShift;
  drag.alt = io.KeyAlt;
  drag.dx = io.MouseDelta.x * io.DisplayFramebufferScale.x;
  drag.dy = io.MouseDelta.y * io.DisplayFramebufferScale.y;
  travelled_ += std::hypot(drag.dx, drag.dy);
  const bool camera_drag = !tool_drag_ && event.pressed == core::MouseButton::kNone;
  if (camera_drag && travelled_ > kClickSlop && (drag.dx != 0.0 || drag.dy != 0.0)) {
    *camera = core::ApplyMouseDrag(*camera, drag, viewport_height);
  }
  event.dragging = travelled_ > kClickSlop;
  if (!ButtonDown(io, button_)) {
    event.clicked = button_ == core::MouseButton::kLeft && travelled_ <= kClickSlop && !tool_drag_;
    event.released = true;
    button_ = core::MouseButton::kNone;
    event.dragging = false;
  }
  return event;
}

}  // namespace lamina::ui
