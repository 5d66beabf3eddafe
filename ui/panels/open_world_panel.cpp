// SPDX-License-Identifier: MIT
// File > Open: a path field (Enter or Open loads it) and the world files found under worlds/
// (a click fills the field, a double click opens). No native dialog is needed.
#include <algorithm>
#include <array>
#include <cstring>

#include <imgui.h>

#include "ui/panels/panels.h"

namespace lamina::ui {

namespace {

void DrawPathField(ViewerState* state) {
  std::array<char, 1024> buffer{};
  std::strncpy(buffer.data(), state->open_path_input.c_str(), buffer.size() - 1);
  ImGui::SetNextItemWidth(-70);
  const bool entered = ImGui::InputText("##path", buffer.data(), buffer.size(),
                                        ImGuiInputTextFlags_EnterReturnsTrue);
  state->open_path_input = buffer.data();
  ImGui::SameLine();
  if ((ImGui::Button("Open") || entered) && !state->open_path_input.empty()) {
    state->requests.open_path = state->open_path_input;
  }
}

void DrawWorldList(ViewerState* state) {
  ImGui::BeginChild("worlds", ImVec2(0, 0), true);
  const std::string& prefix = state->worlds_dir;
  for (const std::string& file : state->world_files) {
    const bool chosen = file == state->open_path_input;
    const bool inside = !prefix.empty() && file.rfind(prefix + "/", 0) == 0;
    const std::string label = inside ? file.substr(prefix.size() + 1) : file;
    if (ImGui::Selectable(label.c_str(), chosen, ImGuiSelectableFlags_AllowDoubleClick)) {
      state->open_path_input = file;
      if (ImGui::IsMouseDoubleClicked(0)) state->requests.open_path = file;
    }
  }
  ImGui::EndChild();
}

}  // namespace

void DrawOpenWorldPanel(ViewerState* state) {
  if (!state->panels.open) return;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f - 190, display.y * 0.3f), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(380, 260), ImGuiCond_FirstUseEver);
  if (ImGui::Begin("Open world", &state->panels.open)) {
    ImGui::TextDisabled("a path, or drop a file onto the window");
    DrawPathField(state);
    DrawWorldList(state);
  }
  ImGui::End();
}

}  // namespace lamina::ui
