// SPDX-License-Identifier: MIT
// `lamina-headless info`: runs the real binary and checks its output, exit code and
// diagnostics.
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/common/test_support.h"

namespace lamina {
namespace {

using test::CommandResult;
using test::RunHeadless;

TEST(InfoCommandTest, JsonDescribesAthleteWorld) {
  const CommandResult result =
      RunHeadless("info --json " + test::WorldsPath("klampt/athlete_fractal_1.xml"));
  ASSERT_EQ(result.exit_code, 0) << result.err;
  // the one warning is the athlete.rob continuation quirk, reported on stderr
  EXPECT_THAT(result.err, ::testing::HasSubstr("athlete.rob:247: warning: 'servoI' continues"));
  const nlohmann::json json = nlohmann::json::parse(result.out);
  ASSERT_EQ(json["robots"].size(), 1u);
  EXPECT_EQ(json["robots"][0]["name"], "ATHLETE");
  EXPECT_EQ(json["robots"][0]["links"], 42);
  EXPECT_EQ(json["robots"][0]["drivers"], 36);
  EXPECT_EQ(json["terrains"][0]["triangles"], 32768);
  EXPECT_EQ(json["simulation"]["timestep"], 0.001);
  EXPECT_EQ(json["simulation"]["maxContacts"], 20);
}

TEST(InfoCommandTest, TextListsEveryObject) {
  const CommandResult result =
      RunHeadless("info " + test::WorldsPath("klampt/simulation_test_worlds/bounce_test.xml"));
  ASSERT_EQ(result.exit_code, 0) << result.out;
  EXPECT_THAT(result.out, ::testing::HasSubstr("object 10 'sphere10': mass 1 kg"));
  EXPECT_THAT(result.out, ::testing::HasSubstr("terrain 0 'Terrain0': 12 triangles"));
}

TEST(InfoCommandTest, ErrorsExitNonZeroWithDiagnostics) {
  const std::string path =
      test::WriteScratchFile("bad.xml", "<world>\n  <robot name=\"r\"/>\n  <terrain/>\n</world>\n");
  const CommandResult result = RunHeadless("info " + path);
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(result.out, "");
  EXPECT_EQ(result.err, path + ":2: error: <robot name=\"r\">: missing attribute 'file'\n" + path +
                            ":3: error: <terrain>: missing attribute 'file'\n");
}

TEST(InfoCommandTest, MissingArgumentIsAUsageError) {
  const CommandResult result = RunHeadless("info");
  EXPECT_NE(result.exit_code, 0);
  EXPECT_THAT(result.err, ::testing::HasSubstr("world is required"));
}

}  // namespace
}  // namespace lamina
