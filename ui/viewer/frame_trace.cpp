// SPDX-License-Identifier: MIT
#include "ui/viewer/frame_trace.h"

#include <nlohmann/json.hpp>

#include "core/render/world_poses.h"

namespace lamina::ui {

namespace {

nlohmann::json Vector(const core::Vec3& v) {
  return {v.x(), v.y(), v.z()};
}

const char* ToolName(MouseTool tool) {
  switch (tool) {
    case MouseTool::kSelect:
      return "select";
    case MouseTool::kForce:
      return "force";
    case MouseTool::kTorque:
      return "torque";
    case MouseTool::kKinematic:
      return "kinematic";
    case MouseTool::kPose:
      return "pose";
  }
  return "";
}

nlohmann::json DragJson(const SessionFrame& frame) {
  const core::DragState& drag = frame.drag;
  return {{"body", drag.body},
          {"force", Vector(drag.force)},
          {"target", Vector(drag.target)},
          {"local_point", Vector(drag.local_point)},
          {"effective_mass", drag.effective_mass},
          {"impulse", Vector(frame.drag_impulse)}};
}

nlohmann::json ObjectPositions(const SessionFrame& frame) {
  nlohmann::json positions = nlohmann::json::array();
  for (const core::Pose& pose : frame.poses.objects)
    positions.push_back(Vector(pose.translation()));
  return positions;
}

}  // namespace

bool FrameTrace::Open(const std::string& path, std::string* error) {
  out_.open(path, std::ios::trunc);
  if (!out_) *error = "--trace: cannot write '" + path + "'";
  return static_cast<bool>(out_);
}

void FrameTrace::Write(const SessionFrame& frame, const ViewerState& state) {
  if (!out_.is_open()) return;
  nlohmann::json line = {
      {"frame", frames_++},           {"time", frame.time},         {"playing", frame.playing},
      {"dirty", frame.dirty},         {"path", frame.path},         {"selected", state.selected_id},
      {"tool", ToolName(state.tool)}, {"dragging", frame.dragging}, {"kinematic", frame.kinematic},
      {"undo", frame.undo_label},     {"redo", frame.redo_label},   {"message", state.message}};
  if (frame.dragging) {
    line["drag"] = DragJson(frame);
    const std::optional<core::Pose> body =
        core::DrawnBodyFrame(*frame.world, frame.poses, frame.drag.body);
    if (body) line["drag"]["point"] = Vector(*body * frame.drag.local_point);
  }
  if (frame.loaded) {
    line["objects"] = ObjectPositions(frame);
    line["sampled_velocity"] = {Vector(frame.sampled_velocity.angular),
                                Vector(frame.sampled_velocity.linear)};
  }
  out_ << line.dump() << "\n";
  out_.flush();
}

}  // namespace lamina::ui
