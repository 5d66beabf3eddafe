// SPDX-License-Identifier: MIT
// Where a simulation's wall time goes: the split that `lamina-headless run` and the benchmarks
// report, and the stopwatch that measures it.
#pragma once

#include <chrono>

namespace lamina::core {

/// Wall time (s) spent in each part of Simulate since construction or the last Reset.
struct SimTimeSplit {
  double broad_phase = 0.0;         ///< padded bounds and candidate pairs
  double contact_generation = 0.0;  ///< exact contacts of candidate pairs
  double clustering = 0.0;          ///< merging and clustering each pair's contacts
  double solver = 0.0;              ///< contact joints and the ODE step
  double other = 0.0;               ///< the rest: state capture, rollback checks, feedback, ...
  double total() const { return broad_phase + contact_generation + clustering + solver + other; }
};

/// Adds the time since construction (or the last Lap) to a counter.
class Stopwatch {
 public:
  Stopwatch() : start_(Clock::now()) {}
  /// Seconds since the start or the last Lap; restarts.
  double Lap() {
    const Clock::time_point now = Clock::now();
    const double seconds = std::chrono::duration<double>(now - start_).count();
    start_ = now;
    return seconds;
  }

 private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point start_;
};

}  // namespace lamina::core
