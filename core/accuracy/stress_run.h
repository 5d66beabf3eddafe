// SPDX-License-Identifier: MIT
// Running the stress suite (stress_case.h): one case (RunStressCase) and a list of cases on worker
// threads (RunStressCases), each judged stable, flagged or failed. As in the accuracy sweep, the
// CPU time is the stepping loop's on the run's own thread; loading and building are not timed.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/accuracy/stress_case.h"

namespace lamina::core {

/// One case's record, as the report lists it.
struct StressRecord {
  std::string name;
  std::string world;
  std::string solver;  ///< "exact", "quick20"
  double step = 0.0;   ///< largest step, s
  double duration = 0.0;
  StressVerdict verdict = StressVerdict::kFailed;
  StressVerdict expected = StressVerdict::kStable;
  std::string why;     ///< the verdict's reason ("" when stable)
  std::string status;  ///< the worst step status
  long steps = 0;
  long rollbacks = 0;
  long corrections = 0;          ///< instability corrections (bodies slowed or stopped)
  long nonfinite = 0;            ///< steps that undid a non-finite state
  long unreliable = 0;           ///< steps after which geometries interpenetrated
  long joint_open = 0;           ///< steps after which a joint was open (StepStatus kJointOpen)
  double max_joint_gap = 0.0;    ///< widest joint gap in an accepted state, m
  double min_step = 0.0;         ///< the shortest accepted step, s
  double max_penetration = 0.0;  ///< deepest boundary-layer overlap, m
  double cpu_seconds = 0.0;
  std::string metric_text, unit;
  double metric = 0.0;            ///< the case's own number (NaN when the probe had none)
  ProbeResult probe;              ///< everything the probe measured
  std::vector<std::string> lost;  ///< names of the bodies beyond a keep-out plane at the end
  std::string failure;            ///< what stopped the run (loading, an ODE error)
};

/// Loads `worlds_dir`/`c.world`, runs the case and judges it.
StressRecord RunStressCase(const StressCase& c, const std::string& worlds_dir);

/// Runs `cases` on `threads` threads (0: every core), the longest first; records in the order
/// given. `progress` (optional) is called from one thread at a time after each case.
std::vector<StressRecord> RunStressCases(
    const std::vector<const StressCase*>& cases, const std::string& worlds_dir, int threads,
    const std::function<void(int done, int total, const StressRecord&)>& progress);

}  // namespace lamina::core
