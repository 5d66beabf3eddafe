// SPDX-License-Identifier: MIT
// Overlays panel: what is drawn besides the bodies (core::OverlayOptions), edited in place.
#include <imgui.h>

#include "ui/panels/panels.h"

namespace lamina::ui {

namespace {

void DrawScale(const char* label, double* value, float minimum, float maximum) {
  float scale = static_cast<float>(*value);
  if (ImGui::SliderFloat(label, &scale, minimum, maximum, "%.3g", ImGuiSliderFlags_Logarithmic)) {
    *value = scale;
  }
}

}  // namespace

void DrawOverlaysPanel(ViewerState* state) {
  ImGui::SetNextWindowPos(ImVec2(10, 300), ImGuiCond_FirstUseEver);
  if (ImGui::Begin("Overlays", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::PushItemWidth(200);
    core::OverlayOptions& overlays = state->overlays;
    ImGui::Checkbox("contacts", &overlays.contacts);
    ImGui::SameLine(110);
    ImGui::Checkbox("normals", &overlays.normals);
    ImGui::SameLine(210);
    ImGui::Checkbox("forces", &overlays.forces);
    ImGui::Checkbox("padding", &overlays.padding);
    ImGui::SameLine(110);
    ImGui::Checkbox("com", &overlays.com);
    ImGui::SameLine(210);
    ImGui::Checkbox("frames", &overlays.frames);
    ImGui::Checkbox("bbox", &overlays.bbox);
    ImGui::Separator();
    DrawScale("normal m", &overlays.normal_length, 0.005f, 1.0f);
    DrawScale("force m/N", &overlays.force_scale, 0.0001f, 0.1f);
    ImGui::PopItemWidth();
  }
  ImGui::End();
}

}  // namespace lamina::ui
