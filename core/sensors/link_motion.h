// SPDX-License-Identifier: MIT
// LinkMotion: the frame, velocity and acceleration of every link of a robot from its joint
// values, rates and accelerations (forward kinematics to second order). Pure.
//
// Conventions: everything in the world frame. A link's linear velocity and acceleration are
// those of its frame's origin (where its joint sits, Klamp't's T_link); angular ones are the
// link's. A revolute link turns about its axis through its origin; a prismatic one slides along
// its axis (robot.links[i].axis, link frame), as core/robot/kinematics.h composes them.
#pragma once

#include <vector>

#include "core/math_types.h"
#include "core/model/world_desc.h"

namespace lamina::core {

struct LinkMotion {
  std::vector<Pose> frames;                ///< link frames in the world
  std::vector<Vec3> angular_velocity;      ///< rad/s
  std::vector<Vec3> linear_velocity;       ///< of the frame origin, m/s
  std::vector<Vec3> angular_acceleration;  ///< rad/s²
  std::vector<Vec3> linear_acceleration;   ///< of the frame origin, m/s²

  /// Velocity (m/s) of a point fixed to link i at `point_world` (world coordinates).
  Vec3 PointVelocity(int i, const Vec3& point_world) const;
  /// Acceleration (m/s²) of that point.
  Vec3 PointAcceleration(int i, const Vec3& point_world) const;
};

/// The motion of every link for joint values q, rates dq and accelerations ddq (link-sized).
/// Throws std::invalid_argument when a vector has the wrong size.
LinkMotion ComputeLinkMotion(const RobotDesc& robot, const VecX& q, const VecX& dq,
                             const VecX& ddq);

}  // namespace lamina::core
