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
  double sample_time = 0.0;           ///< s, of the last sample (when started)
  VecX sample_dq;                     ///< the joint rates then
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
std::vector<std::unique_ptr<Sensor>> ParseSensorsXml(const std::string& xml, const RobotDesc& robot,
                                                     const SourceLocation& first_line,
                                                     Diagnostics* diagnostics);

/// A sensor's state copied off the simulation, for a view on another thread (the editor).
struct SensorReadout {
  std::string name, type;
  int link = -1;
  bool image = false;              ///< a camera: names and values left out
  std::vector<std::string> names;  ///< measurement names
  std::vector<double> values;      ///< measurements (fewer than names before a delivery)
};

/// A sensor whose measurements are an image (CameraSensor): left out of logs and reports, which
/// list it with its size only (`run --sensor-images` writes the images).
bool IsImageSensor(const Sensor& sensor);

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
  /// Simulation time (s) of sensor i's next sample; it moves on by the sensor's period at
  /// every sample (0 before the first).
  double next_time(int i) const { return next_times_.at(i); }
  /// Some sensor is an image sensor (a camera): the simulation needs a CameraRenderer.
  bool has_images() const { return has_images_; }
  /// The robot declares no sensors: these are the defaults q and dq.
  bool defaults() const { return defaults_; }

  /// Some sensor reads contacts (contact and force/torque sensors).
  bool needs_contacts() const { return needs_contacts_; }
  /// Some sensor reads link motion, rays or pictures (all but joint and driver sensors and
  /// wrappers); some reads the drivers' efforts (DriverTorqueSensor). The simulation computes
  /// only the inputs that are read.
  bool needs_motion() const { return needs_motion_; }
  bool needs_driver_torques() const { return needs_driver_torques_; }
  /// Some enabled sensor is due in a step starting at `time` (s).
  bool AnyDue(double time) const;
  /// Samples every due sensor (see the schedule above) for a step of `step` s, and keeps the
  /// time and the joint rates of `inputs` for the next MeanAcceleration.
  void Sample(const SensorInputs& inputs, double step, double control_period);
  /// The joint accelerations sensors see at `time` with rates `dq`: the mean since the robot's
  /// last sample, (dq − dq_last) / (time − t_last) (zero before the first). Like Klamp't's
  /// difference over the sensor period, this is what a sampled sensor's anti-aliasing gives: a
  /// sample at the control rate does not alias a stiff servo's vibration at the physics rate
  /// into a bias (a TX90 tracking a ramp read 48 m/s² of it from one-step differences).
  VecX MeanAcceleration(double time, const VecX& dq) const;
  /// After an accepted physics step: its contacts on the robot, inputs of the next samples.
  void RecordContacts(std::vector<LinkContact> contacts) { contacts_ = std::move(contacts); }
  const std::vector<LinkContact>& last_contacts() const { return contacts_; }

  /// What the controller senses (Klamp't's controllers read their joint sensors): the
  /// measurements of the first enabled JointPositionSensor (JointVelocitySensor with
  /// `velocity`) that measures every link, written into `*out`; false (nothing written) when
  /// there is none or it has not sampled yet.
  bool SensedJoints(bool velocity, VecX* out) const;

  /// Every sensor's readout, in order.
  std::vector<SensorReadout> Readouts() const;
  /// Every sensor drawn for links at `link_frames` (world).
  SensorDrawing Drawing(const std::vector<Pose>& link_frames) const;

  /// Back to the start: every sensor reset, no sample taken.
  void Reset();
  RobotSensorsState GetState() const;
  /// False (nothing changed) when the state is of another sensor list.
  bool SetState(const RobotSensorsState& state);

 private:
  void Seed(const std::string& robot_name);
  void FindNeeds();
  std::vector<std::unique_ptr<Sensor>> sensors_;
  std::vector<double> next_times_;
  bool started_ = false;
  bool defaults_ = false;
  bool needs_contacts_ = false, needs_motion_ = false, needs_driver_torques_ = false;
  bool has_images_ = false;
  double sample_time_ = 0.0;
  VecX sample_dq_;
  std::vector<LinkContact> contacts_;
};

}  // namespace lamina::core
