// SPDX-License-Identifier: MIT
#include "app/headless_accuracy.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <unistd.h>

#include "app/worlds_dir.h"
#include "core/accuracy/accuracy_report.h"
#include "core/accuracy/accuracy_run.h"

namespace lamina::app {
namespace {

namespace fs = std::filesystem;

struct AccuracyOptions {
  std::vector<std::string> scenes, solvers;
  std::vector<double> steps;
  bool bars = false;
  bool check = false;
  bool quiet = false;
  int threads = 0;
  std::string worlds;
  std::string out = "accuracy";
  std::string markdown;
  std::string peers;
};

void Error(const std::string& message) {
  std::cerr << "lamina-headless accuracy: " << message << "\n";
}

bool PickScenes(const AccuracyOptions& options, core::AccuracyGrid* grid) {
  if (options.scenes.empty()) return true;
  grid->scenes.clear();
  for (const std::string& name : options.scenes) {
    const core::AccuracyScene* scene = core::FindAccuracyScene(name);
    if (scene == nullptr) {
      std::string known;
      for (const core::AccuracyScene& s : core::AccuracyScenes()) known += " " + s.name;
      Error("no scene '" + name + "'; the scenes are:" + known);
      return false;
    }
    grid->scenes.push_back(scene);
  }
  return true;
}

bool PickSolvers(const AccuracyOptions& options, core::AccuracyGrid* grid) {
  if (options.solvers.empty()) return true;
  grid->solvers.clear();
  for (const std::string& label : options.solvers) {
    const auto solver = core::ParseAccuracySolver(label);
    if (!solver || !solver->peer.empty()) {
      Error("--solvers: '" + label + "' is not exact, newton, quickN (N iterations) or one of " +
            "those with -fixed" + (solver ? " (MuJoCo and Bullet runs come from --peers)" : ""));
      return false;
    }
    grid->solvers.push_back(*solver);
  }
  return true;
}

std::optional<core::AccuracyGrid> MakeGrid(const AccuracyOptions& options) {
  core::AccuracyGrid grid = options.bars ? core::BarAccuracyGrid() : core::FullAccuracyGrid();
  if (!options.steps.empty()) {
    grid.steps = options.steps;
    grid.bars_only = false;
  }
  if (!PickScenes(options, &grid) || !PickSolvers(options, &grid)) return std::nullopt;
  return grid;
}

// "runs 37/120  ballistic_box exact 1e-05 s" rewritten in place on a terminal
void PrintProgress(const core::AccuracyProgress& p) {
  const int width = 30;
  const int filled = p.total > 0 ? width * p.done / p.total : width;
  std::fprintf(stderr, "\r[%s%s] %d/%d  %-24s %-14s h=%-8g", std::string(filled, '#').c_str(),
               std::string(width - filled, ' ').c_str(), p.done, p.total, p.last->scene.c_str(),
               p.last->solver.Label().c_str(), p.last->step);
  if (p.done == p.total) std::fprintf(stderr, "\n");
  std::fflush(stderr);
}

bool WriteFile(const fs::path& path, const std::string& text) {
  std::ofstream file(path, std::ios::binary);
  file << text;
  file.close();
  if (!file) Error("cannot write " + path.string());
  return static_cast<bool>(file);
}

// the cores, the CPU and how many runs shared them at a time (`threads`, 0: one per core)
std::string Machine(int threads) {
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  const unsigned at_once = threads > 0 ? static_cast<unsigned>(threads) : cores;
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line, model = "unknown CPU";
  while (std::getline(cpuinfo, line)) {
    if (line.rfind("model name", 0) == 0) {
      model = line.substr(line.find(':') + 2);
      break;
    }
  }
  return std::to_string(cores) + " cores, " + model + ", " + std::to_string(at_once) +
         (at_once == 1 ? " run" : " runs") + " at a time";
}

std::string Today() {
  const std::time_t now = std::time(nullptr);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%d", std::gmtime(&now));
  return text;
}

bool WritePlots(const std::vector<core::AccuracyRun>& runs, const fs::path& out) {
  bool ok = true;
  for (const core::AccuracyScene& scene : core::AccuracyScenes()) {
    bool has_runs = false;
    for (const core::AccuracyRun& run : runs) has_runs = has_runs || run.scene == scene.name;
    if (!has_runs) continue;
    for (core::PlotAxis axis : {core::PlotAxis::kCpuTime, core::PlotAxis::kStep}) {
      ok = WriteFile(out / core::AccuracyPlotName(scene, axis),
                     core::AccuracySceneSvg(scene, runs, axis)) &&
           ok;
    }
  }
  return ok;
}

bool WriteMarkdown(const std::vector<core::AccuracyRun>& runs,
                   const std::vector<core::BarVerdict>& bars, const AccuracyOptions& options) {
  const fs::path file = fs::absolute(options.markdown);
  core::MarkdownContext context;
  context.plots_dir = fs::relative(fs::absolute(options.out), file.parent_path()).generic_string();
  context.command = "make accuracy";
  context.machine = Machine(options.threads);
  context.date = Today();
  return WriteFile(file, core::AccuracyMarkdown(runs, bars, context));
}

bool WriteOutputs(const std::vector<core::AccuracyRun>& runs,
                  const std::vector<core::BarVerdict>& bars, const AccuracyOptions& options) {
  std::error_code error;
  fs::create_directories(options.out, error);
  if (error) {
    Error("cannot create " + options.out + ": " + error.message());
    return false;
  }
  const fs::path out(options.out);
  bool ok = WriteFile(out / "runs.csv", core::AccuracyCsv(runs));
  ok = WriteFile(out / "runs.json", core::AccuracyJson(runs, bars)) && ok;
  ok = WritePlots(runs, out) && ok;
  if (!options.markdown.empty()) ok = WriteMarkdown(runs, bars, options) && ok;
  return ok;
}

// The runs of tests/bench/peers' lamina-peers in `file` (its runs.json) of the scenes in `grid`,
// after Lamina's.
bool AddPeerRuns(const std::string& file, const core::AccuracyGrid& grid,
                 std::vector<core::AccuracyRun>* runs) {
  if (file.empty()) return true;
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    Error("--peers: cannot read " + file);
    return false;
  }
  std::ostringstream text;
  text << in.rdbuf();
  std::string error;
  std::vector<core::AccuracyRun> peers;
  if (!core::ReadAccuracyRunsJson(text.str(), file, &peers, &error)) {
    Error("--peers: " + error);
    return false;
  }
  for (const core::AccuracyRun& run : peers) {
    for (const core::AccuracyScene* scene : grid.scenes) {
      if (scene->name == run.scene) runs->push_back(run);
    }
  }
  return true;
}

void PrintBars(const std::vector<core::BarVerdict>& bars) {
  for (const core::BarVerdict& bar : bars) {
    const char* verdict = bar.check.pass ? "pass  " : bar.known_failure ? "known " : "FAIL  ";
    std::cout << verdict << bar.scene << ": " << bar.text << " — " << bar.check.measured << "\n";
  }
}

int RunAccuracy(const AccuracyOptions& options) {
  const std::optional<core::AccuracyGrid> grid = MakeGrid(options);
  if (!grid) return 2;
  const std::string worlds = options.worlds.empty() ? WorldsDir() + "/accuracy" : options.worlds;
  std::function<void(const core::AccuracyProgress&)> progress;
  if (!options.quiet && isatty(STDERR_FILENO)) progress = PrintProgress;
  auto runs = core::RunAccuracySweep(*grid, worlds, options.threads, progress);
  if (!AddPeerRuns(options.peers, *grid, &runs)) return 1;
  const auto bars = core::JudgeAccuracyBars(runs);
  PrintBars(bars);
  if (!WriteOutputs(runs, bars, options)) return 1;
  for (const core::AccuracyRun& run : runs) {
    if (!run.failure.empty()) Error(run.scene + " " + run.solver.Label() + ": " + run.failure);
  }
  bool passed = true;
  // a known failure fails --check only once it passes (its mark should then go)
  for (const core::BarVerdict& bar : bars) passed = passed && bar.check.pass != bar.known_failure;
  return options.check && !passed ? 1 : 0;
}

}  // namespace

Subcommand AddAccuracyCommand(CLI::App& app) {
  auto options = std::make_shared<AccuracyOptions>();
  CLI::App* command = app.add_subcommand(
      "accuracy", "error against run time over steps and solvers (docs/accuracy.md)");
  command->add_option("--scenes", options->scenes, "scenes to run (default: all)")->delimiter(',');
  command->add_option("--steps", options->steps, "largest steps, s (default 1e-5 … 1e-2)")
      ->delimiter(',')
      ->check(CLI::PositiveNumber);
  command
      ->add_option("--solvers", options->solvers,
                   "exact, newton, quickN, each optionally -fixed (no adaptive stepping); default "
                   "exact,newton,quick20,quick40,quick100,exact-fixed")
      ->delimiter(',');
  command->add_flag("--bars", options->bars,
                    "only the runs the pass bars need (each scene's bar steps, exact solver)");
  command->add_flag("--check", options->check,
                    "exit 1 when a bar is not met (or a bar marked as a known failure is met)");
  command->add_option("--threads", options->threads, "worker threads (default: every core)")
      ->check(CLI::PositiveNumber);
  command->add_option("--worlds", options->worlds, "folder of the scene worlds")
      ->check(CLI::ExistingDirectory);
  command->add_option("--out", options->out, "folder for runs.csv, runs.json and the plots")
      ->capture_default_str();
  command->add_option("--markdown", options->markdown, "also write the report page here");
  command
      ->add_option("--peers", options->peers,
                   "also plot these MuJoCo and Bullet runs (lamina-peers' runs.json, "
                   "tests/bench/peers)")
      ->check(CLI::ExistingFile);
  command->add_flag("-q,--quiet", options->quiet, "no progress bar");
  return {command, [options] { return RunAccuracy(*options); }};
}

}  // namespace lamina::app
