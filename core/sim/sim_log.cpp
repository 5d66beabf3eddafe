// SPDX-License-Identifier: MIT
#include "core/sim/sim_log.h"

#include "core/number_text.h"
#include "core/sim/sim_timing.h"

namespace lamina::core {

namespace {

// Klamp't SimTest's sensor columns, `<robot>_<sensor>[<measurement>]` and an empty column per
// sensor, after every robot's state; image sensors are left out (their measurements are images)
std::string SensorHeader(const Simulator& simulator) {
  std::string header;
  for (int r = 0; r < simulator.robot_count(); ++r) {
    const RobotSensors& sensors = simulator.sensors(r);
    for (int i = 0; i < sensors.size(); ++i) {
      const Sensor& s = sensors.sensor(i);
      if (IsImageSensor(s)) continue;
      const std::string prefix = simulator.world().robots[r].name + "_" + s.name() + "[";
      for (const std::string& name : s.MeasurementNames()) header += prefix + name + "],";
      header += ",";
    }
  }
  return header;
}

// a sensor with fewer measurements than names (a delayed one before its first delivery)
// leaves the rest of its columns empty
std::string SensorRow(const Simulator& simulator) {
  std::string row;
  for (int r = 0; r < simulator.robot_count(); ++r) {
    const RobotSensors& sensors = simulator.sensors(r);
    for (int i = 0; i < sensors.size(); ++i) {
      const Sensor& s = sensors.sensor(i);
      if (IsImageSensor(s)) continue;
      const size_t n = s.MeasurementNames().size();
      for (size_t k = 0; k < n; ++k) {
        row += (k < s.measurements().size() ? FormatDouble(s.measurements()[k]) : "") + ",";
      }
      row += ",";
    }
  }
  return row;
}

}  // namespace

std::string SimLogHeader(const Simulator& simulator) {
  std::string header = "time,";
  // robots first, as Klamp't's simtest_log.csv: configuration, velocity, actuator torques
  for (const RobotDesc& robot : simulator.world().robots) {
    for (const char* column : {"_q[", "_dq["}) {
      for (const LinkDesc& link : robot.links) header += robot.name + column + link.name + "],";
    }
    for (const DriverDesc& driver : robot.drivers) {
      header += robot.name + "_torque[" + driver.name + "],";
    }
    header += ",";
  }
  header += SensorHeader(simulator);
  for (const RigidObjectDesc& object : simulator.world().objects) {
    for (const char* column :
         {"_x", "_y", "_z", "_rz", "_ry", "_rx", "_dx", "_dy", "_dz", "_wz", "_wy", "_wx"}) {
      header += object.name + column + ",";
    }
    header += ",";
  }
  return header + "\n";
}

std::string SimLogRow(const Simulator& simulator) {
  std::string row = FormatDouble(simulator.time()) + ",";
  for (int r = 0; r < simulator.robot_count(); ++r) {
    for (const VecX& values : {simulator.GetRobotConfig(r), simulator.GetRobotVelocity(r),
                               simulator.GetActuatorTorques(r)}) {
      for (const double value : values) row += FormatDouble(value) + ",";
    }
    row += ",";
  }
  row += SensorRow(simulator);
  for (int i = 0; i < simulator.object_count(); ++i) {
    const Pose pose = simulator.GetObjectPose(i);
    const Vec3 rpy = RollPitchYawFromRotation(pose.linear());
    const Twist velocity = simulator.GetObjectVelocity(i);
    const double values[12] = {pose.translation().x(),
                               pose.translation().y(),
                               pose.translation().z(),
                               rpy.z(),
                               rpy.y(),
                               rpy.x(),
                               velocity.linear.x(),
                               velocity.linear.y(),
                               velocity.linear.z(),
                               velocity.angular.z(),
                               velocity.angular.y(),
                               velocity.angular.x()};
    for (double value : values) row += FormatDouble(value) + ",";
    row += ",";
  }
  return row + "\n";
}

SimLogWriter::SimLogWriter(std::ostream* out, const Simulator& simulator, double interval)
    : out_(out), interval_(interval) {
  *out_ << SimLogHeader(simulator);
  Write(simulator);
}

void SimLogWriter::operator()(const StepEvent& event) {
  // a mark reached within a part per million of the interval counts (accumulated step times)
  if (event.time < next_ - 1e-6 * interval_) return;
  Write(event.simulator);
}

void SimLogWriter::Finish(const Simulator& simulator) {
  if (simulator.time() > last_row_) Write(simulator);
}

void SimLogWriter::Write(const Simulator& simulator) {
  Stopwatch watch;
  *out_ << SimLogRow(simulator);
  last_row_ = simulator.time();
  while (next_ <= last_row_ + 1e-6 * interval_) next_ += interval_;
  seconds_ += watch.Lap();
}

}  // namespace lamina::core
