// SPDX-License-Identifier: MIT
// The mouse tools over the 3D view (MuJoCo simulate's conventions; docs/editor.md):
//  * force: the grabbed point of a body (object or robot link) is pulled toward the cursor by
//    the simulator's mouse spring (interaction.h), in the plane through the grabbed point facing
//    the camera, or the horizontal plane with Shift; drawn as a line from the point to the
//    cursor with the spring's force in newtons beside it;
//  * torque: the rotational spring turns the body as the mouse moves (about the camera's up axis
//    for horizontal motion, its right axis for vertical motion);
//  * kinematic drag: the body becomes a kinematic target following the cursor (it pushes what
//    it meets and carries what rests on it) and is released with its last velocity (a throw);
//  * pose (paused): moves an object's initial pose, or a robot's by its floating base (its
//    initial configuration's six base values, floating_base.h; a robot with a fixed base is
//    refused with a message), one undoable edit per drag; X, Y or Z held moves along that world
//    axis only, Ctrl turns about it (z when no axis is held). A world that has run is reset
//    first: poses are edited at the start.
// Everything reaches the physics through EditorActions (one queue); the overlay is drawn from
// the latest frame.
#pragma once

#include <optional>
#include <vector>

#include "core/render/camera.h"
#include "core/render/render_scene.h"
#include "ui/viewer/editor_actions.h"
#include "ui/viewer/viewer_input.h"

namespace lamina::ui {

struct ToolInput {
  const ViewMouseEvent& event;
  const core::RenderScene& scene;
  const core::OrbitCamera& camera;
  int width = 0, height = 0;
  const SessionFrame& frame;
  ViewerState* state;
  EditorActions* actions;
};

class MouseTools {
 public:
  /// A button went down over the view: starts a tool drag when it is on a movable body and the
  /// gesture or the current tool asks for one. True when it did (the camera leaves it alone).
  bool Press(const ToolInput& input);
  /// Every frame of the drag.
  void Move(const ToolInput& input);
  void Release(const ToolInput& input);
  bool active() const { return kind_ != Kind::kNone; }
  /// The drag's line, target and force (or torque) label, over the 3D view (ImGui draw list).
  void DrawOverlay(const SessionFrame& frame, const core::OrbitCamera& camera, int width,
                   int height) const;

 private:
  enum class Kind { kNone, kForce, kTorque, kKinematic, kPose };
  Kind KindFor(const ToolInput& input) const;
  std::optional<core::Vec3> CursorOnPlane(const ToolInput& input) const;
  void MovePose(const ToolInput& input, const core::Vec3& point);
  bool StartRobotPose(const ToolInput& input, int robot);
  void PlaceRobot(const ToolInput& input, const core::Pose& moved);

  Kind kind_ = Kind::kNone;
  int body_ = -1;
  int object_ = -1;                         ///< pose tool: the object's index
  int robot_ = -1;                          ///< pose tool: the robot's index (object_ = -1)
  std::vector<int> base_links_;             ///< pose tool: the robot's floating base
  core::VecX start_config_;                 ///< pose tool: the robot's initial configuration
  core::Pose start_base_;                   ///< pose tool: its base link's frame
  core::Vec3 grab_local_;                   ///< grabbed point in the body frame
  core::Vec3 grab_world_;                   ///< where it was grabbed (world)
  core::Vec3 plane_normal_;                 ///< of the drag plane through grab_world_
  core::Pose start_pose_;                   ///< the body frame when grabbed
  core::Vec3 target_ = core::Vec3::Zero();  ///< the cursor on the plane (world)
  double mouse_dx_ = 0.0, mouse_dy_ = 0.0;  ///< pixels moved since the press
  double angle_ = 0.0;                      ///< pose tool: turned so far, rad
};

}  // namespace lamina::ui
