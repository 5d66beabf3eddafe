// SPDX-License-Identifier: MIT
// The main menu bar: File (open, save, save as, revert, quit), Edit (undo, redo, current state
// as initial), View (panels), Tools (the mouse tool) and Help. Shortcuts shown here are bound in
// viewer_input.cpp.
#include <imgui.h>

#include "ui/panels/panels.h"

namespace lamina::ui {

namespace {

void DrawFileMenu(const PanelContext& context) {
  ViewerState* state = context.state;
  if (!ImGui::BeginMenu("File")) return;
  if (ImGui::MenuItem("Open...", "Ctrl+O")) state->panels.open = true;
  if (ImGui::MenuItem("Save", "Ctrl+S", false, context.frame.loaded)) state->requests.save = true;
  if (ImGui::MenuItem("Save As...", "Ctrl+Shift+S", false, context.frame.loaded)) {
    state->requests.save_as = true;
  }
  if (ImGui::MenuItem("Revert to file", nullptr, false, context.frame.dirty)) {
    state->requests.revert = true;
  }
  ImGui::Separator();
  if (ImGui::MenuItem("Screenshot", "F12")) state->requests.screenshot = true;
  if (ImGui::MenuItem("Quit", "Ctrl+Q")) state->requests.quit = true;
  ImGui::EndMenu();
}

void DrawEditMenu(const PanelContext& context) {
  ViewerState* state = context.state;
  if (!ImGui::BeginMenu("Edit")) return;
  const std::string undo = "Undo " + context.frame.undo_label;
  const std::string redo = "Redo " + context.frame.redo_label;
  if (ImGui::MenuItem(undo.c_str(), "Ctrl+Z", false, !context.frame.undo_label.empty())) {
    state->requests.undo = true;
  }
  if (ImGui::MenuItem(redo.c_str(), "Ctrl+Shift+Z", false, !context.frame.redo_label.empty())) {
    state->requests.redo = true;
  }
  ImGui::Separator();
  if (ImGui::MenuItem("Use current state as initial", nullptr, false, context.frame.loaded)) {
    context.actions->MakeCurrentStateInitial();
  }
  ImGui::EndMenu();
}

void DrawViewMenu(ViewerState* state) {
  if (!ImGui::BeginMenu("View")) return;
  PanelVisibility& panels = state->panels;
  for (const PanelEntry& panel : kPanels) {
    if (panel.shown != &PanelVisibility::help && panel.shown != &PanelVisibility::open)
      ImGui::MenuItem(panel.title, nullptr, &(panels.*panel.shown));
  }
  ImGui::Separator();
  ImGui::MenuItem("All panels", "H", &state->show_panels);
  if (ImGui::MenuItem("Frame the world", "F")) state->requests.reframe = true;
  ImGui::EndMenu();
}

void DrawToolsMenu(ViewerState* state) {
  if (!ImGui::BeginMenu("Tools")) return;
  struct Item {
    const char* name;
    const char* key;
    MouseTool tool;
  };
  for (const Item& item :
       {Item{"Select", "Q", MouseTool::kSelect}, Item{"Force (pull)", "W", MouseTool::kForce},
        Item{"Torque (turn)", "E", MouseTool::kTorque},
        Item{"Kinematic drag", "T", MouseTool::kKinematic},
        Item{"Pose (paused)", "G", MouseTool::kPose}}) {
    if (ImGui::MenuItem(item.name, item.key, state->tool == item.tool)) state->tool = item.tool;
  }
  ImGui::EndMenu();
}

}  // namespace

float MenuBarHeight() {
  return ImGui::GetFrameHeight();  // ImGui's main menu bar is one frame high
}

void DrawMainMenu(const PanelContext& context) {
  if (!ImGui::BeginMainMenuBar()) return;
  DrawFileMenu(context);
  DrawEditMenu(context);
  DrawViewMenu(context.state);
  DrawToolsMenu(context.state);
  if (ImGui::BeginMenu("Help")) {
    ImGui::MenuItem("Keys and mouse", "F1", &context.state->panels.help);
    ImGui::EndMenu();
  }
  ImGui::EndMainMenuBar();
}

}  // namespace lamina::ui
