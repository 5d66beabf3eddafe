// SPDX-License-Identifier: MIT
// F1: every key and mouse binding, listed from the binding tables the input code runs
// (viewer_input.h), so the help cannot drift from what the keys do.
#include <imgui.h>

#include "ui/panels/panels.h"
#include "ui/viewer/viewer_input.h"

namespace lamina::ui {

namespace {

void Row(const char* what, const char* action) {
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(what);
  ImGui::TableNextColumn();
  ImGui::TextWrapped("%s", action);
}

// two columns: the keys as wide as the widest, the action wrapped in the rest
bool BeginBindingTable(const char* id) {
  if (!ImGui::BeginTable(id, 2, ImGuiTableFlags_RowBg)) return false;
  ImGui::TableSetupColumn("what", ImGuiTableColumnFlags_WidthFixed);
  ImGui::TableSetupColumn("action", ImGuiTableColumnFlags_WidthStretch);
  return true;
}

}  // namespace

void DrawHelpWindow(ViewerState* state) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Appearing,
                          ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(640, display.y * 0.8f), ImGuiCond_Appearing);
  if (ImGui::Begin("Keys and mouse (F1)", &state->panels.help)) {
    if (BeginBindingTable("keys")) {
      for (const KeyBinding& binding : KeyBindings()) {
        if (binding.keys[0] != '\0') Row(binding.keys, binding.action);
      }
      ImGui::EndTable();
    }
    ImGui::Separator();
    if (BeginBindingTable("mouse")) {
      for (const MouseBinding& binding : MouseBindings()) Row(binding.gesture, binding.action);
      ImGui::EndTable();
    }
    ImGui::TextDisabled("Hover over a field's name for its help, rule and how an edit applies.");
  }
  ImGui::End();
}

}  // namespace lamina::ui
