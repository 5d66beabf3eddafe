// SPDX-License-Identifier: MIT
// lamina_bench: Google Benchmark's main plus the run-time registered world benchmarks. With
// repetitions the console shows each benchmark's median and coefficient of variation only (the
// mean and standard deviation stay in --benchmark_out files); the exit code is non-zero when a
// benchmark failed its physical sanity check.
#include <cstring>
#include <vector>

#include <benchmark/benchmark.h>
#include <unistd.h>

#include "tests/bench/bench_support.h"
#include "tests/bench/robot_bench.h"
#include "tests/bench/world_bench.h"

namespace lamina::bench {
namespace {

class MedianConsoleReporter : public benchmark::ConsoleReporter {
 public:
  using ConsoleReporter::ConsoleReporter;

  void ReportRuns(const std::vector<Run>& runs) override {
    std::vector<Run> shown;
    for (const Run& run : runs) {
      const bool hidden = run.run_type == Run::RT_Aggregate &&
                          (run.aggregate_name == "mean" || run.aggregate_name == "stddev");
      if (!hidden) shown.push_back(run);
    }
    if (!shown.empty()) ConsoleReporter::ReportRuns(shown);
  }
};

// an explicit --benchmark_format asks for Google Benchmark's own reporters
bool FormatRequested(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], "--benchmark_format", 18) == 0) return true;
  }
  return false;
}

}  // namespace
}  // namespace lamina::bench

int main(int argc, char** argv) {
  const bool own_format = lamina::bench::FormatRequested(argc, argv);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  lamina::bench::RegisterWorldBenchmarks();
  lamina::bench::RegisterRobotBenchmarks();
  lamina::bench::RegisterErrorMeterBenchmarks();
  if (own_format) {
    benchmark::RunSpecifiedBenchmarks();
  } else {
    const auto options = isatty(STDOUT_FILENO) ? benchmark::ConsoleReporter::OO_ColorTabular
                                               : benchmark::ConsoleReporter::OO_Tabular;
    lamina::bench::MedianConsoleReporter reporter(options);
    benchmark::RunSpecifiedBenchmarks(&reporter);
  }
  benchmark::Shutdown();
  return lamina::bench::FailureCount() > 0 ? 1 : 0;
}
