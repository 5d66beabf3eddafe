// SPDX-License-Identifier: MIT
// The Simulator's record of one world id, shared by the simulator's source files.
#pragma once

#include <memory>

#include <ode/ode.h>

#include "core/sim/simulator.h"

namespace lamina::core {

struct Simulator::BodyRecord {
  WorldId::Kind kind = WorldId::Kind::kInvalid;
  int index = -1;          ///< terrain, object or robot index
  int link = -1;           ///< robot links
  dBodyID body = nullptr;  ///< null for static bodies (terrains, fixed bases) and ids without one
  bool owns_body = true;   ///< false for a link merged into its parent's body
  Mat3 rotation_in_body = Mat3::Identity();  ///< this record's frame in the ODE body's axes
  Pose fixed_pose = Pose::Identity();        ///< frame of a static body (no ODE body)
  std::shared_ptr<const CollisionGeometry> geometry;
  Vec3 com = Vec3::Zero();  ///< the ODE body's centre of mass in this record's frame
  double mass = 0.0;
  Mat3 inertia = Mat3::Zero();  ///< about the COM, body axes
  bool enabled = true;
  bool dynamic = true;         ///< false: kinematic
  Vec3 force = Vec3::Zero();   ///< world, at the COM, for the sub-steps of the next Simulate
  Vec3 torque = Vec3::Zero();  ///< world
  Eigen::AlignedBox3d bounds;  ///< padded world bounds
  double energy = -1.0;        ///< kinetic energy after the last accepted step; < 0 unknown

  bool moves_freely() const { return body != nullptr && enabled && dynamic; }
};

}  // namespace lamina::core
