// SPDX-License-Identifier: MIT
// Real-time pacing: whole fixed steps per frame, the remainder carried, the per-frame cap, and
// the measured real-time factor (ui/viewer/sim_clock.h).
#include "ui/viewer/sim_clock.h"

#include <gtest/gtest.h>

namespace lamina::ui {
namespace {

TEST(FixedStepClock, TakesWholeStepsAndCarriesTheRemainder) {
  FixedStepClock clock;
  EXPECT_EQ(clock.StepsForFrame(0.0165, 1.0, 0.001), 16);
  EXPECT_NEAR(clock.owed(), 0.0005, 1e-12);
  EXPECT_EQ(clock.StepsForFrame(0.0165, 1.0, 0.001), 17);  // the carried half step completes
  EXPECT_NEAR(clock.owed(), 0.0, 1e-12);
}

TEST(FixedStepClock, SixtyFramesOfASecondAreOneThousandSteps) {
  FixedStepClock clock;
  int steps = 0;
  for (int frame = 0; frame < 60; ++frame) steps += clock.StepsForFrame(1.0 / 60, 1.0, 0.001);
  EXPECT_EQ(steps, 1000);
}

TEST(FixedStepClock, SpeedScalesTheSimulatedTime) {
  FixedStepClock slow, fast;
  EXPECT_EQ(slow.StepsForFrame(0.02, 0.25, 0.001), 5);
  EXPECT_EQ(fast.StepsForFrame(0.01, 4.0, 0.001), 40);
}

TEST(FixedStepClock, ASlowFrameIsCappedInsteadOfSpiralling) {
  FixedStepClock clock;
  EXPECT_EQ(clock.StepsForFrame(2.0, 1.0, 0.001), 50);  // 50 ms at most
  EXPECT_NEAR(clock.owed(), 0.0, 1e-12);
}

TEST(FixedStepClock, NothingForZeroTimeOrBadSteps) {
  FixedStepClock clock;
  EXPECT_EQ(clock.StepsForFrame(0.0, 1.0, 0.001), 0);
  EXPECT_EQ(clock.StepsForFrame(0.01, 1.0, 0.0), 0);
  EXPECT_EQ(clock.StepsForFrame(0.01, 0.0, 0.001), 0);
}

TEST(RealTimeFactorMeter, MeasuresSimulatedOverWallTimeInAWindow) {
  RealTimeFactorMeter meter(1.0);
  EXPECT_EQ(meter.factor(), 0.0);
  for (int i = 0; i < 100; ++i) meter.AddFrame(0.02, 0.01);  // half speed
  EXPECT_NEAR(meter.factor(), 0.5, 1e-9);
  for (int i = 0; i < 100; ++i) meter.AddFrame(0.02, 0.02);  // then real time
  EXPECT_NEAR(meter.factor(), 1.0, 1e-9);                    // the old frames left the window
  meter.Clear();
  EXPECT_EQ(meter.factor(), 0.0);
}

}  // namespace
}  // namespace lamina::ui
