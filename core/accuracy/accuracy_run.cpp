// SPDX-License-Identifier: MIT
#include "core/accuracy/accuracy_run.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "core/accuracy/probe_support.h"
#include "core/io/world_file.h"
#include "core/sim/simulator.h"

namespace lamina::core {
namespace {

void ApplySolver(const AccuracySolver& solver, double step, WorldDesc* world) {
  world->settings.timestep = step;
  world->settings.solver = solver.type;
  world->settings.quick_step_iterations = solver.iterations;
  world->settings.adaptive_time_stepping = solver.adaptive;
  world->settings.joint_coordinates = solver.joint_coordinates;
}

// Per-step bookkeeping the runner keeps itself: the shortest step and the non-finite recoveries.
struct StepTally {
  double min_step = kInf;
  long nonfinite = 0;
  void Add(const StepEvent& event) {
    min_step = std::min(min_step, event.h);
    if ((event.flags & kStepRecovered) != 0u) ++nonfinite;
  }
};

void CopyStatistics(const SimStatistics& statistics, AccuracyRun* run) {
  run->steps = statistics.steps;
  run->rollbacks = statistics.rollbacks;
  run->corrections = statistics.instability_corrections;
  run->unreliable = statistics.unreliable_steps;
  run->status = StepStatusName(statistics.worst_status);
  if (!statistics.error.empty()) run->failure = statistics.error;
}

void Simulate(const AccuracyScene& scene, Simulator* simulator, AccuracyProbe* probe,
              AccuracyRun* run) {
  StepTally tally;
  simulator->AddStepObserver([&](const StepEvent& event) {
    tally.Add(event);
    probe->Observe(event);
  });
  probe->Begin(*simulator);
  const double start = ThreadCpuSeconds();
  simulator->Simulate(scene.duration);
  run->cpu_seconds = ThreadCpuSeconds() - start;
  run->real_time_factor = scene.duration / std::max(run->cpu_seconds, 1e-9);
  run->min_step = std::isfinite(tally.min_step) ? tally.min_step : 0.0;
  run->nonfinite = tally.nonfinite;
  run->result = probe->Finish(*simulator);
}

double RunCost(const AccuracyScene& scene, double step) {
  return scene.duration / step;
}

AccuracyRun NewRun(const AccuracyScene& scene, const AccuracySolver& solver, double step) {
  AccuracyRun run;
  run.scene = scene.name;
  run.solver = solver;
  run.step = step;
  return run;
}

}  // namespace

AccuracyRun RunAccuracySceneOn(const AccuracyScene& scene, WorldDesc world,
                               const AccuracySolver& solver, double step) {
  AccuracyRun run = NewRun(scene, solver, step);
  if (!solver.peer.empty()) {
    run.failure = solver.Label() + " is another engine's: tests/bench/peers runs it";
    return run;
  }
  try {
    if (scene.adjust) scene.adjust(&world);
    ApplySolver(solver, step, &world);
    Simulator simulator(world);
    const std::unique_ptr<AccuracyProbe> probe = scene.probe(world);
    Simulate(scene, &simulator, probe.get(), &run);
    CopyStatistics(simulator.statistics(), &run);
  } catch (const std::exception& error) {
    run.failure = error.what();
  }
  return run;
}

AccuracyRun RunAccuracyScene(const AccuracyScene& scene, const std::string& worlds_dir,
                             const AccuracySolver& solver, double step) {
  Diagnostics diagnostics;
  MeshCache meshes;
  LoadContext context{diagnostics, meshes};
  WorldDesc world;
  if (!LoadWorldFile(worlds_dir + "/" + scene.world, context, &world)) {
    AccuracyRun run = NewRun(scene, solver, step);
    run.failure = diagnostics.FormatAll();
    return run;
  }
  return RunAccuracySceneOn(scene, std::move(world), solver, step);
}

std::string AccuracySolver::Label() const {
  if (peer == "bullet") return peer + std::to_string(iterations);
  if (!peer.empty()) return peer;
  std::string label = type == SolverType::kStep     ? "exact"
                      : type == SolverType::kNewton ? "newton"
                                                    : "quick" + std::to_string(iterations);
  if (joint_coordinates) label += "-joints";
  return adaptive ? label : label + "-fixed";
}

AccuracyGrid FullAccuracyGrid() {
  AccuracyGrid grid;
  for (const AccuracyScene& scene : AccuracyScenes()) grid.scenes.push_back(&scene);
  const SolverType quick = SolverType::kQuickStep;
  grid.solvers = {{},
                  {SolverType::kNewton, 20, true, ""},
                  {quick, 20, true, ""},
                  {quick, 40, true, ""},
                  {quick, 100, true, ""},
                  {SolverType::kStep, 20, false, ""}};
  grid.steps = {1e-5, 4e-5, 1e-4, 4e-4, 1e-3, 4e-3, 1e-2};
  return grid;
}

AccuracyGrid BarAccuracyGrid() {
  AccuracyGrid grid;
  for (const AccuracyScene& scene : AccuracyScenes()) grid.scenes.push_back(&scene);
  grid.solvers = {DefaultAccuracySolver()};
  grid.bars_only = true;
  return grid;
}

namespace {

struct Job {
  const AccuracyScene* scene;
  AccuracySolver solver;
  double step;
  std::size_t slot;
};

// the steps of the bars judged with `solver`
std::vector<double> BarSteps(const AccuracyScene& scene, const AccuracySolver& solver) {
  std::vector<double> steps;
  for (const AccuracyBar& bar : scene.bars) {
    if (bar.solver == solver) steps.insert(steps.end(), bar.steps.begin(), bar.steps.end());
  }
  std::sort(steps.begin(), steps.end());
  steps.erase(std::unique(steps.begin(), steps.end()), steps.end());
  return steps;
}

// a solver of the grid's runs at the default solver's bar steps, one that only a bar names at
// that bar's
std::vector<double> SceneSteps(const AccuracyGrid& grid, const AccuracyScene& scene,
                               const AccuracySolver& solver, bool grid_solver) {
  if (grid.bars_only) return BarSteps(scene, grid_solver ? DefaultAccuracySolver() : solver);
  std::vector<double> steps;
  for (double step : grid.steps) {
    if (step >= scene.min_step * (1.0 - 1e-9)) steps.push_back(step);
  }
  return steps;
}

// the solvers a bar of the scene is judged with that the grid does not have
std::vector<AccuracySolver> BarOnlySolvers(const AccuracyGrid& grid, const AccuracyScene& scene) {
  std::vector<AccuracySolver> solvers;
  for (const AccuracyBar& bar : scene.bars) {
    const auto has = [&](const std::vector<AccuracySolver>& list) {
      return std::find(list.begin(), list.end(), bar.solver) != list.end();
    };
    if (!has(grid.solvers) && !has(solvers)) solvers.push_back(bar.solver);
  }
  return solvers;
}

std::vector<Job> MakeJobs(const AccuracyGrid& grid) {
  std::vector<Job> jobs;
  for (const AccuracyScene* scene : grid.scenes) {
    const auto add = [&](const AccuracySolver& solver, bool grid_solver) {
      for (double step : SceneSteps(grid, *scene, solver, grid_solver)) {
        jobs.push_back({scene, solver, step, jobs.size()});
      }
    };
    for (const AccuracySolver& solver : grid.solvers) add(solver, true);
    if (!grid.bar_solvers) continue;
    for (const AccuracySolver& solver : BarOnlySolvers(grid, *scene)) add(solver, false);
  }
  return jobs;
}

}  // namespace

std::vector<AccuracyRun> RunAccuracySweep(
    const AccuracyGrid& grid, const std::string& worlds_dir, int threads,
    const std::function<void(const AccuracyProgress&)>& progress, const AccuracyRunner& runner) {
  std::vector<Job> jobs = MakeJobs(grid);
  std::vector<AccuracyRun> runs(jobs.size());
  std::sort(jobs.begin(), jobs.end(), [](const Job& a, const Job& b) {
    return RunCost(*a.scene, a.step) > RunCost(*b.scene, b.step);
  });
  std::atomic<std::size_t> next{0};
  std::mutex report;
  int done = 0;
  auto work = [&] {
    for (std::size_t i = next++; i < jobs.size(); i = next++) {
      const Job& job = jobs[i];
      runs[job.slot] = runner(*job.scene, worlds_dir, job.solver, job.step);
      const std::lock_guard<std::mutex> lock(report);
      ++done;
      if (progress) progress({done, static_cast<int>(jobs.size()), &runs[job.slot]});
    }
  };
  const int count = threads > 0 ? threads : std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::thread> pool;
  for (int t = 0; t < count; ++t) pool.emplace_back(work);
  for (std::thread& thread : pool) thread.join();
  return runs;
}

std::vector<const AccuracyRun*> FindAccuracyRuns(const std::vector<AccuracyRun>& runs,
                                                 const std::string& scene,
                                                 const AccuracySolver& solver,
                                                 const std::vector<double>& steps) {
  std::vector<const AccuracyRun*> found;
  for (double step : steps) {
    const AccuracyRun* match = nullptr;
    for (const AccuracyRun& run : runs) {
      if (run.scene == scene && run.solver == solver && std::abs(run.step - step) <= 1e-12 * step) {
        match = &run;
      }
    }
    found.push_back(match);
  }
  return found;
}

}  // namespace lamina::core
