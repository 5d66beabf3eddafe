// SPDX-License-Identifier: MIT
#include "core/accuracy/scene_bars.h"

#include <cmath>

#include "core/accuracy/probe_support.h"
#include "core/sim/step_observer.h"

namespace lamina::core {

double BarValue(const AccuracyRun& run, const BarQuantity& quantity) {
  return quantity.metric.empty() ? run.result.error : RunMetric(run, quantity.metric);
}

std::string StepText(double step) {
  return Measured(step * 1e3, "ms");
}

BarCheck AtMost(const std::vector<const AccuracyRun*>& runs, const BarQuantity& quantity,
                double bound) {
  BarCheck check;
  if (!RunsUsable(runs, &check)) return check;
  check.pass = true;
  for (const AccuracyRun* run : runs) {
    const double value = BarValue(*run, quantity);
    check.pass = check.pass && value <= bound;  // false for NaN
    check.measured += (check.measured.empty() ? "" : "; ") +
                      Measured(value * quantity.scale, quantity.unit) + " at " +
                      StepText(run->step);
  }
  check.measured += " (bound " + Measured(bound * quantity.scale, quantity.unit) + ")";
  return check;
}

BarCheck Stable(const std::vector<const AccuracyRun*>& runs) {
  BarCheck check;
  if (!RunsUsable(runs, &check)) return check;
  check.pass = true;
  for (const AccuracyRun* run : runs) {
    // a joint broken open (beyond JointBreakGap) is a blow-up too, corrected or not
    check.pass = check.pass && run->corrections == 0 && run->nonfinite == 0 &&
                 run->status != StepStatusName(StepStatus::kJointOpen);
    check.measured += (check.measured.empty() ? "" : "; ") + std::to_string(run->corrections) +
                      " corrections, " + std::to_string(run->nonfinite) + " non-finite, " +
                      run->status + " at " + StepText(run->step);
  }
  return check;
}

}  // namespace lamina::core
