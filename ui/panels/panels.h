// SPDX-License-Identifier: MIT
// The viewer's ImGui panels, one function (and one file) per panel. Each draws from the session
// and writes settings and requests into ViewerState; none acts on the simulation itself.
#pragma once

#include <string>

#include "core/model/world_desc.h"
#include "ui/viewer/viewer_state.h"
#include "ui/viewer/world_session.h"

namespace lamina::ui {

/// Top edge (pixels) of the Open world panel at the right, under the World panel: the World
/// panel grows down to it and no further, so the two never overlap.
float OpenWorldPanelTop(float display_height);

/// Play/pause, step, reset, speed, solver; time, real-time factor, status, rollbacks.
void DrawSimulationPanel(const WorldSession& session, ViewerState* state);
/// One checkbox per overlay and the overlay scales.
void DrawOverlaysPanel(ViewerState* state);
/// What is loaded, the load diagnostics and the selected body.
void DrawWorldPanel(const WorldSession& session, ViewerState* state);
/// File > Open: a path field and the worlds found under worlds/.
void DrawOpenWorldPanel(ViewerState* state);
/// One line at the bottom of the window: time, speed, status, frame time, last message.
void DrawStatusLine(const WorldSession& session, const ViewerState& state);

/// "link 'l1' of robot 'athlete' (id 5)", "object 'box' (id 1)", or "nothing".
std::string BodyLabel(const core::WorldDesc& world, int id);

}  // namespace lamina::ui
