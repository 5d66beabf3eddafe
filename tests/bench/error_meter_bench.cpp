// SPDX-License-Identifier: MIT
// What the live accuracy meter costs (core/sim/error_meter.h): two simulations of the same world,
// one with the meter and one without, advanced in alternating 50 ms slices timed on the thread's
// CPU clock (the order flips every slice), for the 10-box stack and ATHLETE on fractal terrain.
// `overhead` = CPU time with the meter / without − 1 (the bar: ≤ 10 %; the meter's own
// budget is 5 %); `meter_overhead` = what the meter itself measured; `rate_mm_s` its reading.
// An iteration whose two runs end in different states fails: the meter must change nothing.
#include <memory>
#include <string>

#include <benchmark/benchmark.h>

#include "core/sim/simulator.h"
#include "tests/bench/bench_support.h"

namespace lamina::bench {
namespace {

constexpr double kSpan = 2.0;    // simulated s per iteration
constexpr double kSlice = 0.05;  // simulated s per alternating slice

struct MeterTotals {
  double off_seconds = 0.0, on_seconds = 0.0;
};

void RunPair(core::Simulator& off, core::Simulator& on, MeterTotals* totals) {
  bool off_first = true;
  for (double done = 0.0; done < kSpan - 1e-9; done += kSlice) {
    for (int side = 0; side < 2; ++side) {
      const bool run_off = (side == 0) == off_first;
      const double start = ThreadCpuSeconds();
      (run_off ? off : on).Simulate(kSlice);
      (run_off ? totals->off_seconds : totals->on_seconds) += ThreadCpuSeconds() - start;
    }
    off_first = !off_first;
  }
}

void BM_ErrorMeter(benchmark::State& state, const core::WorldDesc& world) {
  MeterTotals totals;
  core::ErrorMeterReading reading;
  for (auto _ : state) {
    core::Simulator off(world), on(world);
    on.SetErrorMeter(true);
    RunPair(off, on, &totals);
    if (!(off.GetState() == on.GetState())) {
      Fail(state, "the meter changed the simulation");
      break;
    }
    reading = on.error_meter_reading();
  }
  state.counters["overhead"] = totals.on_seconds / totals.off_seconds - 1.0;
  state.counters["meter_overhead"] = reading.overhead;
  state.counters["rate_mm_s"] = 1000.0 * reading.rate;
  state.counters["samples"] = static_cast<double>(reading.samples);
}

}  // namespace

void RegisterErrorMeterBenchmarks() {
  auto stack = std::make_shared<core::WorldDesc>(PrimitiveBoxStack());
  benchmark::RegisterBenchmark("ErrorMeter/box_stack",
                               [stack](benchmark::State& s) { BM_ErrorMeter(s, *stack); })
      ->Unit(benchmark::kMillisecond)
      ->Iterations(1);
  auto athlete = std::make_shared<core::WorldDesc>();
  std::string errors;
  const bool loaded = LoadWorld(WorldsPath("klampt/athlete_fractal_1.xml"), athlete.get(), &errors);
  benchmark::RegisterBenchmark("ErrorMeter/athlete_fractal_1",
                               [athlete, loaded, errors](benchmark::State& s) {
                                 if (!loaded) {
                                   Fail(s, "cannot load the world: " + errors);
                                   return;
                                 }
                                 BM_ErrorMeter(s, *athlete);
                               })
      ->Unit(benchmark::kMillisecond)
      ->Iterations(1);
}

}  // namespace lamina::bench
