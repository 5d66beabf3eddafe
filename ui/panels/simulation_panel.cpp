// SPDX-License-Identifier: MIT
// Simulation panel: the transport controls and what the simulation is doing.
#include <imgui.h>

#include "ui/panels/panels.h"

namespace lamina::ui {

namespace {

void DrawTransport(const WorldSession& session, ViewerState* state) {
  if (ImGui::Button(state->playing ? "Pause" : "Play", ImVec2(70, 0))) {
    state->playing = !state->playing;
  }
  ImGui::SameLine();
  if (ImGui::Button("Step")) state->requests.step = true;
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("one physics step (S or Right); Shift: 1/60 s");
  ImGui::SameLine();
  if (ImGui::Button("Reset")) state->requests.reset = true;
  float speed = static_cast<float>(state->speed);
  if (ImGui::SliderFloat("speed", &speed, static_cast<float>(kMinSpeed),
                         static_cast<float>(kMaxSpeed), "%.2fx", ImGuiSliderFlags_Logarithmic)) {
    state->speed = speed;
  }
  int solver = state->solver == core::SolverType::kStep ? 0 : 1;
  ImGui::Text("solver");
  ImGui::SameLine();
  bool changed = ImGui::RadioButton("step", &solver, 0);
  ImGui::SameLine();
  changed |= ImGui::RadioButton("quick step", &solver, 1);
  if (changed) state->solver = solver == 0 ? core::SolverType::kStep : core::SolverType::kQuickStep;
  ImGui::Checkbox("sleep idle objects", &state->sleep);
  if (ImGui::IsItemHovered()) {
    const core::Simulator* simulator = session.simulator();
    const double sleep_time =
        simulator ? simulator->world().settings.sleep_time : core::SimSettings{}.sleep_time;
    ImGui::SetTooltip("objects idle for %.2g s leave the steps until something touches them",
                      sleep_time);
  }
}

void DrawStatistics(const WorldSession& session, const ViewerState& state) {
  const core::Simulator* simulator = session.simulator();
  if (!simulator) {
    ImGui::TextUnformatted("no world loaded");
    return;
  }
  const core::SimStatistics& statistics = simulator->statistics();
  ImGui::Text("time          %.3f s", simulator->time());
  ImGui::Text("real time     %.2fx %s", state.real_time_factor, state.playing ? "" : "(paused)");
  ImGui::Text("step          %.4g s", simulator->sim_step());
  ImGui::Text("status        %s", core::StepStatusName(session.last_status()));
  ImGui::Text("worst status  %s", core::StepStatusName(statistics.worst_status));
  ImGui::Text("steps         %ld", statistics.steps);
  ImGui::Text("rollbacks     %ld", statistics.rollbacks);
  ImGui::Text("contacts      %zu pairs (max %d joints)", simulator->contact_pairs().size(),
              statistics.max_contacts_in_step);
  if (simulator->sleeping()) {
    ImGui::Text("asleep        %d of %d objects", simulator->SleepingObjectCount(),
                simulator->object_count());
  }
  ImGui::Text("frame         %.1f ms", state.frame_milliseconds);
  if (!statistics.error.empty()) ImGui::TextWrapped("error: %s", statistics.error.c_str());
}

}  // namespace

void DrawSimulationPanel(const WorldSession& session, ViewerState* state) {
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
  if (ImGui::Begin("Simulation", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::PushItemWidth(200);
    DrawTransport(session, state);
    ImGui::Separator();
    DrawStatistics(session, *state);
    ImGui::PopItemWidth();
  }
  ImGui::End();
}

}  // namespace lamina::ui
