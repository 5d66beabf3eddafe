// SPDX-License-Identifier: MIT
// One widget per row of the parameter table (core/model/params.h), generated from the row: its
// label and unit, a widget for its type (drag field, checkbox, choice, vector, pose as position
// and roll/pitch/yaw in degrees, text for ranges, inertias and per-link vectors), `inf` as a
// choice where the row allows it, its help, rule and apply kind as the tooltip, and a button
// that takes the value back to the file's. Nothing is clamped here: the table on the physics
// thread accepts or refuses the value, and a refusal reaches the status line with its message.
// A drag is one undo step (BeginGroup on activation, EndGroup on deactivation).
#pragma once

#include "core/edit/element_ref.h"
#include "core/model/params.h"
#include "core/model/world_desc.h"
#include "ui/viewer/editor_actions.h"

namespace lamina::ui {

/// Where a row's value lives and what it was in the file.
struct ParamRowContext {
  const core::WorldDesc& world;       ///< the document now
  const core::WorldDesc* file_world;  ///< the document as last loaded or saved (null: unknown)
  core::ElementIndex element;         ///< in `world`
  core::ElementRef ref;               ///< the same element by uid
};

/// Draws the widget of `spec` (a two-column table row: label, widget) and posts any edit.
void DrawParamRow(const ParamRowContext& row, const core::ParamSpec& spec, EditorActions* actions);

/// Every row of `kind` for one element, as a two-column table; `filter` (or null) keeps some.
void DrawParamTable(const char* id, const ParamRowContext& row, core::ElementKind kind,
                    EditorActions* actions, bool (*filter)(const core::ParamSpec&) = nullptr);

/// "live", "rebuilds the geometry", ... for tooltips.
const char* ApplyKindText(core::ParamApply apply);

}  // namespace lamina::ui
