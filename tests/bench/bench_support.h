// SPDX-License-Identifier: MIT
// What the benchmarks share: the worlds directory, loading a world, the 10-box stack of Klamp't's
// stacktest.xml as primitives, the physical sanity check of a stack, and failure reporting that
// makes lamina_bench exit non-zero.
#pragma once

#include <string>

#include <benchmark/benchmark.h>

#include "core/model/world_desc.h"
#include "core/sim/simulator.h"

namespace lamina::bench {

/// Absolute path of `relative` under worlds/.
std::string WorldsPath(const std::string& relative);

/// Loads the world file at `path`; false (with the diagnostics in `*errors`) on any error.
bool LoadWorld(const std::string& path, core::WorldDesc* out, std::string* errors);

/// The stack of stacktest.xml: ten 0.1 m, 1 kg boxes with friction 0.5 and restitution 0 over a
/// 4 m x 4 m x 0.1 m slab whose top is z = 0.
inline constexpr int kStackBoxCount = 10;
inline constexpr double kStackBoxSide = 0.1;
inline constexpr double kStackBoxMass = 1.0;
inline constexpr double kStackFriction = 0.5;
inline const core::Vec3 kStackSlabSize(4.0, 4.0, 0.1);
/// Centre of box `index` (0 = bottom) at the start, as in stacktest.xml.
core::Vec3 StackBoxStart(int index);

/// The stack built in code with box primitives: terrain padding 0, stacktest.xml's 1 mm padding
/// on the boxes, the default simulation settings (ERP, CFM, contacts per pair, 1 ms step).
core::WorldDesc PrimitiveBoxStack();

/// A stack still stands when its top box is within 1 mm sideways of where it started (and
/// within a few centimetres vertically).
bool TopBoxStands(const core::Vec3& start, const core::Vec3& now);

/// Marks the benchmark failed (lamina_bench then exits non-zero). The caller leaves its loop.
void Fail(benchmark::State& state, const std::string& message);
/// Benchmarks that failed in this run.
int FailureCount();

/// What Lamina simulations did over a benchmark's iterations, reported as counters.
struct LaminaTotals {
  double simulated = 0.0;  ///< simulated seconds
  long steps = 0;
  long rollbacks = 0;
  long contact_joints = 0;
  core::SimTimeSplit time_split;  ///< summed

  /// Adds what a simulator did over `seconds`: its statistics `now` minus those `before`.
  void Add(double seconds, const core::SimStatistics& now, const core::SimStatistics& before = {});
};
/// Counters: steps/s and the real-time factor (per CPU second of the timed region), rollbacks
/// per iteration, contact joints per step and the fractions of the time split.
void SetLaminaCounters(benchmark::State& state, const LaminaTotals& totals);
/// Average contact joints per step (0 without steps).
double ContactsPerStep(long contact_joints, long steps);

/// Seconds of CPU time used by the calling thread (what Google Benchmark times by default).
double ThreadCpuSeconds();

}  // namespace lamina::bench
