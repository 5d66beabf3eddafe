// SPDX-License-Identifier: MIT
// `lamina-headless run` with every sensor type at once (worlds/examples/sensors.xml): the JSON
// report lists each sensor's measurements by Klamp't's names, and the CSV log has Klamp't
// SimTest's `<robot>_<sensor>[<measurement>]` columns, all while the arm presses on a block.
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/common/test_support.h"

namespace lamina {
namespace {

using test::CommandResult;
using test::RunHeadless;
using ::testing::Contains;
using ::testing::Not;

std::string SensorRun(const std::string& extra) {
  return "run --duration 3 " + test::WorldsPath("examples/sensors.xml") + " --path " +
         test::WorldsPath("examples/sensors_press.path") + " " + extra;
}

std::vector<std::string> Cells(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.push_back("");
  return cells;
}

// at 3 s the wrist presses on the block: its fingertip patch and its force/torque sensor read
// the same push (the F/T also carries the 0.1 kg ball), the encoders read the configuration
TEST(SensorsCliTest, JsonListsEverySensorsMeasurementsWhileTheArmPresses) {
  const CommandResult result = RunHeadless(SensorRun("--json"));
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json json = nlohmann::json::parse(result.out);
  const nlohmann::json& robot = json["robots"][0];
  const nlohmann::json& sensors = robot["sensors"];
  std::vector<std::string> types;
  for (const nlohmann::json& s : sensors) types.push_back(s["type"]);
  EXPECT_EQ(types.size(), 15u);
  for (const char* type :
       {"JointPositionSensor", "JointVelocitySensor", "DriverTorqueSensor", "ContactSensor",
        "ForceTorqueSensor", "Accelerometer", "TiltSensor", "GyroSensor", "IMUSensor",
        "LaserRangeSensor", "CameraSensor", "TransformedSensor", "CorruptedSensor",
        "FilteredSensor", "TimeDelayedSensor"}) {
    EXPECT_THAT(types, Contains(type));
  }
  const auto find = [&](const std::string& name) {
    for (const nlohmann::json& s : sensors) {
      if (s["name"] == name) return s;
    }
    ADD_FAILURE() << name;
    return nlohmann::json();
  };
  const double push = find("fingertip")["measurements"]["force_z"];
  EXPECT_EQ(find("fingertip")["measurements"]["contact"], 1.0);
  EXPECT_LT(push, -100.0);  // pressing in
  const double wrist = find("wrist")["measurements"]["force_z"];
  EXPECT_NEAR(wrist, push, 2.0);
  // sampled at 2.99 s (held still by the block), quantised to 1e-4 rad
  EXPECT_NEAR(find("encoders")["measurements"]["q[2]"].get<double>(),
              robot["config"][2].get<double>(), 1e-4);
  EXPECT_EQ(find("camera")["measurement_count"], 2 * 64 * 48);
  EXPECT_FALSE(find("camera").contains("measurements"));
  // grams: 101.97 × the wrist's force, clamped at ±5000
  EXPECT_NEAR(find("wrist_grams")["measurements"]["force_z"].get<double>(),
              std::max(-5000.0, 101.97 * wrist), 1e-6);
}

TEST(SensorsCliTest, TheLogHasKlamptsSensorColumnsAfterTheRobotsState) {
  const std::string log = test::ScratchDir() + "/sensors.csv";
  const CommandResult result = RunHeadless(SensorRun("--log " + log));
  ASSERT_EQ(result.exit_code, 0) << result.err;
  std::ifstream in(log);
  std::string line;
  ASSERT_TRUE(std::getline(in, line));
  const std::vector<std::string> header = Cells(line);
  EXPECT_THAT(header, Contains("tx90_encoders[q[0]]"));
  EXPECT_THAT(header, Contains("tx90_fingertip[force_z]"));
  EXPECT_THAT(header, Contains("tx90_imu[R_zz]"));
  EXPECT_THAT(header, Contains("tx90_lidar[d[60]]"));
  EXPECT_THAT(header, Contains("tx90_late_encoders[q[6]]"));
  EXPECT_THAT(header, Not(Contains("tx90_camera[rgb[0,0]]")));  // images are not logged
  int rows = 0;
  size_t late = 0;
  for (size_t i = 0; i < header.size(); ++i) {
    if (header[i] == "tx90_late_encoders[q[1]]") late = i;
  }
  ASSERT_GT(late, 0u);
  std::vector<std::string> last;
  while (std::getline(in, line)) {
    last = Cells(line);
    ASSERT_EQ(last.size(), header.size()) << "row " << rows;
    if (rows == 0) {
      EXPECT_EQ(last[late], "");  // nothing delivered at t = 0
    }
    ++rows;
  }
  EXPECT_EQ(rows, 301);
  EXPECT_NE(last[late], "");
}

}  // namespace
}  // namespace lamina
