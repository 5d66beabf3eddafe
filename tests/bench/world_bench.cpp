// SPDX-License-Identifier: MIT
// Each Klamp't simulation test world with dWorldStep, with dWorldQuickStep (20 iterations) and
// with dWorldStep and sleeping on (numerics.md: report with sleep on and off):
// every iteration simulates a fixed span from the start on a fresh simulator, and the counters
// give steps/s, the real-time factor, rollbacks and where the time goes.
#include "tests/bench/world_bench.h"

#include <algorithm>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "core/sim/simulator.h"
#include "tests/bench/bench_support.h"

namespace lamina::bench {
namespace {

// simulated seconds per iteration: long enough to include the impacts of the drop tests (the
// 10 m and 15 m drops land after 1.4 s and 1.75 s)
constexpr double kWorldSpan = 2.0;

struct SolverCase {
  const char* name;
  core::SolverSettings settings;
  bool sleep;
};

const SolverCase kSolvers[] = {
    {"step", {core::SolverType::kStep, 20}, false},
    {"quick20", {core::SolverType::kQuickStep, 20}, false},
    {"newton", {core::SolverType::kNewton, 20}, false},
    {"step_sleep", {core::SolverType::kStep, 20}, true},
};

void RunWorld(benchmark::State& state, const core::WorldDesc& world, const SolverCase& solver) {
  LaminaTotals totals;
  int asleep = 0;
  for (auto _ : state) {
    state.PauseTiming();
    auto simulator = std::make_unique<core::Simulator>(world, solver.settings);
    simulator->SetSleeping(solver.sleep);
    state.ResumeTiming();
    simulator->Simulate(kWorldSpan);
    state.PauseTiming();
    if (simulator->statistics().worst_status == core::StepStatus::kError) {
      Fail(state, "simulation failed: " + simulator->statistics().error);
      break;
    }
    totals.Add(kWorldSpan, simulator->statistics());
    asleep = simulator->SleepingObjectCount();
    simulator.reset();
    state.ResumeTiming();
  }
  SetLaminaCounters(state, totals);
  if (solver.sleep) state.counters["asleep_at_end"] = asleep;
}

std::vector<std::filesystem::path> TestWorldFiles() {
  std::vector<std::filesystem::path> files;
  const std::filesystem::path directory = WorldsPath("klampt/simulation_test_worlds");
  for (const auto& entry : std::filesystem::directory_iterator(directory)) {
    if (entry.path().extension() == ".xml") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

void RegisterWorld(const std::filesystem::path& file) {
  auto world = std::make_shared<core::WorldDesc>();
  std::string errors;
  const bool loaded = LoadWorld(file.string(), world.get(), &errors);
  for (const SolverCase& solver : kSolvers) {
    const std::string name = "World/" + file.stem().string() + "/" + solver.name;
    benchmark::RegisterBenchmark(name.c_str(), [world, solver, loaded,
                                                errors](benchmark::State& state) {
      if (!loaded) {
        Fail(state, "cannot load the world: " + errors);
        return;
      }
      RunWorld(state, *world, solver);
    })->Unit(benchmark::kMillisecond);
  }
}

}  // namespace

void RegisterWorldBenchmarks() {
  for (const std::filesystem::path& file : TestWorldFiles()) RegisterWorld(file);
}

}  // namespace lamina::bench
