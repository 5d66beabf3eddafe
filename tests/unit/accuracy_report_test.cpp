// SPDX-License-Identifier: MIT
// The accuracy report's pure pieces: the log–log slope fit, decade ticks, the SVG plot, solver
// labels, CSV quoting and the bar verdicts on hand-made runs.
#include "core/accuracy/accuracy_report.h"

#include <cmath>
#include <set>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/accuracy/accuracy_run.h"
#include "core/accuracy/probe_support.h"
#include "core/accuracy/scene_bars.h"
#include "core/accuracy/svg_plot.h"

namespace lamina::core {
namespace {

using ::testing::HasSubstr;

int Count(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(AccuracyReportTest, SlopeOfAPowerLawIsItsExponent) {
  const std::vector<double> x = {1e-5, 1e-4, 1e-3, 1e-2};
  std::vector<double> y;
  for (double v : x) y.push_back(3.0 * v * v);
  EXPECT_NEAR(LogLogSlope(x, y), 2.0, 1e-12);
}

TEST(AccuracyReportTest, SlopeLeavesOutZerosAndNeedsTwoPoints) {
  EXPECT_NEAR(LogLogSlope({1, 2, 4, 8}, {0.0, 2.0, 4.0, 8.0}), 1.0, 1e-12);
  EXPECT_TRUE(std::isnan(LogLogSlope({1, 2}, {0.0, 1.0})));
  EXPECT_TRUE(std::isnan(LogLogSlope({2, 2}, {1.0, 3.0})));
}

TEST(AccuracyReportTest, DecadesCoverTheRange) {
  EXPECT_EQ(DecadeTicks(2e-5, 3e-3), (std::vector<double>{1e-5, 1e-4, 1e-3, 1e-2}));
  EXPECT_EQ(DecadeTicks(1e-3, 1e-3).size(), 2u);
}

TEST(AccuracyReportTest, SvgDrawsEveryPlottablePointAndCountsTheRest) {
  LogLogPlot plot;
  plot.title = "t<1>";
  plot.series = {{"a", {1e-3, 1e-2, 1e-1}, {1.0, 0.0, 2.0}}, {"b", {1e-3}, {5.0}}};
  const std::string svg = LogLogSvg(plot);
  EXPECT_EQ(Count(svg, "<circle"), 3);
  EXPECT_EQ(Count(svg, "<polyline"), 2);
  EXPECT_THAT(svg, HasSubstr("a (1 at 0)"));
  EXPECT_THAT(svg, HasSubstr("t&lt;1&gt;"));
  EXPECT_THAT(svg, HasSubstr(">1e-3<"));
  EXPECT_EQ(svg.rfind("</svg>\n"), svg.size() - 7);
}

TEST(AccuracyReportTest, SolverLabelsRoundTrip) {
  for (const char* label : {"exact", "exact-fixed", "quick20", "quick100-fixed"}) {
    const auto solver = ParseAccuracySolver(label);
    ASSERT_TRUE(solver) << label;
    EXPECT_EQ(solver->Label(), label);
  }
  for (const char* bad : {"", "quick", "quick0", "quickx", "exact-", "fixed", "quick20-fixe"}) {
    EXPECT_FALSE(ParseAccuracySolver(bad)) << bad;
  }
}

TEST(AccuracyReportTest, PeerLabelsRoundTripAndNameNoLaminaSolver) {
  const auto mujoco = ParseAccuracySolver("mujoco");
  ASSERT_TRUE(mujoco);
  EXPECT_EQ(mujoco->peer, "mujoco");
  const auto bullet = ParseAccuracySolver("bullet10");
  ASSERT_TRUE(bullet);
  EXPECT_EQ(bullet->peer, "bullet");
  EXPECT_EQ(bullet->iterations, 10);
  EXPECT_EQ(bullet->Label(), "bullet10");
  EXPECT_FALSE(*bullet == *ParseAccuracySolver("bullet20"));
  for (const char* bad : {"bullet", "bullet0", "mujoco-fixed", "bullet10-fixed", "mujoco2"}) {
    EXPECT_FALSE(ParseAccuracySolver(bad)) << bad;
  }
  // Lamina's runner refuses a peer's label rather than running exact under its name
  const AccuracyRun run = RunAccuracySceneOn(*FindAccuracyScene("pendulum"), {}, *mujoco, 1e-3);
  EXPECT_THAT(run.failure, HasSubstr("tests/bench/peers"));
}

AccuracyRun MakeRun(const std::string& scene, double step, double error) {
  AccuracyRun run;
  run.scene = scene;
  run.step = step;
  run.result.error = error;
  run.status = "normal";
  return run;
}

TEST(AccuracyReportTest, BarsJudgeTheDefaultSolversRuns) {
  // ballistic_box's first bar: error <= ½·g·h·T·1.01 at 1 ms = 0.01485 m
  std::vector<AccuracyRun> runs = {MakeRun("ballistic_box", 1e-3, 0.0147),
                                   MakeRun("ballistic_box", 1e-4, 0.00147)};
  runs[0].result.metrics = {{"L drift", 1e-3}};
  const std::vector<BarVerdict> bars = JudgeAccuracyBars(runs);
  ASSERT_EQ(bars.size(), 3u);
  EXPECT_TRUE(bars[0].check.pass) << bars[0].check.measured;
  EXPECT_TRUE(bars[1].check.pass) << bars[1].check.measured;  // slope 1
  EXPECT_TRUE(bars[2].check.pass) << bars[2].check.measured;
  runs[0].result.error = 0.0150;
  EXPECT_FALSE(JudgeAccuracyBars(runs)[0].check.pass);
  runs[0].failure = "boom";
  EXPECT_EQ(JudgeAccuracyBars(runs)[0].check.measured, "failed: boom");
}

TEST(AccuracyReportTest, NoBlowUpFailsCorrectionsNonFiniteStatesAndJointsBrokenOpen) {
  AccuracyRun run = MakeRun("chain", 1e-2, 0.0);
  EXPECT_TRUE(Stable({&run}).pass);
  run.status = "joint open";  // the step guard's flag: a joint beyond JointBreakGap, uncorrected
  const BarCheck open = Stable({&run});
  EXPECT_FALSE(open.pass);
  EXPECT_EQ(open.measured, "0 corrections, 0 non-finite, joint open at 10 ms");
  run.status = "normal";
  run.corrections = 3;
  EXPECT_FALSE(Stable({&run}).pass);
  run.corrections = 0;
  run.nonfinite = 1;
  EXPECT_FALSE(Stable({&run}).pass);
}

TEST(AccuracyReportTest, CsvQuotesAndJsonHasNullForInfinity) {
  AccuracyRun run = MakeRun("bouncing_ball", 1e-3, 0.01);
  run.failure = "a, \"b\"";
  run.result.metrics = {{"creep m/s", std::numeric_limits<double>::infinity()}};
  const std::string csv = AccuracyCsv({run});
  EXPECT_THAT(csv, HasSubstr(",\"a, \"\"b\"\"\","));
  const nlohmann::json json = nlohmann::json::parse(AccuracyJson({run}, {}));
  EXPECT_TRUE(json["runs"][0]["metrics"]["creep m/s"].is_null());
  EXPECT_EQ(json["runs"][0]["solver"], "exact");
}

TEST(AccuracyReportTest, MarkdownLinksBothPlotsOfEachSceneRun) {
  const std::vector<AccuracyRun> runs = {MakeRun("bouncing_ball", 1e-3, 0.01)};
  const std::string md = AccuracyMarkdown(runs, JudgeAccuracyBars(runs), {"acc", "cmd", "m", "d"});
  EXPECT_THAT(md, HasSubstr("(acc/bouncing_ball-time.svg)"));
  EXPECT_THAT(md, HasSubstr("(acc/bouncing_ball-step.svg)"));
  EXPECT_EQ(Count(md, "### "), 1);
}

TEST(AccuracyReportTest, BarGridRunsEachScenesBarStepsOnly) {
  const AccuracyGrid grid = BarAccuracyGrid();
  EXPECT_TRUE(grid.bars_only);
  ASSERT_EQ(grid.solvers.size(), 1u);
  EXPECT_EQ(grid.solvers[0], DefaultAccuracySolver());
  EXPECT_EQ(grid.scenes.size(), AccuracyScenes().size());
}

// the pendulum's bars are judged with newton-joints as well: a sweep adds it to a grid that
// lacks it, unless the grid leaves the bars' solvers out (lamina-peers: no peer runs them)
TEST(AccuracyReportTest, ASweepAddsTheBarsSolversUnlessTheGridLeavesThemOut) {
  AccuracyGrid grid;
  grid.scenes = {FindAccuracyScene("pendulum")};
  ASSERT_NE(grid.scenes[0], nullptr);
  grid.solvers = {*ParseAccuracySolver("quick20")};
  grid.steps = {1e-3};
  const AccuracyRunner label_only = [](const AccuracyScene& scene, const std::string&,
                                       const AccuracySolver& solver, double step) {
    AccuracyRun run;
    run.scene = scene.name;
    run.solver = solver;
    run.step = step;
    return run;
  };
  const auto labels = [&] {
    std::set<std::string> out;
    for (const AccuracyRun& run : RunAccuracySweep(grid, "", 1, nullptr, label_only)) {
      out.insert(run.solver.Label());
    }
    return out;
  };
  EXPECT_EQ(labels().count("newton-joints"), 1u);
  grid.bar_solvers = false;
  EXPECT_EQ(labels(), std::set<std::string>{"quick20"});
}

}  // namespace
}  // namespace lamina::core

namespace lamina::core {
namespace {

AccuracyRun PeerRun() {
  AccuracyRun run;
  run.scene = "box_stack";
  run.solver = *ParseAccuracySolver("bullet10");
  run.step = 4e-3;
  run.result.error = std::numeric_limits<double>::infinity();
  run.result.metrics = {{"deepest overlap m", 1.25e-3}, {"top box moved m", 0.5}};
  run.result.note = "it fell";
  run.cpu_seconds = 0.125;
  run.real_time_factor = 40;
  run.steps = 1250;
  run.min_step = 4e-3;
  run.status = "normal";
  return run;
}

TEST(AccuracyReportTest, APlotLabelsItsErrorWithTheSceneUnitOrAsRelative) {
  std::vector<AccuracyRun> runs = {MakeRun("bouncing_ball", 1e-3, 0.01),
                                   MakeRun("slide_to_roll", 1e-3, 1e-8)};
  EXPECT_THAT(AccuracySceneSvg(*FindAccuracyScene("bouncing_ball"), runs, PlotAxis::kStep),
              HasSubstr(">error (m)<"));
  const std::string unitless =
      AccuracySceneSvg(*FindAccuracyScene("slide_to_roll"), runs, PlotAxis::kStep);
  EXPECT_THAT(unitless, HasSubstr(">relative error<"));
  EXPECT_THAT(unitless, ::testing::Not(HasSubstr("error ()")));
}

TEST(AccuracyReportTest, RunsReadBackFromTheirJson) {
  std::vector<AccuracyRun> runs = {MakeRun("pendulum", 1e-3, 0.5)};
  std::string error;
  ASSERT_TRUE(ReadAccuracyRunsJson(AccuracyJson({PeerRun()}, {}), "peers.json", &runs, &error))
      << error;
  ASSERT_EQ(runs.size(), 2u);
  const AccuracyRun& read = runs[1];
  const AccuracyRun written = PeerRun();
  EXPECT_EQ(read.scene, written.scene);
  EXPECT_EQ(read.solver, written.solver);
  EXPECT_EQ(read.step, written.step);
  EXPECT_TRUE(std::isnan(read.result.error));  // inf was written as null
  EXPECT_EQ(read.result.note, written.result.note);
  EXPECT_EQ(read.cpu_seconds, written.cpu_seconds);
  EXPECT_EQ(read.real_time_factor, written.real_time_factor);
  EXPECT_EQ(read.steps, written.steps);
  EXPECT_EQ(read.min_step, written.min_step);
  EXPECT_EQ(read.status, written.status);
  EXPECT_EQ(RunMetric(read, "deepest overlap m"), 1.25e-3);
  EXPECT_EQ(RunMetric(read, "top box moved m"), 0.5);
}

TEST(AccuracyReportTest, ABadRunsFileSaysWhereAndAddsNothing) {
  std::vector<AccuracyRun> runs;
  std::string error;
  EXPECT_FALSE(ReadAccuracyRunsJson("{\"runs\": [", "a.json", &runs, &error));
  EXPECT_EQ(error, "a.json: not JSON with a \"runs\" array");
  nlohmann::json json = nlohmann::json::parse(AccuracyJson({PeerRun(), PeerRun()}, {}));
  json["runs"][1]["solver"] = "havok";
  EXPECT_FALSE(ReadAccuracyRunsJson(json.dump(), "b.json", &runs, &error));
  EXPECT_EQ(error, "b.json: runs[1]: solver: 'havok' names no solver");
  json["runs"][1]["solver"] = "mujoco";
  json["runs"][0]["scene"] = "moon_landing";
  EXPECT_FALSE(ReadAccuracyRunsJson(json.dump(), "c.json", &runs, &error));
  EXPECT_EQ(error, "c.json: runs[0]: scene: no scene 'moon_landing'");
  json["runs"][0]["scene"] = "box_stack";
  json["runs"][0].erase("cpu_s");
  EXPECT_FALSE(ReadAccuracyRunsJson(json.dump(), "d.json", &runs, &error));
  EXPECT_THAT(error, HasSubstr("d.json: runs[0]: "));
  EXPECT_THAT(error, HasSubstr("cpu_s"));
  EXPECT_TRUE(runs.empty());
}

}  // namespace
}  // namespace lamina::core
