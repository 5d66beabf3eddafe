// SPDX-License-Identifier: MIT
// The questions the editor asks: before quitting, opening another world or reverting with
// unsaved edits ("Save", "Discard", "Cancel"), and Save As (a path field). Modal popups.
#include <array>
#include <cstring>

#include <imgui.h>

#include "ui/panels/panels.h"
#include "ui/widgets/item_registry.h"

namespace lamina::ui {

namespace {

constexpr const char* kConfirmTitle = "Unsaved changes";
constexpr const char* kSaveAsTitle = "Save As";

const char* ActionText(PendingConfirmation::Action action) {
  switch (action) {
    case PendingConfirmation::Action::kQuit:
      return "quitting";
    case PendingConfirmation::Action::kOpen:
      return "opening another world";
    case PendingConfirmation::Action::kRevert:
      return "reverting to the file";
    case PendingConfirmation::Action::kNone:
      break;
  }
  return "";
}

// carries out the confirmed action (the editor loop does the work)
void Proceed(ViewerState* state) {
  const PendingConfirmation confirm = state->confirm;
  state->confirm = {};
  switch (confirm.action) {
    case PendingConfirmation::Action::kQuit:
      state->requests.quit_confirmed = true;
      break;
    case PendingConfirmation::Action::kOpen:
      state->requests.open_confirmed = confirm.path;
      break;
    case PendingConfirmation::Action::kRevert:
      state->requests.revert_confirmed = true;
      break;
    case PendingConfirmation::Action::kNone:
      break;
  }
}

void DrawConfirm(const PanelContext& context) {
  ViewerState* state = context.state;
  if (state->confirm.action != PendingConfirmation::Action::kNone &&
      !ImGui::IsPopupOpen(kConfirmTitle)) {
    ImGui::OpenPopup(kConfirmTitle);
  }
  if (!ImGui::BeginPopupModal(kConfirmTitle, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  ImGui::Text("'%s' has unsaved changes.",
              context.frame.loaded ? context.frame.world->name.c_str() : "");
  ImGui::Text("Save them before %s?", ActionText(state->confirm.action));
  const bool save = ImGui::Button("Save");
  RecordItem("dialog.confirm.save");
  if (save && context.actions->Save(context.frame)) {
    Proceed(state);
    ImGui::CloseCurrentPopup();
  }
  ImGui::SameLine();
  const bool discard = ImGui::Button("Discard");
  RecordItem("dialog.confirm.discard");
  if (discard) {
    Proceed(state);
    ImGui::CloseCurrentPopup();
  }
  ImGui::SameLine();
  const bool cancel = ImGui::Button("Cancel");
  RecordItem("dialog.confirm.cancel");
  if (cancel || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) {
    state->confirm = {};
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

void DrawSaveAs(const PanelContext& context) {
  ViewerState* state = context.state;
  if (state->requests.save_as) {
    state->requests.save_as = false;
    if (state->save_as_input.empty()) state->save_as_input = context.frame.path;
    ImGui::OpenPopup(kSaveAsTitle);
  }
  if (!ImGui::BeginPopupModal(kSaveAsTitle, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  std::array<char, 1024> buffer{};
  std::strncpy(buffer.data(), state->save_as_input.c_str(), buffer.size() - 1);
  ImGui::TextUnformatted("world file (robot files are written beside it)");
  ImGui::SetNextItemWidth(480);
  if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
  const bool entered = ImGui::InputText("##path", buffer.data(), buffer.size(),
                                        ImGuiInputTextFlags_EnterReturnsTrue);
  RecordItem("dialog.save_as.path", buffer.data());
  state->save_as_input = buffer.data();
  const bool save = ImGui::Button("Save");
  RecordItem("dialog.save_as.save");
  if ((save || entered) && !state->save_as_input.empty()) {
    context.actions->SaveAs(state->save_as_input);
    ImGui::CloseCurrentPopup();
  }
  ImGui::SameLine();
  if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
  RecordItem("dialog.save_as.cancel");
  ImGui::EndPopup();
}

}  // namespace

void DrawDialogs(const PanelContext& context) {
  DrawConfirm(context);
  DrawSaveAs(context);
}

}  // namespace lamina::ui
