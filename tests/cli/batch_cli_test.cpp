// SPDX-License-Identifier: MIT
// `lamina-headless batch`: the result files with Klamp't's column names, bad specs, shards
// (given and from a Slurm array task), merge, and the histogram.
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/common/test_support.h"

namespace lamina {
namespace {

using test::CommandResult;
using test::RunHeadless;
using ::testing::HasSubstr;

std::string FirstLine(const std::string& text) {
  return text.substr(0, text.find('\n'));
}

// a small batch of the seed world (8 runs of 0.5 s) in the scratch folder
std::string WriteSpec(const std::string& name = "spin.json") {
  return test::WriteScratchFile(
      name, "{\"world\": \"" + test::WorldsPath("klampt/control/world1.xml") +
                "\", \"duration\": 0.5, \"N\": 8, \"seed\": 3, "
                "\"samplers\": {\"robots[0].config[0]\": {\"uniform\": [-1, 1]}}, "
                "\"setup\": [{\"kP\": [20], \"kI\": [8], \"kD\": [5], \"milestones\": [[0]]}], "
                "\"return\": [\"robots[0].actualConfig\", \"controllers[0].commandedConfig\"]}");
}

TEST(BatchCommandTest, WritesCsvJsonLinesAndSummary) {
  const std::string spec = WriteSpec();
  const std::string prefix = test::ScratchDir() + "/out";
  const CommandResult result = RunHeadless("batch " + spec + " --threads 2 --out " + prefix +
                                           " --plot 'robots[0].actualConfig[0]'");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_THAT(result.out, HasSubstr("runs: 8 (8 normal)"));
  EXPECT_THAT(result.out, HasSubstr("robots[0].actualConfig[0]"));
  EXPECT_EQ(result.err.find("runs/s"), std::string::npos);  // not a terminal: no progress
  const std::string csv = test::ReadFile(prefix + ".csv");
  EXPECT_EQ(FirstLine(csv),
            "index,robots[0].config[0],robots[0].actualConfig[0],"
            "controllers[0].commandedConfig[0],status,time,wall_clock_time");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 9);
  EXPECT_THAT(test::ReadFile(prefix + ".jsonl"), HasSubstr("\"lamina_batch\""));
  EXPECT_THAT(test::ReadFile(prefix + ".summary.json"), HasSubstr("\"q95\""));
  EXPECT_EQ(test::ReadFile(prefix + ".hist.png").substr(1, 3), "PNG");
}

TEST(BatchCommandTest, BadSpecExitsWithStatus2NamingTheKey) {
  const std::string spec = test::WriteScratchFile(
      "seed1.json", "{\"world\": \"" + test::WorldsPath("klampt/control/world1.xml") +
                        "\", \"duration\": 1, \"samplers\": {\"robots[0].config[0]\": "
                        "{\"uniform\": [-3.14]}}}");
  const CommandResult result = RunHeadless("batch " + spec);
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err, "seed1.json: samplers[\"robots[0].config[0]\"]: uniform needs [lo, hi]\n");
  const std::string world =
      test::WriteScratchFile("world.json", "{\"world\": \"nowhere.xml\", \"duration\": 1}");
  const CommandResult missing = RunHeadless("batch " + world);
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_THAT(missing.err, HasSubstr("world.json: world: cannot load"));
}

TEST(BatchCommandTest, TwoShardsMergeIntoTheSingleRun) {
  const std::string spec = WriteSpec();
  const std::string dir = test::ScratchDir();
  ASSERT_EQ(RunHeadless("batch " + spec + " --no-wall-time -q --out " + dir + "/whole").exit_code,
            0);
  for (int k = 0; k < 2; ++k) {
    const CommandResult part =
        RunHeadless("batch " + spec + " --no-wall-time --threads 1 --shard " + std::to_string(k) +
                    "/2 --out " + dir + "/s");
    ASSERT_EQ(part.exit_code, 0) << part.err;
  }
  const std::string part0 = dir + "/s.part-0-of-2.jsonl", part1 = dir + "/s.part-1-of-2.jsonl";
  const CommandResult merged =
      RunHeadless("batch merge " + part1 + " " + part0 + " --no-wall-time --out " + dir + "/m");
  ASSERT_EQ(merged.exit_code, 0) << merged.err;
  EXPECT_EQ(test::ReadFile(dir + "/m.csv"), test::ReadFile(dir + "/whole.csv"));
  EXPECT_EQ(test::ReadFile(dir + "/m.jsonl"), test::ReadFile(dir + "/whole.jsonl"));
  EXPECT_EQ(test::ReadFile(dir + "/m.summary.json"), test::ReadFile(dir + "/whole.summary.json"));

  const CommandResult missing = RunHeadless("batch merge " + part1 + " --out " + dir + "/x");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_EQ(missing.err, "lamina-headless batch: merge: missing shard 0 of 2 (runs 0, 2, 4, 6)\n");
}

TEST(BatchCommandTest, ASlurmArrayTaskRunsItsShard) {
  const std::string spec = WriteSpec();
  const std::string dir = test::ScratchDir();
  // an array 4-5: task 5 is shard 1 of 2
  setenv("SLURM_ARRAY_TASK_ID", "5", 1);
  setenv("SLURM_ARRAY_TASK_MIN", "4", 1);
  setenv("SLURM_ARRAY_TASK_COUNT", "2", 1);
  const CommandResult result = RunHeadless("batch " + spec + " -q --out " + dir + "/t");
  unsetenv("SLURM_ARRAY_TASK_ID");
  unsetenv("SLURM_ARRAY_TASK_MIN");
  unsetenv("SLURM_ARRAY_TASK_COUNT");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const std::string csv = test::ReadFile(dir + "/t.part-1-of-2.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 5);  // runs 1, 3, 5, 7
  EXPECT_THAT(csv, HasSubstr("\n7,"));
}

}  // namespace
}  // namespace lamina
