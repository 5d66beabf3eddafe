// SPDX-License-Identifier: MIT
#include "core/sensors/sensor.h"

#include <cmath>

#include "core/math_types.h"
#include "core/sensors/sensor_text.h"
#include "core/sensors/sensor_types.h"

namespace lamina::core {

namespace {

// splitmix64: a well-mixed 64-bit value of a counter
std::uint64_t Mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

}  // namespace

std::uint64_t SensorNoise::Next() {
  return Mix(Mix(seed_) ^ count_++);
}

double SensorNoise::Uniform() {
  return static_cast<double>(Next() >> 11) * 0x1.0p-53;
}

// Box–Muller from two uniforms (the first kept away from 0)
double SensorNoise::Normal() {
  const double u1 = 1.0 - Uniform();
  const double u2 = Uniform();
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(kTwoPi * u2);
}

double Discretize(double value, double resolution, double variance, SensorNoise& noise) {
  if (variance > 0.0) value += std::sqrt(variance) * noise.Normal();
  if (resolution > 0.0 && std::isfinite(value)) value = std::round(value / resolution) * resolution;
  return value;
}

void Sensor::Reset() {
  std::fill(measurements_.begin(), measurements_.end(), 0.0);
}

bool Sensor::SetSetting(const std::string& key, const std::string& text, std::string* error) {
  bool ok = false;
  if (key == "rate") {
    double rate = 0.0;
    ok = ReadSensorDouble(text, &rate, error);
    if (ok && !(rate >= 0.0 && std::isfinite(rate))) {
      ok = false;
      if (error) *error = "rate must be a finite number of Hz >= 0 (0: the control rate)";
    }
    if (ok) rate_ = rate;
  } else if (key == "enabled") {
    ok = ReadSensorBool(text, &enabled_, error);
  } else {
    bool known = false;
    for (const SensorSettingSpec& spec : SettingSpecs()) known = known || key == spec.name;
    if (!known) {
      if (error) *error = std::string("unknown setting '") + key + "' of a " + type();
      return false;
    }
    ok = ApplySetting(key, text, error);
  }
  if (ok) texts_[key] = text;
  return ok;
}

bool Sensor::GetSetting(const std::string& key, std::string* text) const {
  if (auto it = texts_.find(key); it != texts_.end()) return *text = it->second, true;
  if (key == "rate") return *text = "0", true;
  if (key == "enabled") return *text = "1", true;
  for (const SensorSettingSpec& spec : SettingSpecs()) {
    if (key == spec.name) return *text = spec.default_text, true;
  }
  return false;
}

std::vector<std::pair<std::string, std::string>> Sensor::Settings() const {
  std::vector<std::pair<std::string, std::string>> settings;
  std::vector<std::string> keys = {"rate", "enabled"};
  for (const SensorSettingSpec& spec : SettingSpecs()) keys.push_back(spec.name);
  for (const std::string& key : keys) {
    std::string text;
    GetSetting(key, &text);
    settings.emplace_back(key, text);
  }
  return settings;
}

std::vector<std::string> SensorTypes() {
  return {"JointPositionSensor", "JointVelocitySensor", "DriverTorqueSensor", "ContactSensor",
          "ForceTorqueSensor",   "Accelerometer",       "TiltSensor",         "GyroSensor",
          "IMUSensor",           "LaserRangeSensor",    "CameraSensor",       "TransformedSensor",
          "CorruptedSensor",     "FilteredSensor",      "TimeDelayedSensor"};
}

std::unique_ptr<Sensor> MakeSensor(const std::string& type, const RobotDesc& robot) {
  if (auto s = MakeJointSensor(type, robot)) return s;
  if (auto s = MakeInertialSensor(type, robot)) return s;
  if (auto s = MakeForceSensor(type, robot)) return s;
  if (auto s = MakeVisualSensor(type, robot)) return s;
  return MakeWrapperSensor(type);
}

}  // namespace lamina::core
