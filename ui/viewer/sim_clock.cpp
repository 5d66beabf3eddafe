// SPDX-License-Identifier: MIT
#include "ui/viewer/sim_clock.h"

#include <algorithm>
#include <cmath>

namespace lamina::ui {

int FixedStepClock::StepsForFrame(double wall_seconds, double speed, double step) {
  if (!(step > 0.0) || !(wall_seconds > 0.0) || !(speed > 0.0)) return 0;
  owed_ += std::min(wall_seconds * speed, kMaxSimulatedPerFrame);
  // a step is due when the owed time reaches it up to rounding
  const int steps = static_cast<int>(std::floor(owed_ / step + 1e-9));
  owed_ = std::max(0.0, owed_ - steps * step);
  return steps;
}

void RealTimeFactorMeter::AddFrame(double wall_seconds, double sim_seconds) {
  samples_.push_back({wall_seconds, sim_seconds});
  wall_total_ += wall_seconds;
  sim_total_ += sim_seconds;
  while (samples_.size() > 1 && wall_total_ - samples_.front().wall >= window_) {
    wall_total_ -= samples_.front().wall;
    sim_total_ -= samples_.front().sim;
    samples_.pop_front();
  }
}

double RealTimeFactorMeter::factor() const {
  return wall_total_ > 0.0 ? sim_total_ / wall_total_ : 0.0;
}

void RealTimeFactorMeter::Clear() {
  samples_.clear();
  wall_total_ = sim_total_ = 0.0;
}

}  // namespace lamina::ui
