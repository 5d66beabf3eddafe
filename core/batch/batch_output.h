// SPDX-License-Identifier: MIT
// The results of a batch as files: CSV (one row per run), JSON Lines (a header line, then one
// object per run with its trace), and a summary of every returned number (text and JSON);
// partial results of shards and merging them into exactly the single-machine result.
//
// CSV columns, as Klamp't's saveStatesCSV names them: `index`, the sampled values, the returned
// items, `status`, `time`, `wall_clock_time` (s). A value with several numbers is flattened
// into `name[0]`, `name[1]`, ...; one number (a scalar item, a component `[k]`, a one-number
// argument) keeps its name. Numbers are written with the shortest text that reads back exactly.
// A run that failed (status `error`) has empty item cells; its message is in the JSON Lines.
//
// Determinism: everything but `wall_clock_time` (and `build_wall_time` in JSON Lines) depends
// only on the spec; OutputOptions::wall_time = false leaves those out, so that files of the
// same spec are byte-identical whatever the threads or shards.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/batch/batch_sim.h"

namespace lamina::core {

/// A named value of every run: its name and how many numbers it has.
struct ColumnGroup {
  std::string name;
  int size = 1;
  bool scalar = true;  ///< one number that keeps its name (no `[0]`)
};

/// Identity of a batch (or of a part of one) carried in the JSON Lines header.
struct BatchMeta {
  std::string spec;       ///< the spec file's name
  std::string spec_hash;  ///< hash of the spec and the world it names (16 hex digits)
  int runs = 0;           ///< N of the whole batch
  std::uint64_t seed = 0;
  bool part = false;  ///< a shard's result
  Shard shard;        ///< part: which
  /// The runs carry their wall times (the file was written without --no-wall-time). A merge
  /// of parts without them writes none either, instead of zeros.
  bool wall_time = true;
};

/// Results with the names of their columns; runs in index order.
struct BatchTable {
  std::vector<ColumnGroup> sampled;
  std::vector<ColumnGroup> items;
  std::vector<RunResult> runs;
};

struct OutputOptions {
  bool wall_time = true;  ///< write wall_clock_time (CSV) and the wall times (JSON Lines)
};

/// The CSV header names of `groups`, flattened.
std::vector<std::string> FlatNames(const std::vector<ColumnGroup>& groups);
std::string CsvText(const BatchTable& table, const OutputOptions& options = {});
/// First line {"lamina_batch": {meta, columns}}, then one JSON object per run.
std::string JsonLinesText(const BatchTable& table, const BatchMeta& meta,
                          const OutputOptions& options = {});
/// Reads JsonLinesText back exactly; nullopt with `error` ("<name>:<line>: ...").
std::optional<BatchTable> ReadJsonLines(const std::string& text, const std::string& name,
                                        BatchMeta* meta, std::string* error);

/// Statistics of one returned number over the runs that have it (not `error`, finite).
struct ColumnSummary {
  std::string name;
  int count = 0;
  double mean = 0, std = 0, min = 0, max = 0;  ///< std: sample standard deviation (n - 1)
  double q[5] = {0, 0, 0, 0, 0};  ///< quantiles 5, 25, 50, 75, 95 % (linear interpolation)
};
struct BatchSummary {
  int runs = 0;
  std::vector<std::pair<std::string, int>> statuses;  ///< status -> runs, first seen first
  std::vector<ColumnSummary> columns;
};
BatchSummary Summarize(const BatchTable& table);
std::string SummaryText(const BatchSummary& summary);
std::string SummaryJson(const BatchSummary& summary, const BatchMeta& meta);
/// Linear-interpolation quantile (numpy's default) of sorted values; p in [0, 1].
double Quantile(const std::vector<double>& sorted, double p);

/// The values of one flattened column (by CSV name) for the runs that have it.
std::optional<std::vector<double>> ColumnValues(const BatchTable& table, const std::string& name);

/// Joins shard parts (JSON Lines texts with their file names) into the whole batch: every part
/// of the same spec (hash), of the same N and shard count, all with or all without wall times,
/// each shard once, every run once.
/// nullopt with `error` naming the part and what is wrong ("missing shard 2 of 3 (runs 2, 5,
/// 8, ...)").
std::optional<BatchTable> MergeParts(const std::vector<std::pair<std::string, std::string>>& parts,
                                     BatchMeta* meta, std::string* error);

/// Writes `text` to `path` through a temporary file in the same folder and a rename, so that a
/// reader never sees half a file; false with `error` naming the path.
bool WriteFileAtomic(const std::string& path, const std::string& text, std::string* error);

}  // namespace lamina::core
