// SPDX-License-Identifier: MIT
// The stress suite's verdict rules (core/accuracy/stress_case.h), its case patterns and its JSON.
#include <cmath>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/accuracy/stress_report.h"

namespace lamina::core {
namespace {

StressVerdict Judge(const StressOutcome& outcome, std::string* why = nullptr) {
  return JudgeStress(outcome, why);
}

TEST(StressJudgeTest, AdaptiveStepsAloneAreStable) {
  StressOutcome outcome;
  outcome.worst = StepStatus::kAdaptiveStep;
  std::string why = "x";
  EXPECT_EQ(Judge(outcome, &why), StressVerdict::kStable);
  EXPECT_EQ(why, "");
}

TEST(StressJudgeTest, StatusCorrectionsAndRecoveriesFlag) {
  StressOutcome unreliable;
  unreliable.worst = StepStatus::kContactUnreliable;
  EXPECT_EQ(Judge(unreliable), StressVerdict::kFlagged);
  StressOutcome corrected;
  corrected.corrections = 3;
  corrected.worst = StepStatus::kUnstable;
  std::string why;
  EXPECT_EQ(Judge(corrected, &why), StressVerdict::kFlagged);
  EXPECT_EQ(why, "status unstable, 3 corrections, 0 non-finite recoveries");
  StressOutcome recovered;
  recovered.nonfinite = 1;
  EXPECT_EQ(Judge(recovered), StressVerdict::kFlagged);
}

TEST(StressJudgeTest, ALostBodyNeedsAStatusThatSaysSo) {
  StressOutcome silent;
  silent.lost = 1;
  silent.worst = StepStatus::kAdaptiveStep;  // a rollback does not say a body was lost
  std::string why;
  EXPECT_EQ(Judge(silent, &why), StressVerdict::kFailed);
  EXPECT_EQ(why, "1 bodies lost without a status saying so");
  StressOutcome said = silent;
  said.worst = StepStatus::kContactUnreliable;
  EXPECT_EQ(Judge(said), StressVerdict::kFlagged);
}

TEST(StressJudgeTest, HaltsAndNonFiniteEndsFail) {
  StressOutcome halted;
  halted.halted = true;
  halted.worst = StepStatus::kError;
  EXPECT_EQ(Judge(halted), StressVerdict::kFailed);
  StressOutcome nan;
  nan.finite = false;
  nan.worst = StepStatus::kUnstable;  // even when flagged: never end on a NaN
  EXPECT_EQ(Judge(nan), StressVerdict::kFailed);
  StressOutcome not_run;
  not_run.ran = false;
  EXPECT_EQ(Judge(not_run), StressVerdict::kFailed);
}

TEST(StressCasesTest, PatternsPickCasesInReportOrder) {
  const auto stacks = FindStressCases({"box_stack_20/*"});
  ASSERT_EQ(stacks.size(), 5u);
  EXPECT_EQ(stacks[0]->name, "box_stack_20/exact/1ms");
  EXPECT_EQ(stacks[2]->name, "box_stack_20/exact/10ms");
  EXPECT_EQ(stacks[4]->name, "box_stack_20/newton/10ms");
  // 22 QuickStep runs, and absurd_torque with the exact and Newton solvers too
  EXPECT_EQ(FindStressCases({"*/quick20/*", "absurd_torque*"}).size(), 24u);
  EXPECT_TRUE(FindStressCases({"nope"}).empty());
  EXPECT_EQ(FindStressCases({}).size(), StressCases().size());
  for (const StressCase& c : StressCases()) {
    EXPECT_TRUE(c.probe) << c.name;
    EXPECT_FALSE(c.keep_out.empty()) << c.name;
  }
}

TEST(StressReportTest, JsonHasARecordPerCase) {
  StressRecord record;
  record.name = "drop_15m/exact/1ms";
  record.verdict = StressVerdict::kFlagged;
  record.metric = std::nan("");
  record.lost = {"box"};
  const nlohmann::json json = nlohmann::json::parse(StressJson({record, StressRecord{}}));
  ASSERT_EQ(json["cases"].size(), 2u);
  EXPECT_EQ(json["failed"], 1);  // a default record is failed
  EXPECT_EQ(json["cases"][0]["verdict"], "flagged");
  EXPECT_TRUE(json["cases"][0]["metric"]["value"].is_null());
  EXPECT_EQ(json["cases"][0]["lost"][0], "box");
}

}  // namespace
}  // namespace lamina::core
