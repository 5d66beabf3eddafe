// SPDX-License-Identifier: MIT
// Robots standing on their own: ATHLETE dropped on fractal terrain (athlete_fractal_1.xml) and
// the HRP-2 humanoid on a plane (hrp2_plane.xml, 30 hinges with joint friction, its servos holding
// the zero pose), each with dWorldStep, the Newton solver and dWorldQuickStep (20 iterations):
// every iteration
// simulates 5 s from the start on a fresh simulator; the counters give the real-time factor, the
// time split and how far the base moved over the last 2 s (the bar: < 1 cm; Klamp't's ATHLETE
// creeps downhill). An iteration whose base moves more than that fails the benchmark.
#include "tests/bench/robot_bench.h"

#include <memory>
#include <string>

#include <benchmark/benchmark.h>

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
    if (simulator->statistics().worst_status == core::StepStatus::kError) {
      Fail(state, "simulation failed: " + simulator->statistics().error);
      break;
    }
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

void RegisterStanding(const std::string& world_name) {
  auto world = std::make_shared<core::WorldDesc>();
  std::string errors;
  const bool loaded = LoadWorld(WorldsPath("klampt/" + world_name + ".xml"), world.get(), &errors);
  const SolverCase solvers[] = {{"step", {core::SolverType::kStep, 20}},
                                {"newton", {core::SolverType::kNewton, 20}},
                                {"quick20", {core::SolverType::kQuickStep, 20}}};
  for (const SolverCase& solver : solvers) {
    const std::string name = "Robot/" + world_name + "/" + solver.name;
    const core::SolverSettings settings = solver.settings;
    benchmark::RegisterBenchmark(name.c_str(),
                                 [world, settings, loaded, errors](benchmark::State& state) {
                                   if (!loaded) {
                                     Fail(state, "cannot load the world: " + errors);
                                     return;
                                   }
                                   RunStanding(state, *world, settings);
                                 })
        ->Unit(benchmark::kMillisecond)
        ->Iterations(1);
  }
}

}  // namespace

void RegisterRobotBenchmarks() {
  RegisterStanding("athlete_fractal_1");
  RegisterStanding("hrp2_plane");
}

}  // namespace lamina::bench
