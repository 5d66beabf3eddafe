// SPDX-License-Identifier: MIT
#include "app/headless_stress.h"

#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <unistd.h>

#include "app/worlds_dir.h"
#include "core/accuracy/stress_report.h"

namespace lamina::app {
namespace {

struct StressOptions {
  std::vector<std::string> cases;
  std::string json;
  std::string markdown;
  std::string worlds;
  int threads = 0;
  bool quiet = false;
};

void Error(const std::string& message) {
  std::cerr << "lamina-headless stress: " << message << "\n";
}

bool WriteFile(const std::string& path, const std::string& text) {
  std::ofstream file(path, std::ios::binary);
  file << text;
  file.close();
  if (!file) Error("cannot write " + path);
  return static_cast<bool>(file);
}

// "[#####     ] 12/27  box_stack_20/exact/1ms  stable" rewritten in place on a terminal
void PrintProgress(int done, int total, const core::StressRecord& record) {
  const int width = 30;
  const int filled = total > 0 ? width * done / total : width;
  std::fprintf(stderr, "\r[%s%s] %d/%d  %-32s %-8s", std::string(filled, '#').c_str(),
               std::string(width - filled, ' ').c_str(), done, total, record.name.c_str(),
               core::StressVerdictName(record.verdict));
  if (done == total) std::fprintf(stderr, "\n");
  std::fflush(stderr);
}

int RunStress(const StressOptions& options) {
  const std::vector<const core::StressCase*> cases = core::FindStressCases(options.cases);
  if (cases.empty()) {
    std::string known;
    for (const core::StressCase& c : core::StressCases()) known += " " + c.name;
    Error("no case matches; the cases are:" + known);
    return 2;
  }
  const std::string worlds = options.worlds.empty() ? WorldsDir() : options.worlds;
  std::function<void(int, int, const core::StressRecord&)> progress;
  if (!options.quiet && isatty(STDERR_FILENO)) progress = PrintProgress;
  const auto records = core::RunStressCases(cases, worlds, options.threads, progress);
  std::cout << core::StressTable(records);
  bool written = true;
  if (!options.json.empty()) written = WriteFile(options.json, core::StressJson(records));
  if (!options.markdown.empty()) {
    written = WriteFile(options.markdown, core::StressMarkdownTable(records)) && written;
  }
  if (!written) return 1;
  return core::FailedCount(records) > 0 ? 1 : 0;
}

}  // namespace

Subcommand AddStressCommand(CLI::App& app) {
  auto options = std::make_shared<StressOptions>();
  CLI::App* command = app.add_subcommand(
      "stress", "stiff and extreme cases, each judged stable, flagged or failed (docs/stress.md)");
  command
      ->add_option("--cases", options->cases,
                   "cases to run: names or shell patterns such as 'box_stack*' (default: all)")
      ->delimiter(',');
  command->add_option("--json", options->json, "write every case's record here");
  command->add_option("--markdown", options->markdown, "write the Markdown table here");
  command->add_option("--threads", options->threads, "worker threads (default: every core)")
      ->check(CLI::PositiveNumber);
  command->add_option("--worlds", options->worlds, "the worlds folder (with accuracy/, stress/)")
      ->check(CLI::ExistingDirectory);
  command->add_flag("-q,--quiet", options->quiet, "no progress bar");
  return {command, [options] { return RunStress(*options); }};
}

}  // namespace lamina::app
