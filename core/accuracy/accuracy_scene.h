// SPDX-License-Identifier: MIT
// One scene of the accuracy suite (docs/accuracy.md, numerics §6): a world file of
// worlds/accuracy/, how long it runs, and a probe that watches every accepted step and turns what
// it saw into an error against the scene's analytic answer, in physical units. A scene also states
// its pass bars: checks on the runs at given steps of the default solver (exact, adaptive
// stepping on), which both the report's table and `make test`'s short version judge.
//
// A probe reads only the simulation it is given (poses, velocities, the step events); the answer
// it compares with is computed from the world description (masses, friction, initial velocities),
// so editing a scene's world file moves the answer with it.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/model/world_desc.h"
#include "core/sim/step_observer.h"

namespace lamina::core {

class Simulator;

/// A named number a probe measured besides its error (e.g. "L drift", relative).
struct ProbeMetric {
  std::string name;
  double value = 0.0;
};

/// What a probe reports at the end of a run.
struct ProbeResult {
  double error = 0.0;  ///< the scene's error metric, in the scene's unit (>= 0)
  std::vector<ProbeMetric> metrics;
  std::string note;  ///< why the error is what it is, when not self-evident (e.g. "never stopped")
};

/// Watches one run. Begin sees the simulation before the first step, Observe every accepted
/// step, Finish the final state.
class AccuracyProbe {
 public:
  virtual ~AccuracyProbe() = default;
  virtual void Begin(const Simulator& simulator) = 0;
  virtual void Observe(const StepEvent& event) = 0;
  virtual ProbeResult Finish(const Simulator& simulator) = 0;
};

/// The solver a run uses: one of Lamina's, or another engine's (a peer: tests/bench/peers runs
/// the scenes through MuJoCo and Bullet, and the report plots those runs on the same axes).
struct AccuracySolver {
  SolverType type = SolverType::kStep;
  int iterations = 20;   ///< QuickStep, and the Bullet peer's solver iterations
  bool adaptive = true;  ///< adaptive time stepping (rollback and halving); Lamina only
  /// "" for Lamina; "mujoco" (its defaults: Euler, Newton solver, pyramidal cone) or "bullet"
  /// (btSequentialImpulseConstraintSolver with `iterations`) for a peer's run
  std::string peer;
  /// the world's `jointCoordinates` (the Newton solver's robots and world joints in their joint
  /// coordinates)
  bool joint_coordinates = false;

  /// "exact", "newton", "quick20", ..., "newton-joints" with joint coordinates, with "-fixed"
  /// when adaptive stepping is off; a peer's "mujoco" or "bullet10".
  std::string Label() const;
  bool operator==(const AccuracySolver&) const = default;
};

/// The solver a label names ("exact", "exact-fixed", "newton", "quick40", "quick40-fixed",
/// "mujoco", "bullet10"); nullopt for anything else (iterations must be 1 … 10000).
std::optional<AccuracySolver> ParseAccuracySolver(const std::string& label);

/// The solver of a scene's bars and of the editor's default: exact, adaptive.
inline AccuracySolver DefaultAccuracySolver() {
  return {};
}

/// The Newton solver in joint coordinates (the world's `jointCoordinates`: its robots' and its
/// world joints' islands over their joint rates), adaptive: "newton-joints".
inline AccuracySolver JointCoordinateSolver() {
  return {SolverType::kNewton, 20, true, "", true};
}

/// One run's outcome, as the report lists it.
struct AccuracyRun {
  std::string scene;
  AccuracySolver solver;
  double step = 0.0;  ///< the largest physics step, s
  ProbeResult result;
  double cpu_seconds = 0.0;       ///< CPU time of the stepping (this thread), s
  double real_time_factor = 0.0;  ///< simulated time / CPU time
  long steps = 0;
  long rollbacks = 0;
  double min_step = 0.0;  ///< the shortest accepted step, s
  long corrections = 0;   ///< instability corrections (bodies)
  long nonfinite = 0;     ///< steps that undid a non-finite state
  long unreliable = 0;    ///< steps after which geometries interpenetrated
  std::string status;     ///< the worst step status ("normal", ..., "error")
  std::string failure;    ///< what stopped the run (loading, an error), empty when it ran
};

/// A bar's verdict and what was measured, e.g. {true, "0.0490 m (bar 0.0490 m)"}.
struct BarCheck {
  bool pass = false;
  std::string measured;
};

/// A pass bar: the steps it needs (of `solver`'s runs) and the check on those runs, in that
/// order.
struct AccuracyBar {
  std::string text;  ///< e.g. "error ≤ ½·g·h·T at 1 ms"
  std::vector<double> steps;
  std::function<BarCheck(const std::vector<const AccuracyRun*>& runs)> check;
  /// The simulator is known not to meet this bar yet (the scene's comment says by how much and
  /// why). The bar stays in the report as not met; `make test`'s short version expects it to
  /// fail, so that it says so as soon as it passes and the mark can go.
  bool known_failure = false;
  /// The runs it judges (a scene's other bars may name another, e.g. joint coordinates).
  AccuracySolver solver = DefaultAccuracySolver();
};

struct AccuracyScene {
  std::string name;        ///< e.g. "ballistic_box"
  std::string world;       ///< file under worlds/accuracy
  std::string title;       ///< one line
  std::string setup;       ///< what the world holds, for the report
  std::string metric;      ///< what the error measures
  std::string unit;        ///< of the error, e.g. "m"
  std::string answer;      ///< the analytic answer, for the report
  double duration = 1.0;   ///< simulated time of a run, s
  double min_step = 1e-5;  ///< the sweep leaves out smaller steps (cost), s
  /// When > 0: `make test`'s short version (tests/physics/accuracy_bars_test.cpp) runs the bars'
  /// steps this long instead, s. Only for the many-body scenes that would cost seconds of CPU
  /// there; the report and `accuracy --bars` always run `duration`.
  double test_duration = 0.0;
  /// Optional change of the loaded world before a run (a variant of a shared file).
  std::function<void(WorldDesc*)> adjust;
  std::function<std::unique_ptr<AccuracyProbe>(const WorldDesc&)> probe;
  std::vector<AccuracyBar> bars;
};

/// Every scene of the suite, in the report's order.
const std::vector<AccuracyScene>& AccuracyScenes();
/// The scene called `name`, or nullptr.
const AccuracyScene* FindAccuracyScene(const std::string& name);

}  // namespace lamina::core
