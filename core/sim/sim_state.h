// SPDX-License-Identifier: MIT
// A snapshot of a running simulation: restoring it reproduces the same trajectory bit for bit.
#pragma once

#include <vector>

#include "core/control/robot_controller.h"
#include "core/math_types.h"
#include "core/sensors/robot_sensors.h"
#include "core/sim/friction_anchor.h"
#include "core/sim/robot_joint_state.h"

namespace lamina::core {

/// State of one rigid body as ODE holds it (at the centre of mass).
struct BodyState {
  Vec3 com_position = Vec3::Zero();                                 ///< m, world
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  ///< body axes in world
  Vec3 linear_velocity = Vec3::Zero();                              ///< m/s of the COM
  Vec3 angular_velocity = Vec3::Zero();                             ///< rad/s, world

  bool operator==(const BodyState& other) const {
    return com_position == other.com_position &&
           orientation.coeffs() == other.orientation.coeffs() &&
           linear_velocity == other.linear_velocity && angular_velocity == other.angular_velocity;
  }
};

/// A robot's bodies, joint bookkeeping and controller.
struct RobotSimState {
  std::vector<BodyState> bodies;  ///< one per body of the robot, in link order
  RobotJointState joints;
  RobotControllerState controller;
  RobotSensorsState sensors;  ///< captured and restored with the controller
  /// per link: accepted steps its joint friction row stays bounded (friction_rows.h); captured
  /// and restored with the controller, so that a restored state replays the same rows
  std::vector<int> friction_holdoff;
  /// Physical state only (the controller's state has no equality).
  bool operator==(const RobotSimState& other) const {
    return bodies == other.bodies && joints == other.joints;
  }
};

/// Sleeping (Simulator::SetSleeping) of one rigid object.
struct ObjectSleep {
  double idle_time = 0.0;  ///< s spent below the sleep speeds
  bool asleep = false;     ///< taken out of the steps until something wakes it
  bool operator==(const ObjectSleep&) const = default;
};

struct SimState {
  double time = 0.0;  ///< s
  /// the accepted step that led to this state (s; 0: none yet): the next step's gravity kick
  /// spans half of it (gravity_kick.h)
  double last_step = 0.0;
  std::vector<BodyState> objects;  ///< one per rigid object
  std::vector<RobotSimState> robots;
  std::vector<FrictionAnchor> anchors;  ///< pairs that stick, sorted by (a, b)
  std::vector<ObjectSleep> sleep;       ///< one per rigid object
  bool operator==(const SimState&) const = default;
};

}  // namespace lamina::core
