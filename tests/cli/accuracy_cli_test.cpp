// SPDX-License-Identifier: MIT
// `lamina-headless accuracy`: a small sweep writes runs.csv, runs.json, two SVG plots per scene
// and the Markdown page linking them; bad scene and solver names are refused with a message
// naming them.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/common/test_support.h"

namespace lamina {
namespace {

using test::CommandResult;
using test::RunHeadless;
using ::testing::HasSubstr;

TEST(AccuracyCliTest, SmallSweepWritesEveryOutput) {
  const std::string out = test::ScratchDir() + "/accuracy_cli";
  std::filesystem::remove_all(out);
  const CommandResult result = RunHeadless(
      "accuracy --scenes bouncing_ball --steps 1e-3,4e-3 --solvers exact,quick20-fixed -q "
      "--threads 2 --out " +
      out + " --markdown " + out + "/page.md");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_THAT(result.out, HasSubstr("bouncing_ball: rebound height within 1 % of e²H at 1 ms"));
  const nlohmann::json json = nlohmann::json::parse(test::ReadFile(out + "/runs.json"));
  ASSERT_EQ(json["runs"].size(), 4u);
  for (const nlohmann::json& run : json["runs"]) {
    EXPECT_EQ(run["failure"], "");
    EXPECT_GT(run["steps"].get<long>(), 0);
    EXPECT_GT(run["cpu_s"].get<double>(), 0.0);
  }
  EXPECT_EQ(json["runs"][2]["solver"], "quick20-fixed");
  const std::string csv = test::ReadFile(out + "/runs.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 5);
  EXPECT_THAT(test::ReadFile(out + "/bouncing_ball-time.svg"), HasSubstr("exact (slope"));
  EXPECT_THAT(test::ReadFile(out + "/page.md"), HasSubstr("](./bouncing_ball-step.svg)"));
}

TEST(AccuracyCliTest, UnknownSceneAndSolverAreNamed) {
  const CommandResult scene = RunHeadless("accuracy --scenes nope -q --out /tmp");
  EXPECT_EQ(scene.exit_code, 2);
  EXPECT_THAT(scene.err, HasSubstr("no scene 'nope'"));
  EXPECT_THAT(scene.err, HasSubstr("ballistic_box"));
  const CommandResult solver = RunHeadless("accuracy --solvers quick -q --out /tmp");
  EXPECT_EQ(solver.exit_code, 2);
  EXPECT_THAT(solver.err, HasSubstr("'quick'"));
}

}  // namespace
}  // namespace lamina
