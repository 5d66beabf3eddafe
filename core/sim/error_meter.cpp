// SPDX-License-Identifier: MIT
#include "core/sim/error_meter.h"

#include <algorithm>

namespace lamina::core {

StepErrorSample MakeStepErrorSample(double time, double step, const std::vector<Vec3>& full,
                                    const std::vector<Vec3>& halves) {
  StepErrorSample sample{time, step, 0.0, 0.0, 0.0};
  for (std::size_t i = 0; i < full.size() && i < halves.size(); ++i) {
    sample.difference = std::max(sample.difference, (full[i] - halves[i]).norm());
  }
  sample.local_error = 2.0 * sample.difference;
  sample.rate = step > 0.0 ? sample.local_error / step : 0.0;
  return sample;
}

bool ErrorMeter::Due() const {
  if (tried_) return sampling_ + last_cost_ <= budget_ * stepping_;
  if (steps_ == 0) return false;
  return sampling_ + kSampleSteps * stepping_ / static_cast<double>(steps_) <= budget_ * stepping_;
}

void ErrorMeter::Add(const StepErrorSample& sample, double seconds) {
  sampling_ += seconds;
  last_cost_ = seconds;
  tried_ = true;
  ++samples_;
  recent_.push_back(sample);
  if (static_cast<int>(recent_.size()) > window_) recent_.erase(recent_.begin());
}

ErrorMeterReading ErrorMeter::Reading() const {
  ErrorMeterReading reading;
  if (recent_.empty()) return reading;
  const auto worst = std::max_element(
      recent_.begin(), recent_.end(),
      [](const StepErrorSample& a, const StepErrorSample& b) { return a.rate < b.rate; });
  reading.valid = true;
  reading.rate = worst->rate;
  reading.local_error = worst->local_error;
  reading.time = recent_.back().time;
  reading.samples = samples_;
  reading.overhead = stepping_ > 0.0 ? sampling_ / stepping_ : 0.0;
  return reading;
}

void ErrorMeter::Reset() {
  stepping_ = sampling_ = last_cost_ = 0.0;
  samples_ = steps_ = 0;
  tried_ = false;
  recent_.clear();
}

}  // namespace lamina::core
