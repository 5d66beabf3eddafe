// SPDX-License-Identifier: MIT
// Inspector: the selected terrain, object, robot or link — where it is now, then every row of
// the parameter table for its kind (surface and padding, mass properties, initial conditions),
// each a live edit, then its contacts now (contacts_view.cpp).
#include <imgui.h>

#include "core/edit/document.h"
#include "core/render/world_poses.h"
#include "ui/panels/panels.h"
#include "ui/panels/param_widgets.h"

namespace lamina::ui {

namespace {

// the element a world id names, with its reference by uid (terrains, objects, robots, links)
std::optional<ParamRowContext> RowContextOf(const PanelContext& context, int id) {
  const core::WorldDesc& world = *context.frame.world;
  const std::optional<core::ElementIndex> element = core::ElementOfWorldId(world, id);
  const std::optional<core::ElementRef> ref =
      element ? core::RefOfElement(world, *element) : std::nullopt;
  if (!ref) return std::nullopt;
  return ParamRowContext{world, context.file_world, *element, *ref};
}

bool IsInitialCondition(const core::ParamSpec& spec) {
  return spec.apply == core::ParamApply::kOnReset;
}
bool IsBodyOrMassRow(const core::ParamSpec& spec) {
  return spec.apply != core::ParamApply::kOnReset;
}

void DrawWhereNow(const PanelContext& context, int id) {
  const std::optional<core::Pose> frame =
      core::DrawnBodyFrame(*context.frame.world, context.frame.poses, id);
  if (!frame) return;
  const core::Vec3 p = frame->translation();
  ImGui::TextDisabled("now at %.4f %.4f %.4f m", p.x(), p.y(), p.z());
}

}  // namespace

void DrawInspector(const PanelContext& context) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x - 400, MenuBarHeight() + 8), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(390, display.y * 0.55f), ImGuiCond_FirstUseEver);
  if (ImGui::Begin("Inspector", &context.state->panels.inspector)) {
    const int id = context.state->selected_id;
    const std::optional<ParamRowContext> row =
        context.frame.loaded && id >= 0 ? RowContextOf(context, id) : std::nullopt;
    if (!row) {
      ImGui::TextDisabled("click a body (in the view or the World tree) to inspect it");
    } else {
      ImGui::TextWrapped("%s", BodyDescription(*context.frame.world, id).c_str());
      DrawWhereNow(context, id);
      DrawParamTable("body", *row, row->element.kind, context.actions, IsBodyOrMassRow);
      if (ImGui::CollapsingHeader("initial conditions")) {
        DrawParamTable("initial", *row, row->element.kind, context.actions, IsInitialCondition);
      }
      if (row->element.kind != core::ElementKind::kRobot) DrawContactsNow(context, id);
    }
  }
  ImGui::End();
}

}  // namespace lamina::ui
