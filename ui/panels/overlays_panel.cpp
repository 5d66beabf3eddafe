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

// the toggles of core::kOverlayToggles, three to a row, each with its help as a tooltip
void DrawToggles(core::OverlayOptions* overlays) {
  constexpr float kColumn = 100.0f;  // px between the starts of the toggles in a row
  int i = 0;
  for (const core::OverlayToggle& toggle : core::kOverlayToggles) {
    if (i % 3 != 0) ImGui::SameLine(10.0f + kColumn * static_cast<float>(i % 3));
    ImGui::Checkbox(toggle.name, &(overlays->*toggle.flag));
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", toggle.help);
    ++i;
  }
}

}  // namespace

void DrawOverlaysPanel(ViewerState* state) {
  ImGui::SetNextWindowPos(ImVec2(320, 40), ImGuiCond_FirstUseEver);
  if (ImGui::Begin("Overlays", &state->panels.overlays, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::PushItemWidth(200);
    core::OverlayOptions& overlays = state->overlays;
    DrawToggles(&overlays);
    ImGui::Separator();
    DrawScale("normal m", &overlays.normal_length, 0.005f, 1.0f);
    DrawScale("force m/N", &overlays.force_scale, 0.0001f, 0.1f);
    ImGui::PopItemWidth();
  }
  ImGui::End();
}

}  // namespace lamina::ui
