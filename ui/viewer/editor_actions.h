// SPDX-License-Identifier: MIT
// EditorActions: what the panels, the keys and the mouse tools ask of the world, each posted to
// the LiveSession as one command (carried out on the physics thread between two steps). Panels
// never touch the LiveWorld; they read SessionFrames and call these.
//
// Pending values: a widget that edits a row shows the value it sent until the command has been
// carried out and a frame with it published (a refused edit then shows the document's value
// again, and its message reaches the status line). Without this a dragged slider would read the
// previous frame's value and lose the mouse motion of every frame the physics had not caught up.
//
// Undo steps: SetParam inside BeginGroup/EndGroup (ImGui's IsItemActivated and
// IsItemDeactivated of the widget) is one history entry however many values a drag sent.
#pragma once

#include <map>
#include <string>
#include <tuple>

#include "core/edit/element_ref.h"
#include "core/model/params.h"
#include "ui/viewer/live_session.h"

namespace lamina::ui {

class EditorActions {
 public:
  explicit EditorActions(LiveSession* session) : session_(session) {}

  // ---- edits of the document (through core::LiveWorld::Do: one undo step each) ------------
  /// Row `spec` of element `ref` becomes `value` (checked by the table on the physics thread).
  void SetParam(const core::ElementRef& ref, const core::ParamSpec& spec, core::ParamValue value);
  /// Edits until EndGroup are one undo step named `label` ("": named by its first edit).
  void BeginGroup(std::string label);
  void EndGroup();
  /// A widget's group (its activation to its deactivation). A widget that is not drawn on the
  /// frame it is left (its panel closed, the selection changed) never sees its deactivation:
  /// EndIdleWidgetGroups, called once a frame after the panels, ends the group when no widget is
  /// active any more, so that later edits do not join it.
  void BeginWidgetGroup();
  void EndWidgetGroup();
  void EndIdleWidgetGroups(bool any_widget_active);
  /// `current` (the frame's value), or the value of an edit of this row still on its way.
  const core::ParamValue& Shown(const core::ElementRef& ref, const core::ParamSpec& spec,
                                const core::ParamValue& current) const;
  /// Forgets pending values whose edits `frame` already shows.
  void Forget(const SessionFrame& frame);
  void Undo();
  void Redo();
  /// "Use current state as initial" for the whole world.
  void MakeCurrentStateInitial();
  /// Saves to the document's file (Save As when it has none: returns false, nothing posted).
  bool Save(const SessionFrame& frame);
  void SaveAs(const std::string& path);

  // ---- time -----------------------------------------------------------------------------
  void Reset();
  /// The real-time solver choice on or off (LiveSession::SetAutoSolver).
  void SetAutoSolver(bool on);
  /// `steps` physics steps now (while paused).
  void Step(int steps);

  // ---- robots ---------------------------------------------------------------------------
  /// Sends the controller of `robot` to `q` (link space) as a milestone: a smooth motion.
  void CommandJoints(int robot, const core::VecX& q);

  // ---- mouse tools (interaction.h) -------------------------------------------------------
  /// Grabs body `id` at world `point` with the mouse spring (force tool).
  void StartForce(int id, const core::Vec3& point);
  void MoveForce(const core::Vec3& target);
  /// Grabs body `id` with the rotational spring (torque tool).
  void StartTorque(int id);
  void TurnTorque(const core::Mat3& rotation);
  void EndDrag();
  /// Body `id` follows `target` kinematically, reaching it after `duration` s of simulated time.
  void MoveKinematic(int id, const core::Pose& target, double duration);
  void ReleaseKinematic(int id);

 private:
  using RowKey = std::tuple<int, std::uint64_t, int, int>;  ///< kind, uid, sub, row
  struct Pending {
    long sequence = 0;
    core::ParamValue value;
  };
  static RowKey KeyOf(const core::ElementRef& ref, const core::ParamSpec& spec);

  LiveSession* session_;
  std::map<RowKey, Pending> pending_;
  int open_widget_groups_ = 0;
};

}  // namespace lamina::ui
