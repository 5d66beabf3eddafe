// SPDX-License-Identifier: MIT
// A robot's floating base (Klamp't `joint floating L -1`: six virtual links from the world to
// link L, three prismatic then three revolute, in whatever axis order the file gives: ATHLETE's
// are x, y, z, then yaw, roll, pitch). Placing the base where the user drags it — the editor's
// pose tool — means finding the six joint values that put link L's frame at a target pose.
// The chain is solved by Newton's method on the six values from the current ones (finite
// differences of the forward kinematics, kinematics.h), so no axis order is assumed; a target
// the chain cannot reach (a base whose virtual links are limited or coupled) is reported, not
// approximated.
#pragma once

#include <optional>
#include <vector>

#include "core/math_types.h"
#include "core/model/world_desc.h"

namespace lamina::core {

/// The six links of the robot's floating joint at the world, root first; empty when it has
/// none (a fixed base, or a floating joint on another link).
std::vector<int> FloatingBaseLinks(const RobotDesc& robot);

/// `q` with the floating base's six values changed so that the frame of `links.back()` is
/// `target` (position within 1e-9 m, rotation within 1e-9 rad); the other values as given.
/// nullopt when it does not get there (an unreachable target).
std::optional<VecX> PlaceFloatingBase(const RobotDesc& robot, const std::vector<int>& links,
                                      const VecX& q, const Pose& target);

}  // namespace lamina::core
