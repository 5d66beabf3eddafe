// SPDX-License-Identifier: MIT
// `lamina-headless stress`: a pattern picks cases, the table and the JSON record each one, the
// exit code is 1 when a case fails (here a world that does not load) and 2 when no case matches.
#include <filesystem>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/common/test_support.h"

namespace lamina {
namespace {

using test::CommandResult;
using test::RunHeadless;
using ::testing::HasSubstr;

TEST(StressCliTest, PatternPicksCasesAndTheJsonRecordsEach) {
  const std::string json_path = test::ScratchDir() + "/stress_cli.json";
  const CommandResult result = RunHeadless(
      "stress --cases 'drop_15m/*,absurd_torque/exact/*' -q --threads 2 --json " + json_path);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_THAT(result.out, HasSubstr("drop_15m/exact/10ms"));
  EXPECT_THAT(result.out, HasSubstr("absurd_torque/exact/1ms: flagged: status unstable"));
  const nlohmann::json json = nlohmann::json::parse(test::ReadFile(json_path));
  ASSERT_EQ(json["cases"].size(), 5u);  // drop_15m: exact 1 ms, quick 1 ms, exact and newton 10 ms
  EXPECT_EQ(json["failed"], 0);
  const nlohmann::json& drop = json["cases"][0];
  EXPECT_EQ(drop["name"], "drop_15m/exact/1ms");
  EXPECT_EQ(drop["verdict"], "stable");
  EXPECT_EQ(drop["step"], 1e-3);
  EXPECT_GT(drop["steps"].get<long>(), 2000);
  EXPECT_GT(drop["metric"]["value"].get<double>(), 0.0);  // no core below the floor
  EXPECT_LT(drop["metric"]["value"].get<double>(), 0.0025);
  const nlohmann::json& arm = json["cases"][4];
  EXPECT_EQ(arm["name"], "absurd_torque/exact/1ms");
  EXPECT_EQ(arm["verdict"], "flagged");
  EXPECT_EQ(arm["status"], "unstable");
  EXPECT_GT(arm["instability_corrections"].get<long>(), 0);
}

TEST(StressCliTest, AFailedCaseExitsWithOne) {
  const std::string worlds = test::ScratchDir() + "/stress_cli_worlds";
  std::filesystem::create_directories(worlds + "/stress");
  test::WriteScratchFile("stress_cli_worlds/stress/drop_15m.xml", "<world><nope");
  const CommandResult result =
      RunHeadless("stress --cases 'drop_15m/exact/1ms' -q --worlds " + worlds);
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_THAT(result.out, HasSubstr("drop_15m/exact/1ms: failed: the run did not start"));
  EXPECT_THAT(result.out, HasSubstr("drop_15m.xml"));
}

TEST(StressCliTest, NoMatchingCaseIsRefused) {
  const CommandResult result = RunHeadless("stress --cases 'nope*' -q");
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_THAT(result.err, HasSubstr("no case matches"));
  EXPECT_THAT(result.err, HasSubstr("box_stack_20/exact/1ms"));
}

}  // namespace
}  // namespace lamina
