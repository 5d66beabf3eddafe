// SPDX-License-Identifier: MIT
#include "ui/viewer/frame_trace.h"

#include <cmath>

#include <nlohmann/json.hpp>

#include "core/render/world_poses.h"
#include "ui/widgets/item_registry.h"

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

// JSON has no infinity: "inf" (nlohmann would write null)
nlohmann::json Number(double value) {
  if (std::isfinite(value)) return value;
  return value > 0 ? "inf" : "-inf";
}

// the sampled (selected) body's contacts now, one entry per partner
nlohmann::json ContactsJson(const SessionFrame& frame) {
  nlohmann::json contacts = nlohmann::json::array();
  for (const core::PairReadout& pair : frame.sampled_contacts) {
    contacts.push_back({{"partner", pair.partner},
                        {"friction", pair.friction.value},
                        {"own_friction", pair.friction.own},
                        {"partner_friction", pair.friction.partner},
                        {"restitution", pair.restitution.value},
                        {"stiffness", Number(pair.stiffness.value)},
                        {"damping", Number(pair.damping.value)},
                        {"count", pair.contact_count},
                        {"max_depth", pair.max_depth}});
  }
  return contacts;
}

// the named items the panels drew (item_registry.h): rectangle and text
nlohmann::json ItemsJson() {
  nlohmann::json items = nlohmann::json::object();
  for (const auto& [name, item] : RecordedItems())
    items[name] = {{"rect", {item.x0, item.y0, item.x1, item.y1}}, {"text", item.text}};
  return items;
}

}  // namespace

bool FrameTrace::Open(const std::string& path, std::string* error) {
  out_.open(path, std::ios::trunc);
  if (!out_) *error = "--trace: cannot write '" + path + "'";
  SetItemRecording(static_cast<bool>(out_));
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
    line["contacts"] = ContactsJson(frame);
    line["robots"] = nlohmann::json::array();
    for (const core::VecX& q : frame.poses.robots)
      line["robots"].push_back(std::vector<double>(q.data(), q.data() + q.size()));
  }
  line["items"] = ItemsJson();
  out_ << line.dump() << "\n";
  out_.flush();
}

}  // namespace lamina::ui
