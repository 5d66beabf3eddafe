// SPDX-License-Identifier: MIT
// `lamina-headless accuracy`: a small sweep writes runs.csv, runs.json, two SVG plots per scene
// and the Markdown page linking them; bad scene and solver names are refused with a message
// naming them; other engines' runs (--peers) join the plots and tables.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <tuple>

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
  const std::string page = test::ReadFile(out + "/page.md");
  EXPECT_THAT(page, HasSubstr("](./bouncing_ball-step.svg)"));
  // the runs shared the machine two at a time, and the page says so
  EXPECT_THAT(page, HasSubstr(", 2 runs at a time, by `make accuracy`"));
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

// A runs.json as lamina-peers writes it: bullet10 on bouncing_ball at 1 and 4 ms, and on
// box_stack, which the sweep below does not run.
std::string PeerRunsFile() {
  nlohmann::json runs = nlohmann::json::array();
  for (const auto& [scene, step, error] :
       {std::tuple{"bouncing_ball", 1e-3, 0.17}, std::tuple{"bouncing_ball", 4e-3, 0.05},
        std::tuple{"box_stack", 1e-3, 4e-4}}) {
    runs.push_back({{"scene", scene},
                    {"solver", "bullet10"},
                    {"step", step},
                    {"error", error},
                    {"cpu_s", 0.001},
                    {"real_time_factor", 800},
                    {"steps", 800},
                    {"rollbacks", 0},
                    {"min_step", step},
                    {"corrections", 0},
                    {"nonfinite", 0},
                    {"unreliable", 0},
                    {"status", "normal"},
                    {"failure", ""},
                    {"note", ""},
                    {"metrics", {{"rebound m", 0.42}}}});
  }
  return test::WriteScratchFile("peers/runs.json", nlohmann::json{{"runs", runs}}.dump());
}

TEST(AccuracyCliTest, PeerRunsArePlottedDashedBesideLaminasAndNeverJudged) {
  const std::string out = test::ScratchDir() + "/accuracy_peers";
  const CommandResult result =
      RunHeadless("accuracy --scenes bouncing_ball --steps 1e-3,4e-3 --solvers exact -q --out " +
                  out + " --markdown " + out + "/page.md --peers " + PeerRunsFile());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json json = nlohmann::json::parse(test::ReadFile(out + "/runs.json"));
  ASSERT_EQ(json["runs"].size(), 4u);  // box_stack's peer run is left out with its scene
  EXPECT_EQ(json["runs"][3]["solver"], "bullet10");
  EXPECT_EQ(json["bars"].size(), 1u);  // bouncing_ball's one bar, on the exact runs
  const std::string svg = test::ReadFile(out + "/bouncing_ball-time.svg");
  EXPECT_THAT(svg, HasSubstr("bullet10 (slope"));
  EXPECT_THAT(svg, HasSubstr("stroke-dasharray"));
  EXPECT_THAT(test::ReadFile(out + "/page.md"), HasSubstr("| bullet10 |"));
  EXPECT_THAT(test::ReadFile(out + "/page.md"), HasSubstr("**Peers** (dashed)"));
}

TEST(AccuracyCliTest, ABadPeersFileAndAPeerAsALaminaSolverAreRefused) {
  const std::string bad = test::WriteScratchFile("bad_peers.json", "{\"runs\": 3}");
  const CommandResult file = RunHeadless("accuracy --scenes bouncing_ball --steps 1e-3 -q --out " +
                                         test::ScratchDir() + " --peers " + bad);
  EXPECT_EQ(file.exit_code, 1);
  EXPECT_THAT(file.err, HasSubstr("--peers: " + bad + ": not JSON with a \"runs\" array"));
  const CommandResult solver = RunHeadless("accuracy --solvers mujoco -q --out /tmp");
  EXPECT_EQ(solver.exit_code, 2);
  EXPECT_THAT(solver.err, HasSubstr("MuJoCo and Bullet runs come from --peers"));
}

}  // namespace
}  // namespace lamina
