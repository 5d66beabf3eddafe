// SPDX-License-Identifier: MIT
#include "ui/panels/sensors_panel.h"

#include <cmath>
#include <span>

#include <imgui.h>

namespace lamina::ui {

namespace {

constexpr size_t kShownAtFirst = 12;  // SimTest's fixed colours; the rest start hidden
constexpr int kValueColumns = 3;
constexpr size_t kOpenAtFirst = 2;  // sensors whose section starts open

// a file name made of the sensor's safe characters
std::string CsvName(const std::string& robot, const std::string& sensor) {
  std::string name = "lamina-sensor-" + robot + "-" + sensor + ".csv";
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-') c = '_';
  }
  return name;
}

void DrawValues(const core::SensorReadout& readout) {
  if (!ImGui::BeginTable("values", kValueColumns * 2, ImGuiTableFlags_SizingFixedFit)) return;
  for (size_t i = 0; i < readout.names.size(); ++i) {
    ImGui::TableNextColumn();
    ImGui::TextDisabled("%s", readout.names[i].c_str());
    ImGui::TableNextColumn();
    if (i < readout.values.size()) {
      ImGui::Text("%.5g", readout.values[i] + 0.0);  // + 0: -0 shows as 0
    } else {
      ImGui::TextDisabled("-");
    }
  }
  ImGui::EndTable();
}

}  // namespace

SensorPanel::SensorPanel() = default;
SensorPanel::~SensorPanel() = default;

// the plots follow the sensors' names: another world or edited sensors start afresh
bool SensorPanel::Matches(const SessionFrame& frame) const {
  if (plots_.size() != frame.robots.size()) return false;
  for (size_t r = 0; r < plots_.size(); ++r) {
    const std::vector<core::SensorReadout>& sensors = frame.robots[r].sensors;
    if (plots_[r].size() != sensors.size()) return false;
    for (size_t i = 0; i < sensors.size(); ++i) {
      if (plots_[r][i].name != sensors[i].name || plots_[r][i].type != sensors[i].type) {
        return false;
      }
    }
  }
  return true;
}

void SensorPanel::Rebuild(const SessionFrame& frame) {
  plots_.clear();
  for (size_t r = 0; r < frame.robots.size(); ++r) {
    plots_.emplace_back();
    const std::string& robot = frame.world->robots[r].name;
    for (const core::SensorReadout& s : frame.robots[r].sensors) {
      Plot plot{s.name, s.type, std::make_unique<PlotGroup>(s.name), {}};
      for (size_t k = 0; k < s.names.size(); ++k) {
        plot.group->AddSeries(s.names[k], "");
        if (k >= kShownAtFirst) plot.view.hidden.insert(s.names[k]);
      }
      plot.view.csv_path = CsvName(robot, s.name);
      plots_.back().push_back(std::move(plot));
    }
  }
}

void SensorPanel::Add(const std::vector<SessionSample>& samples, const SessionFrame& frame) {
  if (!frame.loaded) return;
  if (!Matches(frame)) Rebuild(frame);
  for (const SessionSample& sample : samples) {
    for (size_t r = 0; r < plots_.size() && r < sample.sensors.size(); ++r) {
      for (size_t i = 0; i < plots_[r].size() && i < sample.sensors[r].size(); ++i) {
        if (plots_[r][i].group->series().empty()) continue;
        plots_[r][i].group->AddRow(sample.time, std::span<const double>(sample.sensors[r][i]));
      }
    }
  }
}

// the selected link's robot, else the first
int SensorPanel::Robot(const PanelContext& context) const {
  const SessionFrame& frame = context.frame;
  if (!frame.loaded || frame.robots.empty()) return -1;
  const core::WorldId id = frame.world->Resolve(context.state->selected_id);
  return id.kind == core::WorldId::Kind::kRobotLink ? id.index : 0;
}

void SensorPanel::DrawSensor(const core::SensorReadout& readout, Plot* plot, bool open,
                             ViewerState* state) {
  const std::string header = readout.name + "  (" + readout.type + ")";
  if (!ImGui::CollapsingHeader(header.c_str(), open ? ImGuiTreeNodeFlags_DefaultOpen : 0)) return;
  ImGui::PushID(header.c_str());
  if (readout.link >= 0) ImGui::TextDisabled("on link %d", readout.link);
  if (readout.image) {
    ImGui::TextWrapped(
        "A camera: its pictures come from lamina-headless run --sensor-images DIR (the editor "
        "gives its simulation no camera renderer yet). Overlay 9 draws its frustum.");
  } else {
    DrawValues(readout);
    if (plot && DrawPlot("plot", *plot->group, &plot->view, ImVec2(0, 160))) {
      state->message = plot->view.message;
    }
  }
  ImGui::PopID();
}

void SensorPanel::Draw(const PanelContext& context) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x - 420, 300), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(400, 480), ImGuiCond_FirstUseEver);
  if (ImGui::Begin("Sensors", &context.state->panels.sensors)) {
    const int r = Robot(context);
    if (r < 0) {
      ImGui::TextDisabled("No robot in this world.");
    } else {
      const std::vector<core::SensorReadout>& sensors = context.frame.robots[r].sensors;
      ImGui::Text("robot '%s': %zu sensors", context.frame.world->robots[r].name.c_str(),
                  sensors.size());
      ImGui::TextDisabled("select a link of another robot to see its sensors");
      for (size_t i = 0; i < sensors.size(); ++i) {
        Plot* plot =
            r < static_cast<int>(plots_.size()) && i < plots_[r].size() ? &plots_[r][i] : nullptr;
        DrawSensor(sensors[i], plot, i < kOpenAtFirst, context.state);
      }
    }
  }
  ImGui::End();
}

}  // namespace lamina::ui
