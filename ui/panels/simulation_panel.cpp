// SPDX-License-Identifier: MIT
// Simulation panel: the transport controls, the mouse tool and what the simulation is doing.
#include <algorithm>
#include <cstdio>
#include <string>

#include <imgui.h>

#include "ui/panels/panels.h"
#include "ui/panels/param_widgets.h"
#include "ui/widgets/item_registry.h"

namespace lamina::ui {

namespace {

void DrawTransport(const PanelContext& context) {
  ViewerState* state = context.state;
  if (ImGui::Button(state->playing ? "Pause" : "Play", ImVec2(70, 0))) {
    state->playing = !state->playing;
  }
  RecordItem("button.play");
  ImGui::SameLine();
  if (ImGui::Button("Step")) state->requests.step = true;
  RecordItem("button.step");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("one physics step (S or Right); Shift: 1/60 s");
  ImGui::SameLine();
  if (ImGui::Button("Reset")) state->requests.reset = true;
  RecordItem("button.reset");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("back to the initial state (R or Backspace)");
  float speed = static_cast<float>(state->speed);
  if (ImGui::SliderFloat("speed", &speed, static_cast<float>(kMinSpeed),
                         static_cast<float>(kMaxSpeed), "%.2fx", ImGuiSliderFlags_Logarithmic)) {
    state->speed = speed;
  }
}

void DrawToolChoice(ViewerState* state) {
  struct Choice {
    const char* name;
    MouseTool tool;
    const char* help;
  };
  static const Choice kChoices[] = {
      {"select", MouseTool::kSelect, "click selects; drag turns the camera (Q)"},
      {"force", MouseTool::kForce, "drag a body: a spring pulls the grabbed point (W)"},
      {"torque", MouseTool::kTorque, "drag a body: a spring turns it (E)"},
      {"drag", MouseTool::kKinematic, "drag a body kinematically; release throws it (T)"},
      {"pose", MouseTool::kPose, "paused: move a body's initial pose; X/Y/Z lock an axis (G)"}};
  ImGui::TextUnformatted("tool");
  int i = 0;
  for (const Choice& choice : kChoices) {
    if (i++ != 3) ImGui::SameLine(i > 3 ? 0.0f : 45.0f + 75.0f * static_cast<float>(i - 1));
    if (i == 4) ImGui::SetCursorPosX(ImGui::GetCursorPosX() + 45.0f);
    if (ImGui::RadioButton(choice.name, state->tool == choice.tool)) state->tool = choice.tool;
    RecordItem(std::string("tool.") + choice.name);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", choice.help);
  }
}

// the solver running now (orange when the real-time choice put another solver in place of the
// world's exact solver), and the choice's switch (solver_choice.h)
void DrawSolver(const PanelContext& context) {
  const SessionFrame& frame = context.frame;
  const char* name = frame.solver.type == core::SolverType::kStep     ? "exact"
                     : frame.solver.type == core::SolverType::kNewton ? "newton"
                                                                      : "quick step";
  ImGui::TextUnformatted("solver     ");
  ImGui::SameLine();
  if (frame.solver_chosen) {
    ImGui::TextColored(ImVec4(1.0f, 0.75f, 0.3f, 1.0f), "%s", name);
  } else {
    ImGui::TextUnformatted(name);
  }
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "%s%s", SolverText(frame).c_str(),
        frame.solver_chosen ? ".\nThe world's own solver is exact; its file keeps it." : "");
  }
  ImGui::SameLine(190.0f);
  bool on = frame.auto_solver;
  if (ImGui::Checkbox("auto", &on)) context.actions->SetAutoSolver(on);
  RecordItem("solver.auto");
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "When the exact solver cannot keep real time within 80 %% of a core, play with the\n"
        "Newton solver instead (the same answer, faster); the world's file is not changed.\n"
        "Off: always the world's solver.");
  }
}

// "4.9 mm/s": the meter's rate in the unit that keeps it at 1 or more (nm/s at the least; the
// font has µ but no ≈)
std::string RateText(double rate) {
  struct Unit {
    double scale;
    const char* name;
  };
  static const Unit kUnits[] = {{1.0, "m/s"}, {1e3, "mm/s"}, {1e6, "µm/s"}, {1e9, "nm/s"}};
  const Unit* unit = &kUnits[0];
  for (const Unit& u : kUnits) {
    unit = &u;
    if (rate * u.scale >= 1.0) break;
  }
  char text[48];
  std::snprintf(text, sizeof text, "%.2g %s", rate * unit->scale, unit->name);
  return text;
}

void DrawErrorMeter(const SessionFrame& frame) {
  const core::ErrorMeterReading& meter = frame.error_meter;
  if (!meter.valid) {
    ImGui::TextUnformatted("error       (not sampled yet)");
  } else {
    ImGui::Text("error       ~%s", RateText(meter.rate).c_str());
  }
  RecordItem("text.error_meter");
  if (ImGui::IsItemHovered() && meter.valid) {
    ImGui::SetTooltip(
        "How fast the simulation's position error grows, per simulated second, estimated by\n"
        "taking sampled steps whole and in halves from the same state (step doubling):\n"
        "%.3g m per step, largest of the recent samples at t = %.3f s. A smaller step\n"
        "lowers it (first order: half the step, half the rate). %ld samples, %.1f %% extra time;\n"
        "the results are the same with or without it.",
        meter.local_error, meter.time, meter.samples, 100.0 * meter.overhead);
  }
}

void DrawStatistics(const PanelContext& context) {
  const SessionFrame& frame = context.frame;
  if (!frame.loaded) {
    ImGui::TextUnformatted("no world loaded");
    return;
  }
  ImGui::Text("time        %.3f s", frame.time);
  ImGui::Text("real time   %.2fx %s", frame.real_time_factor, frame.playing ? "" : "(paused)");
  ImGui::Text("step        %.4g s", frame.step);
  DrawSolver(context);
  ImGui::Text("status      %s", core::StepStatusName(frame.status));
  ImGui::Text("steps       %ld", frame.steps);
  ImGui::Text("contacts    %zu", frame.contacts.size());
  ImGui::Text("energy      %.4g J (kinetic %.3g)", frame.kinetic_energy + frame.potential_energy,
              frame.kinetic_energy);
  DrawErrorMeter(frame);
  ImGui::Text("frame       %.1f ms", context.state->frame_milliseconds);
  if (!frame.problem.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
    ImGui::TextWrapped("%s", frame.problem.c_str());
    ImGui::PopStyleColor();
  }
}

}  // namespace

void DrawSimulationPanel(const PanelContext& context) {
  ImGui::SetNextWindowPos(ImVec2(10, MenuBarHeight() + 8), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSizeConstraints(ImVec2(300, 0), ImVec2(300, 1e6f));
  if (ImGui::Begin("Simulation", &context.state->panels.simulation,
                   ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::PushItemWidth(180);
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + 280);
    DrawTransport(context);
    DrawToolChoice(context.state);
    ImGui::Separator();
    DrawStatistics(context);
    ImGui::PopTextWrapPos();
    ImGui::PopItemWidth();
  }
  ImGui::End();
}

void DrawSettingsPanel(const PanelContext& context) {
  if (!context.frame.loaded) return;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  // between the Overlays panel and the Inspector, above the Plots
  ImGui::SetNextWindowPos(ImVec2(display.x - 792, MenuBarHeight() + 8), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(390, std::max(200.0f, display.y - 440 - MenuBarHeight())),
                           ImGuiCond_FirstUseEver);
  if (ImGui::Begin("Simulation settings", &context.state->panels.settings)) {
    const ParamRowContext row{*context.frame.world, context.file_world,
                              core::ElementIndex::Settings(), core::ElementRef::Settings()};
    DrawParamTable("settings", row, core::ElementKind::kSettings, context.actions);
  }
  ImGui::End();
}

}  // namespace lamina::ui
