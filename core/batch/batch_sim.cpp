// SPDX-License-Identifier: MIT
#include "core/batch/batch_sim.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <utility>

#include "core/control/send_motion.h"
#include "core/number_text.h"
#include "core/sim/sim_access.h"

namespace lamina::core {

namespace {

using Clock = std::chrono::steady_clock;

double Seconds(Clock::time_point since) {
  return std::chrono::duration<double>(Clock::now() - since).count();
}

// ---- one run ----------------------------------------------------------------------------

const std::vector<double>& Resolve(const ValueSource& source, const RunContext& context) {
  return source.arg.empty() ? source.literal : context.Arg(source.arg);
}

VecX ToVec(const std::vector<double>& values) {
  return Eigen::Map<const VecX>(values.data(), static_cast<Eigen::Index>(values.size()));
}

void SendCommand(const RobotCommand& command, RunContext& context) {
  Simulator& simulator = context.simulator;
  if (command.robot < 0 || command.robot >= simulator.robot_count()) {
    throw std::invalid_argument("robots[" + std::to_string(command.robot) + "]: the world has " +
                                std::to_string(simulator.robot_count()) + " robot(s)");
  }
  RobotController& controller = simulator.controller(command.robot);
  const std::string who = "robots[" + std::to_string(command.robot) + "]: ";
  bool ok = true;
  std::string error;
  switch (command.kind) {
    case RobotCommand::Kind::kPid: {
      const VecX q = ToVec(Resolve(command.values.at(0), context));
      ok = controller.SetPIDCommand(q, VecX::Zero(q.size()));
      break;
    }
    case RobotCommand::Kind::kMilestones:
      for (size_t i = 0; i < command.values.size() && ok; ++i) {
        const VecX q = ToVec(Resolve(command.values[i], context));
        ok = i == 0 ? controller.SetMilestone(q) : controller.AddMilestone(q);
      }
      break;
    case RobotCommand::Kind::kMotion:
      if (!SendMotion(command.motion, &controller, &error))
        throw std::invalid_argument(who + error);
      break;
  }
  if (!ok) throw std::invalid_argument(who + controller.last_error());
}

std::vector<AccessTarget> ResolveItems(const Simulator& simulator,
                                       const std::vector<std::string>& paths) {
  std::vector<AccessTarget> targets;
  for (const std::string& path : paths) {
    std::string error;
    std::optional<AccessTarget> target = ResolveSimulationPath(simulator, path, &error);
    if (!target) throw std::invalid_argument(error);
    targets.push_back(*target);
  }
  return targets;
}

std::vector<std::vector<double>> ReadItems(const Simulator& simulator,
                                           const std::vector<AccessTarget>& targets) {
  std::vector<std::vector<double>> values;
  for (const AccessTarget& target : targets) {
    std::string error;
    std::optional<ParamValue> value = GetPath(simulator, target, &error);
    if (!value) throw std::runtime_error(error);
    values.push_back(std::move(*value));
  }
  return values;
}

double ReadScalar(const Simulator& simulator, const AccessTarget& target) {
  std::string error;
  std::optional<ParamValue> value = GetPath(simulator, target, &error);
  if (!value) throw std::runtime_error(error);
  if (value->size() != 1) {
    throw std::invalid_argument(target.path +
                                ": a termination needs one number (select a "
                                "component with [k])");
  }
  return value->front();
}

// the reason to stop before the next outer step, or "" to go on
std::string StopReason(const RunPlan& plan, const std::vector<AccessTarget>& bounds,
                       RunContext& context, StepStatus worst) {
  const Simulator& simulator = context.simulator;
  // the clock is a sum of physics steps: 0.9999999999999 is 1 s
  if (plan.stop_time > 0 && simulator.time() >= plan.stop_time - 1e-9) return "time";
  if (plan.stop_on_unstable && worst >= StepStatus::kUnstable) return "unstable";
  for (size_t i = 0; i < bounds.size(); ++i) {
    const Termination& t = plan.terminate[i];
    const double value = ReadScalar(simulator, bounds[i]);
    if (t.above ? value > t.bound : value < t.bound) {
      return t.path + (t.above ? " above " : " below ") + FormatDouble(t.bound);
    }
  }
  if (plan.hooks.term && plan.hooks.term(context)) return "term hook";
  return "";
}

WorldDesc PrepareWorld(const WorldDesc& world, const InitialCondition& initial) {
  WorldDesc copy = world;
  for (const NamedValue& value : initial.values) {
    std::string error;
    if (!SetPath(&copy, value.name, value.value, &error)) throw std::invalid_argument(error);
  }
  return copy;
}

// the outer steps of a run: ceil(duration / dt) with a part per million of slack
long OuterSteps(const RunPlan& plan) {
  return std::max(0L, static_cast<long>(std::ceil(plan.duration / plan.sim_dt - 1e-6)));
}

void Simulate(const RunPlan& plan, const std::vector<AccessTarget>& items, RunContext& context,
              RunResult* result) {
  Simulator& simulator = context.simulator;
  std::vector<AccessTarget> bounds;
  for (const Termination& t : plan.terminate) {
    bounds.push_back(ResolveItems(simulator, {t.path}).front());
  }
  const long steps = OuterSteps(plan);
  const long trace_every =
      plan.trace_rate > 0 ? std::max(1L, std::lround(plan.trace_rate / plan.sim_dt)) : 0;
  auto trace = [&] {
    result->trace_time.push_back(simulator.time());
    result->trace.push_back(ReadItems(simulator, items));
  };
  if (trace_every) trace();
  StepStatus worst = StepStatus::kNormal;
  result->stop = "duration";
  for (long step = 0; step < steps; ++step) {
    const std::string stop = StopReason(plan, bounds, context, worst);
    if (!stop.empty()) {
      result->stop = stop;
      break;
    }
    if (plan.hooks.step) plan.hooks.step(context);
    const double dt =
        std::min(plan.sim_dt, plan.duration - static_cast<double>(step) * plan.sim_dt);
    worst = std::max(worst, simulator.Simulate(dt));
    if (worst == StepStatus::kError) {
      throw std::runtime_error(simulator.statistics().error.empty()
                                   ? std::string("the simulation stopped with an error")
                                   : simulator.statistics().error);
    }
    if (trace_every && ((step + 1) % trace_every == 0 || step + 1 == steps)) trace();
  }
  result->status = StepStatusName(worst);
}

}  // namespace

const std::vector<double>& RunContext::Arg(const std::string& name) const {
  for (const NamedValue& arg : args) {
    if (arg.name == name) return arg.value;
  }
  throw std::out_of_range("args." + name + ": no such argument");
}

std::vector<std::string> DefaultReturnItems(const WorldDesc& world) {
  std::vector<std::string> items;
  for (size_t i = 0; i < world.objects.size(); ++i) {
    const std::string object = "rigidObjects[" + std::to_string(i) + "].";
    items.push_back(object + "transform");
    items.push_back(object + "velocity");
  }
  for (size_t i = 0; i < world.robots.size(); ++i) {
    const std::string controller = "controllers[" + std::to_string(i) + "].";
    const std::string robot = "robots[" + std::to_string(i) + "].";
    for (const char* item :
         {"commandedConfig", "commandedVelocity", "sensedConfig", "sensedVelocity"}) {
      items.push_back(controller + item);
    }
    for (const char* item : {"actualConfig", "actualVelocity", "actualTorques"}) {
      items.push_back(robot + item);
    }
  }
  return items;
}

RunResult DoSim(const WorldDesc& world, const RunPlan& plan, const InitialCondition& initial,
                int index) {
  RunResult result;
  result.index = index;
  const Clock::time_point start = Clock::now();
  try {
    if (!(plan.sim_dt > 0) || !std::isfinite(plan.sim_dt) || !std::isfinite(plan.duration)) {
      throw std::invalid_argument("simDt must be > 0 and duration finite");
    }
    const std::vector<std::string> paths =
        plan.return_items.empty() ? DefaultReturnItems(world) : plan.return_items;
    Simulator simulator(PrepareWorld(world, initial));
    result.build_wall_time = Seconds(start);
    RunContext context{simulator, index, initial.args};
    const std::vector<AccessTarget> items = ResolveItems(simulator, paths);
    for (const RobotCommand& command : plan.commands) SendCommand(command, context);
    if (plan.hooks.init) plan.hooks.init(context);
    Simulate(plan, items, context, &result);
    result.time = simulator.time();
    result.items = ReadItems(simulator, items);
  } catch (const std::exception& e) {
    result.status = "error";
    result.error = e.what();
    result.items.clear();
  }
  result.wall_clock_time = Seconds(start);
  return result;
}

void RunPool(int count, const PoolOptions& options, const std::function<void(int)>& job) {
  int threads =
      options.threads > 0 ? options.threads : static_cast<int>(std::thread::hardware_concurrency());
  threads = std::max(1, std::min(threads, count));
  std::atomic<int> next{0};
  std::mutex progress_mutex;
  int done = 0;
  const Clock::time_point start = Clock::now();
  auto worker = [&] {
    for (int i = next.fetch_add(1); i < count; i = next.fetch_add(1)) {
      job(i);
      if (!options.progress) continue;
      std::lock_guard<std::mutex> lock(progress_mutex);
      BatchProgress progress;
      progress.done = ++done;
      progress.total = count;
      progress.elapsed = Seconds(start);
      progress.runs_per_second = progress.elapsed > 0 ? done / progress.elapsed : 0.0;
      progress.eta = progress.runs_per_second > 0 ? (count - done) / progress.runs_per_second : 0;
      options.progress(progress);
    }
  };
  if (count <= 0) return;
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& thread : pool) thread.join();
}

std::vector<RunResult> BatchSim(const WorldDesc& world, const RunPlan& plan,
                                const std::vector<InitialCondition>& initial,
                                const PoolOptions& options) {
  std::vector<RunResult> results(initial.size());
  RunPool(static_cast<int>(initial.size()), options,
          [&](int i) { results[i] = DoSim(world, plan, initial[i], i); });
  return results;
}

InitialCondition SampleRun(const MonteCarloSamplers& samplers, std::uint64_t seed, int index) {
  RunRandom random(seed, static_cast<std::uint64_t>(index));
  InitialCondition initial;
  for (const NamedSampler& s : samplers.initial) {
    initial.values.push_back({s.name, s.sampler.Draw(&random, index)});
  }
  for (const NamedSampler& s : samplers.args) {
    initial.args.push_back({s.name, s.sampler.Draw(&random, index)});
  }
  return initial;
}

std::vector<RunResult> MonteCarloSim(const WorldDesc& world, const RunPlan& plan,
                                     const MonteCarloSamplers& samplers, std::uint64_t seed,
                                     const std::vector<int>& indices, const PoolOptions& options) {
  std::vector<RunResult> results(indices.size());
  RunPool(static_cast<int>(indices.size()), options, [&](int k) {
    const int index = indices[k];
    InitialCondition initial;
    try {
      initial = SampleRun(samplers, seed, index);
    } catch (const std::exception& e) {
      results[k].index = index;
      results[k].status = "error";
      results[k].error = e.what();
      return;
    }
    results[k] = DoSim(world, plan, initial, index);
    for (const NamedValue& v : initial.values) results[k].sampled.push_back(v.value);
    for (const NamedValue& v : initial.args) results[k].sampled.push_back(v.value);
  });
  return results;
}

std::vector<int> ShardIndices(int runs, const Shard& shard) {
  std::vector<int> indices;
  if (shard.contiguous) {
    const int begin = static_cast<int>(static_cast<long long>(runs) * shard.k / shard.n);
    const int end = static_cast<int>(static_cast<long long>(runs) * (shard.k + 1) / shard.n);
    for (int i = begin; i < end; ++i) indices.push_back(i);
    return indices;
  }
  for (int i = shard.k; i < runs; i += shard.n) indices.push_back(i);
  return indices;
}

std::optional<Shard> ParseShard(const std::string& text, std::string* error) {
  Shard shard;
  std::string body = text;
  const std::string block = ":block";
  if (body.size() > block.size() &&
      body.compare(body.size() - block.size(), block.size(), block) == 0) {
    shard.contiguous = true;
    body.resize(body.size() - block.size());
  }
  const size_t slash = body.find('/');
  if (slash == std::string::npos || !ParseInt(body.substr(0, slash), &shard.k) ||
      !ParseInt(body.substr(slash + 1), &shard.n) || shard.n < 1 || shard.k < 0 ||
      shard.k >= shard.n) {
    *error = "shard '" + text + "' must be K/N with 0 <= K < N (optionally K/N:block)";
    return std::nullopt;
  }
  return shard;
}

std::optional<Shard> ShardFromSlurm(std::string* error) {
  error->clear();
  const char* id = std::getenv("SLURM_ARRAY_TASK_ID");
  const char* count = std::getenv("SLURM_ARRAY_TASK_COUNT");
  if (id == nullptr) return std::nullopt;
  const char* min = std::getenv("SLURM_ARRAY_TASK_MIN");
  int task = 0, tasks = 0, first = 0;
  if (count == nullptr || !ParseInt(id, &task) || !ParseInt(count, &tasks) ||
      (min != nullptr && !ParseInt(min, &first)) || tasks < 1 || task - first < 0 ||
      task - first >= tasks) {
    *error = "SLURM_ARRAY_TASK_ID=" + std::string(id) +
             ", SLURM_ARRAY_TASK_MIN=" + (min ? min : "(unset)") +
             ", SLURM_ARRAY_TASK_COUNT=" + (count ? count : "(unset)") +
             " do not make a shard (the array must be MIN..MIN+COUNT-1 with step 1)";
    return std::nullopt;
  }
  return Shard{task - first, tasks, false};
}

}  // namespace lamina::core
