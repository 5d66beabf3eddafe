// SPDX-License-Identifier: MIT
// Batch simulation on the seed world (control/world1.xml): determinism over threads and shards,
// merging, runs that fail, stop conditions, result files. The seed example itself (100 runs of
// 5 s) is tests/physics/batch_seed_example_test.cpp.
#include "core/batch/batch_sim.h"

#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/batch/batch_output.h"
#include "core/batch/batch_spec.h"
#include "tests/batch/batch_test_support.h"

namespace lamina {
namespace {

using core::BatchSpec;
using core::BatchTable;
using core::RunResult;
using test::AllRuns;
using test::LoadSpec;
using test::RunBatch;
using test::ScratchSpec;
using ::testing::HasSubstr;

// ---- determinism, shards and merge ---------------------------------------------------------

constexpr const char* kSmallBatch =
    "\"duration\": 1, \"N\": 12, \"seed\": 5, "
    "\"samplers\": {\"robots[0].config[0]\": {\"uniform\": [-3, 3]}, "
    "               \"robots[0].drivers[0].kP\": {\"normal\": [20, 2]}}, "
    "\"args\": {\"target\": {\"choice\": [[-0.25], [0.25]]}}, "
    "\"setup\": [{\"kI\": [8], \"kD\": [5], \"milestones\": [\"args.target\"]}], "
    "\"return\": [\"robots[0].actualConfig\", \"controllers[0].commandedConfig[0]\"], "
    "\"trace\": {\"rate\": 0.25}";

// the small batch's spec (a failure fails the test)
BatchSpec SmallSpec() {
  std::string error;
  const auto spec = ScratchSpec("small.json", kSmallBatch, &error);
  EXPECT_TRUE(spec) << error;
  return spec ? *spec : BatchSpec{};
}

// files without wall times: byte-identical for one spec
core::OutputOptions NoWallTime() {
  core::OutputOptions options;
  options.wall_time = false;
  return options;
}

TEST(BatchDeterminismTest, SameCsvWithOneAndTwoThreads) {
  const BatchSpec spec = SmallSpec();
  const core::OutputOptions no_wall = NoWallTime();
  const BatchTable one = RunBatch(spec, AllRuns(spec), 1);
  const BatchTable two = RunBatch(spec, AllRuns(spec), 2);
  for (const RunResult& run : one.runs) EXPECT_EQ(run.status, "normal") << run.error;
  EXPECT_EQ(core::CsvText(one, no_wall), core::CsvText(two, no_wall));
  EXPECT_EQ(core::JsonLinesText(one, spec.Meta(), no_wall),
            core::JsonLinesText(two, spec.Meta(), no_wall));
  // the trace: t = 0, 0.25, 0.5, 0.75, 1
  ASSERT_EQ(one.runs[0].trace_time.size(), 5u);
  EXPECT_NEAR(one.runs[0].trace_time[4], 1.0, 1e-9);
}

// QuickStep draws from ODE's one process-wide random generator, which the simulator seeds before
// every quick step: the seed and the step must not interleave with another thread's
TEST(BatchDeterminismTest, QuickStepWorldsToo) {
  const std::string text =
      "{\"world\": \"" + test::DataPath("worlds/sliding_block.xml") +
      "\", \"duration\": 0.3, \"N\": 6, \"set\": {\"settings.solver\": \"quick\"}, "
      "\"samplers\": {\"objects[0].velocity[3]\": {\"uniform\": [0.5, 1.5]}}, "
      "\"return\": [\"objects[0].transform\", \"objects[0].velocity\"]}";
  std::string error;
  const auto spec = core::ParseBatchSpec(text, test::ScratchDir() + "/quick.json", &error);
  ASSERT_TRUE(spec) << error;
  const core::OutputOptions no_wall = NoWallTime();
  const std::string one = core::CsvText(RunBatch(*spec, AllRuns(*spec), 1), no_wall);
  EXPECT_EQ(one, core::CsvText(RunBatch(*spec, AllRuns(*spec), 2), no_wall));
  EXPECT_EQ(one, core::CsvText(RunBatch(*spec, AllRuns(*spec), 2), no_wall));
}

std::vector<std::pair<std::string, std::string>> Parts(const BatchSpec& spec, int n,
                                                       bool contiguous, bool wall_time = true) {
  std::vector<std::pair<std::string, std::string>> parts;
  core::OutputOptions output;
  output.wall_time = wall_time;
  for (int k = n - 1; k >= 0; --k) {  // any order
    const core::Shard shard{k, n, contiguous};
    core::BatchMeta meta = spec.Meta();
    meta.part = true;
    meta.shard = shard;
    parts.push_back({"part-" + std::to_string(k),
                     core::JsonLinesText(RunBatch(spec, core::ShardIndices(spec.runs, shard), 1),
                                         meta, output)});
  }
  return parts;
}

TEST(BatchShardTest, ThreeMergedShardsAreTheSingleMachineResult) {
  std::string error;
  const BatchSpec spec = SmallSpec();
  const core::OutputOptions no_wall = NoWallTime();
  const BatchTable whole = RunBatch(spec, AllRuns(spec), 2);
  for (bool contiguous : {false, true}) {
    core::BatchMeta meta;
    const auto merged = core::MergeParts(Parts(spec, 3, contiguous), &meta, &error);
    ASSERT_TRUE(merged) << error;
    EXPECT_EQ(core::CsvText(*merged, no_wall), core::CsvText(whole, no_wall));
    EXPECT_EQ(core::JsonLinesText(*merged, meta, no_wall),
              core::JsonLinesText(whole, spec.Meta(), no_wall));
  }
  EXPECT_EQ(core::ShardIndices(10, {1, 3, false}), (std::vector<int>{1, 4, 7}));
  EXPECT_EQ(core::ShardIndices(10, {1, 3, true}), (std::vector<int>{3, 4, 5}));
}

// parts written with --no-wall-time merge into a result without wall times (not zeros), and
// parts with and without them are not merged
TEST(BatchShardTest, PartsWithoutWallTimesMergeWithoutThem) {
  std::string error;
  const BatchSpec spec = SmallSpec();
  core::BatchMeta meta;
  ASSERT_TRUE(core::MergeParts(Parts(spec, 2, false, false), &meta, &error)) << error;
  EXPECT_FALSE(meta.wall_time);
  ASSERT_TRUE(core::MergeParts(Parts(spec, 2, false, true), &meta, &error)) << error;
  EXPECT_TRUE(meta.wall_time);

  auto mixed = Parts(spec, 2, false, false);  // parts of shards 1, 0
  mixed[1] = Parts(spec, 2, false, true)[1];
  EXPECT_FALSE(core::MergeParts(mixed, &meta, &error));
  EXPECT_EQ(error,
            "part-0: has wall times, part-1 has none (write every part with or every part "
            "without --no-wall-time)");
}

TEST(BatchShardTest, MergeRefusesMissingDuplicateAndForeignParts) {
  std::string error;
  std::string body = kSmallBatch;
  const auto spec = ScratchSpec("small.json", body, &error);
  ASSERT_TRUE(spec) << error;
  auto parts = Parts(*spec, 3, false);  // parts of shards 2, 1, 0
  core::BatchMeta meta;

  auto missing = parts;
  missing.erase(missing.begin() + 1);
  EXPECT_FALSE(core::MergeParts(missing, &meta, &error));
  EXPECT_EQ(error, "missing shard 1 of 3 (runs 1, 4, 7, 10)");

  auto twice = parts;
  twice.push_back(parts[0]);
  EXPECT_FALSE(core::MergeParts(twice, &meta, &error));
  EXPECT_EQ(error, "part-2: shard 2 of 3 given twice (also part-2)");

  body.replace(body.find("\"seed\": 5"), 9, "\"seed\": 6");
  const auto other = ScratchSpec("small.json", body, &error);
  ASSERT_TRUE(other) << error;
  auto foreign = parts;
  foreign[1] = Parts(*other, 3, false)[1];
  foreign[1].first = "other-part-1";
  EXPECT_FALSE(core::MergeParts(foreign, &meta, &error));
  EXPECT_THAT(error, HasSubstr("other-part-1: from another batch than part-2"));

  auto truncated = parts;
  truncated[0].second.resize(truncated[0].second.rfind('\n', truncated[0].second.size() - 2) + 1);
  EXPECT_FALSE(core::MergeParts(truncated, &meta, &error));
  EXPECT_EQ(error, "part-2: holds 3 runs, shard 2 of 3 has 4 (a truncated or edited part?)");
}

// ---- failures --------------------------------------------------------------------------------

TEST(BatchErrorTest, AHookThatThrowsFailsItsRunOnly) {
  std::string error;
  const auto spec = ScratchSpec("hook.json", "\"duration\": 0.5, \"N\": 6", &error);
  ASSERT_TRUE(spec) << error;
  core::RunPlan plan = spec->plan;
  plan.hooks.step = [](core::RunContext& context) {
    if (context.index == 3 && context.simulator.time() >= 0.2) {
      throw std::runtime_error("hook gave up at 0.2 s");
    }
  };
  int terms = 0;
  plan.hooks.term = [&terms](core::RunContext& context) {
    if (context.index == 0) ++terms;  // only run 0 counts: no data race
    return false;
  };
  const auto results =
      core::MonteCarloSim(spec->world, plan, spec->samplers, spec->seed, AllRuns(*spec), {2, {}});
  ASSERT_EQ(results.size(), 6u);
  for (const RunResult& run : results) {
    if (run.index == 3) {
      EXPECT_EQ(run.status, "error");
      EXPECT_EQ(run.error, "hook gave up at 0.2 s");
      EXPECT_TRUE(run.items.empty());
    } else {
      EXPECT_EQ(run.status, "normal") << run.error;
      EXPECT_DOUBLE_EQ(run.time, 0.5);
      EXPECT_EQ(run.items.size(), spec->items.size());
    }
  }
  EXPECT_EQ(terms, 50);  // checked before each of the 50 outer steps
}

TEST(BatchErrorTest, ASetUpValueTheTableRefusesIsRejectedAtSpecTime) {
  std::string error;
  EXPECT_FALSE(ScratchSpec("gains.json",
                           "\"duration\": 1, \"samplers\": {\"robots[0].drivers[0].kP\": "
                           "{\"uniform\": [-1, 5]}}",
                           &error));
  EXPECT_EQ(error,
            "gains.json: samplers[\"robots[0].drivers[0].kP\"]: robots[0].drivers[0].kP must be "
            ">= 0, got -1");
  EXPECT_FALSE(ScratchSpec("uniform.json",
                           "\"duration\": 1, \"samplers\": {\"robots[0].config[0]\": "
                           "{\"uniform\": [1]}}",
                           &error));
  EXPECT_EQ(error, "uniform.json: samplers[\"robots[0].config[0]\"]: uniform needs [lo, hi]");
  EXPECT_FALSE(
      ScratchSpec("path.json", "\"duration\": 1, \"return\": [\"robots[0].actualConfg\"]", &error));
  EXPECT_THAT(error, HasSubstr("path.json: return[0]: robots[0].actualConfg: robots have no "
                               "'actualConfg' (did you mean 'actualConfig'?)"));
  EXPECT_FALSE(ScratchSpec("key.json", "\"duration\": 1, \"sampler\": {}", &error));
  EXPECT_EQ(error, "key.json: \"sampler\": unknown key (did you mean 'samplers'?)");
  EXPECT_FALSE(
      ScratchSpec("arg.json", "\"duration\": 1, \"setup\": [{\"pid\": \"args.goal\"}]", &error));
  EXPECT_EQ(error, "arg.json: setup[0][\"pid\"]: args.goal: no such argument in \"args\"");
}

// a sampled value the table refuses in one run only (a normal's tail) fails that run
TEST(BatchErrorTest, ARefusedSampledValueFailsItsRun) {
  std::string error;
  const auto spec =
      ScratchSpec("normal.json",
                  "\"duration\": 0.1, \"N\": 40, \"samplers\": {\"robots[0].drivers[0].kP\": "
                  "{\"normal\": [1, 1]}}",
                  &error);
  ASSERT_TRUE(spec) << error;
  const BatchTable table = RunBatch(*spec, AllRuns(*spec), 2);
  int failed = 0;
  for (const RunResult& run : table.runs) {
    if (run.sampled[0][0] < 0) {
      ++failed;
      EXPECT_EQ(run.status, "error");
      EXPECT_THAT(run.error, HasSubstr("robots[0].drivers[0].kP must be >= 0, got -"));
    } else {
      EXPECT_EQ(run.status, "normal") << run.error;
    }
  }
  EXPECT_GT(failed, 0);  // P(kP < 0) = 16 %: several of 40 (the draws are fixed by the seed)
}

TEST(BatchTerminationTest, ABoundStopsTheRunBeforeItsDuration) {
  std::string error;
  const auto spec =
      ScratchSpec("bound.json",
                  "\"duration\": 5, \"set\": {\"robots[0].config\": \"1.5\"}, "
                  "\"setup\": [{\"kP\": [20], \"kI\": [8], \"kD\": [5], \"milestones\": [[0]]}], "
                  "\"terminate\": [{\"path\": \"robots[0].actualConfig[0]\", \"below\": 1}], "
                  "\"return\": [\"robots[0].actualConfig[0]\"]",
                  &error);
  ASSERT_TRUE(spec) << error;
  const RunResult run = core::DoSim(spec->world, spec->plan, {});
  EXPECT_EQ(run.status, "normal");
  EXPECT_EQ(run.stop, "robots[0].actualConfig[0] below 1");
  // from rest at 1.5 with 1 rad/s² the ramp reaches 1 rad after about sqrt(2 * 0.5) = 1 s
  EXPECT_GT(run.time, 0.9);
  EXPECT_LT(run.time, 1.3);
  EXPECT_LT(run.items[0][0], 1.0);
  EXPECT_GT(run.items[0][0], 0.98);  // within one outer step of the bound
}

// Klamp't's batchSim: a list of initial conditions, result i for condition i
TEST(BatchSimTest, ResultIBelongsToInitialConditionI) {
  std::string error;
  const auto spec = ScratchSpec(
      "list.json", "\"duration\": 0.02, \"return\": [\"robots[0].actualConfig[0]\"]", &error);
  ASSERT_TRUE(spec) << error;
  std::vector<core::InitialCondition> initial;
  for (double q : {0.25, 1.0, 2.0, 3.0, 5.0}) {  // within the limits [0, 6.28319]
    initial.push_back({{{"robots[0].config[0]", {q}}}, {}});
  }
  initial.push_back({{{"robots[0].drivers[0].kD", {-1}}}, {}});  // refused in its run
  const auto results = core::BatchSim(spec->world, spec->plan, initial, {2, {}});
  ASSERT_EQ(results.size(), 6u);
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(results[i].index, i);
    EXPECT_EQ(results[i].status, "normal") << results[i].error;
    // 20 ms from rest, held by the default PID at its start: gravity's torque (at most 4.9 N·m
    // on about 1/3 kg·m²) moves the link by less than 14.7 rad/s² * (0.02 s)^2 / 2 = 3 mrad
    EXPECT_NEAR(results[i].items[0][0], initial[i].values[0].value[0], 4e-3);
  }
  EXPECT_EQ(results[5].status, "error");
  EXPECT_EQ(results[5].error, "robots[0].drivers[0].kD must be >= 0, got -1");
}

TEST(BatchShardTest, SlurmArrayVariablesGiveTheShard) {
  std::string error;
  unsetenv("SLURM_ARRAY_TASK_ID");
  EXPECT_FALSE(core::ShardFromSlurm(&error));
  EXPECT_EQ(error, "");
  setenv("SLURM_ARRAY_TASK_ID", "7", 1);
  setenv("SLURM_ARRAY_TASK_MIN", "5", 1);
  setenv("SLURM_ARRAY_TASK_COUNT", "4", 1);
  const auto shard = core::ShardFromSlurm(&error);
  ASSERT_TRUE(shard) << error;
  EXPECT_EQ(shard->k, 2);
  EXPECT_EQ(shard->n, 4);
  setenv("SLURM_ARRAY_TASK_ID", "9", 1);  // 5..8 has no task 9 (a stepped array)
  EXPECT_FALSE(core::ShardFromSlurm(&error));
  EXPECT_THAT(error, HasSubstr("SLURM_ARRAY_TASK_ID=9, SLURM_ARRAY_TASK_MIN=5, "
                               "SLURM_ARRAY_TASK_COUNT=4 do not make a shard"));
  unsetenv("SLURM_ARRAY_TASK_ID");
  unsetenv("SLURM_ARRAY_TASK_MIN");
  unsetenv("SLURM_ARRAY_TASK_COUNT");
  EXPECT_FALSE(core::ParseShard("3/3", &error));
  EXPECT_EQ(error, "shard '3/3' must be K/N with 0 <= K < N (optionally K/N:block)");
  const auto block = core::ParseShard("1/3:block", &error);
  ASSERT_TRUE(block);
  EXPECT_TRUE(block->contiguous);
}

TEST(BatchTerminationTest, ATimeLimitStopsAtThatTime) {
  std::string error;
  const auto spec = ScratchSpec("time.json",
                                "\"duration\": 5, \"terminate\": [{\"time\": 1.5}], "
                                "\"return\": [\"robots[0].actualConfig[0]\"]",
                                &error);
  ASSERT_TRUE(spec) << error;
  const RunResult run = core::DoSim(spec->world, spec->plan, {});
  EXPECT_EQ(run.stop, "time");
  EXPECT_NEAR(run.time, 1.5, 1e-9);
}

TEST(BatchOutputTest, CsvHeadersAreKlamptsFlattenedNames) {
  std::string error;
  const auto spec = ScratchSpec("csv.json",
                                "\"duration\": 0.05, \"N\": 2, \"args\": {\"gain\": [1, 2]}, "
                                "\"samplers\": {\"robots[0].config[0]\": [0.5]}",
                                &error);
  ASSERT_TRUE(spec) << error;
  const std::string csv = core::CsvText(RunBatch(*spec, AllRuns(*spec), 1));
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "index,robots[0].config[0],args.gain[0],args.gain[1],"
            "controllers[0].commandedConfig[0],controllers[0].commandedVelocity[0],"
            "controllers[0].sensedConfig[0],controllers[0].sensedVelocity[0],"
            "robots[0].actualConfig[0],robots[0].actualVelocity[0],robots[0].actualTorques[0],"
            "status,time,wall_clock_time");
}

TEST(BatchOutputTest, SummaryQuantilesInterpolateLinearly) {
  const std::vector<double> sorted = {1, 2, 3, 4, 5};
  EXPECT_DOUBLE_EQ(core::Quantile(sorted, 0.5), 3);
  EXPECT_DOUBLE_EQ(core::Quantile(sorted, 0.05), 1.2);
  EXPECT_DOUBLE_EQ(core::Quantile(sorted, 0.95), 4.8);
}

}  // namespace
}  // namespace lamina
