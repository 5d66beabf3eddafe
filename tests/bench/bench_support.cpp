// SPDX-License-Identifier: MIT
// Shared benchmark helpers: paths, world loading, the primitive box stack, failure reporting.
#include "tests/bench/bench_support.h"

#include <atomic>
#include <cmath>

#include <time.h>

#include "core/io/world_file.h"

namespace lamina::bench {

namespace {

std::atomic<int> failures{0};

// stacktest.xml places the boxes 0.1021 m apart, the bottom one 2 mm above the slab
constexpr double kStackBottomCentre = 0.052;
constexpr double kStackPitch = 0.1021;
// stacktest.xml's padding: the layers of neighbouring boxes (2 mm together) do not overlap at
// the start. With the default 2.5 mm padding they would overlap by 2.9 mm per pair, and
// correcting that in one step launches the top box about a metre.
constexpr double kStackBoxPadding = 0.001;

core::TerrainDesc Slab() {
  core::TerrainDesc slab;
  slab.name = "slab";
  slab.geometry.kind = core::GeometryKind::kPrimitive;
  core::Pose centre = core::Pose::Identity();
  centre.translation() = core::Vec3(0, 0, -kStackSlabSize.z() / 2);
  slab.geometry.primitive = core::Primitive::Box(kStackSlabSize, centre);
  slab.sim = core::DefaultTerrainSimParams();
  slab.sim.padding = 0.0;
  slab.sim.surface = {0.0, kStackFriction, core::kInf, core::kInf};
  return slab;
}

core::RigidObjectDesc StackBox(int index) {
  core::RigidObjectDesc box;
  box.name = "block" + std::to_string(index + 1);
  box.geometry.kind = core::GeometryKind::kPrimitive;
  box.geometry.primitive = core::Primitive::Box(core::Vec3::Constant(kStackBoxSide));
  box.mass = kStackBoxMass;
  box.inertia = core::Mat3::Identity() * (kStackBoxMass * kStackBoxSide * kStackBoxSide / 6.0);
  box.pose.translation() = StackBoxStart(index);
  box.sim = core::DefaultObjectSimParams();
  box.sim.padding = kStackBoxPadding;
  box.sim.surface = {0.0, kStackFriction, core::kInf, core::kInf};
  return box;
}

void SetTimeSplitCounters(benchmark::State& state, const LaminaTotals& totals) {
  const core::SimTimeSplit& split = totals.time_split;
  const double total = split.total();
  if (total <= 0.0) return;
  state.counters["broad"] = split.broad_phase / total;
  state.counters["contact"] = split.contact_generation / total;
  state.counters["cluster"] = split.clustering / total;
  state.counters["solver"] = split.solver / total;
  state.counters["other"] = split.other / total;
}

}  // namespace

double ContactsPerStep(long contact_joints, long steps) {
  return steps > 0 ? static_cast<double>(contact_joints) / static_cast<double>(steps) : 0.0;
}

void LaminaTotals::Add(double seconds, const core::SimStatistics& now,
                       const core::SimStatistics& before) {
  simulated += seconds;
  steps += now.steps - before.steps;
  rollbacks += now.rollbacks - before.rollbacks;
  contact_joints += now.contact_joints - before.contact_joints;
  time_split.broad_phase += now.time_split.broad_phase - before.time_split.broad_phase;
  time_split.contact_generation +=
      now.time_split.contact_generation - before.time_split.contact_generation;
  time_split.clustering += now.time_split.clustering - before.time_split.clustering;
  time_split.solver += now.time_split.solver - before.time_split.solver;
  time_split.other += now.time_split.other - before.time_split.other;
}

void SetLaminaCounters(benchmark::State& state, const LaminaTotals& totals) {
  state.counters["steps/s"] =
      benchmark::Counter(static_cast<double>(totals.steps), benchmark::Counter::kIsRate);
  state.counters["rtf"] = benchmark::Counter(totals.simulated, benchmark::Counter::kIsRate);
  state.counters["rollbacks"] =
      benchmark::Counter(static_cast<double>(totals.rollbacks), benchmark::Counter::kAvgIterations);
  state.counters["contacts"] = ContactsPerStep(totals.contact_joints, totals.steps);
  SetTimeSplitCounters(state, totals);
}

std::string WorldsPath(const std::string& relative) {
  return std::string(LAMINA_WORLDS_DIR) + "/" + relative;
}

bool LoadWorld(const std::string& path, core::WorldDesc* out, std::string* errors) {
  core::Diagnostics diagnostics;
  core::MeshCache meshes;
  core::LoadContext context{diagnostics, meshes};
  const bool ok = core::LoadWorldFile(path, context, out);
  *errors = diagnostics.FormatAll();
  return ok;
}

core::Vec3 StackBoxStart(int index) {
  return {0.0, 0.0, kStackBottomCentre + index * kStackPitch};
}

core::WorldDesc PrimitiveBoxStack() {
  core::WorldDesc world;
  world.name = "primitive box stack";
  world.terrains.push_back(Slab());
  for (int i = 0; i < kStackBoxCount; ++i) world.objects.push_back(StackBox(i));
  return world;
}

bool TopBoxStands(const core::Vec3& start, const core::Vec3& now) {
  // closing the 2 mm gaps between the ten boxes lowers the top by about 2 cm; a fallen or
  // launched stack is far off
  return (now - start).head<2>().norm() < 1e-3 && std::abs(now.z() - start.z()) < 0.03;
}

void Fail(benchmark::State& state, const std::string& message) {
  ++failures;
  state.SkipWithError(message.c_str());
}

int FailureCount() {
  return failures;
}

double ThreadCpuSeconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

}  // namespace lamina::bench
