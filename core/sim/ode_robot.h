// SPDX-License-Identifier: MIT
// A robot on ODE: links grouped into bodies (welded links merged into their parent's body with
// the exact composite inertia, a floating base as one free body, links welded to the world as
// static geometry), hinges and sliders with stops, joint friction motors, and the map between
// joint coordinates and body states. The Simulator owns one per robot.
#pragma once

#include <vector>

#include <ode/ode.h>

#include "core/control/robot_controller.h"
#include "core/diagnostics.h"
#include "core/model/world_desc.h"
#include "core/sim/friction_rows.h"
#include "core/sim/ode_joint_rows.h"
#include "core/sim/robot_joint_state.h"

namespace lamina::core {

class OdeRobot {
 public:
  enum class LinkKind {
    kVirtual,  ///< a floating base's virtual link: no body, no geometry
    kStatic,   ///< welded to the world (fixed base): geometry at a fixed pose
    kBody,     ///< carried by an ODE body (its own, or its parent's when welded)
  };
  struct Link {
    LinkKind kind = LinkKind::kBody;
    dBodyID body = nullptr;                    ///< the carrying body (kBody)
    bool owns_body = false;                    ///< the body was made for this link
    Mat3 rotation_in_body = Mat3::Identity();  ///< link axes in the carrying body's axes
    Vec3 com = Vec3::Zero();             ///< the carrying body's centre of mass in the link frame
    Pose fixed_pose = Pose::Identity();  ///< kStatic: link frame in the world
    dJointID joint = nullptr;            ///< hinge or slider to the parent's body (or the world)
    dJointID servo = nullptr;            ///< motor along the joint for the implicit PD
    int carrier = -1;  ///< the link that owns `body` (itself, or the one it is welded into)
    /// what ODE keeps of `joint` and `servo` and does not return (ode_joint_rows.h)
    JointFrame frame;
    double reference = 0.0;       ///< joint value where the ODE joint reads zero
    double mass = 0.0;            ///< owners: the body's mass (kg)
    Mat3 inertia = Mat3::Zero();  ///< owners: about the COM, in the link axes
  };

  /// Builds the robot at robot.config. Unsupported joints (floating planar, ball and socket)
  /// are reported to `diagnostics` and treated as welds.
  OdeRobot(dWorldID world, const RobotDesc& robot, Diagnostics& diagnostics);
  ~OdeRobot();
  OdeRobot(const OdeRobot&) = delete;
  OdeRobot& operator=(const OdeRobot&) = delete;

  int dof() const { return static_cast<int>(links_.size()); }
  const Link& link(int i) const { return links_[i]; }
  /// The link's joint moves (a hinge, a slider or a floating base's axis); false for welds.
  bool DofFree(int i) const { return joint_types_[i] != JointType::kWeld; }
  /// The links in an order where every link comes before its parent (the Newton solver's
  /// matrix stays narrow when a robot's bodies come in it: object_islands.h).
  const std::vector<int>& children_first() const { return children_first_; }
  /// A 6-link floating base rotates; a 3-link one (x, y, z) only translates.
  bool floating_rotates() const { return floating_link_ - floating_first_ == 5; }

  /// Joint values (rad or m) and rates of every link; revolute joints count whole turns.
  void GetConfig(VecX* q) const;
  void GetVelocity(VecX* dq) const;
  /// Places every body for configuration q / joint rates dq (teleports the robot).
  void SetConfig(const VecX& q);
  void SetVelocity(const VecX& dq);
  /// Places every body on its joints: the joint values and rates as ODE reads them (relative
  /// rotations, slider positions), the floating base's body (or the fixed base) where it is.
  /// What a step that integrated each body on its own left of a joint's drift (a child off its
  /// hinge's anchor or axis) is removed, and each body's velocity is the one its joints give it
  /// (the Newton solver's reduced step: reduced_basis.h).
  void ProjectOntoJoints();

  /// After robot().links[i]'s q_min/q_max changed: the joint's stops follow. A revolute joint
  /// whose new range no longer fits in its built half-turn counts turns from now on.
  void UpdateStops(int i);
  /// Before each ODE step of `step` s from configuration q (GetConfig): the stops of wide-range
  /// joints around the current angle; the stop ERP (the world's `erp`) of a joint beyond its
  /// range limited so that it comes back gently.
  void PrepareStep(const VecX& q, double step, double erp);
  /// Adds the generalized force of every link (N·m on hinges, N on sliders, along the virtual
  /// axes of a floating base) for the coming ODE step.
  void ApplyLinkForces(const VecX& forces);
  /// Implicit PD motors: every servo off, then the given ones on for the coming step (bounded by
  /// their fmax unless `unbounded`).
  void SetServos(const std::vector<ServoMotorCommand>& motors);
  /// Joint friction motors: each driven link resists motion with up to dry + viscous·|dq|. With
  /// `guess` the dry-friction rows go unbounded or become torques where their answer is known
  /// (friction_rows.h), except on the links whose `holdoff` is above 0; `commands` receives each
  /// guessed row (its kExplicit torques are for the caller to apply).
  void SetJointFriction(const std::vector<DriverDesc>& drivers, const VecX& q, const VecX& dq,
                        const std::vector<ServoMotorCommand>& motors, bool guess,
                        const std::vector<int>& holdoff, std::vector<FrictionCommand>* commands);
  /// After SetServos and SetJointFriction: each joint whose friction row goes unbounded this step
  /// (`friction`) and whose servo row is unbounded too gets one row for both
  /// (MergeServoAndFrictionRows, friction_rows.h) on the servo's axis, and no friction row.
  void MergeHoldingFriction(const std::vector<ServoMotorCommand>& motors,
                            const std::vector<FrictionCommand>& friction);
  /// After an accepted step: counts the turns of revolute joints.
  void AcceptStep();

  void CaptureJointState(RobotJointState* state) const;
  void RestoreJointState(const RobotJointState& state);

 private:
  void BuildBodies(dWorldID world, const VecX& q, Diagnostics& diagnostics);
  std::vector<int> AssignOwners(const std::vector<Pose>& frames);
  void CreateBody(dWorldID world, int o, const std::vector<int>& owner,
                  const std::vector<Pose>& frames, Diagnostics& diagnostics);
  void BuildJoints(dWorldID world, const VecX& q);
  void SetStops(int i);
  void SetJointMotor(int i, double fmax, double cfm);
  double HingeAngle(int i) const;
  void SetLinkVelocities(const std::vector<Pose>& frames, const VecX& dq,
                         const Eigen::Matrix<double, 6, 1>* base);
  Pose FloatingBaseLocalFrame() const;

  const RobotDesc& robot_;
  std::vector<Link> links_;
  std::vector<JointType> joint_types_;  ///< per link
  std::vector<bool> wide_;              ///< revolute range of 2π or more (turns are counted)
  RobotJointState joint_state_;
  int floating_link_ = -1;
  int floating_first_ = -1;  ///< first virtual link of the floating base
  VecX model_config_;        ///< values of welded links
  std::vector<int> children_first_;
};

}  // namespace lamina::core
