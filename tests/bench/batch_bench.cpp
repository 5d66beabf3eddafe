// SPDX-License-Identifier: MIT
// Monte-Carlo batches of the seed example (worlds/batch/spin_to_zero.json: 100 runs of 5 s of
// Klamp't's 1R planar robot) on 1 and 2 threads. Wall time (the pool's threads are not this
// thread's CPU time). Counters: runs/s; build_ms and step_ms, the mean wall time per run spent
// copying the world and building its Simulator and the rest (commands, stepping, reading items);
// Batch/Speedup alternates 1 and 2 threads and reports `speedup` = time(1) / time(2).
#include <chrono>
#include <stdexcept>
#include <string>

#include <benchmark/benchmark.h>

#include "core/batch/batch_spec.h"
#include "tests/bench/bench_support.h"

namespace lamina::bench {
namespace {

const core::BatchSpec& SeedSpec() {
  static const core::BatchSpec spec = [] {
    std::string error;
    auto loaded =
        core::LoadBatchSpec(std::string(LAMINA_WORLDS_DIR) + "/batch/spin_to_zero.json", &error);
    if (!loaded) throw std::runtime_error(error);
    return *loaded;
  }();
  return spec;
}

// one batch on `threads`: wall seconds; the per-run times added to `build` and `step`
double RunBatch(int threads, double* build, double* step, bool* failed) {
  const core::BatchSpec& spec = SeedSpec();
  core::PoolOptions pool;
  pool.threads = threads;
  const auto start = std::chrono::steady_clock::now();
  const auto runs = core::MonteCarloSim(spec.world, spec.plan, spec.samplers, spec.seed,
                                        core::ShardIndices(spec.runs, {}), pool);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (const auto& run : runs) {
    *build += run.build_wall_time;
    *step += run.wall_clock_time - run.build_wall_time;
    *failed = *failed || run.status == "error";
  }
  return seconds;
}

void BatchThreads(benchmark::State& state) {
  const int threads = static_cast<int>(state.range(0));
  double build = 0, step = 0, runs = 0;
  bool failed = false;
  for (auto _ : state) {
    RunBatch(threads, &build, &step, &failed);
    runs += SeedSpec().runs;
  }
  if (failed) Fail(state, "a run of the seed example failed");
  state.counters["runs/s"] = benchmark::Counter(runs, benchmark::Counter::kIsRate);
  state.counters["build_ms"] = 1000 * build / runs;
  state.counters["step_ms"] = 1000 * step / runs;
}
BENCHMARK(BatchThreads)
    ->Name("Batch/spin_to_zero/threads")
    ->Arg(1)
    ->Arg(2)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

void BatchSpeedup(benchmark::State& state) {
  double one = 0, two = 0, build = 0, step = 0;
  bool failed = false;
  for (auto _ : state) {
    one += RunBatch(1, &build, &step, &failed);
    two += RunBatch(2, &build, &step, &failed);
  }
  if (failed) Fail(state, "a run of the seed example failed");
  state.counters["speedup"] = one / two;
}
BENCHMARK(BatchSpeedup)->Name("Batch/Speedup")->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace lamina::bench
