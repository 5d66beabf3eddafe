// SPDX-License-Identifier: MIT
// lamina-headless: the command-line tool (no window). Argument parsing and wiring only.
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "app/headless_render_commands.h"
#include "core/control/send_motion.h"
#include "core/io/trajectory_file.h"
#include "core/io/world_file.h"
#include "core/model/world_summary.h"
#include "core/sim/run_report.h"
#include "core/sim/sim_log.h"
#include "core/sim/simulator.h"

namespace {

using lamina::core::Diagnostics;
using lamina::core::LoadContext;
using lamina::core::MeshCache;
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

int RunInfo(const std::string& path, bool json) {
  WorldDesc world;
  if (!LoadWorldReporting(path, &world)) return 1;
  std::cout << (json ? lamina::core::WorldSummaryJson(world)
                     : lamina::core::WorldSummaryText(world));
  return 0;
}

struct RunOptions {
  std::string world;
  double duration = 1.0;
  double step = 0.0;
  std::string solver = "step";
  std::string log;
  std::string motion;  ///< --path or --milestones file, sent to robot 0
  bool json = false;
  bool sleep = false;  ///< Simulator::SetSleeping
};

// Klamp't SimTest logs every 0.01 s of simulated time
constexpr double kLogInterval = 0.01;

// "step", "quick" or "quick:N"
bool ParseSolver(const std::string& text, lamina::core::SolverSettings* solver) {
  if (text == "step") {
    solver->type = lamina::core::SolverType::kStep;
    return true;
  }
  if (text.rfind("quick", 0) != 0) return false;
  solver->type = lamina::core::SolverType::kQuickStep;
  if (text.size() == 5) return true;
  if (text[5] != ':') return false;
  try {
    solver->quick_step_iterations = std::stoi(text.substr(6));
  } catch (const std::exception&) {
    return false;
  }
  return solver->quick_step_iterations > 0;
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

int RunSimulation(const RunOptions& options) {
  lamina::core::SolverSettings solver;
  if (!ParseSolver(options.solver, &solver)) {
    std::cerr << "lamina-headless: --solver must be step, quick or quick:N, got '" << options.solver
              << "'\n";
    return 2;
  }
  WorldDesc world;
  if (!LoadWorldReporting(options.world, &world)) return 1;
  lamina::core::Simulator simulator(world, solver);
  if (options.step > 0.0) simulator.SetSimStep(options.step);
  simulator.SetSleeping(options.sleep);
  if (!options.motion.empty() && !SendMotionFile(options.motion, &simulator)) return 1;
  std::ofstream log;
  if (!options.log.empty()) {
    log.open(options.log);
    if (!log) {
      std::cerr << "lamina-headless: cannot write " << options.log << "\n";
      return 1;
    }
    log << lamina::core::SimLogHeader(simulator) << lamina::core::SimLogRow(simulator);
  }
  lamina::core::RunTiming timing;
  const auto start = std::chrono::steady_clock::now();
  if (log.is_open()) {
    // log rows are written outside the timed simulation
    for (double t = 0.0; t < options.duration - 1e-12; t += kLogInterval) {
      const auto chunk_start = std::chrono::steady_clock::now();
      const double dt = std::min(kLogInterval, options.duration - t);
      const bool ok = simulator.Simulate(dt) != lamina::core::StepStatus::kError;
      timing.wall_time +=
          std::chrono::duration<double>(std::chrono::steady_clock::now() - chunk_start).count();
      log << lamina::core::SimLogRow(simulator);
      if (!ok) break;
    }
  } else {
    simulator.Simulate(options.duration);
    timing.wall_time =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  std::cout << (options.json ? lamina::core::RunReportJson(simulator, timing)
                             : lamina::core::RunReportText(simulator, timing));
  return simulator.statistics().worst_status == lamina::core::StepStatus::kError ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"lamina-headless: load, inspect, simulate and render Lamina/Klamp't worlds"};
  app.require_subcommand(1);

  std::string info_world;
  bool info_json = false;
  CLI::App* info = app.add_subcommand("info", "print what a world file holds");
  info->add_option("world", info_world, "world .xml, or a .rob/.urdf/.obj/.env/mesh file")
      ->required();
  info->add_flag("--json", info_json, "print JSON instead of text");

  RunOptions run_options;
  CLI::App* run = app.add_subcommand("run", "simulate a world and report the final state");
  run->add_option("world", run_options.world, "world file")->required();
  run->add_option("--duration", run_options.duration, "simulated time, s")
      ->check(CLI::PositiveNumber);
  run->add_option("--dt", run_options.step, "largest physics step, s (default: the world's)")
      ->check(CLI::PositiveNumber);
  run->add_option("--solver", run_options.solver, "step (exact), quick or quick:N");
  run->add_option("--log", run_options.log, "write a Klamp't-style CSV log (every 0.01 s)");
  run->add_flag("--json", run_options.json, "print JSON instead of text");
  run->add_flag("--sleep", run_options.sleep,
                "let idle objects sleep (leave the steps until something touches them)");
  CLI::Option* path = run->add_option("--path", run_options.motion,
                                      "timed .path (or MultiPath .xml) sent to robot 0");
  run->add_option("--milestones", run_options.motion, ".milestones file sent to robot 0")
      ->excludes(path);

  const lamina::app::Subcommand shot = lamina::app::AddShotCommand(app);
  const lamina::app::Subcommand record = lamina::app::AddRecordCommand(app);

  CLI11_PARSE(app, argc, argv);
  if (shot.command->parsed()) return shot.run();
  if (record.command->parsed()) return record.run();
  if (info->parsed()) return RunInfo(info_world, info_json);
  if (run->parsed()) return RunSimulation(run_options);
  return 2;
}
