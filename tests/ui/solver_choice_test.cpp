// SPDX-License-Identifier: MIT
// The real-time solver choice on measured step costs: it waits for enough evidence, compares the
// cost times the playback speed with the physics budget, and never takes its decision back.
#include "ui/viewer/solver_choice.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

namespace lamina::ui {
namespace {

// frames of 1/60 s of simulated time, each costing `cost` wall s per simulated s
void Play(SolverChoice* choice, double cost, double seconds, double speed = 1.0) {
  for (double t = 0.0; t < seconds; t += 1.0 / 60.0) choice->Add(cost / 60.0, 1.0 / 60.0, speed);
}

TEST(SolverChoiceTest, AWorldTooHeavyForTheBudgetIsTooSlowOnceMeasured) {
  SolverChoice choice;
  choice.Add(0.1, 0.05, 1.0);  // 2 s a second, but 0.05 simulated seconds of evidence only
  EXPECT_FALSE(choice.too_slow());
  Play(&choice, 2.0, 1.0);
  EXPECT_TRUE(choice.too_slow());
  EXPECT_NEAR(choice.cost(), 2.0, 1e-9);
  EXPECT_NEAR(choice.reachable_factor(), 0.5, 1e-9);
}

TEST(SolverChoiceTest, AWorldWithinTheBudgetStaysExact) {
  SolverChoice choice;
  Play(&choice, 0.7, 10.0);  // 70 % of a core: within the 80 % budget
  EXPECT_FALSE(choice.too_slow());
  EXPECT_NEAR(choice.cost(), 0.7, 1e-9);
}

TEST(SolverChoiceTest, PlaybackSpeedScalesWhatRealTimeCosts) {
  SolverChoice fast, slow;
  Play(&fast, 0.5, 2.0, 2.0);  // twice real time needs a whole core
  Play(&slow, 1.2, 2.0, 0.5);  // half real time needs 60 % of one
  EXPECT_TRUE(fast.too_slow());
  EXPECT_FALSE(slow.too_slow());
}

TEST(SolverChoiceTest, TheDecisionIsNeverTakenBackAndClearStartsOver) {
  SolverChoice choice;
  Play(&choice, 3.0, 1.0);
  ASSERT_TRUE(choice.too_slow());
  Play(&choice, 0.01, 100.0);  // (nothing measures the exact solver after the switch)
  EXPECT_TRUE(choice.too_slow());
  choice.Clear();
  EXPECT_FALSE(choice.too_slow());
  EXPECT_EQ(choice.cost(), 0.0);
}

TEST(SolverChoiceTest, TheBudgetIsAShareOfACore) {
  SolverChoice whole_core(1.0);
  Play(&whole_core, 0.9, 2.0);  // 90 %: too slow for the default budget, not for a whole core
  EXPECT_FALSE(whole_core.too_slow());
  SolverChoice usual;
  Play(&usual, 0.9, 2.0);
  EXPECT_TRUE(usual.too_slow());
  whole_core.Clear();
  EXPECT_EQ(whole_core.budget(), 1.0);
}

TEST(SolverChoiceTest, EmptyAndNonFiniteMeasurementsAreIgnored) {
  SolverChoice choice;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  choice.Add(1.0, 0.0, 1.0);  // paused: nothing simulated
  choice.Add(nan, 0.1, 1.0);
  choice.Add(1.0, std::numeric_limits<double>::infinity(), 1.0);
  choice.Add(1.0, 0.1, 0.0);
  EXPECT_FALSE(choice.too_slow());
  EXPECT_EQ(choice.cost(), 0.0);
}

}  // namespace
}  // namespace lamina::ui
