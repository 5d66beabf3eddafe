// SPDX-License-Identifier: MIT
// The accuracy meter's bookkeeping (core/sim/error_meter.h): the step-doubling estimate from two
// sets of positions, the time budget that decides when to sample, and the reading over the
// recent samples.
#include "core/sim/error_meter.h"

#include <gtest/gtest.h>

namespace lamina::core {
namespace {

TEST(ErrorMeterTest, SampleDoublesTheLargestDifferenceAndDividesByTheStep) {
  const std::vector<Vec3> full = {Vec3(0, 0, 1), Vec3(1, 0, 0)};
  const std::vector<Vec3> halves = {Vec3(0, 0, 1.001), Vec3(1, 0.003, 0.004)};
  const StepErrorSample sample = MakeStepErrorSample(2.0, 0.01, full, halves);
  EXPECT_DOUBLE_EQ(sample.difference, 0.005);
  EXPECT_DOUBLE_EQ(sample.local_error, 0.01);
  EXPECT_DOUBLE_EQ(sample.rate, 1.0);
  EXPECT_DOUBLE_EQ(sample.time, 2.0);
}

TEST(ErrorMeterTest, SamplesOnlyWithinItsBudgetOfTheSteppingTime) {
  ErrorMeter meter(0.05);
  EXPECT_TRUE(meter.Due());  // the first step
  meter.Add({0.0, 0.001, 1e-6, 2e-6, 2e-3}, 0.003);
  EXPECT_FALSE(meter.Due());
  meter.AddSteppingTime(0.10);  // 0.003 + 0.003 > 0.05 · 0.10
  EXPECT_FALSE(meter.Due());
  meter.AddSteppingTime(0.02);  // 0.006 <= 0.05 · 0.12
  EXPECT_TRUE(meter.Due());
  meter.AddSamplingTime(0.003);
  EXPECT_FALSE(meter.Due());
  EXPECT_NEAR(meter.Reading().overhead, 0.006 / 0.12, 1e-12);
}

TEST(ErrorMeterTest, ReadsTheLargestRateOfTheRecentSamples) {
  ErrorMeter meter(0.05, 2);
  EXPECT_FALSE(meter.Reading().valid);
  meter.Add({1.0, 0.001, 0, 9e-6, 9e-3}, 0.0);
  meter.Add({2.0, 0.001, 0, 1e-6, 1e-3}, 0.0);
  EXPECT_DOUBLE_EQ(meter.Reading().rate, 9e-3);
  meter.Add({3.0, 0.001, 0, 2e-6, 2e-3}, 0.0);  // the first leaves the window of 2
  const ErrorMeterReading reading = meter.Reading();
  EXPECT_TRUE(reading.valid);
  EXPECT_DOUBLE_EQ(reading.rate, 2e-3);
  EXPECT_DOUBLE_EQ(reading.local_error, 2e-6);
  EXPECT_DOUBLE_EQ(reading.time, 3.0);
  EXPECT_EQ(reading.samples, 3);
  meter.Reset();
  EXPECT_FALSE(meter.Reading().valid);
  EXPECT_TRUE(meter.Due());
}

}  // namespace
}  // namespace lamina::core
