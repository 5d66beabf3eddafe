// SPDX-License-Identifier: MIT
// lamina-peers: the accuracy scenes (docs/accuracy.md) through MuJoCo and Bullet, measured by the
// scenes' own probes, written as the accuracy report's runs.json and runs.csv so that
// `lamina-headless accuracy --peers runs.json` plots them beside Lamina's solvers. Built when
// Debian's libmujoco-dev and libbullet-dev are installed (`make peers` installs them and runs it);
// never part of `make test`.
#include <algorithm>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <mutex>
#include <set>
#include <string>
#include <thread>
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
using lamina::core::AccuracySolver;

struct Options {
  std::vector<std::string> scenes, peers = {"mujoco", "bullet10"};
  std::vector<double> steps = {1e-5, 4e-5, 1e-4, 4e-4, 1e-3, 4e-3, 1e-2};
  std::string worlds = LAMINA_WORLDS_DIR "/accuracy";
  std::string out = "peers";
  int threads = 0;
  bool quiet = false;
};

struct Job {
  const AccuracyScene* scene;
  AccuracySolver solver;
  double step;
};

bool MakeJobs(const Options& options, std::vector<Job>* jobs) {
  std::vector<AccuracySolver> solvers;
  for (const std::string& label : options.peers) {
    const auto solver = lamina::core::ParseAccuracySolver(label);
    if (!solver || solver->peer.empty()) {
      std::cerr << "lamina-peers: --peers: '" << label << "' is not mujoco or bulletN\n";
      return false;
    }
    solvers.push_back(*solver);
  }
  for (const AccuracyScene& scene : lamina::core::AccuracyScenes()) {
    const bool picked =
        options.scenes.empty() ||
        std::find(options.scenes.begin(), options.scenes.end(), scene.name) != options.scenes.end();
    if (!picked) continue;
    for (const AccuracySolver& solver : solvers) {
      for (double step : options.steps) {
        if (step >= scene.min_step * (1 - 1e-9)) jobs->push_back({&scene, solver, step});
      }
    }
  }
  if (jobs->empty()) std::cerr << "lamina-peers: no scene matches --scenes\n";
  return !jobs->empty();
}

void Progress(int done, int total, const AccuracyRun& run) {
  std::fprintf(stderr, "\r%d/%d  %-24s %-10s h=%-8g", done, total, run.scene.c_str(),
               run.solver.Label().c_str(), run.step);
  if (done == total) std::fprintf(stderr, "\n");
}

std::vector<AccuracyRun> RunJobs(const std::vector<Job>& jobs, const Options& options) {
  std::vector<AccuracyRun> runs(jobs.size());
  std::atomic<std::size_t> next{0};
  std::mutex report;
  int done = 0;
  const bool show = !options.quiet && isatty(STDERR_FILENO);
  auto work = [&] {
    for (std::size_t i = next++; i < jobs.size(); i = next++) {
      runs[i] =
          lamina::peers::RunPeerScene(*jobs[i].scene, options.worlds, jobs[i].solver, jobs[i].step);
      const std::lock_guard<std::mutex> lock(report);
      if (show) Progress(++done, static_cast<int>(jobs.size()), runs[i]);
    }
  };
  const int count =
      options.threads > 0 ? options.threads : static_cast<int>(std::thread::hardware_concurrency());
  std::vector<std::thread> pool;
  for (int t = 0; t < std::max(count, 1); ++t) pool.emplace_back(work);
  for (std::thread& thread : pool) thread.join();
  return runs;
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
  std::vector<Job> jobs;
  if (!MakeJobs(options, &jobs)) return 2;
  const std::vector<AccuracyRun> runs = Report(RunJobs(jobs, options));
  std::filesystem::create_directories(options.out);
  const std::filesystem::path out(options.out);
  const bool ok = Write(out / "runs.json", lamina::core::AccuracyJson(runs, {})) &&
                  Write(out / "runs.csv", lamina::core::AccuracyCsv(runs));
  return ok ? 0 : 1;
}
