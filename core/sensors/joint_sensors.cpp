// SPDX-License-Identifier: MIT
// Joint encoders, joint velocity sensors and driver torque sensors (Klamp't's
// JointPositionSensor, JointVelocitySensor, DriverTorqueSensor).
//
// q / dq: the simulated joint values (rad or m) and rates (rad/s or m/s) of the links in
// `indices` (all links when empty); t: the drivers' clamped efforts (N·m or N), the torque the
// actuator law asks of each driver in `indices` (all drivers when empty). Variance and
// resolution vectors hold one entry per robot link (or driver), one per measurement, or one for
// all. Measurement names q[k], dq[k], t[k] with k the link or driver index, as Klamp't's.
#include <string>
#include <vector>

#include "core/sensors/sensor_text.h"
#include "core/sensors/sensor_types.h"

namespace lamina::core {

namespace {

// entry for full index `k` (measurement `i`) of a per-link, per-measurement or single vector
double Entry(const std::vector<double>& v, int k, int i, int full) {
  if (v.empty()) return 0.0;
  if (v.size() == 1) return v[0];
  if (static_cast<int>(v.size()) == full && k < full) return v[k];
  return i < static_cast<int>(v.size()) ? v[i] : 0.0;
}

class JointSensor : public Sensor {
 public:
  JointSensor(const char* type, const char* prefix, int full)
      : type_(type), prefix_(prefix), full_(full) {
    Sensor::Reset();
    measurements_.assign(full, 0.0);
  }
  const char* type() const override { return type_; }
  std::vector<SensorSettingSpec> SettingSpecs() const override {
    return {{"indices", "", "the link (driver) indices measured; empty: all"},
            {variance_key_.c_str(), "", "noise variance per entry (unit²)"},
            {resolution_key_.c_str(), "", "quantisation step per entry (unit)"}};
  }
  std::vector<std::string> MeasurementNames() const override {
    std::vector<std::string> names;
    for (int i = 0; i < count(); ++i)
      names.push_back(prefix_ + "[" + std::to_string(Index(i)) + "]");
    return names;
  }
  void Simulate(const SensorInputs& inputs) override {
    const VecX& values = Values(inputs);
    measurements_.assign(count(), 0.0);
    for (int i = 0; i < count(); ++i) {
      const int k = Index(i);
      const double v = k < values.size() ? values[k] : 0.0;
      measurements_[i] =
          Discretize(v, Entry(resolution_, k, i, full_), Entry(variance_, k, i, full_), noise_);
    }
  }
  void Reset() override { measurements_.assign(count(), 0.0); }

 protected:
  bool ApplySetting(const std::string& key, const std::string& text, std::string* error) override {
    if (key == "indices") return ApplyIndices(text, error);
    return ReadSensorList(text, key == variance_key_ ? &variance_ : &resolution_, error);
  }
  virtual const VecX& Values(const SensorInputs& inputs) const = 0;
  std::string variance_key_, resolution_key_;

 private:
  bool ApplyIndices(const std::string& text, std::string* error) {
    std::vector<int> indices;
    if (!ReadSensorIndices(text, &indices, error)) return false;
    for (int k : indices) {
      if (k >= full_) {
        *error = "index " + std::to_string(k) + " is out of range (" + std::to_string(full_) +
                 " entries)";
        return false;
      }
    }
    indices_ = std::move(indices);
    Reset();
    return true;
  }
  int count() const { return indices_.empty() ? full_ : static_cast<int>(indices_.size()); }
  int Index(int i) const { return indices_.empty() ? i : indices_[i]; }

  const char* type_;
  std::string prefix_;
  int full_;
  std::vector<int> indices_;
  std::vector<double> variance_, resolution_;
};

class JointPositionSensor : public JointSensor {
 public:
  explicit JointPositionSensor(const RobotDesc& robot)
      : JointSensor("JointPositionSensor", "q", robot.dof()) {
    variance_key_ = "qvariance";
    resolution_key_ = "qresolution";
  }
  const VecX& Values(const SensorInputs& inputs) const override { return inputs.q; }
};

class JointVelocitySensor : public JointSensor {
 public:
  explicit JointVelocitySensor(const RobotDesc& robot)
      : JointSensor("JointVelocitySensor", "dq", robot.dof()) {
    variance_key_ = "dqvariance";
    resolution_key_ = "dqresolution";
  }
  const VecX& Values(const SensorInputs& inputs) const override { return inputs.dq; }
};

class DriverTorqueSensor : public JointSensor {
 public:
  explicit DriverTorqueSensor(const RobotDesc& robot)
      : JointSensor("DriverTorqueSensor", "t", static_cast<int>(robot.drivers.size())) {
    variance_key_ = "tvariance";
    resolution_key_ = "tresolution";
  }
  const VecX& Values(const SensorInputs& inputs) const override { return inputs.driver_torques; }
};

}  // namespace

std::unique_ptr<Sensor> MakeJointSensor(const std::string& type, const RobotDesc& robot) {
  if (type == "JointPositionSensor") return std::make_unique<JointPositionSensor>(robot);
  if (type == "JointVelocitySensor") return std::make_unique<JointVelocitySensor>(robot);
  if (type == "DriverTorqueSensor") return std::make_unique<DriverTorqueSensor>(robot);
  return nullptr;
}

}  // namespace lamina::core
