// SPDX-License-Identifier: MIT
// The live accuracy meter: an estimate of the simulation's current error in metres, from step
// doubling on sampled steps (Richardson's estimate, as adaptive ODE integrators use it). Now and
// then the simulator takes the coming step once at h and once as two halves from the same state,
// throws both away, and restores its state exactly; the bodies' positions after the two differ by
// about half the full step's local error for a first-order method (the one ODE's semi-implicit
// Euler is): full-step error C h², two half steps 2 C (h/2)² = C h²/2, difference C h²/2. So:
//
//   local error of a step ≈ 2 · max over moving bodies |p_full − p_halves|   (m)
//   error growth rate     ≈ local error / h                                   (m per simulated s)
//
// The rate is what the meter shows: over T seconds of smooth motion the position error grows to
// about rate · T (a ballistic body: ½·g·h per second, 4.9 mm/s at 1 ms). It rises with the step,
// jumps at impacts and stick–slip transitions (where the step error is real), and reads 0 for
// bodies at rest.
//
// Cost: a sample costs three steps and two state restores. The meter samples only while the time
// spent sampling stays within `budget` (default 5 %) of the time spent stepping, so it never costs
// more than that however heavy the scene. The first sample, whose cost is not known yet, is
// counted as three ordinary steps: it waits for 3 / budget steps (60 at 5 %). (It used to be
// taken before the first step, where a pile's start is at its costliest: on the 1,275-box pyramid
// it took 4.8 s, against 6.7 s for the 30 steps after it.) This class holds that accounting and
// the smoothing; it is pure (no simulator), Simulator::SampleStepError does the stepping.
//
// Not in Klamp't (which has no error estimate); MuJoCo offers only the energy monitor.
#pragma once

#include <vector>

#include "core/math_types.h"

namespace lamina::core {

/// One step-doubling sample.
struct StepErrorSample {
  double time = 0.0;         ///< simulated time of the sampled state (s)
  double step = 0.0;         ///< the full step h (s)
  double difference = 0.0;   ///< max over moving bodies |p_full − p_halves| (m)
  double local_error = 0.0;  ///< 2 · difference (m)
  double rate = 0.0;         ///< local_error / step (m/s)
};

/// The sample from the bodies' positions after one full step and after two half steps (same
/// order, same length).
StepErrorSample MakeStepErrorSample(double time, double step, const std::vector<Vec3>& full,
                                    const std::vector<Vec3>& halves);

struct ErrorMeterReading {
  bool valid = false;        ///< false until the first sample
  double rate = 0.0;         ///< m per simulated second: the largest of the recent samples
  double local_error = 0.0;  ///< m per step, of that sample
  double time = 0.0;         ///< simulated time of the latest sample (s)
  long samples = 0;          ///< samples taken since the start (or Reset)
  double overhead = 0.0;     ///< time spent sampling / time spent stepping
};

class ErrorMeter {
 public:
  /// The steps a sample takes (one full step, two halves): the first sample's estimated cost in
  /// mean steps.
  static constexpr double kSampleSteps = 3.0;

  /// `budget`: largest fraction of the stepping time spent sampling; `window`: the reading is
  /// the largest rate among the last `window` samples (so a brief impact stays visible).
  explicit ErrorMeter(double budget = 0.05, int window = 8) : budget_(budget), window_(window) {}

  /// Whether the next step should be sampled: whenever the sampling time, with the last sample's
  /// cost once more (before the first: kSampleSteps times the mean step), would stay within
  /// budget of the stepping time.
  bool Due() const;
  /// Counts one ordinary step that took `seconds` of (wall) time.
  void AddSteppingTime(double seconds) {
    stepping_ += seconds;
    ++steps_;
  }
  /// Records a sample that took `seconds`.
  void Add(const StepErrorSample& sample, double seconds);
  /// Counts a sample that failed (a probe step halted the simulation) and took `seconds`.
  void AddSamplingTime(double seconds) {
    sampling_ += seconds;
    last_cost_ = seconds;
    tried_ = true;
  }
  ErrorMeterReading Reading() const;
  void Reset();

 private:
  double budget_;
  int window_;
  double stepping_ = 0.0, sampling_ = 0.0;
  double last_cost_ = 0.0;  ///< seconds the last sample took
  bool tried_ = false;      ///< a sample was taken (or failed) since the start
  long steps_ = 0;          ///< ordinary steps counted
  long samples_ = 0;
  std::vector<StepErrorSample> recent_;
};

}  // namespace lamina::core
