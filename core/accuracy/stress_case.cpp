// SPDX-License-Identifier: MIT
#include "core/accuracy/stress_case.h"

#include <fnmatch.h>

namespace lamina::core {

std::vector<const StressCase*> FindStressCases(const std::vector<std::string>& globs) {
  std::vector<const StressCase*> found;
  for (const StressCase& c : StressCases()) {
    bool match = globs.empty();
    for (const std::string& glob : globs) {
      match = match || fnmatch(glob.c_str(), c.name.c_str(), 0) == 0;
    }
    if (match) found.push_back(&c);
  }
  return found;
}

const char* StressVerdictName(StressVerdict verdict) {
  switch (verdict) {
    case StressVerdict::kStable:
      return "stable";
    case StressVerdict::kFlagged:
      return "flagged";
    case StressVerdict::kFailed:
      return "failed";
  }
  return "failed";
}

StressVerdict JudgeStress(const StressOutcome& outcome, std::string* why) {
  std::string reason;
  StressVerdict verdict = StressVerdict::kStable;
  const bool says_unreliable = outcome.worst >= StepStatus::kContactUnreliable;
  if (!outcome.ran || outcome.halted) {
    verdict = StressVerdict::kFailed;
    reason = outcome.ran ? "the simulation stopped with an error" : "the run did not start";
  } else if (!outcome.finite) {
    verdict = StressVerdict::kFailed;
    reason = "a body state is not finite at the end";
  } else if (outcome.lost > 0 && !says_unreliable) {
    verdict = StressVerdict::kFailed;
    reason = std::to_string(outcome.lost) + " bodies lost without a status saying so";
  } else if (outcome.lost > 0) {
    verdict = StressVerdict::kFlagged;
    reason = std::to_string(outcome.lost) + " bodies lost, status " + StepStatusName(outcome.worst);
  } else if (says_unreliable || outcome.corrections > 0 || outcome.nonfinite > 0) {
    verdict = StressVerdict::kFlagged;
    reason = std::string("status ") + StepStatusName(outcome.worst) + ", " +
             std::to_string(outcome.corrections) + " corrections, " +
             std::to_string(outcome.nonfinite) + " non-finite recoveries";
  }
  if (why) *why = reason;
  return verdict;
}

}  // namespace lamina::core
