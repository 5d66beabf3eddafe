// SPDX-License-Identifier: MIT
#include "app/headless_batch.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "app/batch_plot.h"
#include "core/batch/batch_output.h"
#include "core/batch/batch_sim.h"
#include "core/batch/batch_spec.h"

namespace lamina::app {

namespace {

struct BatchOptions {
  std::string spec;
  int threads = 0;
  std::string shard;
  std::string out;
  std::string plot;
  bool quiet = false;
  bool no_wall_time = false;
  std::vector<std::string> parts;  ///< merge
};

void Error(const std::string& message) {
  std::cerr << "lamina-headless batch: " << message << "\n";
}

// "runs 37/100  41.2 runs/s  ETA 1.5 s" rewritten in place on a terminal, at most every 0.1 s
// (the pool calls it serialised) and at the end
void PrintProgress(const core::BatchProgress& p) {
  static double last = -1.0;
  if (p.done != p.total && p.elapsed - last < 0.1) return;
  last = p.elapsed;
  std::fprintf(stderr, "\rruns %d/%d  %.1f runs/s  ETA %.1f s   ", p.done, p.total,
               p.runs_per_second, p.eta);
  if (p.done == p.total) std::fprintf(stderr, "\n");
  std::fflush(stderr);
}

// writes PREFIX.csv, PREFIX.jsonl, PREFIX.summary.json (and the plot), prints the summary;
// the exit code
int WriteResults(const core::BatchTable& table, const core::BatchMeta& meta,
                 const BatchOptions& options, const std::string& prefix) {
  core::OutputOptions output;
  output.wall_time = !options.no_wall_time && meta.wall_time;
  const core::BatchSummary summary = core::Summarize(table);
  std::string error;
  for (const auto& [suffix, text] :
       {std::pair<std::string, std::string>{".csv", core::CsvText(table, output)},
        {".jsonl", core::JsonLinesText(table, meta, output)},
        {".summary.json", core::SummaryJson(summary, meta)}}) {
    if (!core::WriteFileAtomic(prefix + suffix, text, &error)) {
      Error(error);
      return 1;
    }
  }
  if (!options.plot.empty()) {
    const auto values = core::ColumnValues(table, options.plot);
    if (!values) {
      Error("--plot " + options.plot + ": not a returned number (CSV column) of this batch");
      return 2;
    }
    if (!WriteHistogramPng(prefix + ".hist.png", *values, options.plot, &error)) {
      Error(error);
      return 1;
    }
  }
  std::cout << core::SummaryText(summary);
  int failed = 0;
  for (const core::RunResult& run : table.runs) {
    if (run.status != "error") continue;
    if (failed++ == 0) Error("run " + std::to_string(run.index) + ": " + run.error);
  }
  if (failed > 0) Error(std::to_string(failed) + " run(s) ended with status error");
  std::cerr << "wrote " << prefix << ".csv, " << prefix << ".jsonl, " << prefix << ".summary.json"
            << (options.plot.empty() ? "" : ", " + prefix + ".hist.png") << "\n";
  return failed > 0 ? 1 : 0;
}

// the shard from --shard, else from a Slurm array task, else the whole batch
std::optional<core::Shard> ChooseShard(const BatchOptions& options, bool* given) {
  std::string error;
  *given = true;
  if (!options.shard.empty()) {
    auto shard = core::ParseShard(options.shard, &error);
    if (!shard) Error("--shard: " + error);
    return shard;
  }
  if (auto shard = core::ShardFromSlurm(&error)) return shard;
  if (!error.empty()) {
    Error(error);
    return std::nullopt;
  }
  *given = false;
  return core::Shard{};
}

int RunBatch(const BatchOptions& options) {
  if (options.spec.empty()) {
    Error("give a spec file (lamina-headless batch SPEC.json) or 'merge PART...'");
    return 2;
  }
  std::string error;
  std::optional<core::BatchSpec> spec = core::LoadBatchSpec(options.spec, &error);
  if (!spec) {
    std::cerr << error << "\n";
    return 2;
  }
  if (!options.plot.empty()) {
    const std::vector<std::string> columns = core::FlatNames(spec->items);
    if (std::find(columns.begin(), columns.end(), options.plot) == columns.end()) {
      Error("--plot " + options.plot + ": not a returned number (CSV column) of " + options.spec);
      return 2;
    }
  }
  bool sharded = false;
  const std::optional<core::Shard> shard = ChooseShard(options, &sharded);
  if (!shard) return 2;
  std::string prefix =
      options.out.empty() ? std::filesystem::path(options.spec).stem().string() : options.out;
  core::BatchMeta meta = spec->Meta();
  if (sharded) {
    prefix += ".part-" + std::to_string(shard->k) + "-of-" + std::to_string(shard->n);
    meta.part = true;
    meta.shard = *shard;
  }
  core::PoolOptions pool;
  pool.threads = options.threads;
  if (!options.quiet && isatty(STDERR_FILENO)) pool.progress = PrintProgress;
  core::BatchTable table;
  table.sampled = spec->sampled;
  table.items = spec->items;
  table.runs = core::MonteCarloSim(spec->world, spec->plan, spec->samplers, spec->seed,
                                   core::ShardIndices(spec->runs, *shard), pool);
  return WriteResults(table, meta, options, prefix);
}

int RunMerge(const BatchOptions& options) {
  std::vector<std::pair<std::string, std::string>> parts;
  for (const std::string& path : options.parts) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
      Error("merge: cannot read " + path);
      return 2;
    }
    std::ostringstream text;
    text << in.rdbuf();
    parts.push_back({path, text.str()});
  }
  core::BatchMeta meta;
  std::string error;
  std::optional<core::BatchTable> table = core::MergeParts(parts, &meta, &error);
  if (!table) {
    Error("merge: " + error);
    return 2;
  }
  const std::string prefix =
      options.out.empty() ? std::filesystem::path(meta.spec).stem().string() : options.out;
  return WriteResults(*table, meta, options, prefix);
}

void AddOutputOptions(CLI::App* command, BatchOptions* options) {
  command->add_option("--out", options->out,
                      "output prefix: PREFIX.csv, PREFIX.jsonl, PREFIX.summary.json "
                      "(default: the spec file's name without .json, in the current folder)");
  command->add_option("--plot", options->plot,
                      "write PREFIX.hist.png, a histogram of this returned number (CSV column)");
  command->add_flag("--no-wall-time", options->no_wall_time,
                    "leave wall-clock times out: the files of a spec are then byte-identical "
                    "whatever the threads and shards");
}

}  // namespace

Subcommand AddBatchCommand(CLI::App& app) {
  auto options = std::make_shared<BatchOptions>();
  CLI::App* batch = app.add_subcommand(
      "batch", "Monte-Carlo batch of simulations from a JSON spec, on every core (docs/batch.md)");
  batch->add_option("spec", options->spec, "batch spec (.json)");
  batch->add_option("--threads", options->threads, "worker threads (default: every core)")
      ->check(CLI::PositiveNumber);
  batch->add_option("--shard", options->shard,
                    "K/N: run only the runs i with i % N == K (K/N:block: the K-th of N blocks); "
                    "default inside a Slurm array task: the task's");
  batch->add_flag("-q,--quiet", options->quiet, "no progress line");
  AddOutputOptions(batch, options.get());
  CLI::App* merge = batch->add_subcommand("merge", "join the parts of a sharded batch");
  merge->add_option("parts", options->parts, "PREFIX.part-K-of-N.jsonl files")->required();
  AddOutputOptions(merge, options.get());
  return {batch,
          [options, merge] { return merge->parsed() ? RunMerge(*options) : RunBatch(*options); }};
}

}  // namespace lamina::app
