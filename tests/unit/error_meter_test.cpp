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

// the first sample's cost is not known yet: it is counted as three mean steps, so it waits for
// 3 / budget steps (60 at 5 %), however costly the first steps were
TEST(ErrorMeterTest, TheFirstSampleWaitsUntilTheBudgetPaysForThreeMeanSteps) {
  ErrorMeter meter(0.05);
  EXPECT_FALSE(meter.Due());  // before any step
  // a costly start: three steps of 0.5 s, then 56 of 1 ms
  for (int i = 0; i < 59; ++i) meter.AddSteppingTime(i < 3 ? 0.5 : 0.001);
  EXPECT_FALSE(meter.Due());  // 3 · S / 59 > 0.05 · S
  meter.AddSteppingTime(0.001);
  meter.AddSteppingTime(0.001);
  EXPECT_TRUE(meter.Due());  // 61 steps
  ErrorMeter generous(0.5);  // 3 / 0.5 = 6 steps
  for (int i = 0; i < 5; ++i) generous.AddSteppingTime(0.001);
  EXPECT_FALSE(generous.Due());
  generous.AddSteppingTime(0.001);
  generous.AddSteppingTime(0.001);
  EXPECT_TRUE(generous.Due());
}

TEST(ErrorMeterTest, SamplesOnlyWithinItsBudgetOfTheSteppingTime) {
  ErrorMeter meter(0.05);
  for (int i = 0; i < 100; ++i) meter.AddSteppingTime(0.001);  // 0.1 s: the first sample is due
  EXPECT_TRUE(meter.Due());
  meter.Add({0.1, 0.001, 1e-6, 2e-6, 2e-3}, 0.003);
  EXPECT_FALSE(meter.Due());    // 0.003 + 0.003 > 0.05 · 0.1
  meter.AddSteppingTime(0.03);  // 0.006 <= 0.05 · 0.13
  EXPECT_TRUE(meter.Due());
  meter.AddSamplingTime(0.003);  // (a sample whose probe step failed counts as well)
  EXPECT_FALSE(meter.Due());
  EXPECT_NEAR(meter.Reading().overhead, 0.006 / 0.13, 1e-12);
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
  EXPECT_FALSE(meter.Due());  // as at the start: no step counted
  meter.AddSteppingTime(0.001);
  EXPECT_FALSE(meter.Due());
}

}  // namespace
}  // namespace lamina::core
