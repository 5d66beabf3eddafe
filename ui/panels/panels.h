// SPDX-License-Identifier: MIT
// The editor's ImGui panels, one function (and one file) per panel. Each draws from the latest
// SessionFrame, writes view settings and requests into ViewerState, and posts edits of the world
// through EditorActions; none touches the simulation itself.
#pragma once

#include <string>

#include "core/model/world_desc.h"
#include "ui/viewer/editor_actions.h"
#include "ui/viewer/live_session.h"
#include "ui/viewer/viewer_state.h"

namespace lamina::ui {

class PlotPanel;

/// What every panel gets.
struct PanelContext {
  const SessionFrame& frame;
  /// The document as last loaded or saved (the "back to the file's value" buttons); may be null.
  const core::WorldDesc* file_world;
  ViewerState* state;
  EditorActions* actions;
};

/// Height of the main menu bar.
float MenuBarHeight();

/// File, Edit, View, Tools and Help menus.
void DrawMainMenu(const PanelContext& context);
/// Play/pause, step, reset, speed, the mouse tool; time, real-time factor, status.
void DrawSimulationPanel(const PanelContext& context);
/// The settings rows of the parameter table (timestep, gravity, solver, ...).
void DrawSettingsPanel(const PanelContext& context);
/// Terrains, objects, robots and their links, with a filter box; click selects.
void DrawWorldTree(const PanelContext& context);
/// The selected body's rows of the table, and its contacts now.
void DrawInspector(const PanelContext& context);
/// Inside the Inspector: the contacts of body `id` now (contacts_view.cpp).
void DrawContactsNow(const PanelContext& context, int id);
/// The selected robot's drivers (gains, limits, friction) and a slider per joint.
void DrawRobotPanel(const PanelContext& context);
/// One checkbox per overlay and the overlay scales.
void DrawOverlaysPanel(ViewerState* state);
/// File > Open: a path field and the worlds found under worlds/.
void DrawOpenWorldPanel(ViewerState* state);
/// F1: every key and mouse binding (from the binding table, viewer_input.h).
void DrawHelpWindow(ViewerState* state);
/// The questions asked before unsaved edits would be lost, and the Save As dialog.
void DrawDialogs(const PanelContext& context);
/// One line at the bottom of the window: time, speed, status, frame time, last message.
void DrawStatusLine(const PanelContext& context);
/// Begins the borderless, translucent strip along the bottom of the window that the status line
/// draws in (ImGui::Begin with `id`); call ImGui::End afterwards whatever it returns.
bool BeginStatusStrip(const char* id);

/// "link 'l1' of robot 'athlete' (id 5)", "object 'box' (id 1)", or "nothing".
std::string BodyDescription(const core::WorldDesc& world, int id);

}  // namespace lamina::ui
