// SPDX-License-Identifier: MIT
// Forward kinematics of a RobotDesc: link frames in the world for a configuration, the Klamp't
// convention T_link = T_parent * parent_transform * joint(q) (rotation about, or translation
// along, the link's axis).
#pragma once

#include <vector>

#include "core/math_types.h"
#include "core/model/world_desc.h"

namespace lamina::core {

/// The motion of one link's joint at value q, in the link frame at q = 0.
Pose LinkJointMotion(const LinkDesc& link, double q);

/// World frame of every link for configuration `q` (one entry per link; parents come first
/// in a RobotDesc). Throws std::invalid_argument when q has the wrong size.
std::vector<Pose> LinkTransforms(const RobotDesc& robot, const VecX& q);

/// World position of every link's centre of mass for link frames `frames`.
std::vector<Vec3> LinkComPositions(const RobotDesc& robot, const std::vector<Pose>& frames);

}  // namespace lamina::core
