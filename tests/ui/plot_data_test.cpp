// SPDX-License-Identifier: MIT
// The plots' data (ui/widgets/plot_data.h): the ring buffer, time going backwards, the visible
// window and its min/max decimation, ticks, the y range, NaN, and the CSV export.
#include "ui/widgets/plot_data.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace lamina::ui {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

PlotSeries Ramp(int count, std::size_t capacity = kDefaultPlotCapacity) {
  PlotSeries series("x", "m", capacity);
  for (int i = 0; i < count; ++i) series.Append(i, 10.0 * i);
  return series;
}

std::vector<double> Times(const std::vector<PlotSample>& samples) {
  std::vector<double> times;
  for (const PlotSample& s : samples) times.push_back(s.t);
  return times;
}

TEST(PlotSeries, KeepsTheLastCapacitySamplesInOrderAfterWrapping) {
  const PlotSeries series = Ramp(13, 5);
  ASSERT_EQ(series.size(), 5u);
  EXPECT_EQ(series.capacity(), 5u);
  EXPECT_EQ(series.dropped(), 8u);
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_EQ(series[i].t, 8.0 + i);
    EXPECT_EQ(series[i].y, 80.0 + 10.0 * i);
  }
  EXPECT_EQ(series.back().t, 12.0);
  EXPECT_EQ(series.Label(), "x [m]");
}

TEST(PlotGroup, ARowGoesToEverySeriesAndMissingValuesAreNaN) {
  PlotGroup group("energy");
  group.AddSeries("kinetic", "J");
  group.AddSeries("potential", "J");
  EXPECT_TRUE(group.AddRow(0.5, {1.0}));
  EXPECT_FALSE(group.AddRow(kNaN, {2.0, 3.0}));  // not stored
  ASSERT_EQ(group.series()[0].size(), 1u);
  ASSERT_EQ(group.series()[1].size(), 1u);
  EXPECT_EQ(group.series()[0][0].y, 1.0);
  EXPECT_TRUE(std::isnan(group.series()[1][0].y));
  EXPECT_EQ(group.last_time(), 0.5);
}

TEST(PlotGroup, TimeGoingBackwardsClearsTheGroup) {
  PlotGroup group("energy");
  group.AddSeries("total", "J");
  for (int i = 0; i <= 5; ++i) group.AddRow(i, {100.0 + i});
  EXPECT_EQ(group.series()[0].size(), 6u);
  group.AddRow(2.0, {7.0});  // a Reset, an undo
  ASSERT_EQ(group.series()[0].size(), 1u);
  EXPECT_EQ(group.series()[0][0].t, 2.0);
  EXPECT_EQ(group.series()[0][0].y, 7.0);
  EXPECT_EQ(group.resets(), 1);
  EXPECT_EQ(group.first_time(), 2.0);
}

TEST(PlotGroup, ARowAtTheSameTimeReplacesTheLast) {
  PlotGroup group("paused");
  group.AddSeries("y", "");
  group.AddRow(1.0, {1.0});
  group.AddRow(1.0, {2.0});
  group.AddRow(1.0, {3.0});
  ASSERT_EQ(group.series()[0].size(), 1u);
  EXPECT_EQ(group.series()[0][0].y, 3.0);
  EXPECT_EQ(group.resets(), 0);
}

TEST(PlotGroup, TheCapacityAppliesToEverySeries) {
  PlotGroup group("small", 3);
  group.AddSeries("a", "");
  for (int i = 0; i < 10; ++i) group.AddRow(i, {double(i)});
  EXPECT_EQ(group.series()[0].size(), 3u);
  EXPECT_EQ(group.first_time(), 7.0);
  EXPECT_EQ(group.last_time(), 9.0);
}

TEST(PlotWindow, SelectsExactlyTheSamplesInTheClosedWindow) {
  const PlotSeries series = Ramp(100);
  EXPECT_EQ(Times(SamplesInWindow(series, {10.0, 20.0})),
            (std::vector<double>{10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20}));
  EXPECT_EQ(Times(SamplesInWindow(series, {10.5, 13.5})), (std::vector<double>{11, 12, 13}));
  EXPECT_TRUE(SamplesInWindow(series, {200.0, 300.0}).empty());
  EXPECT_EQ(LowerIndex(series, 42.0), 42u);
  EXPECT_EQ(LowerIndex(series, 1e9), 100u);
}

TEST(PlotWindow, SelectsInAWrappedBuffer) {
  const PlotSeries series = Ramp(130, 50);  // holds t = 80..129
  EXPECT_EQ(Times(SamplesInWindow(series, {70.0, 83.0})), (std::vector<double>{80, 81, 82, 83}));
  EXPECT_EQ(Times(SamplesInWindow(series, {127.5, 1000.0})), (std::vector<double>{128, 129}));
}

TEST(PlotWindow, ScrollsOnceTheDataCoversTheSpan) {
  PlotGroup group("g");
  group.AddSeries("y", "");
  for (int i = 0; i <= 3; ++i) group.AddRow(i, {0.0});
  TimeWindow window = ScrollingWindow(group, 10.0, group.last_time());
  EXPECT_EQ(window.t0, 0.0);  // the line grows from the left edge
  EXPECT_EQ(window.t1, 10.0);
  for (int i = 4; i <= 25; ++i) group.AddRow(i, {0.0});
  window = ScrollingWindow(group, 10.0, group.last_time());
  EXPECT_EQ(window.t0, 15.0);
  EXPECT_EQ(window.t1, 25.0);
}

TEST(PlotDecimation, KeepsAOneSampleSpikeAndDipAndAtMostFourPerColumn) {
  PlotSeries series("force", "N");
  for (int i = 0; i < 10000; ++i) {
    const double y = i == 5003 ? 100.0 : i == 7001 ? -50.0 : 0.0;
    series.Append(i * 0.001, y);
  }
  const std::vector<PlotSample> drawn = DecimatedWindow(series, {0.0, 10.0}, 100);
  EXPECT_LE(drawn.size(), 400u);
  EXPECT_GE(drawn.size(), 200u);  // first and last of each of the 100 columns at least
  ValueRange range = EmptyRange();
  ExtendRange(drawn, &range);
  EXPECT_EQ(range.hi, 100.0);
  EXPECT_EQ(range.lo, -50.0);
  bool spike_at_its_time = false;
  for (const PlotSample& s : drawn) spike_at_its_time |= s.y == 100.0 && s.t == 5003 * 0.001;
  EXPECT_TRUE(spike_at_its_time);
  for (std::size_t i = 1; i < drawn.size(); ++i) EXPECT_LT(drawn[i - 1].t, drawn[i].t);
}

TEST(PlotDecimation, ASparseWindowIsReturnedWhole) {
  const PlotSeries series = Ramp(100);
  EXPECT_EQ(DecimatedWindow(series, {10.0, 20.0}, 800).size(), 11u);
}

TEST(PlotDecimation, SkipsNaNAndInfinity) {
  PlotSeries series("y", "");
  const double values[] = {1.0, kNaN, 3.0, kInf, -kInf, 2.0};
  for (int i = 0; i < 6; ++i) series.Append(i, values[i]);
  const std::vector<PlotSample> drawn = DecimatedWindow(series, {0.0, 5.0}, 2);
  EXPECT_EQ(Times(drawn), (std::vector<double>{0, 2, 5}));
  for (const PlotSample& s : drawn) EXPECT_TRUE(std::isfinite(s.y));
}

TEST(PlotHover, ReadsTheNearestSample) {
  const PlotSeries series = Ramp(3);  // y = 0, 10, 20 at t = 0, 1, 2
  EXPECT_EQ(ValueNear(series, 1.4), 10.0);
  EXPECT_EQ(ValueNear(series, 1.6), 20.0);
  EXPECT_EQ(ValueNear(series, -5.0), 0.0);
  EXPECT_EQ(ValueNear(series, 99.0), 20.0);
  EXPECT_TRUE(std::isnan(ValueNear(PlotSeries("e", ""), 1.0)));
}

TEST(PlotRange, IgnoresNaNAndInfinityAndAddsAMargin) {
  const std::vector<PlotSample> samples = {{0, 1.0}, {1, kNaN}, {2, 3.0}, {3, kInf}, {4, -kInf}};
  ValueRange range = EmptyRange();
  ExtendRange(samples, &range);
  EXPECT_EQ(range.lo, 1.0);
  EXPECT_EQ(range.hi, 3.0);
  const ValueRange padded = PaddedRange(range);
  EXPECT_DOUBLE_EQ(padded.lo, 0.9);
  EXPECT_DOUBLE_EQ(padded.hi, 3.1);
}

TEST(PlotRange, AFlatLineOrNoDataIsNeverZeroHeight) {
  ValueRange flat = PaddedRange({5.0, 5.0});
  EXPECT_DOUBLE_EQ(flat.lo, 4.5);
  EXPECT_DOUBLE_EQ(flat.hi, 5.5);
  flat = PaddedRange({-20.0, -20.0});
  EXPECT_DOUBLE_EQ(flat.lo, -22.0);
  EXPECT_DOUBLE_EQ(flat.hi, -18.0);
  flat = PaddedRange({0.0, 0.0});
  EXPECT_EQ(flat.lo, -1.0);
  EXPECT_EQ(flat.hi, 1.0);
  const ValueRange none = PaddedRange(EmptyRange());  // only NaN samples, or none
  EXPECT_EQ(none.lo, -1.0);
  EXPECT_EQ(none.hi, 1.0);
}

std::vector<std::string> Labels(const Ticks& ticks) {
  std::vector<std::string> labels;
  for (double v : ticks.values) labels.push_back(TickLabel(ticks, v));
  return labels;
}

TEST(NiceTicks, ZeroToOneInFifths) {
  const Ticks ticks = NiceTicks(0.0, 1.0, 6);
  EXPECT_DOUBLE_EQ(ticks.step, 0.2);
  EXPECT_EQ(ticks.values, (std::vector<double>{0.0, 0.2, 0.4, 0.6, 0.8, 1.0}));
  EXPECT_EQ(Labels(ticks), (std::vector<std::string>{"0.0", "0.2", "0.4", "0.6", "0.8", "1.0"}));
  EXPECT_EQ(NiceTicks(0.0, 1.0, 11).step, 0.1);
  EXPECT_EQ(NiceTicks(0.0, 1.0, 4).step, 0.5);
  EXPECT_EQ(NiceTicks(0.0, 1.0, 2).step, 1.0);
}

TEST(NiceTicks, NegativeToPositive) {
  Ticks ticks = NiceTicks(-3.7, 12.1, 10);
  EXPECT_EQ(ticks.step, 2.0);
  EXPECT_EQ(ticks.values, (std::vector<double>{-2, 0, 2, 4, 6, 8, 10, 12}));
  EXPECT_EQ(Labels(ticks).front(), "-2");
  ticks = NiceTicks(-3.7, 12.1, 6);
  EXPECT_EQ(ticks.step, 5.0);
  EXPECT_EQ(ticks.values, (std::vector<double>{0, 5, 10}));
}

TEST(NiceTicks, MicroUnitsGetScientificLabels) {
  const Ticks ticks = NiceTicks(1e-6, 3e-6, 5);
  EXPECT_DOUBLE_EQ(ticks.step, 5e-7);
  ASSERT_EQ(ticks.values.size(), 5u);
  EXPECT_DOUBLE_EQ(ticks.values[0], 1e-6);
  EXPECT_DOUBLE_EQ(ticks.values[4], 3e-6);
  EXPECT_EQ(Labels(ticks),
            (std::vector<std::string>{"1.0e-06", "1.5e-06", "2.0e-06", "2.5e-06", "3.0e-06"}));
}

TEST(NiceTicks, DegenerateAndInvalidRanges) {
  const Ticks single = NiceTicks(2.0, 2.0, 6);
  EXPECT_EQ(single.values, (std::vector<double>{2.0}));
  EXPECT_EQ(TickLabel(single, 2.0), "2.00");
  EXPECT_TRUE(NiceTicks(3.0, 1.0, 6).values.empty());
  EXPECT_TRUE(NiceTicks(kNaN, 1.0, 6).values.empty());
  EXPECT_TRUE(NiceTicks(0.0, kInf, 6).values.empty());
  EXPECT_TRUE(NiceTicks(-1e308, 1e308, 6).values.empty());  // the width overflows
  EXPECT_LE(NiceTicks(0.0, 1.0, 0).values.size(), 2u);      // at least 2 asked for
}

TEST(NiceTicks, NeitherMoreThanAskedNorTooFewOverManyRanges) {
  for (double lo = -7.3; lo < 7.0; lo += 0.77) {
    for (double width = 1e-3; width < 1e4; width *= 3.1) {
      for (int max_ticks = 2; max_ticks <= 12; ++max_ticks) {
        const Ticks ticks = NiceTicks(lo, lo + width, max_ticks);
        EXPECT_LE(ticks.values.size(), std::size_t(max_ticks)) << lo << " " << width;
        // the step is at most 2.5 × width / (max_ticks - 1)
        const std::size_t at_least = max_ticks >= 6 ? 2 : max_ticks >= 4 ? 1 : 0;
        EXPECT_GE(ticks.values.size(), at_least) << lo << " " << width;
      }
    }
  }
}

// ---- CSV ----

std::string TempPath(const std::string& name) {
  return (std::filesystem::path(testing::TempDir()) / name).string();
}

std::vector<std::string> SplitCsv(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream in(line);
  std::string field;
  while (std::getline(in, field, ',')) fields.push_back(field);
  if (!line.empty() && line.back() == ',') fields.push_back("");
  return fields;
}

std::vector<std::string> ReadLines(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::uint64_t Bits(double v) {
  return std::bit_cast<std::uint64_t>(v);
}

TEST(PlotCsv, RoundTripsEveryDoubleBitForBit) {
  const std::vector<double> values = {0.1,    1.0 / 3.0,           -2.5e300,
                                      5e-324, 3.141592653589793,   -0.0,
                                      1e-300, 123456789.123456789, 2.0 / 3.0};
  PlotGroup group("energy");
  group.AddSeries("kinetic", "J");
  group.AddSeries("total", "J");
  for (std::size_t i = 0; i < values.size(); ++i) {
    group.AddRow(0.001 * i + 0.1, {values[i], -values[i] / 7.0});
  }
  const std::string path = TempPath("plot_round_trip.csv");
  std::string error;
  ASSERT_TRUE(WriteCsv(group, path, &error)) << error;
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
  const std::vector<std::string> lines = ReadLines(path);
  ASSERT_EQ(lines.size(), values.size() + 1);
  EXPECT_EQ(lines[0], "time,kinetic [J],total [J]");
  for (std::size_t i = 0; i < values.size(); ++i) {
    const std::vector<std::string> fields = SplitCsv(lines[i + 1]);
    ASSERT_EQ(fields.size(), 3u) << lines[i + 1];
    EXPECT_EQ(Bits(std::strtod(fields[0].c_str(), nullptr)), Bits(0.001 * i + 0.1));
    EXPECT_EQ(Bits(std::strtod(fields[1].c_str(), nullptr)), Bits(values[i]));
    EXPECT_EQ(Bits(std::strtod(fields[2].c_str(), nullptr)), Bits(-values[i] / 7.0));
  }
  std::filesystem::remove(path);
}

TEST(PlotCsv, NaNIsWrittenAndALateSeriesLeavesEmptyFields) {
  PlotGroup group("g");
  group.AddSeries("a", "");
  group.AddRow(0.0, {kNaN});
  group.AddSeries("b, quoted", "N");
  group.AddRow(1.0, {1.0, 2.0});
  const std::string path = TempPath("plot_late_series.csv");
  std::string error;
  ASSERT_TRUE(WriteCsv(group, path, &error)) << error;
  EXPECT_EQ(ReadLines(path),
            (std::vector<std::string>{"time,a,\"b, quoted [N]\"", "0,nan,", "1,1,2"}));
  std::filesystem::remove(path);
}

TEST(PlotCsv, AnUnwritablePathIsAnErrorNamingItAndLeavesNoFile) {
  PlotGroup group("g");
  group.AddSeries("a", "");
  group.AddRow(0.0, {1.0});
  const std::string path = "/nonexistent/dir/x.csv";
  std::string error;
  EXPECT_FALSE(WriteCsv(group, path, &error));
  EXPECT_NE(error.find(path), std::string::npos) << error;
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
}

TEST(PlotCsv, ReplacesAnExistingFile) {
  PlotGroup group("g");
  group.AddSeries("a", "");
  group.AddRow(0.0, {1.0});
  const std::string path = TempPath("plot_replace.csv");
  std::ofstream(path) << "old contents that are longer than the new ones\n";
  std::string error;
  ASSERT_TRUE(WriteCsv(group, path, &error)) << error;
  EXPECT_EQ(ReadLines(path), (std::vector<std::string>{"time,a", "0,1"}));
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace lamina::ui
