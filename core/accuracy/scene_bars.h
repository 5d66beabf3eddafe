// SPDX-License-Identifier: MIT
// Bar checks that several accuracy scenes share: a run's error or one of its metrics held under a
// bound at every step a bar names, and a run that stayed stable. Each check says what it measured
// at each step ("0.0012 m at 1 ms (bound 0.0025 m)").
#pragma once

#include <string>
#include <vector>

#include "core/accuracy/accuracy_scene.h"

namespace lamina::core {

/// What a bar compares: the run's error (metric "") or a named metric, shown × `scale` in `unit`.
struct BarQuantity {
  std::string metric;  ///< "" for the run's error
  std::string unit;    ///< of the shown value, e.g. "m", "%"
  double scale = 1.0;  ///< shown value = value × scale (e.g. 100 for a percentage)
};

/// The quantity of `run` (NaN when the run has no such metric).
double BarValue(const AccuracyRun& run, const BarQuantity& quantity);

/// Passes when the quantity is at most `bound` (same unit as the value, before scaling) in every
/// run; a NaN never passes.
BarCheck AtMost(const std::vector<const AccuracyRun*>& runs, const BarQuantity& quantity,
                double bound);

/// Passes when every run ran without instability corrections, non-finite states, joints broken
/// open (status "joint open": beyond JointBreakGap) or errors.
BarCheck Stable(const std::vector<const AccuracyRun*>& runs);

/// "1 ms" for 1e-3, "0.1 ms" for 1e-4.
std::string StepText(double step);

}  // namespace lamina::core
