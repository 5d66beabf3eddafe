// SPDX-License-Identifier: MIT
// lamina-peers: the accuracy scenes (docs/accuracy.md) through MuJoCo and Bullet, measured by the
// scenes' own probes, written as the accuracy report's runs.json and runs.csv so that
// `lamina-headless accuracy --peers runs.json` plots them beside Lamina's solvers. Built when
// Debian's libmujoco-dev and libbullet-dev are installed (`make peers` installs them and runs it);
// never part of `make test`.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <mujoco/mujoco.h>
#include <unistd.h>

#include "core/accuracy/accuracy_report.h"
#include "core/accuracy/accuracy_run.h"
#include "tests/bench/peers/peer_run.h"

namespace {

using lamina::core::AccuracyRun;
using lamina::core::AccuracyScene;

struct Options {
  std::vector<std::string> scenes, peers = {"mujoco", "bullet10"};
  std::vector<double> steps = {1e-5, 4e-5, 1e-4, 4e-4, 1e-3, 4e-3, 1e-2};
  std::string worlds = LAMINA_WORLDS_DIR "/accuracy";
  std::string out = "peers";
  int threads = 0;
  bool quiet = false;
};

// The sweep's grid: the picked scenes (every one when none is named) with the named peers at
// the steps; nullopt with a message for a label that names no peer or a scene that does not exist.
std::optional<lamina::core::AccuracyGrid> MakeGrid(const Options& options) {
  lamina::core::AccuracyGrid grid;
  grid.steps = options.steps;
  // not the solvers of the scenes' bars: Lamina's own (exact, newton-joints), which no peer runs
  // (as "is not a peer" failures in runs.json they stopped `make accuracy`)
  grid.bar_solvers = false;
  for (const std::string& label : options.peers) {
    const auto solver = lamina::core::ParseAccuracySolver(label);
    if (!solver || solver->peer.empty()) {
      std::cerr << "lamina-peers: --peers: '" << label << "' is not mujoco or bulletN\n";
      return std::nullopt;
    }
    grid.solvers.push_back(*solver);
  }
  for (const AccuracyScene& scene : lamina::core::AccuracyScenes()) {
    if (options.scenes.empty()) grid.scenes.push_back(&scene);
  }
  for (const std::string& name : options.scenes) {
    const AccuracyScene* scene = lamina::core::FindAccuracyScene(name);
    if (scene == nullptr) {
      std::cerr << "lamina-peers: --scenes: no scene '" << name << "'\n";
      return std::nullopt;
    }
    grid.scenes.push_back(scene);
  }
  return grid;
}

void Progress(const lamina::core::AccuracyProgress& p) {
  std::fprintf(stderr, "\r%d/%d  %-24s %-10s h=%-8g", p.done, p.total, p.last->scene.c_str(),
               p.last->solver.Label().c_str(), p.last->step);
  if (p.done == p.total) std::fprintf(stderr, "\n");
}

// The runs that ran; a scene a peer cannot express is said once and left out.
std::vector<AccuracyRun> Report(const std::vector<AccuracyRun>& runs) {
  std::vector<AccuracyRun> kept;
  std::set<std::string> said;
  for (const AccuracyRun& run : runs) {
    if (run.failure.rfind("not expressed: ", 0) != 0) {
      kept.push_back(run);
      if (!run.failure.empty())
        std::cerr << run.scene << " " << run.solver.Label() << " h=" << run.step << ": "
                  << run.failure << "\n";
      continue;
    }
    const std::string key = run.scene + " " + run.solver.Label();
    if (said.insert(key).second) std::cout << "left out: " << key << ": " << run.failure << "\n";
  }
  return kept;
}

bool Write(const std::filesystem::path& path, const std::string& text) {
  std::ofstream file(path, std::ios::binary);
  file << text;
  file.close();
  if (!file) std::cerr << "lamina-peers: cannot write " << path << "\n";
  return static_cast<bool>(file);
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  CLI::App app{"lamina-peers: the accuracy scenes through MuJoCo " +
               std::string(mj_versionString()) + " and Bullet (docs/accuracy.md, Peers)"};
  app.add_option("--scenes", options.scenes, "scenes to run (default: every one)")->delimiter(',');
  app.add_option("--peers", options.peers, "mujoco, bulletN (N solver iterations)")
      ->delimiter(',')
      ->capture_default_str();
  app.add_option("--steps", options.steps, "steps, s")->delimiter(',')->check(CLI::PositiveNumber);
  app.add_option("--worlds", options.worlds, "folder of the scene worlds")
      ->check(CLI::ExistingDirectory);
  app.add_option("--out", options.out, "folder for runs.json and runs.csv")->capture_default_str();
  app.add_option("--threads", options.threads, "worker threads (default: every core)");
  app.add_flag("-q,--quiet", options.quiet, "no progress line");
  CLI11_PARSE(app, argc, argv);
  const std::optional<lamina::core::AccuracyGrid> grid = MakeGrid(options);
  if (!grid) return 2;
  std::function<void(const lamina::core::AccuracyProgress&)> progress;
  if (!options.quiet && isatty(STDERR_FILENO)) progress = Progress;
  const std::vector<AccuracyRun> runs = Report(lamina::core::RunAccuracySweep(
      *grid, options.worlds, options.threads, progress, lamina::peers::RunPeerScene));
  std::filesystem::create_directories(options.out);
  const std::filesystem::path out(options.out);
  const bool ok = Write(out / "runs.json", lamina::core::AccuracyJson(runs, {})) &&
                  Write(out / "runs.csv", lamina::core::AccuracyCsv(runs));
  return ok ? 0 : 1;
}
