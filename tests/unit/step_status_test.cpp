// SPDX-License-Identifier: MIT
// The statuses a step reports (core/sim/step_observer.h): a step's flags give the worst of their
// statuses, "joint open" sits between "contact unreliable" and "unstable", and Klamp't's numbers
// (its SimStatus 0…4, which the Python module returns) name the same statuses, "joint open"
// counting as its "contact unreliable".
#include <gtest/gtest.h>

#include "core/sim/step_observer.h"

namespace lamina::core {
namespace {

TEST(StepStatusTest, AStepReportsTheWorstOfItsFlags) {
  EXPECT_EQ(StatusOfStep(0u), StepStatus::kNormal);
  EXPECT_EQ(StatusOfStep(kStepRetaken | kStepUnreliable), StepStatus::kContactUnreliable);
  EXPECT_EQ(StatusOfStep(kStepUnreliable | kStepJointOpen), StepStatus::kJointOpen);
  EXPECT_EQ(StatusOfStep(kStepJointOpen | kStepCorrected), StepStatus::kUnstable);
  EXPECT_STREQ(StepStatusName(StatusOfStep(kStepJointOpen)), "joint open");
}

TEST(StepStatusTest, KlamptsNumbersNameTheSameStatuses) {
  EXPECT_EQ(KlamptStatusCode(StepStatus::kNormal), 0);
  EXPECT_EQ(KlamptStatusCode(StepStatus::kAdaptiveStep), 1);
  EXPECT_EQ(KlamptStatusCode(StepStatus::kContactUnreliable), 2);
  EXPECT_EQ(KlamptStatusCode(StepStatus::kJointOpen), 2);
  EXPECT_EQ(KlamptStatusCode(StepStatus::kUnstable), 3);
  EXPECT_EQ(KlamptStatusCode(StepStatus::kError), 4);
  for (int code = 0; code <= 4; ++code) {
    EXPECT_EQ(KlamptStatusCode(StatusOfKlamptCode(code)), code) << code;
  }
  EXPECT_EQ(StatusOfKlamptCode(2), StepStatus::kContactUnreliable);
}

}  // namespace
}  // namespace lamina::core
