// SPDX-License-Identifier: MIT
// `lamina-headless run`: the JSON report of a real run, the CSV log, and bad options.
#include <fstream>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/model/params.h"
#include "tests/common/test_support.h"

namespace lamina {
namespace {

using test::CommandResult;
using test::RunHeadless;

TEST(RunCommandTest, JsonReportsFreeFallBeforeImpact) {
  const CommandResult result =
      RunHeadless("run --json --duration 0.3 " +
                  test::WorldsPath("klampt/simulation_test_worlds/bounce_test.xml"));
  ASSERT_EQ(result.exit_code, 0) << result.out;
  const nlohmann::json json = nlohmann::json::parse(result.out);
  EXPECT_NEAR(json["time"].get<double>(), 0.3, 1e-12);
  EXPECT_EQ(json["steps"], 300);
  EXPECT_EQ(json["status"], "normal");
  EXPECT_EQ(json["rollbacks"], 0);
  EXPECT_EQ(json["instability_corrections"], 0);
  ASSERT_EQ(json["objects"].size(), 10u);
  const nlohmann::json& sphere = json["objects"][0];
  EXPECT_EQ(sphere["name"], "sphere1");
  // still falling at 0.3 s (the slab top is z = 0; impact near 0.62 s): z = 2 - g t^2/2 - g h t/2
  const double g = 9.8, t = 0.3, h = 0.001;
  EXPECT_NEAR(sphere["position"][2].get<double>(), 2.0 - g * t * t / 2 - g * h * t / 2, 1e-9);
  EXPECT_NEAR(sphere["velocity"][2].get<double>(), -g * t, 1e-9);
  EXPECT_EQ(sphere["quaternion"][0], 1.0);
}

// --sleep: the tower of stacktest.xml settles and sleeps as one island after sleepTime idle
TEST(RunCommandTest, SleepLetsTheSettledTowerSleep) {
  const std::string world = test::WorldsPath("klampt/simulation_test_worlds/stacktest.xml");
  const CommandResult awake = RunHeadless("run --json --duration 2 " + world);
  const CommandResult asleep = RunHeadless("run --json --sleep --duration 2 " + world);
  ASSERT_EQ(awake.exit_code, 0) << awake.out;
  ASSERT_EQ(asleep.exit_code, 0) << asleep.out;
  const nlohmann::json without = nlohmann::json::parse(awake.out);
  const nlohmann::json with = nlohmann::json::parse(asleep.out);
  EXPECT_EQ(without["sleeping_objects"], 0);
  EXPECT_EQ(with["sleeping_objects"], 10);
  for (size_t i = 0; i < 10; ++i) {
    EXPECT_TRUE(with["objects"][i]["asleep"].get<bool>());
    // asleep where the tower stood anyway: within 0.1 mm of the run without sleeping
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(with["objects"][i]["position"][k].get<double>(),
                  without["objects"][i]["position"][k].get<double>(), 1e-4);
    }
  }
}

TEST(RunCommandTest, JsonReportsContactsAndTheTimeSplit) {
  const CommandResult result =
      RunHeadless("run --json --duration 0.2 " +
                  test::WorldsPath("klampt/simulation_test_worlds/stacktest.xml"));
  ASSERT_EQ(result.exit_code, 0) << result.out;
  const nlohmann::json json = nlohmann::json::parse(result.out);
  // ten boxes, each resting on the one below (or the slab) on 4 corners: 40 contacts per step
  // once the initial millimetre gaps have closed
  EXPECT_EQ(json["max_contacts"], 40);
  EXPECT_GT(json["mean_contacts"].get<double>(), 36.0);
  EXPECT_LE(json["mean_contacts"].get<double>(), 40.0);
  EXPECT_EQ(json["instability_corrections"], 0);
  const nlohmann::json& split = json["time_split"];
  double parts = 0.0;
  for (const char* part : {"broad_phase", "contact_generation", "clustering", "solver", "other"}) {
    ASSERT_TRUE(split.contains(part)) << part;
    EXPECT_GE(split[part].get<double>(), 0.0) << part;
    parts += split[part].get<double>();
  }
  // the parts cover the time spent in Simulate, which is most of the wall time reported
  EXPECT_GT(parts, 0.0);
  EXPECT_LE(parts, json["wall_time"].get<double>() * 1.05 + 1e-3);
}

// The exact solver gives the 10-box stack's island (40 contacts) to the Newton solver every step;
// --ode-objects leaves it to dWorldStep's own LCP, with the same result to rounding
TEST(RunCommandTest, OdeObjectsLeavesTheStackToDWorldStep) {
  const std::string world = test::WorldsPath("accuracy/box_stack.xml");
  const CommandResult own = RunHeadless("run --json --duration 0.2 --dt 0.001 " + world);
  const CommandResult ode =
      RunHeadless("run --json --duration 0.2 --dt 0.001 --ode-objects " + world);
  ASSERT_EQ(own.exit_code, 0) << own.out;
  ASSERT_EQ(ode.exit_code, 0) << ode.out;
  const nlohmann::json with = nlohmann::json::parse(own.out);
  const nlohmann::json without = nlohmann::json::parse(ode.out);
  EXPECT_EQ(with["newton"]["islands"], 200);
  EXPECT_EQ(with["newton"]["fallbacks"], 0);
  EXPECT_EQ(without["newton"]["islands"], 0);
  for (size_t i = 0; i < 10; ++i) {
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(with["objects"][i]["position"][k].get<double>(),
                  without["objects"][i]["position"][k].get<double>(), 1e-12);
    }
  }
}

TEST(RunCommandTest, LogFollowsKlamptColumns) {
  const std::string log = test::ScratchDir() + "/log.csv";
  const CommandResult result =
      RunHeadless("run --duration 0.05 --log " + log + " " +
                  test::WorldsPath("klampt/simulation_test_worlds/heavyblocktest.xml"));
  ASSERT_EQ(result.exit_code, 0) << result.out;
  std::ifstream in(log);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header,
            "time,block_1kg_x,block_1kg_y,block_1kg_z,block_1kg_rz,block_1kg_ry,block_1kg_rx,"
            "block_1kg_dx,block_1kg_dy,block_1kg_dz,block_1kg_wz,block_1kg_wy,block_1kg_wx,,"
            "block_100kg_x,block_100kg_y,block_100kg_z,block_100kg_rz,block_100kg_ry,"
            "block_100kg_rx,block_100kg_dx,block_100kg_dy,block_100kg_dz,block_100kg_wz,"
            "block_100kg_wy,block_100kg_wx,,");
  std::vector<double> times;
  std::string line;
  while (std::getline(in, line)) times.push_back(std::stod(line.substr(0, line.find(','))));
  // the initial state and one row every 0.01 s (written by a step observer in one run)
  ASSERT_EQ(times.size(), 6u);
  for (size_t i = 0; i < times.size(); ++i) EXPECT_NEAR(times[i], 0.01 * i, 1e-12);
}

TEST(RunCommandTest, JsonReportsEverySettingInForce) {
  const CommandResult result =
      RunHeadless("run --duration 0.01 --json --set settings.frictionAnchorGain=0.3 " +
                  test::WorldsPath("klampt/simulation_test_worlds/heavyblocktest.xml"));
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json report = nlohmann::json::parse(result.out);
  const nlohmann::json& settings = report.at("settings");
  for (const core::ParamSpec* spec : core::ParamsOf(core::ElementKind::kSettings)) {
    EXPECT_TRUE(settings.contains(std::string(spec->key))) << spec->key;
  }
  EXPECT_EQ(settings.at("frictionAnchorGain"), 0.3);
  EXPECT_EQ(settings.at("solver"), "step");
  EXPECT_EQ(settings.at("minimumAdaptiveTimeStep"), 1e-6);
  EXPECT_EQ(report.at("unreliable_steps"), 0);
}

TEST(RunCommandTest, BadSolverIsAUsageError) {
  const CommandResult result =
      RunHeadless("run --solver fast " + test::WorldsPath("klampt/block.xml"));
  EXPECT_EQ(result.exit_code, 2);
}

// --milestones sends the milestones to robot 0 (a damped one-link arm): after the motion it holds
// the last milestone; the report gives the configuration, the commanded one and the error
TEST(RunCommandTest, MilestonesDriveRobotZeroAndTheReportTracksIt) {
  const std::string rob = test::WriteScratchFile(
      "cli_robot/arm1.rob",
      "links \"arm\"\nparents -1\nTParent 1 0 0  0 1 0  0 0 1  0 0 0\naxis 0 1 0\nmass 1\n"
      "com 0.25 0 0\n"
      "inertia 0.01 0 0  0 0.03 0  0 0 0.03\nvelMax 2\naccMax 4\njoint normal 0\n"
      "driver normal 0\nservoP 50\nservoI 0\nservoD 5\n");
  const std::string world =
      test::WriteScratchFile("cli_robot/arm_world.xml",
                             "<world>\n  <robot name=\"arm\" file=\"" + rob +
                                 "\"/>\n  <simulation><globals gravity=\"0 0 0\"/></simulation>\n"
                                 "</world>\n");
  // to 0.5 rad, then to -0.3 rad, at rest at both
  const std::string milestones =
      test::WriteScratchFile("cli_robot/arm.milestones", "1 0.5  1 0\n1 -0.3  1 0\n");
  const CommandResult result =
      RunHeadless("run --json --duration 4 " + world + " --milestones " + milestones);
  ASSERT_EQ(result.exit_code, 0) << result.out << result.err;
  const nlohmann::json json = nlohmann::json::parse(result.out);
  ASSERT_EQ(json["robots"].size(), 1u);
  const nlohmann::json& robot = json["robots"][0];
  EXPECT_EQ(robot["name"], "arm");
  ASSERT_TRUE(robot.contains("commanded_config"));
  EXPECT_EQ(robot["velocity"].size(), 1u);
  EXPECT_EQ(robot["actuator_torques"].size(), 1u);
  // ramps of 2 sqrt(0.5 / 4) + 2 sqrt(0.8 / 4) = 1.6 s end long before 4 s
  EXPECT_NEAR(robot["commanded_config"][0].get<double>(), -0.3, 1e-9);
  EXPECT_NEAR(robot["config"][0].get<double>(), -0.3, 1e-3);
  EXPECT_LT(robot["tracking_error"].get<double>(), 1e-3);

  // the log gets the robot's columns first: q, dq and actuator torques, then a blank column
  const std::string log = test::ScratchDir() + "/arm_log.csv";
  const CommandResult logged = RunHeadless("run --duration 0.05 " + world + " --log " + log);
  ASSERT_EQ(logged.exit_code, 0) << logged.err;
  std::ifstream file(log);
  std::string header;
  std::getline(file, header);
  EXPECT_EQ(header.rfind("time,arm_q[arm],arm_dq[arm],arm_torque[", 0), 0u) << header;
}

TEST(RunCommandTest, MotionForAWorldWithoutRobotIsAnError) {
  const CommandResult result = RunHeadless(
      "run --duration 0.1 " + test::WorldsPath("klampt/simulation_test_worlds/bounce_test.xml") +
      " --path " + test::DataPath("motions/arm.path"));
  EXPECT_NE(result.exit_code, 0);
  EXPECT_NE(result.err.find("no robot"), std::string::npos) << result.err;
}

}  // namespace
}  // namespace lamina
