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
    case StepStatus::kUnstable:
      return "unstable";
    case StepStatus::kError:
      return "error";
  }
  return "error";
}

StepStatus StatusOfStep(unsigned flags) {
  if (flags & (kStepCorrected | kStepRecovered | kStepOverflowStop)) return StepStatus::kUnstable;
  if (flags & kStepUnreliable) return StepStatus::kContactUnreliable;
  if (flags & kStepRetaken) return StepStatus::kAdaptiveStep;
  return StepStatus::kNormal;
}

void AccumulateStep(const StepEvent& event, SimStatistics* statistics) {
  ++statistics->steps;
  statistics->rollbacks += event.rollbacks;
  statistics->instability_corrections += event.corrections;
  if (event.flags & kStepUnreliable) ++statistics->unreliable_steps;
  statistics->contact_joints += event.contact_joints;
  statistics->max_contacts_in_step =
      std::max(statistics->max_contacts_in_step, event.contact_joints);
  for (const ContactPair& pair : event.contacts) {
    statistics->max_penetration = std::max(statistics->max_penetration, pair.max_depth);
  }
  statistics->worst_status = std::max(statistics->worst_status, StatusOfStep(event.flags));
}

}  // namespace lamina::core
