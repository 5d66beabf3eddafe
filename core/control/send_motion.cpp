// SPDX-License-Identifier: MIT
#include "core/control/send_motion.h"

namespace lamina::core {

namespace {

bool Check(bool ok, const RobotController& controller, size_t index, std::string* error) {
  if (!ok) *error = "milestone " + std::to_string(index) + ": " + controller.last_error();
  return ok;
}

}  // namespace

bool SendMotion(const MilestoneSequence& motion, RobotController* controller, std::string* error) {
  if (motion.configs.empty()) {
    *error = "the motion has no milestones";
    return false;
  }
  for (size_t k = 0; k < motion.configs.size(); ++k) {
    if (motion.configs[k].size() != controller->dof()) {
      *error = "milestone " + std::to_string(k) + " has " +
               std::to_string(motion.configs[k].size()) + " entries, the robot has " +
               std::to_string(controller->dof()) + " links";
      return false;
    }
  }
  const bool timed = motion.times.size() == motion.configs.size();
  const bool with_velocity = motion.velocities.size() == motion.configs.size();
  if (timed) {
    if (!Check(controller->SetMilestone(motion.configs[0]), *controller, 0, error)) return false;
    for (size_t k = 1; k < motion.configs.size(); ++k) {
      const double duration = motion.times[k] - motion.times[k - 1];
      if (!Check(controller->AddLinear(motion.configs[k], duration), *controller, k, error)) {
        return false;
      }
    }
    return true;
  }
  const bool first = with_velocity
                         ? controller->SetMilestone(motion.configs[0], motion.velocities[0])
                         : controller->SetMilestone(motion.configs[0]);
  if (!Check(first, *controller, 0, error)) return false;
  for (size_t k = 1; k < motion.configs.size(); ++k) {
    const bool ok = with_velocity
                        ? controller->AddMilestone(motion.configs[k], motion.velocities[k])
                        : controller->AddMilestone(motion.configs[k]);
    if (!Check(ok, *controller, k, error)) return false;
  }
  return true;
}

}  // namespace lamina::core
