// SPDX-License-Identifier: MIT
// The sensor types, grouped by file; each Make* returns null for a type it does not know.
// Internal to core/sensors (MakeSensor in sensor.h is the public entry).
#pragma once

#include <memory>
#include <string>

#include "core/sensors/sensor.h"

namespace lamina::core {

/// JointPositionSensor, JointVelocitySensor, DriverTorqueSensor (joint_sensors.cpp).
std::unique_ptr<Sensor> MakeJointSensor(const std::string& type, const RobotDesc& robot);
/// Accelerometer, TiltSensor, GyroSensor, IMUSensor (inertial_sensors.cpp).
std::unique_ptr<Sensor> MakeInertialSensor(const std::string& type, const RobotDesc& robot);
/// ContactSensor, ForceTorqueSensor (force_sensors.cpp).
std::unique_ptr<Sensor> MakeForceSensor(const std::string& type, const RobotDesc& robot);
/// LaserRangeSensor, CameraSensor (visual_sensors.cpp).
std::unique_ptr<Sensor> MakeVisualSensor(const std::string& type, const RobotDesc& robot);
/// TransformedSensor, CorruptedSensor, FilteredSensor, TimeDelayedSensor
/// (wrapper_sensors.cpp); their `sensor` setting names the wrapped one (RobotSensors binds it).
std::unique_ptr<Sensor> MakeWrapperSensor(const std::string& type);

/// A wrapper: reads the latest measurements of the sensor it wraps (which comes earlier in the
/// robot's list and is sampled before it in the same step) and never steps that sensor.
class WrapperSensor : public Sensor {
 public:
  const std::string& wrapped_name() const { return wrapped_name_; }
  void Bind(const Sensor* wrapped) { wrapped_ = wrapped; }
  const Sensor* wrapped() const { return wrapped_; }
  std::vector<std::string> MeasurementNames() const override;
  int link() const override { return wrapped_ ? wrapped_->link() : -1; }
  Pose frame() const override { return wrapped_ ? wrapped_->frame() : Pose::Identity(); }

 protected:
  bool ApplyWrappedName(const std::string& text, std::string* error);
  std::string wrapped_name_;
  const Sensor* wrapped_ = nullptr;
};

}  // namespace lamina::core
