// SPDX-License-Identifier: MIT
// The stress suite (issue 15, "Stiff and extreme cases"; docs/stress.md): worlds pushed to the
// edges of what the simulator can take — layer stiffness up to 1e9 N/m, mass ratios to 1:1000,
// a 20-box stack, a 40-link chain robot, a 15 m drop, 100 m/s against one-triangle walls,
// thin-shell meshes, resting mesh–mesh contact, an absurd robot torque. Each case is one world
// with one solver, step and duration, and is judged on what the run reports:
//
//   stable   the run finished, every body state is finite, no body is lost (beyond a keep-out
//            plane: through the floor or a wall; or flung out of the case's reach), and the worst
//            step status is at most "adaptive step" with no instability correction and no
//            non-finite recovery. Rollbacks are allowed: halving the step is adaptive stepping
//            doing its job.
//   flagged  flagged and recovered: the status says something went wrong (contact unreliable,
//            unstable), or bodies were corrected or recovered from a non-finite state, and the run
//            still finished with a finite state; a lost body is flagged only when the status is
//            at least "contact unreliable" (a status that says geometry interpenetrated).
//   failed   the run stopped (an ODE error or a state that stayed non-finite: status "error"),
//            did not load, ended non-finite, or lost a body without such a status.
//
// Each case also reports one number of its own (top box drift, resting overlap against m·g/k,
// joint gap, ...), measured by a probe (accuracy_scene.h's AccuracyProbe; the accuracy scenes'
// probes are reused where the worlds match).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/accuracy/accuracy_scene.h"
#include "core/math_types.h"
#include "core/sim/step_observer.h"

namespace lamina::core {

class Simulator;

enum class StressVerdict { kStable, kFlagged, kFailed };
/// "stable", "flagged", "failed".
const char* StressVerdictName(StressVerdict verdict);

/// What a run ended with, as far as the verdict is concerned.
struct StressOutcome {
  bool ran = true;      ///< false: the world did not load or the run threw
  bool halted = false;  ///< an error stopped the simulation (status "error")
  bool finite = true;   ///< every body's final state is finite
  int lost = 0;         ///< bodies beyond a keep-out plane at the end
  StepStatus worst = StepStatus::kNormal;
  long corrections = 0;  ///< instability corrections (bodies slowed or stopped)
  long nonfinite = 0;    ///< steps that undid a non-finite state
};

/// The verdict (rules above) and, in `why` (when given), the reason in a few words.
StressVerdict JudgeStress(const StressOutcome& outcome, std::string* why = nullptr);

/// A half-space no body's centre of mass may end in: lost when normal · com > offset (m).
struct StressKeepOut {
  Vec3 normal = -Vec3::UnitZ();  ///< unit, pointing out of the allowed space
  double offset = 0.0;           ///< m
};
/// Below the plane z = `height`.
inline StressKeepOut Below(double height) {
  return {-Vec3::UnitZ(), -height};
}

struct StressCase {
  std::string name;   ///< "<scene>/<solver>/<step>", e.g. "box_stack_20/exact/1ms"
  std::string world;  ///< relative to the worlds folder, e.g. "stress/box_stack_20.xml"
  std::string what;   ///< one line for the report
  AccuracySolver solver;
  double step = 1e-3;     ///< largest step, s
  double duration = 1.0;  ///< simulated time, s
  /// Optional: done to the simulation before the run (e.g. the absurd torque command).
  std::function<void(Simulator*)> prepare;
  std::function<std::unique_ptr<AccuracyProbe>(const WorldDesc&)> probe;
  std::string metric;       ///< the probe metric the case reports; "" for the probe's error
  std::string metric_text;  ///< what it measures, for the report
  std::string unit;         ///< of the metric
  std::vector<StressKeepOut> keep_out;
  double reach = 1000.0;  ///< m: a centre of mass farther from the origin is lost (flung away)
  StressVerdict expected = StressVerdict::kStable;  ///< what the suite's test asserts
};

/// Every case, in the report's order.
const std::vector<StressCase>& StressCases();
/// The cases whose name matches one of `globs` (shell patterns, fnmatch; '*' also matches '/'),
/// in the report's order; every case for an empty list.
std::vector<const StressCase*> FindStressCases(const std::vector<std::string>& globs);

}  // namespace lamina::core
