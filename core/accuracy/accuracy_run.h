// SPDX-License-Identifier: MIT
// Running the accuracy suite: one scene at one step and solver (RunAccuracyScene), and a sweep
// of scenes × solvers × steps on worker threads (RunAccuracySweep). Times are the CPU time of the
// stepping loop on the run's own thread (CLOCK_THREAD_CPUTIME_ID), so runs in parallel do not
// inflate each other's figures; loading and building the simulation are not timed.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/accuracy/accuracy_scene.h"

namespace lamina::core {

/// Runs `scene` loaded from `worlds_dir`/`scene.world` with `solver` at largest step `step` (s).
/// A world that does not load, or a probe that throws, gives a run whose `failure` says why.
AccuracyRun RunAccuracyScene(const AccuracyScene& scene, const std::string& worlds_dir,
                             const AccuracySolver& solver, double step);

/// The same on a world already loaded (and not yet adjusted).
AccuracyRun RunAccuracySceneOn(const AccuracyScene& scene, WorldDesc world,
                               const AccuracySolver& solver, double step);

/// What a sweep runs: every scene with every solver at every step (each scene leaves out steps
/// below its min_step), or with `bars_only` each scene at the steps its bars name. A scene whose
/// bar is judged with a solver the grid lacks (AccuracyBar::solver) runs with it too, unless
/// `bar_solvers` is off (lamina-peers: the bars' solvers are Lamina's, which no peer runs).
struct AccuracyGrid {
  std::vector<const AccuracyScene*> scenes;
  std::vector<AccuracySolver> solvers;
  std::vector<double> steps;
  bool bars_only = false;
  bool bar_solvers = true;
};

/// The sweep the report uses: numerics §6's steps 1e-5 … 1e-2 s; exact and QuickStep at 20, 40
/// and 100 iterations with adaptive stepping, and exact without it.
AccuracyGrid FullAccuracyGrid();
/// Each scene's bar steps with the default solver only (`make test`'s short version).
AccuracyGrid BarAccuracyGrid();

struct AccuracyProgress {
  int done = 0;
  int total = 0;
  const AccuracyRun* last = nullptr;
};

/// What runs one job of a sweep: RunAccuracyScene, or another engine's runner (tests/bench/peers).
using AccuracyRunner = std::function<AccuracyRun(
    const AccuracyScene&, const std::string& worlds_dir, const AccuracySolver&, double step)>;

/// Runs the grid on `threads` threads (0: every core), the costliest runs first; results in the
/// grid's order (scene, solver, step). `progress` (optional) is called from one thread at a time
/// after each run. `runner` runs each job (default RunAccuracyScene).
std::vector<AccuracyRun> RunAccuracySweep(
    const AccuracyGrid& grid, const std::string& worlds_dir, int threads,
    const std::function<void(const AccuracyProgress&)>& progress,
    const AccuracyRunner& runner = RunAccuracyScene);

/// The runs of `scene` with `solver` at each of `steps` (nullptr where missing), in that order.
std::vector<const AccuracyRun*> FindAccuracyRuns(const std::vector<AccuracyRun>& runs,
                                                 const std::string& scene,
                                                 const AccuracySolver& solver,
                                                 const std::vector<double>& steps);

}  // namespace lamina::core
