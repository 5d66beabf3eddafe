// SPDX-License-Identifier: MIT
// World panel: what is loaded, the diagnostics of the last load, and the selected body with
// where it is now (the drawn poses, not the description's initial pose).
#include <imgui.h>

#include "core/render/world_poses.h"
#include "ui/panels/panels.h"

namespace lamina::ui {

std::string BodyLabel(const core::WorldDesc& world, int id) {
  const core::WorldId body = world.Resolve(id);
  const std::string number = " (id " + std::to_string(id) + ")";
  switch (body.kind) {
    case core::WorldId::Kind::kTerrain:
      return "terrain '" + world.terrains[body.index].name + "'" + number;
    case core::WorldId::Kind::kRigidObject:
      return "object '" + world.objects[body.index].name + "'" + number;
    case core::WorldId::Kind::kRobot:
      return "robot '" + world.robots[body.index].name + "'" + number;
    case core::WorldId::Kind::kRobotLink:
      return "link '" + world.robots[body.index].links[body.link].name + "' of robot '" +
             world.robots[body.index].name + "'" + number;
    case core::WorldId::Kind::kInvalid:
      break;
  }
  return "nothing";
}

namespace {

void DrawContents(const core::WorldDesc& world) {
  ImGui::Text("%zu terrains, %zu objects, %zu robots", world.terrains.size(), world.objects.size(),
              world.robots.size());
  for (const auto& robot : world.robots) {
    ImGui::BulletText("robot '%s': %d links, %.3f kg", robot.name.c_str(), robot.dof(),
                      robot.TotalMass());
  }
}

void DrawSelection(const WorldSession& session, ViewerState* state) {
  ImGui::Separator();
  if (state->selected_id < 0) {
    ImGui::TextDisabled("click a body to select it");
    return;
  }
  const core::WorldDesc& world = session.description();
  ImGui::TextWrapped("selected: %s", BodyLabel(world, state->selected_id).c_str());
  const std::optional<core::Pose> frame =
      core::DrawnBodyFrame(world, session.poses(), state->selected_id);
  if (frame) {
    const core::Vec3 p = frame->translation();
    ImGui::Text("frame now at %.4f %.4f %.4f m", p.x(), p.y(), p.z());
  }
  if (ImGui::SmallButton("clear selection")) state->selected_id = -1;
}

}  // namespace

void DrawWorldPanel(const WorldSession& session, ViewerState* state) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x - 390, 10), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSizeConstraints(ImVec2(380, 0),
                                      ImVec2(380, OpenWorldPanelTop(display.y) - 20.0f));
  if (ImGui::Begin("World", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + 360);
    const core::WorldDesc& world = session.description();
    if (session.loaded()) {
      ImGui::Text("%s", world.name.c_str());
      ImGui::TextDisabled("%s", session.path().c_str());
      ImGui::Separator();
      DrawContents(world);
    }
    if (!session.load_messages().entries().empty()) {
      ImGui::Separator();
      const bool errors = session.load_messages().HasErrors();
      if (errors) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
      ImGui::TextWrapped("%s", session.load_messages().FormatAll().c_str());
      if (errors) ImGui::PopStyleColor();
    }
    if (session.loaded()) DrawSelection(session, state);
    ImGui::PopTextWrapPos();
  }
  ImGui::End();
}

}  // namespace lamina::ui
