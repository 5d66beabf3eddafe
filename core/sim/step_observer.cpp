// SPDX-License-Identifier: MIT
#include "core/sim/step_observer.h"

#include <algorithm>

namespace lamina::core {

const char* StepStatusName(StepStatus status) {
  switch (status) {
    case StepStatus::kNormal:
      return "normal";
    case StepStatus::kAdaptiveStep:
      return "adaptive step";
    case StepStatus::kContactUnreliable:
      return "contact unreliable";
    case StepStatus::kJointOpen:
      return "joint open";
    case StepStatus::kUnstable:
      return "unstable";
    case StepStatus::kError:
      return "error";
  }
  return "error";
}

int KlamptStatusCode(StepStatus status) {
  const int code = static_cast<int>(status);
  return status >= StepStatus::kJointOpen ? code - 1 : code;
}

StepStatus StatusOfKlamptCode(int code) {
  return static_cast<StepStatus>(code >= 3 ? code + 1 : code);
}

StepStatus StatusOfStep(unsigned flags) {
  if (flags & (kStepCorrected | kStepRecovered | kStepOverflowStop)) return StepStatus::kUnstable;
  if (flags & kStepJointOpen) return StepStatus::kJointOpen;
  if (flags & kStepUnreliable) return StepStatus::kContactUnreliable;
  if (flags & kStepRetaken) return StepStatus::kAdaptiveStep;
  return StepStatus::kNormal;
}

void AccumulateStep(const StepEvent& event, SimStatistics* statistics) {
  ++statistics->steps;
  statistics->rollbacks += event.rollbacks;
  statistics->instability_corrections += event.corrections;
  if (event.flags & kStepUnreliable) ++statistics->unreliable_steps;
  if (event.flags & kStepJointOpen) ++statistics->joint_open_steps;
  statistics->max_joint_gap = std::max(statistics->max_joint_gap, event.joint_gap);
  statistics->contact_joints += event.contact_joints;
  statistics->max_contacts_in_step =
      std::max(statistics->max_contacts_in_step, event.contact_joints);
  for (const ContactPair& pair : event.contacts) {
    statistics->max_penetration = std::max(statistics->max_penetration, pair.max_depth);
  }
  statistics->worst_status = std::max(statistics->worst_status, StatusOfStep(event.flags));
}

}  // namespace lamina::core
