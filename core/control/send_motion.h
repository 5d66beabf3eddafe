// SPDX-License-Identifier: MIT
// Sending a motion file to a robot's controller as Klamp't's SimTest does: a timed `.path`
// becomes linear segments after a ramp to its first milestone, `.milestones` (configuration +
// velocity records) become a chain of time-optimal ramps.
#pragma once

#include <string>

#include "core/control/milestone_sequence.h"
#include "core/control/robot_controller.h"

namespace lamina::core {

/// Queues `motion` on `controller`: timed sequences as SetMilestone(first) then AddLinear to
/// each later milestone over its time step; untimed ones as SetMilestone(first[, dq]) then
/// AddMilestone(q[, dq]). False with a message in `error` when the sizes do not match the robot
/// or a command fails.
bool SendMotion(const MilestoneSequence& motion, RobotController* controller, std::string* error);

}  // namespace lamina::core
