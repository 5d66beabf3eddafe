// SPDX-License-Identifier: MIT
// The status line: a borderless strip along the bottom of the window (also the script
// window's, ui/viewer/script_window.cpp).
#include <imgui.h>

#include "ui/panels/panels.h"

namespace lamina::ui {

bool BeginStatusStrip(const char* id) {
  const ImGuiIO& io = ImGui::GetIO();
  const float height = ImGui::GetFrameHeight() + 4.0f;
  ImGui::SetNextWindowPos(ImVec2(0, io.DisplaySize.y - height));
  ImGui::SetNextWindowSize(ImVec2(io.DisplaySize.x, height));
  ImGui::SetNextWindowBgAlpha(0.6f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                 ImGuiWindowFlags_NoSavedSettings |
                                 ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav;
  return ImGui::Begin(id, nullptr, flags);
}

void DrawStatusLine(const PanelContext& context) {
  const SessionFrame& frame = context.frame;
  const ViewerState& state = *context.state;
  if (BeginStatusStrip("##status")) {
    // (the two wall-clock figures in fields of fixed width: the default font is monospaced, so
    // what follows them stays in place whatever their digits; a lockstep capture's pixels then
    // differ only in those digits)
    ImGui::Text("%s  t = %.3f s  %6.2fx real time (speed %.2fx)  %s  %6.1f ms/frame%s",
                frame.playing ? "playing" : "paused ", frame.time, frame.real_time_factor,
                frame.speed, core::StepStatusName(frame.status), state.frame_milliseconds,
                frame.dirty ? "  [unsaved]" : "");
    const std::string hovered = state.hovered_id >= 0 && frame.loaded
                                    ? BodyDescription(*frame.world, state.hovered_id)
                                    : "";
    if (!hovered.empty() || !state.message.empty()) {
      ImGui::SameLine();
      ImGui::TextDisabled("| %s", hovered.empty() ? state.message.c_str() : hovered.c_str());
    }
  }
  ImGui::End();
}

}  // namespace lamina::ui
