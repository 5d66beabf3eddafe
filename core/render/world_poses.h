// SPDX-License-Identifier: MIT
// WorldPoses: where the bodies of a world are in one drawn frame, kept apart from the world's
// description. A renderer draws the description (what the bodies are: geometry, colours,
// paddings) at a WorldPoses (where they are), as MuJoCo's mjv_updateScene draws (mjModel,
// mjData); nothing here writes the description. Klamp't has no such split: its WorldModel holds
// the current configuration, and a simulator writes the state into it (UpdateModel) before
// drawing, so the model and "the current frame" are one object.
// Units: object frames are rigid transforms in the world (m); robot configurations have one joint
// value per link (rad for revolute, m for prismatic joints), as RobotDesc::config.
#pragma once

#include <optional>
#include <vector>

#include "core/math_types.h"
#include "core/model/world_desc.h"

namespace lamina::core {

class Simulator;

struct WorldPoses {
  std::vector<Pose> objects;  ///< per rigid object: its frame (not the COM) in the world
  std::vector<VecX> robots;   ///< per robot: its joint values, one per link
};

/// The description's initial conditions: every object at its `pose`, every robot at its
/// DisplayConfiguration.
WorldPoses InitialPoses(const WorldDesc& world);

/// The simulation's current state: Simulator::GetObjectPose of every object and GetRobotConfig
/// of every robot.
WorldPoses CurrentPoses(const Simulator& simulator);

/// The configuration drawn for `robot` at its initial conditions: its config, or the links'
/// q_initial when the config does not have one entry per link.
VecX DisplayConfiguration(const RobotDesc& robot);

// What is drawn where `poses` does not fit `world` (an element added since the poses were
// taken): the description's initial conditions. Indices must be valid in `world`.
/// poses.objects[object], or the object's description pose when `poses` has no entry for it.
Pose DrawnObjectPose(const WorldDesc& world, const WorldPoses& poses, int object);
/// poses.robots[robot] when it has one entry per link, else DisplayConfiguration.
VecX DrawnRobotConfiguration(const WorldDesc& world, const WorldPoses& poses, int robot);
/// The drawn frame of the rigid object or robot link with Klamp't world id `id` (for a link,
/// forward kinematics at DrawnRobotConfiguration); nullopt for terrains (static, no frame of
/// their own), whole robots and ids out of range.
std::optional<Pose> DrawnBodyFrame(const WorldDesc& world, const WorldPoses& poses, int id);

}  // namespace lamina::core
