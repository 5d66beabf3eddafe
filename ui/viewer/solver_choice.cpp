// SPDX-License-Identifier: MIT
#include "ui/viewer/solver_choice.h"

#include <cmath>

namespace lamina::ui {

void SolverChoice::Add(double wall, double simulated, double speed) {
  if (too_slow_ || !(wall > 0.0) || !(simulated > 0.0) || !(speed > 0.0)) return;
  if (!std::isfinite(wall) || !std::isfinite(simulated)) return;
  wall_ += wall;
  simulated_ += simulated;
  speed_ = speed;
  too_slow_ = simulated_ >= kEvidence && cost() * speed_ > budget_;
}

}  // namespace lamina::ui
