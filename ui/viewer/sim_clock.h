// SPDX-License-Identifier: MIT
// Real-time pacing of the simulation: how many fixed physics steps a frame takes for the wall
// time that passed (times a speed factor, capped so that a slow machine slows the simulation
// down instead of spiralling), and the real-time factor actually achieved. Pure, no GL.
#pragma once

#include <deque>

namespace lamina::ui {

class FixedStepClock {
 public:
  /// At most this much simulated time per frame, s.
  static constexpr double kMaxSimulatedPerFrame = 0.05;

  /// Whole physics steps of `step` seconds owed after `wall_seconds` at `speed`; the remainder
  /// is carried to the next frame.
  int StepsForFrame(double wall_seconds, double speed, double step);
  /// Forgets the carried remainder (on pause, reset or a new world).
  void Clear() { owed_ = 0.0; }
  double owed() const { return owed_; }

 private:
  double owed_ = 0.0;
};

/// Simulated seconds per wall second over the last `window` wall seconds.
class RealTimeFactorMeter {
 public:
  explicit RealTimeFactorMeter(double window = 1.0) : window_(window) {}
  /// Records one frame: `wall_seconds` passed and the simulation advanced `sim_seconds`.
  void AddFrame(double wall_seconds, double sim_seconds);
  /// Simulated / wall time over the window; 0 before any wall time passed.
  double factor() const;
  void Clear();

 private:
  struct Sample {
    double wall = 0.0, sim = 0.0;
  };
  double window_;
  std::deque<Sample> samples_;
  double wall_total_ = 0.0, sim_total_ = 0.0;
};

}  // namespace lamina::ui
