// SPDX-License-Identifier: MIT
#include "core/accuracy/stress_run.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>
#include <thread>

#include "core/accuracy/probe_support.h"
#include "core/io/world_file.h"
#include "core/sim/simulator.h"

namespace lamina::core {
namespace {

void ApplySolver(const StressCase& c, WorldDesc* world) {
  world->settings.timestep = c.step;
  world->settings.solver = c.solver.type;
  world->settings.quick_step_iterations = c.solver.iterations;
  world->settings.adaptive_time_stepping = c.solver.adaptive;
  world->settings.joint_coordinates = c.solver.joint_coordinates;
}

bool Finite(const BodyState& body) {
  return body.com_position.allFinite() && body.orientation.coeffs().allFinite() &&
         body.linear_velocity.allFinite() && body.angular_velocity.allFinite();
}

bool StateFinite(const SimState& state) {
  const auto finite = [](const std::vector<BodyState>& bodies) {
    return std::all_of(bodies.begin(), bodies.end(), Finite);
  };
  return finite(state.objects) &&
         std::all_of(state.robots.begin(), state.robots.end(),
                     [&](const RobotSimState& robot) { return finite(robot.bodies); });
}

bool Outside(const StressCase& c, const Vec3& com) {
  // a NaN centre is not "lost": the finiteness check reports it
  return com.norm() > c.reach ||
         std::any_of(c.keep_out.begin(), c.keep_out.end(),
                     [&](const StressKeepOut& k) { return k.normal.dot(com) > k.offset; });
}

// names of the objects and robot links whose centre of mass ended beyond a keep-out plane
std::vector<std::string> LostBodies(const StressCase& c, Simulator* simulator) {
  std::vector<std::string> lost;
  const WorldDesc& world = simulator->world();
  for (int i = 0; i < simulator->object_count(); ++i) {
    if (Outside(c, ObjectCom(*simulator, i))) lost.push_back(world.objects[i].name);
  }
  for (int r = 0; r < simulator->robot_count(); ++r) {
    const RobotDesc& robot = world.robots[r];
    for (int l = 0; l < robot.dof(); ++l) {
      const Vec3 com = simulator->body(world.RobotLinkId(r, l)).GetTransform() * robot.links[l].com;
      if (Outside(c, com)) lost.push_back(robot.name + "." + robot.links[l].name);
    }
  }
  return lost;
}

double MetricOf(const ProbeResult& result, const std::string& name) {
  for (const ProbeMetric& metric : result.metrics) {
    if (metric.name == name) return metric.value;
  }
  return std::nan("");
}

StressRecord NewRecord(const StressCase& c) {
  StressRecord record;
  record.name = c.name;
  record.world = c.world;
  record.solver = c.solver.Label();
  record.step = c.step;
  record.duration = c.duration;
  record.expected = c.expected;
  record.metric_text = c.metric_text;
  record.unit = c.unit;
  record.metric = std::nan("");
  return record;
}

void CopyStatistics(const SimStatistics& statistics, StressRecord* record) {
  record->steps = statistics.steps;
  record->rollbacks = statistics.rollbacks;
  record->corrections = statistics.instability_corrections;
  record->unreliable = statistics.unreliable_steps;
  record->joint_open = statistics.joint_open_steps;
  record->max_joint_gap = statistics.max_joint_gap;
  record->max_penetration = statistics.max_penetration;
  record->status = StepStatusName(statistics.worst_status);
  record->failure = statistics.error;
}

// steps the case and fills in what the run measured; the outcome's `ran` stays the caller's
void Simulate(const StressCase& c, const WorldDesc& world, StressRecord* record,
              StressOutcome* outcome) {
  Simulator simulator(world);
  if (c.prepare) c.prepare(&simulator);
  const std::unique_ptr<AccuracyProbe> probe = c.probe(world);
  double min_step = kInf;
  simulator.AddStepObserver([&](const StepEvent& event) {
    min_step = std::min(min_step, event.h);
    if ((event.flags & kStepRecovered) != 0u) ++record->nonfinite;
    probe->Observe(event);
  });
  probe->Begin(simulator);
  const double start = ThreadCpuSeconds();
  simulator.Simulate(c.duration);
  record->cpu_seconds = ThreadCpuSeconds() - start;
  record->min_step = std::isfinite(min_step) ? min_step : 0.0;
  CopyStatistics(simulator.statistics(), record);
  outcome->worst = simulator.statistics().worst_status;
  outcome->halted = simulator.halted();
  outcome->finite = StateFinite(simulator.GetState());
  if (!outcome->halted && outcome->finite) {
    record->probe = probe->Finish(simulator);
    record->metric = c.metric.empty() ? record->probe.error : MetricOf(record->probe, c.metric);
    record->lost = LostBodies(c, &simulator);
  }
}

}  // namespace

StressRecord RunStressCase(const StressCase& c, const std::string& worlds_dir) {
  StressRecord record = NewRecord(c);
  StressOutcome outcome;
  try {
    Diagnostics diagnostics;
    MeshCache meshes;
    LoadContext context{diagnostics, meshes};
    WorldDesc world;
    if (!LoadWorldFile(worlds_dir + "/" + c.world, context, &world)) {
      record.failure = diagnostics.FormatAll();
      outcome.ran = false;
    } else {
      ApplySolver(c, &world);
      Simulate(c, world, &record, &outcome);
    }
  } catch (const std::exception& error) {
    record.failure = error.what();
    outcome.ran = false;
  }
  outcome.lost = static_cast<int>(record.lost.size());
  outcome.corrections = record.corrections;
  outcome.nonfinite = record.nonfinite;
  record.verdict = JudgeStress(outcome, &record.why);
  return record;
}

std::vector<StressRecord> RunStressCases(
    const std::vector<const StressCase*>& cases, const std::string& worlds_dir, int threads,
    const std::function<void(int done, int total, const StressRecord&)>& progress) {
  std::vector<std::size_t> order(cases.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return cases[a]->duration / cases[a]->step > cases[b]->duration / cases[b]->step;
  });
  std::vector<StressRecord> records(cases.size());
  std::atomic<std::size_t> next{0};
  std::mutex report;
  int done = 0;
  auto work = [&] {
    for (std::size_t i = next++; i < order.size(); i = next++) {
      records[order[i]] = RunStressCase(*cases[order[i]], worlds_dir);
      const std::lock_guard<std::mutex> lock(report);
      ++done;
      if (progress) progress(done, static_cast<int>(cases.size()), records[order[i]]);
    }
  };
  const int count = threads > 0 ? threads : std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::thread> pool;
  for (int t = 0; t < count; ++t) pool.emplace_back(work);
  for (std::thread& thread : pool) thread.join();
  return records;
}

}  // namespace lamina::core
