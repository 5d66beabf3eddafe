// SPDX-License-Identifier: MIT
// Robots standing on their own: ATHLETE dropped on fractal terrain (athlete_fractal_1.xml), the
// HRP-2 humanoid on a plane (hrp2_plane.xml, 30 hinges with joint friction, its servos holding
// the zero pose) and on rough ground (examples/hrp2_rough.xml: mesh soles on a 32768-triangle
// terrain, the contact-rich humanoid), each with dWorldStep, the Newton solver and
// dWorldQuickStep (20 iterations), and with dWorldStep at 2 and 4 ms as well as the worlds' 1 ms:
// every iteration simulates 5 s from the start on a fresh simulator; the counters give the
// real-time factor, the time split and how far the base moved over the last 2 s (the bar: < 1 cm;
// Klamp't's ATHLETE creeps downhill). An iteration whose base moves more than that fails the
// benchmark. And a free-moving arm: the TX90L following milestones with nothing to touch
// (examples/tx90l_milestones.xml, tx90l_reach.milestones: five reaches and back in about 5 s),
// where every step is the arm's own rows and the per-step overhead shows (Klamp't: about 15 µs a
// step); an iteration that does not end within 0.01 rad of the last milestone (0.05 rad with
// QuickStep's explicit servos) fails.
#include "tests/bench/robot_bench.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <string>

#include <benchmark/benchmark.h>

#include "core/control/send_motion.h"
#include "core/io/trajectory_file.h"
#include "core/sim/simulator.h"
#include "tests/bench/bench_support.h"

namespace lamina::bench {
namespace {

constexpr double kSettle = 3.0;         // s before the drift is measured
constexpr double kMeasured = 2.0;       // s over which the base must stand still
constexpr double kMaxBaseDrift = 0.01;  // m

struct SolverCase {
  const char* name;
  core::SolverSettings settings;
};

const SolverCase kRobotSolvers[] = {{"step", {core::SolverType::kStep, 20}},
                                    {"newton", {core::SolverType::kNewton, 20}},
                                    {"quick20", {core::SolverType::kQuickStep, 20}}};

// true (and the benchmark failed) when the run ended in error
bool RunFailed(benchmark::State& state, const core::Simulator& simulator) {
  if (simulator.statistics().worst_status != core::StepStatus::kError) return false;
  Fail(state, "simulation failed: " + simulator.statistics().error);
  return true;
}

// one benchmark "Robot/<name>/<solver>" per solver, each running `run(state, settings)`
template <typename Run>
void RegisterEachSolver(const std::string& name, const Run& run) {
  for (const SolverCase& solver : kRobotSolvers) {
    const core::SolverSettings settings = solver.settings;
    benchmark::RegisterBenchmark(("Robot/" + name + "/" + solver.name).c_str(),
                                 [run, settings](benchmark::State& state) { run(state, settings); })
        ->Unit(benchmark::kMillisecond)
        ->Iterations(1);
  }
}

void RunStanding(benchmark::State& state, const core::WorldDesc& world,
                 const core::SolverSettings& solver) {
  LaminaTotals totals;
  double worst_drift = 0.0;
  for (auto _ : state) {
    state.PauseTiming();
    auto simulator = std::make_unique<core::Simulator>(world, solver);
    state.ResumeTiming();
    simulator->Simulate(kSettle);
    state.PauseTiming();
    const core::Vec3 settled = simulator->GetRobotConfig(0).head<3>();
    state.ResumeTiming();
    simulator->Simulate(kMeasured);
    state.PauseTiming();
    if (RunFailed(state, *simulator)) break;
    const double drift = (simulator->GetRobotConfig(0).head<3>() - settled).norm();
    worst_drift = std::max(worst_drift, drift);
    totals.Add(kSettle + kMeasured, simulator->statistics());
    simulator.reset();
    state.ResumeTiming();
  }
  SetLaminaCounters(state, totals);
  state.counters["base_drift_mm"] = 1000 * worst_drift;
  if (worst_drift > kMaxBaseDrift) {
    Fail(state, "the base moved " + std::to_string(worst_drift) + " m over the last 2 s");
  }
}

// the exact solver at larger steps than the worlds' 1 ms ("Robot/<world>/step_<ms>ms"): the
// trade the fast path is about, speed for a step that still holds (the same base-drift
// bar; adaptive stepping on, as the worlds have it)
constexpr double kLargerSteps[] = {0.002, 0.004};

// RunStanding on `world`, or the benchmark failed when it did not load
void RunStandingIfLoaded(benchmark::State& state, const core::WorldDesc& world, bool loaded,
                         const std::string& errors, const core::SolverSettings& settings) {
  if (!loaded) {
    Fail(state, "cannot load the world: " + errors);
    return;
  }
  RunStanding(state, world, settings);
}

void RegisterLargerSteps(const std::string& world_name,
                         const std::shared_ptr<const core::WorldDesc>& world, bool loaded,
                         const std::string& errors) {
  for (const double step : kLargerSteps) {
    auto larger = std::make_shared<core::WorldDesc>(*world);
    larger->settings.timestep = step;
    const std::string name = "Robot/" + world_name + "/step_" +
                             std::to_string(static_cast<int>(std::lround(1000 * step))) + "ms";
    benchmark::RegisterBenchmark(
        name.c_str(),
        [larger, loaded, errors](benchmark::State& state) {
          RunStandingIfLoaded(state, *larger, loaded, errors, {core::SolverType::kStep, 20});
        })
        ->Unit(benchmark::kMillisecond)
        ->Iterations(1);
  }
}

// `file`: under worlds/, without ".xml"; the benchmark is named by its last part
void RegisterStanding(const std::string& file) {
  const std::string world_name = file.substr(file.find_last_of('/') + 1);
  auto world = std::make_shared<core::WorldDesc>();
  std::string errors;
  const bool loaded = LoadWorld(WorldsPath(file + ".xml"), world.get(), &errors);
  RegisterEachSolver(world_name, [world, loaded, errors](benchmark::State& state,
                                                         const core::SolverSettings& settings) {
    RunStandingIfLoaded(state, *world, loaded, errors, settings);
  });
  RegisterLargerSteps(world_name, world, loaded, errors);
}

constexpr double kFollowed = 6.0;  // s: the reaches end after about 5 s
// rad from the last milestone at the end: the implicit servos of dWorldStep and the Newton
// solver end 2.9 mrad off (the I term still closing on joint friction); QuickStep's explicit PD
// (robots.md) ends 27 mrad off
constexpr double kMaxTrackingError = 0.01;
constexpr double kMaxQuickTrackingError = 0.05;

void RunFollowing(benchmark::State& state, const core::WorldDesc& world,
                  const core::MilestoneSequence& motion, const core::SolverSettings& solver) {
  const double bar =
      solver.type == core::SolverType::kQuickStep ? kMaxQuickTrackingError : kMaxTrackingError;
  LaminaTotals totals;
  double worst_error = 0.0;
  for (auto _ : state) {
    state.PauseTiming();
    auto simulator = std::make_unique<core::Simulator>(world, solver);
    std::string error;
    if (!core::SendMotion(motion, &simulator->controller(0), &error)) {
      Fail(state, "cannot send the milestones: " + error);
      break;
    }
    state.ResumeTiming();
    simulator->Simulate(kFollowed);
    state.PauseTiming();
    if (RunFailed(state, *simulator)) break;
    const core::VecX& last = motion.configs.back();
    worst_error =
        std::max(worst_error, (simulator->GetRobotConfig(0) - last).cwiseAbs().maxCoeff());
    totals.Add(kFollowed, simulator->statistics());
    simulator.reset();
    state.ResumeTiming();
  }
  SetLaminaCounters(state, totals);
  state.counters["tracking_error_mrad"] = 1000 * worst_error;
  if (worst_error > bar) {
    Fail(state, "the arm ended " + std::to_string(worst_error) + " rad from its last milestone");
  }
}

void RegisterFollowing(const std::string& file, const std::string& motion_file) {
  const std::string world_name = file.substr(file.find_last_of('/') + 1);
  auto world = std::make_shared<core::WorldDesc>();
  std::string errors;
  const bool loaded = LoadWorld(WorldsPath(file + ".xml"), world.get(), &errors);
  core::Diagnostics diagnostics;
  auto motion = std::make_shared<std::optional<core::MilestoneSequence>>(
      core::ReadMotionFile(WorldsPath(motion_file), diagnostics));
  RegisterEachSolver(world_name,
                     [world, motion, loaded, errors](benchmark::State& state,
                                                     const core::SolverSettings& settings) {
                       if (!loaded || !*motion) {
                         Fail(state, "cannot load the world or the milestones: " + errors);
                         return;
                       }
                       RunFollowing(state, *world, **motion, settings);
                     });
}

}  // namespace

void RegisterRobotBenchmarks() {
  RegisterStanding("klampt/athlete_fractal_1");
  RegisterStanding("klampt/hrp2_plane");
  RegisterStanding("examples/hrp2_rough");
  RegisterFollowing("examples/tx90l_milestones", "examples/tx90l_reach.milestones");
}

}  // namespace lamina::bench
