// SPDX-License-Identifier: MIT
// Batch simulation: Klamp't's doSim, batchSim and monteCarloSim (klampt.sim.batch) on Lamina's
// simulator, on every core.
//
// One run (DoSim), as Klamp't's doSim: the initial conditions (access path -> value) are set on
// a copy of the world description (an initial condition, a row of the parameter table: gains,
// friction, ...) by the table's rules, a fresh Simulator is built from it, the robot commands of
// the plan are sent, the init hook runs, then while t < duration: the termination conditions and
// the term hook are checked (true: stop), the step hook runs, the simulation advances by the
// outer step simDt (s), the worst step status is kept and, when tracing, the items are read.
// At the end the return items are read from the simulation. Units are SI throughout (s, m, rad).
//
// A run never throws: an exception (from a hook, a refused value, an item that cannot be read)
// or a simulation stopped by an error ends the run with status "error" and the message; the
// batch goes on. An unstable step gives status "unstable" (the run goes on unless a
// termination condition says to stop at instability).
//
// Differences from Klamp't:
//  - Time: the outer loop takes ceil(duration / simDt) steps (with a part per million of slack)
//    and shortens the last one so that a run ends at `duration` exactly; Klamp't adds simDt
//    until t >= duration and may overshoot. `time` is the simulator's clock.
//  - Initial conditions are checked when the batch is prepared (a path the description does not
//    have, a value the table refuses) instead of failing in every run; a value that only a
//    sampler produces out of range fails that run (status "error").
//  - Object velocities given as initial conditions take effect (the description's velocity
//    rows are what a Simulator starts from).
//  - `time` is not a return item: it is the result's `time` (Klamp't's result dict has one
//    `time` key too, its loop time overwriting the item); robots have no `sensors` item.
//  - batchSim takes a list of initial conditions only (Klamp't's dict-of-lists branch is broken
//    there and not copied).
//  - Hooks receive the RunContext (simulator, run index, args) instead of `sim, *args`.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/batch/sampler.h"
#include "core/control/milestone_sequence.h"
#include "core/model/access_path.h"
#include "core/model/world_desc.h"
#include "core/sim/simulator.h"

namespace lamina::core {

/// A named value: an initial condition (access path -> value) or an argument (name -> value).
struct NamedValue {
  std::string name;
  std::vector<double> value;
};

/// What the hooks see of a run.
struct RunContext {
  Simulator& simulator;
  int index;                            ///< the run's index in its batch
  const std::vector<NamedValue>& args;  ///< Klamp't's initialCondition['args']
  /// The value of argument `name`; std::out_of_range naming it when there is none.
  const std::vector<double>& Arg(const std::string& name) const;
};

/// Klamp't's simInit, simStep and simTerm. Empty functions are not called. An exception from a
/// hook ends the run with status "error" and its message.
struct RunHooks {
  std::function<void(RunContext&)> init;  ///< after the simulator is built and commanded
  std::function<void(RunContext&)> step;  ///< before every outer step
  std::function<bool(RunContext&)> term;  ///< before every outer step; true stops the run
};

/// A vector given literally or as the value of an argument (`args.NAME` in a spec).
struct ValueSource {
  std::vector<double> literal;
  std::string arg;  ///< non-empty: the argument's value instead of `literal`
};

/// A command sent to a robot's controller before the init hook (the plan's set-up).
struct RobotCommand {
  enum class Kind {
    kPid,         ///< SetPIDCommand(q, 0): values[0] is q, one per link (rad or m)
    kMilestones,  ///< SetMilestone(values[0]) then AddMilestone(values[i]): time-optimal ramps
    kMotion,      ///< a motion file's milestones, sent as `lamina-headless run --path` does
  };
  int robot = 0;
  Kind kind = Kind::kPid;
  std::vector<ValueSource> values;
  MilestoneSequence motion;  ///< kMotion
};

/// Stops a run when an item crosses a bound (checked before every outer step, as simTerm).
struct Termination {
  std::string path;   ///< a simulation access path with one number (a scalar or a component)
  bool above = true;  ///< stop when the value is > bound (else < bound)
  double bound = 0.0;
};

/// Everything a run does besides its initial conditions.
struct RunPlan {
  double duration = 1.0;  ///< s of simulated time
  double sim_dt = 0.01;   ///< outer step, s (Klamp't's simDt)
  /// Items read at the end (simulation access paths); empty: DefaultReturnItems.
  std::vector<std::string> return_items;
  /// Read the items at the start and every `trace_rate` s (rounded to whole outer steps, at
  /// least one); 0: no trace (Klamp't's trace=True is trace_rate = sim_dt).
  double trace_rate = 0.0;
  std::vector<RobotCommand> commands;
  std::vector<Termination> terminate;
  double stop_time = 0.0;         ///< > 0: stop at this simulated time (s)
  bool stop_on_unstable = false;  ///< stop a run at its first unstable step
  RunHooks hooks;
};

/// Klamp't's default returnItems for `world` (objects' transform and velocity; each
/// robot's controller commanded/sensed config and velocity, actual config, velocity, torques).
std::vector<std::string> DefaultReturnItems(const WorldDesc& world);

/// One run's inputs.
struct InitialCondition {
  std::vector<NamedValue> values;  ///< description access path -> value, applied in order
  std::vector<NamedValue> args;
};

/// One run's outcome.
struct RunResult {
  int index = 0;
  std::vector<std::vector<double>> sampled;  ///< MonteCarloSim: the samplers' values, in order
  std::vector<std::vector<double>> items;    ///< final value of each return item
  std::vector<double> trace_time;            ///< s, when tracing
  std::vector<std::vector<std::vector<double>>> trace;  ///< [sample][item]
  std::string status = "normal";  ///< the worst step status (StepStatusName), or "error"
  std::string error;              ///< status "error": why
  std::string stop;               ///< what ended the run: "duration", "time", "term hook", ...
  double time = 0.0;              ///< simulated time at the end, s
  double wall_clock_time = 0.0;   ///< s from the copy of the world to the last item read
  double build_wall_time = 0.0;   ///< s of that spent copying the world and building it
};

/// Klamp't's doSim: one run of `world` (not modified) with `initial`. Never throws.
RunResult DoSim(const WorldDesc& world, const RunPlan& plan, const InitialCondition& initial,
                int index = 0);

/// Progress of a batch: runs done out of total, the rate and the estimated time left (s).
struct BatchProgress {
  int done = 0;
  int total = 0;
  double elapsed = 0.0;
  double runs_per_second = 0.0;
  double eta = 0.0;
};

struct PoolOptions {
  int threads = 0;  ///< 0: std::thread::hardware_concurrency()
  /// Called after every finished run (from the worker that finished it, serialised).
  std::function<void(const BatchProgress&)> progress;
};

/// Runs `count` jobs on a pool of threads: job(i) for i in [0, count), handed out in order by
/// an atomic counter. `job` must not throw.
void RunPool(int count, const PoolOptions& options, const std::function<void(int)>& job);

/// Klamp't's batchSim over a list of initial conditions; result i belongs to initial[i]
/// (whatever order the runs finish in).
std::vector<RunResult> BatchSim(const WorldDesc& world, const RunPlan& plan,
                                const std::vector<InitialCondition>& initial,
                                const PoolOptions& options = {});

/// A sampler of an initial condition (`name` is a description access path) or of an argument.
struct NamedSampler {
  std::string name;
  Sampler sampler;
};

/// The samplers of a Monte-Carlo batch: initial conditions, then arguments (drawn in this order).
struct MonteCarloSamplers {
  std::vector<NamedSampler> initial;
  std::vector<NamedSampler> args;
};

/// Run `index`'s values: RunRandom(seed, index), every sampler in order.
InitialCondition SampleRun(const MonteCarloSamplers& samplers, std::uint64_t seed, int index);

/// Klamp't's monteCarloSim for the runs `indices` (all N of a batch, or a shard's): result k is
/// run indices[k], with its sampled values (initial conditions then args) in `sampled`.
std::vector<RunResult> MonteCarloSim(const WorldDesc& world, const RunPlan& plan,
                                     const MonteCarloSamplers& samplers, std::uint64_t seed,
                                     const std::vector<int>& indices,
                                     const PoolOptions& options = {});

/// A part of a batch: shard `k` of `n` (0 <= k < n) takes the runs i with i % n == k, or with
/// `contiguous` the k-th of n blocks of consecutive runs (sizes differ by at most one).
struct Shard {
  int k = 0;
  int n = 1;
  bool contiguous = false;
};
std::vector<int> ShardIndices(int runs, const Shard& shard);
/// "K/N" (or "K/N:block"): nullopt with `error` saying what is wrong.
std::optional<Shard> ParseShard(const std::string& text, std::string* error);
/// The shard of a Slurm array task: SLURM_ARRAY_TASK_ID minus SLURM_ARRAY_TASK_MIN (0 when
/// unset) of SLURM_ARRAY_TASK_COUNT; nullopt when not in an array task (or the variables do not
/// make a shard; `error` then says why, empty when simply not in one).
std::optional<Shard> ShardFromSlurm(std::string* error);

}  // namespace lamina::core
