// SPDX-License-Identifier: MIT
// lamina-headless: the command-line tool (no window). Argument parsing and wiring only.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/headless_accuracy.h"
#include "app/headless_batch.h"
#include "app/headless_render_commands.h"
#include "app/headless_sensors.h"
#include "app/headless_stress.h"
#include "core/control/send_motion.h"
#include "core/io/trajectory_file.h"
#include "core/io/world_file.h"
#include "core/model/access_path.h"
#include "core/model/world_summary.h"
#include "core/number_text.h"
#include "core/sim/run_report.h"
#include "core/sim/sim_access.h"
#include "core/sim/sim_log.h"
#include "core/sim/simulator.h"

namespace {

using lamina::core::AccessContext;
using lamina::core::AccessTarget;
using lamina::core::Diagnostics;
using lamina::core::LoadContext;
using lamina::core::MeshCache;
using lamina::core::ParamValue;
using lamina::core::Simulator;
using lamina::core::WorldDesc;

// loads `path`, printing every diagnostic to stderr; false on any error
bool LoadWorldReporting(const std::string& path, WorldDesc* world) {
  Diagnostics diagnostics;
  MeshCache meshes;
  LoadContext context{diagnostics, meshes};
  const bool ok = lamina::core::LoadWorldFile(path, context, world);
  std::cerr << diagnostics.FormatAll();
  return ok && !diagnostics.HasErrors();
}

// ---- --set and --get (access paths, core/model/access_path.h) ------------------------------

// the one message of a refused --set or --get (the caller exits with status 2)
void AccessError(const char* option, const std::string& argument, const std::string& reason) {
  std::cerr << "lamina-headless: " << option << " '" << argument << "': " << reason << "\n";
}

// one --set PATH=VALUE, resolved on the description when the path names something of it (rows,
// initial conditions), else on the simulation (state items)
struct SetArgument {
  std::string argument;
  AccessTarget target;
  ParamValue value;
  bool on_description = false;
};

std::optional<SetArgument> ReadSet(const std::string& argument, const WorldDesc& world,
                                   bool simulation, std::string* error) {
  std::string path, text;
  if (!lamina::core::SplitAssignment(argument, &path, &text, error)) return std::nullopt;
  SetArgument set;
  set.argument = argument;
  std::optional<AccessTarget> target =
      lamina::core::ResolveAccessPath(world, path, AccessContext::kDescription, error);
  set.on_description = target.has_value();
  if (!target && simulation) {
    target = lamina::core::ResolveAccessPath(world, path, AccessContext::kSimulation, error);
  }
  if (!target) return std::nullopt;
  std::optional<ParamValue> value = lamina::core::ParseAccessValue(*target, text, error);
  if (!value) return std::nullopt;
  set.target = *target;
  set.value = *value;
  return set;
}

// applies the description's --set arguments to `world` in order and returns the simulation's
// (`simulation`: state items are allowed); nullopt, the message printed, on the first bad one
std::optional<std::vector<SetArgument>> ApplySets(const std::vector<std::string>& arguments,
                                                  bool simulation, WorldDesc* world) {
  std::vector<SetArgument> later;
  for (const std::string& argument : arguments) {
    std::string error;
    std::optional<SetArgument> set = ReadSet(argument, *world, simulation, &error);
    if (set && !set->on_description) {
      later.push_back(*set);
      continue;
    }
    if (!set || !lamina::core::SetPath(world, set->target, set->value, &error)) {
      AccessError("--set", argument, error);
      return std::nullopt;
    }
  }
  return later;
}

// applies the simulation's --set arguments in order; false with the message printed
bool ApplySimulationSets(const std::vector<SetArgument>& sets, Simulator* simulator) {
  for (const SetArgument& set : sets) {
    std::string error;
    if (!lamina::core::SetPath(simulator, set.target, set.value, &error)) {
      AccessError("--set", set.argument, error);
      return false;
    }
  }
  return true;
}

// the --get paths resolved on the simulation before it runs; nullopt with the message printed
std::optional<std::vector<AccessTarget>> ResolveGets(const std::vector<std::string>& paths,
                                                     const Simulator& simulator) {
  std::vector<AccessTarget> targets;
  for (const std::string& path : paths) {
    std::string error;
    std::optional<AccessTarget> target =
        lamina::core::ResolveSimulationPath(simulator, path, &error);
    if (!target) {
      AccessError("--get", path, error);
      return std::nullopt;
    }
    targets.push_back(*target);
  }
  return targets;
}

// the --get values at the end of the run; nullopt with the message printed
std::optional<std::vector<lamina::core::PathValue>> ReadGets(
    const std::vector<std::string>& paths, const std::vector<AccessTarget>& targets,
    const Simulator& simulator) {
  std::vector<lamina::core::PathValue> values;
  for (size_t i = 0; i < paths.size(); ++i) {
    std::string error;
    std::optional<ParamValue> value = lamina::core::GetPath(simulator, targets[i], &error);
    if (!value) {
      AccessError("--get", paths[i], error);
      return std::nullopt;
    }
    values.push_back({paths[i], *value});
  }
  return values;
}

std::string GetsText(const std::vector<AccessTarget>& targets,
                     const std::vector<lamina::core::PathValue>& values) {
  std::string out;
  for (size_t i = 0; i < values.size(); ++i) {
    out += values[i].path + " = " + lamina::core::FormatAccessValue(targets[i], values[i].value) +
           "\n";
  }
  return out;
}

// ---- info -----------------------------------------------------------------------------------

int RunInfo(const std::string& path, bool json, const std::vector<std::string>& sets) {
  WorldDesc world;
  if (!LoadWorldReporting(path, &world)) return 1;
  if (!ApplySets(sets, false, &world)) return 2;
  std::cout << (json ? lamina::core::WorldSummaryJson(world)
                     : lamina::core::WorldSummaryText(world));
  return 0;
}

struct RunOptions {
  std::string world;
  double duration = 1.0;
  double step = 0.0;
  std::string solver;  ///< "" = the world's
  std::string log;
  std::string motion;  ///< --path or --milestones file, sent to robot 0
  bool json = false;
  bool sleep = false;             ///< Simulator::SetSleeping (else the world's setting)
  bool no_error_meter = false;    ///< run without the live accuracy meter
  bool no_pair_reuse = false;     ///< search the mesh hierarchies every step
  bool ode_robots = false;        ///< the exact solver leaves robots to dWorldStep's LCP
  bool ode_objects = false;       ///< and object islands
  std::vector<std::string> sets;  ///< --set PATH=VALUE
  std::vector<std::string> gets;  ///< --get PATH
  std::string sensor_images;      ///< --sensor-images DIR
};

// Klamp't SimTest logs every 0.01 s of simulated time
constexpr double kLogInterval = 0.01;

// "step", "newton", "quick" or "quick:N"
bool ParseSolver(const std::string& text, lamina::core::SolverSettings* solver) {
  if (text == "step" || text == "newton") {
    solver->type =
        text == "step" ? lamina::core::SolverType::kStep : lamina::core::SolverType::kNewton;
    return true;
  }
  if (text.rfind("quick", 0) != 0) return false;
  solver->type = lamina::core::SolverType::kQuickStep;
  if (text.size() == 5) return true;
  if (text[5] != ':') return false;
  // the whole rest is the count, in the table's range ("quick:5x" is not 5)
  const lamina::core::ParamSpec& iterations =
      *lamina::core::FindParam("quickStepIterations", lamina::core::ElementKind::kSettings);
  return lamina::core::ParseInt(text.substr(6), &solver->quick_step_iterations) &&
         lamina::core::ParamAccepts(iterations, {double(solver->quick_step_iterations)}, 1);
}

// Klamp't SimTest sends a motion file to robot 0
bool SendMotionFile(const std::string& path, lamina::core::Simulator* simulator) {
  if (simulator->robot_count() == 0) {
    std::cerr << path << ": error: the world has no robot to send the motion to\n";
    return false;
  }
  lamina::core::Diagnostics diagnostics;
  const auto motion = lamina::core::ReadMotionFile(path, diagnostics);
  std::cerr << diagnostics.FormatAll();
  if (!motion) return false;
  std::string error;
  if (!lamina::core::SendMotion(*motion, &simulator->controller(0), &error)) {
    std::cerr << path << ": error: " << error << "\n";
    return false;
  }
  return true;
}

// simulates for the duration in one call, writing the log from a step observer when asked (its
// writing is left out of the wall time); false when the log cannot be written
bool Advance(const RunOptions& options, Simulator* simulator, lamina::core::RunTiming* timing) {
  std::ofstream log;
  std::optional<lamina::core::SimLogWriter> writer;
  if (!options.log.empty()) {
    log.open(options.log);
    if (!log) {
      std::cerr << "lamina-headless: cannot write " << options.log << "\n";
      return false;
    }
    writer.emplace(&log, *simulator, kLogInterval);
  }
  const int observer =
      writer ? simulator->AddStepObserver([&](const lamina::core::StepEvent& e) { (*writer)(e); })
             : -1;
  const auto start = std::chrono::steady_clock::now();
  simulator->Simulate(options.duration);
  timing->wall_time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  simulator->RemoveStepObserver(observer);
  if (writer) {
    timing->wall_time -= writer->seconds_spent();
    writer->Finish(*simulator);
  }
  return true;
}

// the report, with the --get values
int Report(const RunOptions& options, const Simulator& simulator,
           const lamina::core::RunTiming& timing, const std::vector<AccessTarget>& targets) {
  const auto values = ReadGets(options.gets, targets, simulator);
  if (!values) return 2;
  if (options.json) {
    std::cout << lamina::core::AddGetJson(lamina::core::RunReportJson(simulator, timing), *values);
  } else {
    std::cout << lamina::core::RunReportText(simulator, timing) << GetsText(targets, *values);
  }
  return simulator.statistics().worst_status == lamina::core::StepStatus::kError ? 1 : 0;
}

int RunSimulation(const RunOptions& options) {
  if (!std::isfinite(options.duration) || !std::isfinite(options.step)) {
    std::cerr << "lamina-headless: --duration and --dt must be finite\n";
    return 2;
  }
  lamina::core::SolverSettings solver;
  if (!options.solver.empty() && !ParseSolver(options.solver, &solver)) {
    std::cerr
        << "lamina-headless: --solver must be step, newton, quick or quick:N (N in [1, 1e6]), got '"
        << options.solver << "'\n";
    return 2;
  }
  WorldDesc world;
  if (!LoadWorldReporting(options.world, &world)) return 1;
  const auto later = ApplySets(options.sets, true, &world);
  if (!later) return 2;
  Simulator simulator(world, options.solver.empty() ? world.settings.solver_settings() : solver);
  if (options.step > 0.0) simulator.SetSimStep(options.step);
  if (options.sleep) simulator.SetSleeping(true);
  simulator.SetErrorMeter(!options.no_error_meter);
  simulator.SetReuseContactPairs(!options.no_pair_reuse);
  simulator.SetDirectRobotSolve(!options.ode_robots);
  simulator.SetNewtonObjectIslands(!options.ode_objects);
  if (!ApplySimulationSets(*later, &simulator)) return 2;
  const auto targets = ResolveGets(options.gets, simulator);
  if (!targets) return 2;
  if (!options.motion.empty() && !SendMotionFile(options.motion, &simulator)) return 1;
  lamina::app::SensorCameras cameras;
  std::string error;
  if (!cameras.Open(&simulator, options.sensor_images, &error)) {
    std::cerr << "lamina-headless: sensor cameras: " << error << "\n";
    return 1;
  }
  lamina::core::RunTiming timing;
  if (!Advance(options, &simulator, &timing)) return 1;
  if (cameras.failures() > 0) {
    std::cerr << "lamina-headless: " << cameras.failures()
              << " sensor images could not be written, "
              << "the first " << cameras.first_failure() << "\n";
    return 1;
  }
  return Report(options, simulator, timing, *targets);
}

// --set PATH=VALUE, repeatable: one argument per occurrence
void AddSetOption(CLI::App* command, std::vector<std::string>* sets) {
  command
      ->add_option("--set", *sets,
                   "PATH=VALUE: set what an access path names, e.g. "
                   "'objects[box].kFriction=0.1' (repeatable; docs/access-paths.md)")
      ->allow_extra_args(false);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"lamina-headless: load, inspect, simulate and render Lamina/Klamp't worlds"};
  app.require_subcommand(1);

  std::string info_world;
  bool info_json = false;
  std::vector<std::string> info_sets;
  CLI::App* info = app.add_subcommand("info", "print what a world file holds");
  info->add_option("world", info_world, "world .xml, or a .rob/.urdf/.obj/.env/mesh file")
      ->required();
  info->add_flag("--json", info_json, "print JSON instead of text");
  AddSetOption(info, &info_sets);

  RunOptions run_options;
  CLI::App* run = app.add_subcommand("run", "simulate a world and report the final state");
  run->add_option("world", run_options.world, "world file")->required();
  run->add_option("--duration", run_options.duration, "simulated time, s")
      ->check(CLI::PositiveNumber);
  run->add_option("--dt", run_options.step, "largest physics step, s (default: the world's)")
      ->check(CLI::PositiveNumber);
  run->add_option("--solver", run_options.solver,
                  "step (exact), newton, quick or quick:N (default: the world's solver)");
  run->add_option("--log", run_options.log, "write a Klamp't-style CSV log (every 0.01 s)");
  run->add_flag("--json", run_options.json, "print JSON instead of text");
  run->add_flag("--no-error-meter", run_options.no_error_meter,
                "leave out the live accuracy meter (step doubling on sampled steps; at most 5 % "
                "of the stepping time, results unchanged)");
  run->add_flag("--no-pair-reuse", run_options.no_pair_reuse,
                "search the mesh hierarchies for near triangle pairs every step instead of "
                "keeping the candidates while the meshes move less than a slack (results "
                "unchanged, for comparisons)");
  run->add_flag("--ode-robots", run_options.ode_robots,
                "with the exact solver, leave robots to dWorldStep's own LCP instead of the "
                "direct solve of their islands (the same law; for comparisons)");
  run->add_flag("--ode-objects", run_options.ode_objects,
                "with the exact solver, leave islands of free objects with many contacts to "
                "dWorldStep's own LCP instead of the Newton solver (the same law; for "
                "comparisons)");
  run->add_flag("--sleep", run_options.sleep,
                "let idle objects sleep (leave the steps until something touches them)");
  CLI::Option* path = run->add_option("--path", run_options.motion,
                                      "timed .path (or MultiPath .xml) sent to robot 0");
  run->add_option("--milestones", run_options.motion, ".milestones file sent to robot 0")
      ->excludes(path);
  run->add_option("--sensor-images", run_options.sensor_images,
                  "write every camera sensor's pictures into DIR (PNG colour, 16-bit PGM depth "
                  "in mm)");
  AddSetOption(run, &run_options.sets);
  run->add_option("--get", run_options.gets,
                  "report the value an access path names at the end (repeatable)")
      ->allow_extra_args(false);

  const lamina::app::Subcommand shot = lamina::app::AddShotCommand(app);
  const lamina::app::Subcommand record = lamina::app::AddRecordCommand(app);
  const lamina::app::Subcommand batch = lamina::app::AddBatchCommand(app);
  const lamina::app::Subcommand accuracy = lamina::app::AddAccuracyCommand(app);
  const lamina::app::Subcommand stress = lamina::app::AddStressCommand(app);

  CLI11_PARSE(app, argc, argv);
  if (shot.command->parsed()) return shot.run();
  if (record.command->parsed()) return record.run();
  if (batch.command->parsed()) return batch.run();
  if (accuracy.command->parsed()) return accuracy.run();
  if (stress.command->parsed()) return stress.run();
  if (info->parsed()) return RunInfo(info_world, info_json, info_sets);
  if (run->parsed()) return RunSimulation(run_options);
  return 2;
}
