// SPDX-License-Identifier: MIT
#include "ui/viewer/editor_actions.h"

#include <utility>

namespace lamina::ui {

namespace {

// "" on success, else the error: a command's message
std::string Outcome(bool ok, const std::string& error) {
  return ok ? "" : error;
}

std::string SaveOutcome(bool ok, const core::Diagnostics& diagnostics, const std::string& path) {
  return ok ? "saved " + path : "cannot save " + path + ": " + diagnostics.FormatAll();
}

// undo or redo one entry: "undid <label>", or why not
std::string StepHistory(core::LiveWorld& world, bool undo) {
  const core::History& history = world.history();
  if (undo ? !world.CanUndo() : !world.CanRedo()) {
    return undo ? "nothing to undo" : "nothing to redo";
  }
  const std::string label = undo ? history.UndoLabel() : history.RedoLabel();
  std::string error;
  const bool ok = undo ? world.Undo(&error) : world.Redo(&error);
  return ok ? (undo ? "undid " : "redid ") + label : error;
}

}  // namespace

EditorActions::RowKey EditorActions::KeyOf(const core::ElementRef& ref,
                                           const core::ParamSpec& spec) {
  return {static_cast<int>(ref.kind), ref.uid, ref.sub, core::ParamId(spec)};
}

void EditorActions::SetParam(const core::ElementRef& ref, const core::ParamSpec& spec,
                             core::ParamValue value) {
  const long sequence = session_->Post([ref, &spec, value](core::LiveWorld& world) {
    std::string error;
    const std::optional<core::ParamEdit> edit =
        core::MakeParamEdit(world.document(), ref, spec.key, value, &error);
    return Outcome(edit && world.Do(*edit, &error), error);
  });
  pending_[KeyOf(ref, spec)] = {sequence, std::move(value)};
}

void EditorActions::SetAutoSolver(bool on) {
  session_->SetAutoSolver(on);
}

void EditorActions::BeginGroup(std::string label) {
  session_->Post([label = std::move(label)](core::LiveWorld& world) {
    world.BeginGroup(label);
    return std::string();
  });
}

void EditorActions::EndGroup() {
  session_->Post([](core::LiveWorld& world) {
    world.EndGroup();
    return std::string();
  });
}

void EditorActions::BeginWidgetGroup() {
  ++open_widget_groups_;
  BeginGroup("");
}

void EditorActions::EndWidgetGroup() {
  if (open_widget_groups_ == 0) return;
  --open_widget_groups_;
  EndGroup();
}

void EditorActions::EndIdleWidgetGroups(bool any_widget_active) {
  while (!any_widget_active && open_widget_groups_ > 0) EndWidgetGroup();
}

const core::ParamValue& EditorActions::Shown(const core::ElementRef& ref,
                                             const core::ParamSpec& spec,
                                             const core::ParamValue& current) const {
  const auto found = pending_.find(KeyOf(ref, spec));
  return found == pending_.end() ? current : found->second.value;
}

void EditorActions::Forget(const SessionFrame& frame) {
  std::erase_if(pending_,
                [&](const auto& entry) { return entry.second.sequence <= frame.commands_done; });
}

void EditorActions::Undo() {
  session_->Post([](core::LiveWorld& world) { return StepHistory(world, true); });
}

void EditorActions::Redo() {
  session_->Post([](core::LiveWorld& world) { return StepHistory(world, false); });
}

void EditorActions::MakeCurrentStateInitial() {
  session_->Post([](core::LiveWorld& world) {
    std::string error;
    return world.MakeCurrentStateInitial(&error) ? "the current state is now the initial state"
                                                 : error;
  });
}

bool EditorActions::Save(const SessionFrame& frame) {
  if (frame.path.empty()) return false;
  session_->Post([](core::LiveWorld& world) {
    core::Diagnostics diagnostics;
    const bool ok = world.Save(diagnostics);
    return SaveOutcome(ok, diagnostics, world.document().path());
  });
  return true;
}

void EditorActions::SaveAs(const std::string& path) {
  session_->Post([path](core::LiveWorld& world) {
    core::Diagnostics diagnostics;
    return SaveOutcome(world.SaveAs(path, diagnostics), diagnostics, path);
  });
}

void EditorActions::Reset() {
  session_->Post([](core::LiveWorld& world) {
    world.simulator().Reset();
    return std::string();
  });
}

void EditorActions::Step(int steps) {
  session_->Post([steps](core::LiveWorld& world) {
    core::Simulator& simulator = world.simulator();
    for (int i = 0; i < steps && !simulator.halted(); ++i) simulator.Simulate(simulator.sim_step());
    return std::string();
  });
}

void EditorActions::CommandJoints(int robot, const core::VecX& q) {
  session_->Post([robot, q](core::LiveWorld& world) {
    core::RobotController& controller = world.simulator().controller(robot);
    return Outcome(controller.SetMilestone(q), controller.last_error());
  });
}

void EditorActions::StartForce(int id, const core::Vec3& point) {
  session_->Post([id, point](core::LiveWorld& world) {
    return Outcome(world.simulator().StartDrag(id, point),
                   "body " + std::to_string(id) + " cannot be pulled (static or kinematic)");
  });
}

void EditorActions::MoveForce(const core::Vec3& target) {
  session_->Post([target](core::LiveWorld& world) {
    if (world.simulator().dragging()) world.simulator().SetDragTarget(target);
    return std::string();
  });
}

void EditorActions::StartTorque(int id) {
  session_->Post([id](core::LiveWorld& world) {
    return Outcome(world.simulator().StartRotateDrag(id),
                   "body " + std::to_string(id) + " cannot be turned (static or kinematic)");
  });
}

void EditorActions::TurnTorque(const core::Mat3& rotation) {
  session_->Post([rotation](core::LiveWorld& world) {
    if (world.simulator().dragging()) world.simulator().SetDragTargetOrientation(rotation);
    return std::string();
  });
}

void EditorActions::EndDrag() {
  session_->Post([](core::LiveWorld& world) {
    world.simulator().EndDrag();
    return std::string();
  });
}

void EditorActions::MoveKinematic(int id, const core::Pose& target, double duration) {
  session_->Post([id, target, duration](core::LiveWorld& world) {
    return Outcome(world.simulator().SetKinematicTarget(id, target, duration),
                   "body " + std::to_string(id) + " cannot be moved (static or disabled)");
  });
}

void EditorActions::ReleaseKinematic(int id) {
  session_->Post([id](core::LiveWorld& world) {
    world.simulator().ReleaseKinematicTarget(id);
    return std::string();
  });
}

}  // namespace lamina::ui
