// SPDX-License-Identifier: MIT
// RobotSensors: the sensors of one simulated robot (Klamp't's RobotSensors inside its
// SimRobotController), read from the robot's `sensors` property (a `<sensors>` XML block from a
// world file, a `.rob` `property sensors` line or URDF `<klampt>`), else Klamp't's defaults: a
// JointPositionSensor "q" and a JointVelocitySensor "dq" over every link.
//
// Schedule (Klamp't's SimRobotController::Step): at the start of every physics step, before the
// controller runs, each enabled sensor whose next time has come (time ≥ next − 1 ns) takes a
// sample of the state the step starts from, then advances by its period (1/rate, or the control
// period when rate is 0; never shorter than the physics step) and its next time moves on by
// that period. Between samples a sensor holds its measurements. Sensors start at the first step.
// Every sample's noise comes from the sensor's own counter-based generator, seeded from the
// robot's and the sensor's names: a run is the same however it is chunked, and restoring a
// state (which holds the counters, the next times, the measurements and each sensor's own
// state) repeats it exactly.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/diagnostics.h"
#include "core/sensors/sensor.h"

namespace tinyxml2 {
class XMLElement;
}

namespace lamina::core {

/// Everything RobotSensors evolves, for exact save and restore.
struct RobotSensorsState {
  bool started = false;
  std::vector<double> next_times;  ///< s, per sensor
  std::vector<std::vector<double>> measurements, internal;
  std::vector<std::uint64_t> noise_counts;
  VecX ddq;                           ///< the last physics step's joint accelerations
  std::vector<LinkContact> contacts;  ///< the last physics step's contacts on the robot
};

/// The sensors of a `<sensors>` element (each child's tag is a Klamp't type, its attributes the
/// settings, `name` its name; wrappers bind their `sensor` by name to an earlier one).
/// Problems are reported at `file`:(child's line + line_offset): an unknown type or a wrapper
/// whose sensor is missing drops that sensor (an error), an unknown or bad attribute is ignored
/// with a warning, as is a repeated name.
std::vector<std::unique_ptr<Sensor>> ParseSensorsElement(const tinyxml2::XMLElement& sensors,
                                                         const RobotDesc& robot,
                                                         const std::string& file, int line_offset,
                                                         Diagnostics* diagnostics);
/// The same from XML text whose first line is `first_line` (line 0: lines of the text).
std::vector<std::unique_ptr<Sensor>> ParseSensorsXml(const std::string& xml,
                                                     const RobotDesc& robot,
                                                     const SourceLocation& first_line,
                                                     Diagnostics* diagnostics);

class RobotSensors {
 public:
  RobotSensors() = default;
  /// The sensors of `robot` (which must outlive this): its `sensors` property, or q and dq.
  /// Problems of the property go to `diagnostics` (may be null) under the robot's file.
  RobotSensors(const RobotDesc& robot, Diagnostics* diagnostics);
  RobotSensors(RobotSensors&&) noexcept;
  RobotSensors& operator=(RobotSensors&&) noexcept;
  ~RobotSensors();

  int size() const { return static_cast<int>(sensors_.size()); }
  Sensor& sensor(int i) { return *sensors_.at(i); }
  const Sensor& sensor(int i) const { return *sensors_.at(i); }
  /// Index of the sensor named `name`, or -1.
  int Find(const std::string& name) const;
  /// The robot declares no sensors: these are the defaults q and dq.
  bool defaults() const { return defaults_; }

  /// Some sensor reads contacts (contact and force/torque sensors).
  bool needs_contacts() const;
  /// Some enabled sensor is due in a step starting at `time` (s).
  bool AnyDue(double time) const;
  /// Samples every due sensor (see the schedule above) for a step of `step` s.
  void Sample(const SensorInputs& inputs, double step, double control_period);
  /// After an accepted physics step: its joint accelerations and contacts, inputs of the next
  /// samples.
  void RecordStep(VecX ddq, std::vector<LinkContact> contacts);
  const VecX& last_ddq() const { return ddq_; }
  const std::vector<LinkContact>& last_contacts() const { return contacts_; }

  /// Back to the start: every sensor reset, no sample taken.
  void Reset();
  RobotSensorsState GetState() const;
  /// False (nothing changed) when the state is of another sensor list.
  bool SetState(const RobotSensorsState& state);

 private:
  void Seed(const std::string& robot_name);
  std::vector<std::unique_ptr<Sensor>> sensors_;
  std::vector<double> next_times_;
  bool started_ = false;
  bool defaults_ = false;
  VecX ddq_;
  std::vector<LinkContact> contacts_;
};

}  // namespace lamina::core
