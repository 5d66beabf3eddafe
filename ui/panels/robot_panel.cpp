// SPDX-License-Identifier: MIT
// Robot panel: for the robot of the selected body, a slider per driven joint that sends the
// controller a milestone (a smooth motion there) with the sensed and commanded values beside it,
// then every driver's rows of the parameter table (gains, torque and velocity limits, dry and
// viscous friction), each a live edit that is part of the document (it survives Reset and is
// saved).
#include <algorithm>
#include <cmath>

#include <imgui.h>

#include "ui/panels/panels.h"
#include "ui/panels/param_widgets.h"
#include "ui/widgets/item_registry.h"

namespace lamina::ui {

namespace {

constexpr double kPi = 3.14159265358979323846;

// the robot index of the selected body (a robot or one of its links), or -1
int SelectedRobot(const core::WorldDesc& world, int id) {
  const core::WorldId body = world.Resolve(id);
  const bool robot =
      body.kind == core::WorldId::Kind::kRobot || body.kind == core::WorldId::Kind::kRobotLink;
  return robot ? body.index : -1;
}

core::VecX& TargetsOf(ViewerState* state, int robot, const RobotFrame& frame, double time) {
  if (time < state->joint_targets_time) state->joint_targets.clear();  // a reset or an undo
  state->joint_targets_time = time;
  core::VecX& q = state->joint_targets[robot];
  if (q.size() != frame.commanded.size()) q = frame.commanded;
  return q;
}

void SliderRange(const core::LinkDesc& link, double* low, double* high) {
  *low = std::isfinite(link.q_min) ? link.q_min : -kPi;
  *high = std::isfinite(link.q_max) ? link.q_max : kPi;
}

void DrawJointSliders(const PanelContext& context, int r) {
  const core::RobotDesc& robot = context.frame.world->robots[r];
  const RobotFrame& live = context.frame.robots[r];
  core::VecX& q = TargetsOf(context.state, r, live, context.frame.time);
  for (const core::DriverDesc& driver : robot.drivers) {
    if (driver.type != core::DriverType::kNormal || driver.links.size() != 1) continue;
    const int l = driver.links[0];
    double low = 0.0, high = 0.0;
    SliderRange(robot.links[l], &low, &high);
    ImGui::PushID(l);
    ImGui::SetNextItemWidth(120);
    if (ImGui::SliderScalar(driver.name.c_str(), ImGuiDataType_Double, &q[l], &low, &high,
                            "%.3f")) {
      context.actions->CommandJoints(r, q);
    }
    ImGui::SameLine(255);
    ImGui::TextDisabled("%+.3f / %+.3f", live.sensed[l], live.commanded[l]);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("sensed / commanded (the PID target now)");
    ImGui::PopID();
  }
}

void DrawDrivers(const PanelContext& context, int r) {
  const core::RobotDesc& robot = context.frame.world->robots[r];
  for (int d = 0; d < static_cast<int>(robot.drivers.size()); ++d) {
    ImGui::PushID(d);
    const bool open = ImGui::TreeNode(robot.drivers[d].name.c_str());
    if (ItemRecording()) RecordItem(core::ElementPath(core::ElementIndex::Driver(r, d)));
    if (open) {
      const ParamRowContext row{*context.frame.world, context.file_world,
                                core::ElementIndex::Driver(r, d),
                                core::ElementRef::Driver(robot.uid, d)};
      DrawParamTable("driver", row, core::ElementKind::kDriver, context.actions);
      ImGui::TreePop();
    }
    ImGui::PopID();
  }
}

}  // namespace

void DrawRobotPanel(const PanelContext& context) {
  if (!context.frame.loaded) return;
  const int r = SelectedRobot(*context.frame.world, context.state->selected_id);
  if (r < 0 || r >= static_cast<int>(context.frame.robots.size())) return;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x - 400, display.y * 0.55f + 40), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(390, display.y * 0.45f - 80), ImGuiCond_FirstUseEver);
  const std::string title = "Robot " + context.frame.world->robots[r].name + "###Robot";
  if (ImGui::Begin(title.c_str(), &context.state->panels.robot)) {
    if (ImGui::CollapsingHeader("joints", ImGuiTreeNodeFlags_DefaultOpen)) {
      DrawJointSliders(context, r);
    }
    if (ImGui::CollapsingHeader("drivers", ImGuiTreeNodeFlags_DefaultOpen)) {
      DrawDrivers(context, r);
    }
  }
  ImGui::End();
}

}  // namespace lamina::ui
