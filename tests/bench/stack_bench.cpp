// SPDX-License-Identifier: MIT
// The 10-box stack three ways: written directly on ODE, as Lamina primitives (the same boxes, so
// the difference is Lamina's overhead: contact pipeline, clustering, adaptive checks,
// bookkeeping), and Klamp't's stacktest.xml with its meshes.
//
// The raw and primitive stacks are timed standing: every iteration builds them and lets them
// settle for kSettleSpan (untimed), because the drop differs between the two contact models (raw
// ODE contacts only on penetration, so its boxes bounce apart for a while) and a different
// number of contacts would make the ODE solve, not the overhead, differ. Then it times kStackSpan;
// after it the stack must still stand or the benchmark fails.
#include <memory>
#include <string>

#include <benchmark/benchmark.h>

#include "core/sim/simulator.h"
#include "tests/bench/bench_support.h"
#include "tests/bench/raw_ode_stack.h"

namespace lamina::bench {
namespace {

// simulated seconds per iteration
constexpr double kStackSpan = 1.0;
// simulated seconds before timing: both stacks are at rest by then
constexpr double kSettleSpan = 0.5;
// the overhead benchmark alternates between the stacks in slices this long (simulated s)
constexpr double kOverheadSlice = 0.05;

bool RawStackStands(const RawOdeBoxStack& stack) {
  return TopBoxStands(StackBoxStart(kStackBoxCount - 1), stack.BoxPosition(kStackBoxCount - 1));
}

bool LaminaStackStands(const core::Simulator& simulator) {
  const int top = simulator.object_count() - 1;
  return simulator.statistics().worst_status != core::StepStatus::kError &&
         TopBoxStands(simulator.world().objects[top].pose.translation(),
                      simulator.GetObjectPose(top).translation());
}

// a stack that has settled for kSettleSpan: what every timed iteration starts from
std::unique_ptr<RawOdeBoxStack> SettledRawStack() {
  auto stack = std::make_unique<RawOdeBoxStack>();
  stack->Simulate(kSettleSpan);
  return stack;
}

std::unique_ptr<core::Simulator> SettledLaminaStack() {
  auto simulator = std::make_unique<core::Simulator>(PrimitiveBoxStack());
  simulator->Simulate(kSettleSpan);
  return simulator;
}

void BM_BoxStackRawOde(benchmark::State& state) {
  long steps = 0, contact_joints = 0;
  for (auto _ : state) {
    state.PauseTiming();
    std::unique_ptr<RawOdeBoxStack> stack = SettledRawStack();
    const long steps_before = stack->steps();
    const long contacts_before = stack->contact_joints();
    state.ResumeTiming();
    stack->Simulate(kStackSpan);
    state.PauseTiming();
    if (!RawStackStands(*stack)) {
      Fail(state, "the raw ODE stack fell");
      break;
    }
    steps += stack->steps() - steps_before;
    contact_joints += stack->contact_joints() - contacts_before;
    stack.reset();  // destroyed outside the timed region
    state.ResumeTiming();
  }
  state.counters["steps/s"] =
      benchmark::Counter(static_cast<double>(steps), benchmark::Counter::kIsRate);
  state.counters["rtf"] = benchmark::Counter(static_cast<double>(state.iterations()) * kStackSpan,
                                             benchmark::Counter::kIsRate);
  state.counters["contacts"] = ContactsPerStep(contact_joints, steps);
}

void BM_BoxStackLaminaPrimitive(benchmark::State& state) {
  LaminaTotals totals;
  for (auto _ : state) {
    state.PauseTiming();
    std::unique_ptr<core::Simulator> simulator = SettledLaminaStack();
    const core::SimStatistics before = simulator->statistics();
    state.ResumeTiming();
    simulator->Simulate(kStackSpan);
    state.PauseTiming();
    if (!LaminaStackStands(*simulator)) {
      Fail(state, "the Lamina primitive stack fell");
      break;
    }
    totals.Add(kStackSpan, simulator->statistics(), before);
    simulator.reset();
    state.ResumeTiming();
  }
  SetLaminaCounters(state, totals);
}

// What the overhead benchmark measured over its iterations.
struct OverheadTotals {
  double raw_seconds = 0.0, lamina_seconds = 0.0;  // thread CPU time
  long raw_steps = 0, raw_contacts = 0, lamina_steps = 0, lamina_contacts = 0;
};

// kStackSpan of both settled stacks in alternating slices, each timed on the thread's CPU clock,
// so that the two compare under the same machine load. The order flips every slice so that
// neither side always runs with the caches the other one warmed.
void RunBothStacks(RawOdeBoxStack& stack, core::Simulator& simulator, OverheadTotals* totals) {
  const long raw_steps = stack.steps(), raw_contacts = stack.contact_joints();
  const core::SimStatistics lamina_before = simulator.statistics();
  bool raw_first = true;
  for (double done = 0.0; done < kStackSpan - 1e-9; done += kOverheadSlice) {
    for (int side = 0; side < 2; ++side) {
      const double start = ThreadCpuSeconds();
      if ((side == 0) == raw_first) {
        stack.Simulate(kOverheadSlice);
        totals->raw_seconds += ThreadCpuSeconds() - start;
      } else {
        simulator.Simulate(kOverheadSlice);
        totals->lamina_seconds += ThreadCpuSeconds() - start;
      }
    }
    raw_first = !raw_first;
  }
  totals->raw_steps += stack.steps() - raw_steps;
  totals->raw_contacts += stack.contact_joints() - raw_contacts;
  totals->lamina_steps += simulator.statistics().steps - lamina_before.steps;
  totals->lamina_contacts += simulator.statistics().contact_joints - lamina_before.contact_joints;
}

void BM_BoxStackOverhead(benchmark::State& state) {
  OverheadTotals totals;
  for (auto _ : state) {
    state.PauseTiming();
    std::unique_ptr<RawOdeBoxStack> stack = SettledRawStack();
    std::unique_ptr<core::Simulator> simulator = SettledLaminaStack();
    state.ResumeTiming();
    RunBothStacks(*stack, *simulator, &totals);
    state.PauseTiming();
    if (!RawStackStands(*stack) || !LaminaStackStands(*simulator)) {
      Fail(state, "a stack fell");
      break;
    }
    stack.reset();
    simulator.reset();
    state.ResumeTiming();
  }
  const double simulated = static_cast<double>(state.iterations()) * kStackSpan;
  if (simulated <= 0.0 || totals.raw_seconds <= 0.0) return;
  // milliseconds of CPU per simulated second, and Lamina's time over raw ODE's
  state.counters["raw_ms"] = 1e3 * totals.raw_seconds / simulated;
  state.counters["lamina_ms"] = 1e3 * totals.lamina_seconds / simulated;
  state.counters["ratio"] = totals.lamina_seconds / totals.raw_seconds;
  // the ODE solve grows faster than linearly with the contacts: a ratio off 1 with different
  // contact counts is mostly the solve, not the overhead
  state.counters["raw_contacts"] = ContactsPerStep(totals.raw_contacts, totals.raw_steps);
  state.counters["lamina_contacts"] = ContactsPerStep(totals.lamina_contacts, totals.lamina_steps);
}

// stacktest.xml as it is (meshes, its own globals) from the start: the drop included
void BM_BoxStackLaminaMesh(benchmark::State& state) {
  core::WorldDesc world;
  std::string errors;
  if (!LoadWorld(WorldsPath("klampt/simulation_test_worlds/stacktest.xml"), &world, &errors)) {
    return Fail(state, "cannot load stacktest.xml: " + errors);
  }
  LaminaTotals totals;
  for (auto _ : state) {
    state.PauseTiming();
    auto simulator = std::make_unique<core::Simulator>(world);
    state.ResumeTiming();
    simulator->Simulate(kStackSpan);
    state.PauseTiming();
    if (!LaminaStackStands(*simulator)) {
      Fail(state, "the stacktest.xml stack fell: " + simulator->statistics().error);
      break;
    }
    totals.Add(kStackSpan, simulator->statistics());
    simulator.reset();  // destroyed outside the timed region
    state.ResumeTiming();
  }
  SetLaminaCounters(state, totals);
}

}  // namespace

BENCHMARK(BM_BoxStackRawOde)->Name("BoxStack/RawOde")->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BoxStackLaminaPrimitive)
    ->Name("BoxStack/LaminaPrimitive")
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BoxStackOverhead)->Name("BoxStack/Overhead")->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BoxStackLaminaMesh)->Name("BoxStack/LaminaMesh")->Unit(benchmark::kMillisecond);

}  // namespace lamina::bench
