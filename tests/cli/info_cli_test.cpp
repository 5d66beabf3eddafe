// SPDX-License-Identifier: MIT
// `lamina-headless info`: runs the real binary and checks its output, exit code and
// diagnostics.
#include <array>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/common/test_support.h"

namespace lamina {
namespace {

struct CommandResult {
  int exit_code = -1;
  std::string out;  // standard output
  std::string err;  // standard error
};

CommandResult RunHeadless(const std::string& arguments) {
  const std::string err_path = test::ScratchDir() + "/stderr.txt";
  const std::string command =
      std::string(LAMINA_BIN_DIR) + "/lamina-headless " + arguments + " 2>" + err_path;
  CommandResult result;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return result;
  std::array<char, 4096> buffer{};
  size_t read = 0;
  while ((read = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) {
    result.out.append(buffer.data(), read);
  }
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream err(err_path);
  result.err.assign(std::istreambuf_iterator<char>(err), std::istreambuf_iterator<char>());
  return result;
}

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
