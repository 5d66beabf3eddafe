// SPDX-License-Identifier: MIT
// Klamp't motion files: `.config`, `.path`, `.milestones` and MultiPath `.xml`, their writers,
// and the located errors for malformed input.
#include "core/io/trajectory_file.h"

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/io/paths.h"
#include "tests/common/test_support.h"

namespace lamina::core {
namespace {

using ::lamina::test::DataPath;
using ::lamina::test::WorldsPath;
using ::lamina::test::WriteScratchFile;
using ::testing::ElementsAre;

std::vector<std::string> Errors(const Diagnostics& diagnostics) {
  return diagnostics.Messages(Severity::kError);
}

VecX Vector(std::initializer_list<double> values) {
  VecX vector(static_cast<int>(values.size()));
  int i = 0;
  for (const double value : values) vector[i++] = value;
  return vector;
}

// Doubles that are hard to print exactly: random bit patterns over many magnitudes.
VecX AwkwardValues(int count, unsigned seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-300, 300);
  VecX values(count);
  for (int i = 0; i < count; ++i) values[i] = std::ldexp(mantissa(random), exponent(random));
  values[0] = 0.1;
  values[count - 1] = -1.0 / 3.0;
  return values;
}

// [section] the example motions

TEST(TrajectoryFileTest, AthleteStartConfig) {
  Diagnostics diagnostics;
  const auto config =
      ReadConfigFile(WorldsPath("klampt/motions/athlete_start.config"), diagnostics);
  ASSERT_TRUE(config) << diagnostics.FormatAll();
  ASSERT_EQ(config->size(), 42);
  // the values are read exactly as the decimal text
  EXPECT_EQ((*config)[2], 0.0286315);
  EXPECT_EQ((*config)[7], 0.523599);
  EXPECT_EQ((*config)[41], 0.0);
}

TEST(TrajectoryFileTest, AthleteFlexPath) {
  Diagnostics diagnostics;
  const auto path = ReadMotionFile(WorldsPath("klampt/motions/athlete_flex.path"), diagnostics);
  ASSERT_TRUE(path) << diagnostics.FormatAll();
  EXPECT_EQ(diagnostics.entries().size(), 0u);
  EXPECT_EQ(path->times, (std::vector<double>{0, 1, 2}));
  ASSERT_EQ(path->configs.size(), 3u);
  for (const VecX& config : path->configs) EXPECT_EQ(config.size(), 42);
  EXPECT_EQ(path->configs[1][2], -0.389427);
  EXPECT_TRUE(path->velocities.empty());
}

TEST(TrajectoryFileTest, AthleteFlexMilestones) {
  Diagnostics diagnostics;
  const auto milestones =
      ReadMotionFile(WorldsPath("klampt/motions/athlete_flex.milestones"), diagnostics);
  ASSERT_TRUE(milestones) << diagnostics.FormatAll();
  EXPECT_TRUE(milestones->times.empty());
  ASSERT_EQ(milestones->configs.size(), 3u);
  ASSERT_EQ(milestones->velocities.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(milestones->configs[i].size(), 42);
    EXPECT_EQ(milestones->velocities[i], VecX::Zero(42)) << "record " << i;
  }
  EXPECT_EQ(milestones->configs[1][7], -0.973484);
}

TEST(TrajectoryFileTest, AthleteFlexMultiPathIgnoresIkGoalsWithOneNote) {
  const std::string file = WorldsPath("klampt/motions/athlete_flex.xml");
  Diagnostics diagnostics;
  const auto path = ReadMotionFile(file, diagnostics);
  ASSERT_TRUE(path) << diagnostics.FormatAll();
  EXPECT_EQ(path->times, (std::vector<double>{0, 2, 4}));
  ASSERT_EQ(path->configs.size(), 3u);
  for (const VecX& config : path->configs) EXPECT_EQ(config.size(), 42);
  EXPECT_EQ(path->configs[2][3], 6.28319);
  EXPECT_TRUE(path->velocities.empty());
  EXPECT_THAT(diagnostics.Messages(Severity::kNote),
              ElementsAre(file + ":3: note: ignoring 6 <ikgoal> elements (IK constraints are not "
                                 "supported)"));
  EXPECT_EQ(diagnostics.warning_count(), 0);
}

// [section] our fixtures

TEST(TrajectoryFileTest, ConfigAsOneUntimedMilestone) {
  Diagnostics diagnostics;
  const auto motion = ReadMotionFile(DataPath("motions/arm.config"), diagnostics);
  ASSERT_TRUE(motion) << diagnostics.FormatAll();
  EXPECT_TRUE(motion->times.empty());
  EXPECT_TRUE(motion->velocities.empty());
  EXPECT_THAT(motion->configs, ElementsAre(Vector({0.1, -0.2, 0.3})));
}

TEST(TrajectoryFileTest, PathWithCommentsEqualTimesAndExponents) {
  Diagnostics diagnostics;
  const auto path = ReadMotionFile(DataPath("motions/arm.path"), diagnostics);
  ASSERT_TRUE(path) << diagnostics.FormatAll();
  EXPECT_EQ(path->times, (std::vector<double>{0, 0.5, 0.5, 2}));
  EXPECT_THAT(path->configs, ElementsAre(Vector({0, 0, 0}), Vector({0.1, 0.2, -0.3}),
                                         Vector({0.1, 0.25, -0.3}), Vector({1e-3, -25, 0})));
}

TEST(TrajectoryFileTest, MilestoneRecordsMaySpanLines) {
  Diagnostics diagnostics;
  const auto milestones = ReadMotionFile(DataPath("motions/arm.milestones"), diagnostics);
  ASSERT_TRUE(milestones) << diagnostics.FormatAll();
  EXPECT_THAT(milestones->configs,
              ElementsAre(Vector({0, 0, 0}), Vector({0.1, 0.2, -0.3}), Vector({1, 1, 1})));
  EXPECT_THAT(milestones->velocities,
              ElementsAre(Vector({0, 0, 0}), Vector({1, 2, 3}), Vector({0, 0, 0})));
}

TEST(TrajectoryFileTest, MultiPathSectionsAreConcatenated) {
  const std::string file = DataPath("motions/arm_sections.xml");
  Diagnostics diagnostics;
  const auto path = ReadMotionFile(file, diagnostics);
  ASSERT_TRUE(path) << diagnostics.FormatAll();
  EXPECT_EQ(path->times, (std::vector<double>{0, 1, 1, 3}));
  EXPECT_THAT(path->configs, ElementsAre(Vector({0, 0, 0}), Vector({0.5, 0, 0}),
                                         Vector({0.5, 0, 0}), Vector({1, 1, 1})));
  EXPECT_THAT(path->velocities, ElementsAre(Vector({0, 0, 0}), Vector({1, 0, 0}), Vector({1, 0, 0}),
                                            Vector({0, 0, 0})));
  EXPECT_THAT(diagnostics.Messages(Severity::kNote),
              ElementsAre(file + ":9: note: ignoring 1 <ikgoal> elements (IK constraints are not "
                                 "supported)",
                          file + ":3: note: ignoring 1 <hold> elements (contact constraints are "
                                 "not supported)"));
}

TEST(TrajectoryFileTest, UntimedMultiPath) {
  Diagnostics diagnostics;
  const auto path = ParseMultiPath(
      "<multipath><section><milestone config=\"1 5\"/><milestone config=\"1 6\"/></section>"
      "</multipath>",
      "inline.xml", diagnostics);
  ASSERT_TRUE(path) << diagnostics.FormatAll();
  EXPECT_TRUE(path->times.empty());
  EXPECT_THAT(path->configs, ElementsAre(Vector({5}), Vector({6})));
}

// [section] writers

TEST(TrajectoryWriterTest, ConfigRoundTripsExactly) {
  const VecX config = AwkwardValues(42, 1);
  EXPECT_EQ(WriteConfig(Vector({1, 0.5})), "2\t1 0.5\n");
  Diagnostics diagnostics;
  const auto read = ParseConfig(WriteConfig(config), "written.config", diagnostics);
  ASSERT_TRUE(read) << diagnostics.FormatAll();
  EXPECT_EQ(*read, config);  // bit-exact
}

TEST(TrajectoryWriterTest, LinearPathRoundTripsExactly) {
  MilestoneSequence path;
  path.times = {-0.1, 1.0 / 3.0, 1.0 / 3.0, 1e9};
  for (unsigned i = 0; i < 4; ++i) path.configs.push_back(AwkwardValues(7, 10 + i));
  const std::string text = WriteLinearPath(path);
  Diagnostics diagnostics;
  const auto read = ParseLinearPath(text, "written.path", diagnostics);
  ASSERT_TRUE(read) << diagnostics.FormatAll() << text;
  EXPECT_EQ(read->times, path.times);
  EXPECT_EQ(read->configs, path.configs);
}

TEST(TrajectoryWriterTest, MilestonesRoundTripExactly) {
  MilestoneSequence milestones;
  for (unsigned i = 0; i < 3; ++i) {
    milestones.configs.push_back(AwkwardValues(5, 20 + i));
    milestones.velocities.push_back(AwkwardValues(5, 30 + i));
  }
  Diagnostics diagnostics;
  const auto read = ParseMilestones(WriteMilestones(milestones), "written.milestones", diagnostics);
  ASSERT_TRUE(read) << diagnostics.FormatAll();
  EXPECT_EQ(read->configs, milestones.configs);
  EXPECT_EQ(read->velocities, milestones.velocities);
}

TEST(TrajectoryWriterTest, MissingTimesAndVelocitiesAreFilledIn) {
  MilestoneSequence untimed;
  untimed.configs = {Vector({1, 2}), Vector({3, 4})};
  EXPECT_EQ(WriteLinearPath(untimed), "0\t2\t1 2\n1\t2\t3 4\n");
  EXPECT_EQ(WriteMilestones(untimed), "2\t1 2\t2\t0 0\n2\t3 4\t2\t0 0\n");
}

TEST(TrajectoryWriterTest, ExampleFilesSurviveAWriteReadCycle) {
  Diagnostics diagnostics;
  const auto path = ReadMotionFile(WorldsPath("klampt/motions/athlete_flex.path"), diagnostics);
  ASSERT_TRUE(path);
  const std::string file = WriteScratchFile("athlete.path", WriteLinearPath(*path));
  const auto again = ReadMotionFile(file, diagnostics);
  ASSERT_TRUE(again) << diagnostics.FormatAll();
  EXPECT_EQ(again->times, path->times);
  EXPECT_EQ(again->configs, path->configs);
}

// [section] malformed input

TEST(TrajectoryFileErrorsTest, ConfigCountsAndNumbers) {
  const std::string short_config = DataPath("bad/config_short.config");
  const std::string nan_config = DataPath("bad/config_nan.config");
  const std::string bad_count = DataPath("bad/config_bad_count.config");
  Diagnostics diagnostics;
  EXPECT_FALSE(ReadConfigFile(short_config, diagnostics));
  EXPECT_FALSE(ReadConfigFile(nan_config, diagnostics));
  EXPECT_FALSE(ReadConfigFile(bad_count, diagnostics));
  EXPECT_FALSE(ParseConfig("2 1 2\n3", "extra.config", diagnostics));
  EXPECT_FALSE(ParseConfig(" # nothing\n", "empty.config", diagnostics));
  EXPECT_THAT(Errors(diagnostics),
              ElementsAre(short_config + ":1: error: expected 42 values, got 41",
                          nan_config + ":1: error: 'nan' is not a number",
                          bad_count + ":1: error: expected a value count, got '3.5'",
                          "extra.config:1: error: expected 2 values, got 3",
                          "empty.config: error: expected a configuration 'N q1 ... qN', got an "
                          "empty file"));
}

TEST(TrajectoryFileErrorsTest, PathProblemsAreReportedPerLine) {
  const std::string counts = DataPath("bad/path_count_mismatch.path");
  const std::string decreasing = DataPath("bad/path_time_decreasing.path");
  const std::string sizes = DataPath("bad/path_mixed_sizes.path");
  const std::string finite = DataPath("bad/path_not_finite.path");
  Diagnostics diagnostics;
  for (const std::string& file : {counts, decreasing, sizes, finite}) {
    EXPECT_FALSE(ReadMotionFile(file, diagnostics)) << file;
  }
  EXPECT_FALSE(ParseLinearPath("\n# no milestones\n", "empty.path", diagnostics));
  EXPECT_FALSE(ParseLinearPath("0 2 0 0\n1\n", "lonely.path", diagnostics));
  EXPECT_THAT(Errors(diagnostics),
              ElementsAre(counts + ":2: error: expected 3 values, got 2",
                          decreasing + ":3: error: time must be nondecreasing, got '0.5' after '1'",
                          sizes + ":2: error: milestone has 3 values, expected 2 like the first "
                                  "milestone",
                          finite + ":1: error: 'nan' is not a number",
                          finite + ":2: error: expected a finite number, got 'inf'",
                          "empty.path: error: the path has no milestones",
                          "lonely.path:2: error: expected a milestone 't N q1 ... qN', got '1'"));
}

TEST(TrajectoryFileErrorsTest, MilestoneRecords) {
  const std::string truncated = DataPath("bad/milestones_truncated.milestones");
  const std::string no_velocity = DataPath("bad/milestones_no_velocity.milestones");
  const std::string velocity_size = DataPath("bad/milestones_velocity_size.milestones");
  Diagnostics diagnostics;
  for (const std::string& file : {truncated, no_velocity, velocity_size}) {
    EXPECT_FALSE(ReadMotionFile(file, diagnostics)) << file;
  }
  EXPECT_FALSE(ParseMilestones("2 0 0 2 0 0\n3 0 0 0 3 0 0 0\n", "sizes.milestones", diagnostics));
  EXPECT_FALSE(ParseMilestones("", "empty.milestones", diagnostics));
  EXPECT_THAT(Errors(diagnostics),
              ElementsAre(truncated + ":2: error: expected 2 velocity values, got 1",
                          no_velocity + ":2: error: milestone 2 has no velocity 'N dq1 ... dqN'",
                          velocity_size + ":1: error: velocity has 3 values, expected 2 like its "
                                          "configuration",
                          "sizes.milestones:2: error: milestone has 3 values, expected 2 like the "
                          "first milestone",
                          "empty.milestones: error: the file has no milestones"));
}

// tinyxml2 reports a mismatched end tag at the line of the element it fails to close
TEST(TrajectoryFileErrorsTest, MalformedXmlNamesTheLine) {
  const std::string malformed = DataPath("bad/multipath_malformed.xml");
  const std::string wrong_root = DataPath("bad/multipath_wrong_root.xml");
  Diagnostics diagnostics;
  EXPECT_FALSE(ReadMotionFile(malformed, diagnostics));
  EXPECT_FALSE(ReadMotionFile(wrong_root, diagnostics));
  EXPECT_FALSE(ParseMultiPath("<multipath>\n</multipath>\n", "none.xml", diagnostics));
  EXPECT_THAT(Errors(diagnostics),
              ElementsAre(malformed + ":2: error: malformed XML: XML_ERROR_MISMATCHED_ELEMENT",
                          wrong_root + ":1: error: root element must be <multipath>, got <world>",
                          "none.xml:1: error: <multipath> has no milestones"));
}

TEST(TrajectoryFileErrorsTest, MixedTimedAndUntimedMilestones) {
  const std::string file = DataPath("bad/multipath_mixed_timing.xml");
  Diagnostics diagnostics;
  EXPECT_FALSE(ReadMotionFile(file, diagnostics));
  EXPECT_THAT(Errors(diagnostics),
              ElementsAre(file + ":4: error: <milestone>: has no 'time' but the first milestone "
                                 "has one"));
}

TEST(TrajectoryFileErrorsTest, EveryBadMilestoneElementIsReported) {
  const std::string file = DataPath("bad/multipath_bad_values.xml");
  Diagnostics diagnostics;
  EXPECT_FALSE(ReadMotionFile(file, diagnostics));
  EXPECT_THAT(
      Errors(diagnostics),
      ElementsAre(
          file + ":3: error: <milestone>: attribute 'config' declares 3 values but gives 2",
          file + ":5: error: <milestone>: attribute 'config' has 'nan', which is not a number",
          file + ":6: error: <milestone>: attribute 'time' must be nondecreasing, got '0.5' "
                 "after '1'",
          file + ":7: error: <milestone>: attribute 'config' has 3 values, expected 2 like the "
                 "first milestone",
          file + ":8: error: <milestone>: missing attribute 'config'",
          file + ":9: error: <milestone>: has no 'velocity' but the first milestone has one",
          file + ":10: error: <milestone>: attribute 'velocity' has 3 values, expected 2 like "
                 "'config'"));
}

TEST(TrajectoryFileErrorsTest, UnsupportedOrMissingMotionFiles) {
  const std::string text_file = DataPath("motions/arm.txt");
  const std::string missing = DataPath("motions/no_such.path");
  Diagnostics diagnostics;
  EXPECT_FALSE(ReadMotionFile(text_file, diagnostics));
  EXPECT_FALSE(ReadMotionFile(missing, diagnostics));
  EXPECT_FALSE(ReadConfigFile(DataPath("motions/no_such.config"), diagnostics));
  EXPECT_THAT(
      Errors(diagnostics),
      ElementsAre(text_file + ": error: unsupported motion file type '.txt'",
                  missing + ": error: cannot open motion file '" + missing + "'",
                  DataPath("motions/no_such.config") + ": error: cannot open configuration file '" +
                      DataPath("motions/no_such.config") + "'"));
}

}  // namespace
}  // namespace lamina::core
