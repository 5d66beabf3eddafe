// SPDX-License-Identifier: MIT
#include "ui/panels/plots_panel.h"

#include <cmath>

#include <imgui.h>

namespace lamina::ui {

namespace {

// the driver of robot link `link` (a normal driver of that link alone), or -1
int DriverOfLink(const core::RobotDesc& robot, int link) {
  for (int d = 0; d < static_cast<int>(robot.drivers.size()); ++d) {
    if (robot.drivers[d].links.size() == 1 && robot.drivers[d].links[0] == link) return d;
  }
  return -1;
}

void DrawGroup(const char* id, const PlotGroup& group, PlotView* view, ViewerState* state) {
  if (!ImGui::CollapsingHeader(group.title().c_str(), ImGuiTreeNodeFlags_DefaultOpen)) return;
  if (DrawPlot(id, group, view, ImVec2(0, 170))) state->message = view->message;
}

}  // namespace

PlotPanel::PlotPanel()
    : energy_("energy"),
      contact_("contact of the selected body"),
      timing_("timing"),
      joint_("joint of the selected link") {
  energy_.AddSeries("kinetic", "J");
  energy_.AddSeries("potential", "J");
  energy_.AddSeries("total", "J");
  contact_.AddSeries("contact force", "N");
  contact_.AddSeries("overlap", "mm");
  timing_.AddSeries("real-time factor", "");
  timing_.AddSeries("step", "ms");
  joint_.AddSeries("commanded", "rad or m");
  joint_.AddSeries("sensed", "rad or m");
  joint_.AddSeries("torque", "N·m or N");
  energy_view_.csv_path = "lamina-energy.csv";
  contact_view_.csv_path = "lamina-contact.csv";
  timing_view_.csv_path = "lamina-timing.csv";
  joint_view_.csv_path = "lamina-joint.csv";
}

void PlotPanel::Add(const std::vector<SessionSample>& samples, const SessionFrame& frame) {
  for (const SessionSample& sample : samples) {
    if (sample.body != body_) {  // another body: its plots start afresh
      body_ = sample.body;
      contact_.Clear();
      joint_.Clear();
    }
    energy_.AddRow(sample.time,
                   {sample.kinetic, sample.potential, sample.kinetic + sample.potential});
    timing_.AddRow(sample.time, {sample.real_time_factor, sample.step * 1e3});
    if (sample.body >= 0) {
      contact_.AddRow(sample.time, {sample.contact_force, sample.overlap * 1e3});
      AddJoint(sample, frame);
    }
  }
}

void PlotPanel::AddJoint(const SessionSample& sample, const SessionFrame& frame) {
  if (sample.robot < 0 || !frame.loaded) return;
  const core::WorldId body = frame.world->Resolve(sample.body);
  if (body.kind != core::WorldId::Kind::kRobotLink || body.index != sample.robot) return;
  const int link = body.link;
  if (link >= sample.sensed.size() || link >= sample.commanded.size()) return;
  const int driver = DriverOfLink(frame.world->robots[sample.robot], link);
  const double torque =
      driver >= 0 && driver < sample.torques.size() ? sample.torques[driver] : std::nan("");
  joint_.AddRow(sample.time, {sample.commanded[link], sample.sensed[link], torque});
}

void PlotPanel::Draw(const PanelContext& context) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(320, display.y - 420), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(display.x - 730, 390), ImGuiCond_FirstUseEver);
  if (ImGui::Begin("Plots", &context.state->panels.plots)) {
    DrawGroup("energy", energy_, &energy_view_, context.state);
    if (body_ >= 0) DrawGroup("contact", contact_, &contact_view_, context.state);
    if (body_ >= 0 && joint_.series()[0].size() > 0) {
      DrawGroup("joint", joint_, &joint_view_, context.state);
    }
    DrawGroup("timing", timing_, &timing_view_, context.state);
  }
  ImGui::End();
}

}  // namespace lamina::ui
