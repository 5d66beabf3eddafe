// SPDX-License-Identifier: MIT
// `lamina-headless run|info --set PATH=VALUE` and `run --get PATH`: an edit that changes the
// outcome of a run, the JSON and text forms of the values, and one clear message with status 2
// for every bad path or value.
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/common/test_support.h"

namespace lamina {
namespace {

using test::CommandResult;
using test::RunHeadless;

using test::kGravity;

// tests/data/worlds/sliding_block.xml: "block" slides at 1 m/s, friction 0.5 on both surfaces
std::string SlidingBlock() {
  return test::DataPath("worlds/sliding_block.xml");
}

// x where a block sliding at 1 m/s stops with pair friction mu
double StoppingDistance(double mu) {
  return 1.0 / (2 * mu * kGravity);
}

nlohmann::json RunJson(const std::string& arguments) {
  const CommandResult result = RunHeadless("run --json --duration 1 " + arguments);
  EXPECT_EQ(result.exit_code, 0) << result.err;
  return nlohmann::json::parse(result.out, nullptr, false);
}

// the must-show case: the edit changes where the block stops, and --get reports it
TEST(SetGetCommandTest, FrictionSetChangesWhereTheBlockStopsAndGetReportsIt) {
  const nlohmann::json plain = RunJson(SlidingBlock() + " --get 'objects[block].kFriction'");
  const nlohmann::json edited = RunJson(SlidingBlock() +
                                        " --set 'objects[block].kFriction=0.1'"
                                        " --get 'objects[block].kFriction'");
  ASSERT_FALSE(plain.is_discarded());
  ASSERT_FALSE(edited.is_discarded());
  EXPECT_EQ(plain["get"]["objects[block].kFriction"], 0.5);
  EXPECT_EQ(edited["get"]["objects[block].kFriction"], 0.1);
  // pair friction: 0.5 and 0.5 -> 0.5; 0.1 and 0.5 -> the harmonic mean 1/6
  const double plain_x = plain["objects"][0]["position"][0].get<double>();
  const double edited_x = edited["objects"][0]["position"][0].get<double>();
  // (the 1 ms steps stop it within a millimetre of the continuous answer)
  EXPECT_NEAR(plain_x, StoppingDistance(0.5), 2e-3);
  EXPECT_NEAR(edited_x, StoppingDistance(1.0 / 6.0), 2e-3);
}

TEST(SetGetCommandTest, JsonGetHoldsNumbersArraysAndInfinities) {
  const nlohmann::json json =
      RunJson(SlidingBlock() +
              " --set 'settings.gravity[2]=-5' --get time --get settings.gravity"
              " --get 'objects[\"block\"].kStiffness' --get 'rigidObjects[0].transform'"
              " --get 'objects[block].velocity[3]'");
  ASSERT_FALSE(json.is_discarded());
  const nlohmann::json& get = json["get"];
  ASSERT_EQ(get.size(), 5u);
  EXPECT_NEAR(get["time"].get<double>(), 1.0, 1e-12);
  EXPECT_EQ(get["settings.gravity"], nlohmann::json::array({0.0, 0.0, -5.0}));
  // the block is rigid: inf, written as the rest of the JSON writes it
  EXPECT_EQ(get["objects[\"block\"].kStiffness"], "inf");
  ASSERT_EQ(get["rigidObjects[0].transform"].size(), 12u);
  // the final pose: x where the block stopped under g = 5 (friction 0.5 g = 2.5 m/s²)
  EXPECT_NEAR(get["rigidObjects[0].transform"][9].get<double>(), 1.0 / (2 * 0.5 * 5.0), 2e-3);
  EXPECT_NEAR(get["objects[block].velocity[3]"].get<double>(), 0.0, 1e-3);
}

TEST(SetGetCommandTest, TextReportEndsWithOneLinePerGet) {
  const CommandResult result =
      RunHeadless("run --duration 0.1 " + SlidingBlock() +
                  " --set 'objects[block].kFriction=0.25' --get 'objects[block].kFriction'"
                  " --get settings.solver --get settings.adaptiveTimeStepping");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_THAT(result.out, testing::EndsWith("objects[block].kFriction = 0.25\n"
                                            "settings.solver = step\n"
                                            "settings.adaptiveTimeStepping = true\n"));
}

TEST(SetGetCommandTest, InfoSetShowsTheEditedWorld) {
  const CommandResult result =
      RunHeadless("info --json " + SlidingBlock() +
                  " --set 'objects[block].kFriction=0.25' --set 'terrains[floor].padding=0.001'");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json json = nlohmann::json::parse(result.out);
  EXPECT_EQ(json["objects"][0]["simulation"]["kFriction"], 0.25);
  EXPECT_EQ(json["terrains"][0]["simulation"]["padding"], 0.001);
  const CommandResult text =
      RunHeadless("info " + SlidingBlock() + " --set 'objects[block].kFriction=0.25'");
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_THAT(text.out, testing::HasSubstr("kFriction 0.25"));
}

// run's defaults do not override the world's settings: without --solver and --sleep the
// description's solver and sleeping (here as edited by --set) are the simulation's
TEST(SetGetCommandTest, SettingsSetOnTheWorldAreNotOverriddenByRunsDefaults) {
  const nlohmann::json asleep =
      RunJson(SlidingBlock() + " --set settings.sleeping=true --get settings.sleeping");
  ASSERT_FALSE(asleep.is_discarded());
  EXPECT_EQ(asleep["get"]["settings.sleeping"], 1.0);
  // the block stops after 0.2 s and has been idle for the sleep time (0.5 s) by 1 s
  EXPECT_EQ(asleep["sleeping_objects"], 1);
  const nlohmann::json quick =
      RunJson(SlidingBlock() + " --set settings.solver=quick --get settings.solver");
  EXPECT_EQ(quick["get"]["settings.solver"], 1.0);  // the index of "quick"
  // --solver still overrides the world
  const nlohmann::json step =
      RunJson(SlidingBlock() + " --set settings.solver=quick --solver step --get settings.solver");
  EXPECT_EQ(step["get"]["settings.solver"], 0.0);
}

// a bad argument: status 2, nothing on stdout, one line on stderr
void ExpectRefused(const std::string& arguments, const std::string& message) {
  const CommandResult result = RunHeadless(arguments);
  EXPECT_EQ(result.exit_code, 2) << arguments;
  EXPECT_EQ(result.out, "") << arguments;
  EXPECT_EQ(result.err, message + "\n") << arguments;
}

TEST(SetGetCommandTest, BadPathsAndValuesExitWithOneMessage) {
  const std::string run = "run --json " + SlidingBlock();
  ExpectRefused(run + " --set 'objects[blok].kFriction=0.1'",
                "lamina-headless: --set 'objects[blok].kFriction=0.1': objects[blok]: no object "
                "is named 'blok' (did you mean 'block'?)");
  ExpectRefused(run + " --set 'objects[block].kRestitution=1.5'",
                "lamina-headless: --set 'objects[block].kRestitution=1.5': "
                "objects[block].kRestitution must be in [0, 1], got 1.5");
  ExpectRefused(run + " --set 'settings.gravity=nan,0,0'",
                "lamina-headless: --set 'settings.gravity=nan,0,0': settings.gravity must be 3 "
                "finite numbers, got nan,0,0");
  ExpectRefused(run + " --set 'objects[0].kFrction=0.1'",
                "lamina-headless: --set 'objects[0].kFrction=0.1': objects[0].kFrction: objects "
                "have no 'kFrction' (did you mean 'kFriction'?)");
  ExpectRefused(run + " --set 'objects[0].kFriction'",
                "lamina-headless: --set 'objects[0].kFriction': 'objects[0].kFriction': expected "
                "PATH=VALUE");
  ExpectRefused(run + " --get 'robots[0].config'",
                "lamina-headless: --get 'robots[0].config': robots[0]: the world has 0 robots");
}

// robots[0].actualConfig is a state item: set on the simulation once it is built (the sphere
// robot's three prismatic joints, x y z), while robots[0].config is the initial row
TEST(SetGetCommandTest, StateItemsAreSetOnTheBuiltSimulation) {
  const CommandResult result =
      RunHeadless("run --json --duration 0.001 " + test::WorldsPath("klampt/block.xml") +
                  " --set 'robots[robot].actualConfig=0.2,0.1,0.5' --get 'robots[robot].config'"
                  " --get 'controllers[robot].sensedConfig'");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json json = nlohmann::json::parse(result.out);
  const nlohmann::json& config = json["get"]["robots[robot].config"];
  ASSERT_EQ(config.size(), 3u);
  // one millisecond later: moved by at most a few micrometres
  EXPECT_NEAR(config[0].get<double>(), 0.2, 1e-4);
  EXPECT_NEAR(config[1].get<double>(), 0.1, 1e-4);
  EXPECT_NEAR(config[2].get<double>(), 0.5, 1e-4);
}

// a read-only state item is refused on the simulation, and on a description it does not exist
TEST(SetGetCommandTest, ReadOnlyAndSimulationOnlyItemsAreRefused) {
  ExpectRefused("run " + SlidingBlock() + " --set time=1",
                "lamina-headless: --set 'time=1': time: read-only");
  ExpectRefused("info " + SlidingBlock() + " --set time=1",
                "lamina-headless: --set 'time=1': time: exists only on a running simulation");
}

}  // namespace
}  // namespace lamina
