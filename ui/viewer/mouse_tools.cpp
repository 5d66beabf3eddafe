// SPDX-License-Identifier: MIT
#include "ui/viewer/mouse_tools.h"

#include <cmath>
#include <cstdio>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include "core/render/world_poses.h"
#include "core/robot/floating_base.h"
#include "core/robot/kinematics.h"
#include "ui/viewer/tool_geometry.h"

namespace lamina::ui {

namespace {

constexpr double kTurnPerPixel = 0.01;         // rad of turn per pixel (torque and pose tools)
constexpr double kKinematicLead = 1.0 / 30.0;  // s a kinematic target is given to reach the cursor
const ImU32 kToolColour = IM_COL32(255, 200, 60, 255);

// the held axis-lock key: 0, 1, 2 for X, Y, Z; -1 for none
int HeldAxis() {
  if (ImGui::IsKeyDown(GLFW_KEY_X)) return 0;
  if (ImGui::IsKeyDown(GLFW_KEY_Y)) return 1;
  if (ImGui::IsKeyDown(GLFW_KEY_Z)) return 2;
  return -1;
}

ImVec2 ToImGui(const core::Vec3& pixels) {
  const ImVec2 scale = ImGui::GetIO().DisplayFramebufferScale;
  return ImVec2(static_cast<float>(pixels.x()) / scale.x, static_cast<float>(pixels.y()) / scale.y);
}

}  // namespace

MouseTools::Kind MouseTools::KindFor(const ToolInput& input) const {
  const ViewMouseEvent& event = input.event;
  if (event.control) {
    switch (event.pressed) {
      case core::MouseButton::kRight:
        return Kind::kForce;
      case core::MouseButton::kLeft:
        return Kind::kTorque;
      case core::MouseButton::kMiddle:
        return Kind::kKinematic;
      case core::MouseButton::kNone:
        return Kind::kNone;
    }
  }
  if (event.pressed != core::MouseButton::kLeft) return Kind::kNone;
  switch (input.state->tool) {
    case MouseTool::kForce:
      return Kind::kForce;
    case MouseTool::kTorque:
      return Kind::kTorque;
    case MouseTool::kKinematic:
      return Kind::kKinematic;
    case MouseTool::kPose:
      return Kind::kPose;
    case MouseTool::kSelect:
      break;
  }
  return Kind::kNone;
}

bool MouseTools::Press(const ToolInput& input) {
  const Kind kind = KindFor(input);
  if (kind == Kind::kNone || !input.frame.loaded) return false;
  const core::Ray ray =
      core::PixelRay(input.camera, input.width, input.height, input.event.x, input.event.y);
  core::PickFilter bodies;
  bodies.terrains = false;
  const core::PickHit hit = core::PickBody(input.scene, ray, bodies);
  const core::WorldDesc& world = *input.frame.world;
  const std::optional<core::Pose> frame =
      hit.hit() ? core::DrawnBodyFrame(world, input.frame.poses, hit.world_id) : std::nullopt;
  if (!frame) return false;
  const core::WorldId body = world.Resolve(hit.world_id);
  const bool robot =
      body.kind == core::WorldId::Kind::kRobot || body.kind == core::WorldId::Kind::kRobotLink;
  if (kind == Kind::kPose && robot && !StartRobotPose(input, body.index)) return false;
  if (kind == Kind::kPose && !robot && body.kind != core::WorldId::Kind::kRigidObject) {
    return false;
  }
  kind_ = kind;
  body_ = hit.world_id;
  object_ = robot ? -1 : body.index;
  robot_ = robot ? body.index : -1;
  grab_world_ = target_ = hit.point;
  grab_local_ = frame->inverse() * hit.point;
  start_pose_ = *frame;
  plane_normal_ = DragPlaneNormal(input.camera, input.event.shift && kind != Kind::kTorque);
  mouse_dx_ = mouse_dy_ = angle_ = 0.0;
  input.state->selected_id = body_;
  switch (kind_) {
    case Kind::kForce:
      input.actions->StartForce(body_, hit.point);
      break;
    case Kind::kTorque:
      input.actions->StartTorque(body_);
      break;
    case Kind::kPose:
      if (input.frame.time > 0.0) {
        input.actions->Reset();
        input.state->message = "reset: the pose tool edits where bodies start";
      }
      input.state->playing = false;
      input.actions->BeginGroup("move " +
                                (robot ? world.robots[robot_].name : world.objects[object_].name));
      break;
    default:
      break;
  }
  return true;
}

std::optional<core::Vec3> MouseTools::CursorOnPlane(const ToolInput& input) const {
  const core::Ray ray =
      core::PixelRay(input.camera, input.width, input.height, input.event.x, input.event.y);
  return RayPlane(ray, grab_world_, plane_normal_);
}

void MouseTools::Move(const ToolInput& input) {
  if (!active() || !input.event.moved) return;
  const ImVec2 delta = ImGui::GetIO().MouseDelta;
  mouse_dx_ += delta.x;
  mouse_dy_ += delta.y;
  const std::optional<core::Vec3> point = CursorOnPlane(input);
  if (point) target_ = *point;
  switch (kind_) {
    case Kind::kForce:
      input.actions->MoveForce(target_);
      break;
    case Kind::kTorque:
      input.actions->TurnTorque(TurnFromMouse(input.camera, mouse_dx_, mouse_dy_, kTurnPerPixel) *
                                start_pose_.linear());
      break;
    case Kind::kKinematic: {
      core::Pose pose = start_pose_;
      pose.translation() += target_ - grab_world_;
      input.actions->MoveKinematic(body_, pose, kKinematicLead);
      break;
    }
    case Kind::kPose:
      MovePose(input, target_);
      break;
    case Kind::kNone:
      break;
  }
}

// the object's initial pose: moved with the cursor, along one axis, or turned (Ctrl)
void MouseTools::MovePose(const ToolInput& input, const core::Vec3& point) {
  const int axis = HeldAxis();
  core::Pose pose = start_pose_;
  if (input.event.control) {
    const core::Vec3 about = axis >= 0 ? core::Vec3::Unit(axis) : core::Vec3::UnitZ();
    const core::Mat3 turn = Eigen::AngleAxisd(mouse_dx_ * kTurnPerPixel, about).toRotationMatrix();
    pose.linear() = turn * start_pose_.linear();
  } else {
    const core::Vec3 moved = axis >= 0 ? LockToAxis(grab_world_, point, axis) : point;
    pose.translation() += moved - grab_world_;
  }
  if (robot_ >= 0) {
    PlaceRobot(input, pose * start_pose_.inverse());
    return;
  }
  const core::RigidObjectDesc& object = input.frame.world->objects[object_];
  // the description pose of the object, which is what the frame drew at the start
  input.actions->SetParam(core::ElementRef::Object(object.uid),
                          *core::FindParam("transform", core::ElementKind::kObject),
                          core::PoseToValue(pose));
}

// a robot moves by its floating base; false (with a message) for a fixed base
bool MouseTools::StartRobotPose(const ToolInput& input, int robot) {
  const core::RobotDesc& desc = input.frame.world->robots[robot];
  base_links_ = core::FloatingBaseLinks(desc);
  if (base_links_.empty()) {
    input.state->message = "the pose tool moves objects and robots with a floating base; " +
                           desc.name + "'s base is fixed (its joints: the Robot panel)";
    return false;
  }
  start_config_ = desc.InitialConfig();
  start_base_ = core::LinkTransforms(desc, start_config_)[base_links_.back()];
  return true;
}

// the robot's initial configuration with its base moved by `moved` (world)
void MouseTools::PlaceRobot(const ToolInput& input, const core::Pose& moved) {
  const core::RobotDesc& desc = input.frame.world->robots[robot_];
  const std::optional<core::VecX> q =
      core::PlaceFloatingBase(desc, base_links_, start_config_, moved * start_base_);
  if (!q) {
    input.state->message = "the pose tool cannot place " + desc.name + "'s base there";
    return;
  }
  input.actions->SetParam(core::ElementRef::Robot(desc.uid),
                          *core::FindParam("config", core::ElementKind::kRobot),
                          core::ParamValue(q->data(), q->data() + q->size()));
}

void MouseTools::Release(const ToolInput& input) {
  switch (kind_) {
    case Kind::kForce:
    case Kind::kTorque:
      input.actions->EndDrag();
      break;
    case Kind::kKinematic:
      input.actions->ReleaseKinematic(body_);
      break;
    case Kind::kPose:
      input.actions->EndGroup();
      break;
    case Kind::kNone:
      break;
  }
  kind_ = Kind::kNone;
}

void MouseTools::DrawOverlay(const SessionFrame& frame, const core::OrbitCamera& camera, int width,
                             int height) const {
  if (!active() || !frame.loaded || kind_ == Kind::kPose) return;
  const std::optional<core::Pose> body = core::DrawnBodyFrame(*frame.world, frame.poses, body_);
  if (!body) return;
  const auto from = ProjectToPixels(camera, width, height, *body * grab_local_);
  const auto to = ProjectToPixels(camera, width, height, target_);
  if (!from || !to) return;
  ImDrawList* draw = ImGui::GetBackgroundDrawList();
  draw->AddLine(ToImGui(*from), ToImGui(*to), kToolColour, 2.0f);
  draw->AddCircleFilled(ToImGui(*to), 4.0f, kToolColour);
  draw->AddCircleFilled(ToImGui(*from), 3.0f, kToolColour);
  char label[64] = "";
  if (kind_ == Kind::kForce && frame.dragging) {
    std::snprintf(label, sizeof(label), "%.3g N", frame.drag.force.norm());
  } else if (kind_ == Kind::kTorque && frame.dragging) {
    std::snprintf(label, sizeof(label), "%.3g N·m", frame.drag.torque.norm());
  } else if (kind_ == Kind::kKinematic) {
    std::snprintf(label, sizeof(label), "kinematic");
  }
  const ImVec2 at = ToImGui(*to);
  draw->AddText(ImVec2(at.x + 8.0f, at.y - 18.0f), kToolColour, label);
}

}  // namespace lamina::ui
