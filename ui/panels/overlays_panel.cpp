// SPDX-License-Identifier: MIT
// Overlays panel: what is drawn besides the bodies (core::OverlayOptions), edited in place.
#include <imgui.h>

#include "core/render/overlay_options.h"
#include "ui/panels/panels.h"

namespace lamina::ui {

namespace {

void DrawScale(const char* label, double* value, float minimum, float maximum) {
  float scale = static_cast<float>(*value);
  if (ImGui::SliderFloat(label, &scale, minimum, maximum, "%.3g", ImGuiSliderFlags_Logarithmic)) {
    *value = scale;
  }
}

// the toggles of core::kOverlayToggles, two to a row, each with its help as a tooltip
void DrawToggles(core::OverlayOptions* overlays) {
  constexpr float kColumn = 78.0f;  // px between the starts of the toggles in a row
  int i = 0;
  for (const core::OverlayToggle& toggle : core::kOverlayToggles) {
    if (i % 2 != 0) ImGui::SameLine(8.0f + kColumn);
    ImGui::Checkbox(toggle.name, &(overlays->*toggle.flag));
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", toggle.help);
    ++i;
  }
}

}  // namespace

void DrawOverlaysPanel(ViewerState* state) {
  // beside the Simulation panel, narrow enough to leave the Simulation settings room
  ImGui::SetNextWindowPos(ImVec2(318, MenuBarHeight() + 8), ImGuiCond_FirstUseEver);
  if (ImGui::Begin("Overlays", &state->panels.overlays, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::PushItemWidth(72);
    core::OverlayOptions& overlays = state->overlays;
    DrawToggles(&overlays);
    ImGui::Separator();
    DrawScale("normal m", &overlays.normal_length, 0.005f, 1.0f);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("length of a contact normal (m)");
    DrawScale("force m/N", &overlays.force_scale, 0.0001f, 0.1f);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("length of a force arrow per newton (m/N)");
    ImGui::PopItemWidth();
  }
  ImGui::End();
}

}  // namespace lamina::ui
