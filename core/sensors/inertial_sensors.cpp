// SPDX-License-Identifier: MIT
// Inertial sensors on a link: Accelerometer, TiltSensor, GyroSensor and IMUSensor.
//
// Accelerometer: the specific force f = a − g at its point (Tsensor's origin on the link), in
// its own axes (Tsensor's rotation), m/s²: at rest with z up it reads (0, 0, +9.8); falling
// freely, 0. `hasAxis` (default 1 1 1; Klamp't's 0 0 0 read zero until set) masks axes.
// TiltSensor: a_x = asin(d_y), a_y = asin(−d_x), a_z = asin(d_z) (rad) with d the world
// `referenceDir` in the sensor axes (Rsensor on the link), and the link's angular velocity in
// those axes (rad/s), as Klamp't's.
// GyroSensor: rotation R (the link's in the world, row by row), angular velocity (rad/s) and
// angular acceleration (rad/s²) in the link frame (Klamp't's are in the world frame).
// IMUSensor: the accelerometer's reading turned back to the world with gravity added (the
// point's acceleration, m/s²), its integral velocity (m/s) and translation (m) since the start,
// the gyro's angular acceleration and velocity (link frame), and the rotation (the link's when
// hasRotation, else the integral of the angular velocity): dead reckoning, drifting with noise.
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "core/sensors/sensor_text.h"
#include "core/sensors/sensor_types.h"

namespace lamina::core {

namespace {

const char* const kAxes[3] = {"x", "y", "z"};

std::vector<std::string> AxisNames(const std::string& prefix) {
  return {prefix + "_x", prefix + "_y", prefix + "_z"};
}

std::vector<std::string> RotationNames() {
  std::vector<std::string> names;
  for (const char* row : kAxes) {
    for (const char* column : kAxes) names.push_back(std::string("R_") + row + column);
  }
  return names;
}

Vec3 Noisy(const Vec3& v, const Vec3& variance, SensorNoise& noise) {
  Vec3 out;
  for (int i = 0; i < 3; ++i) out[i] = Discretize(v[i], 0.0, variance[i], noise);
  return out;
}

void Append(std::vector<double>* out, const Vec3& v) {
  out->insert(out->end(), v.data(), v.data() + 3);
}

void AppendRotation(std::vector<double>* out, const Mat3& r) {
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) out->push_back(r(i, j));
  }
}

class AccelerometerPart {
 public:
  int link = 0;
  Pose tsensor = Pose::Identity();
  std::array<bool, 3> has_axis{true, true, true};
  Vec3 variance = Vec3::Zero();

  // specific force in the sensor axes, masked
  Vec3 Measure(const SensorInputs& in, SensorNoise& noise) const {
    const Pose sensor = in.motion.frames[link] * tsensor;
    const Vec3 a = in.motion.PointAcceleration(link, sensor.translation());
    Vec3 f = Noisy(sensor.linear().transpose() * (a - in.gravity), variance, noise);
    for (int i = 0; i < 3; ++i) f[i] = has_axis[i] ? f[i] : 0.0;
    return f;
  }
  bool Apply(const std::string& key, const std::string& text, const RobotDesc& robot,
             std::string* error) {
    if (key == "link") return ReadSensorLink(text, robot, false, &link, error);
    if (key == "Tsensor") return ReadSensorPose(text, &tsensor, error);
    if (key == "hasAxis") return ReadSensorBool3(text, &has_axis, error);
    if (key == "accelVariance") return ReadSensorVec3(text, &variance, error);
    return false;
  }
};

class GyroPart {
 public:
  int link = 0;
  bool has_accel = false, has_velocity = false, has_rotation = false;
  Mat3 accel_variance = Mat3::Zero(), velocity_variance = Mat3::Zero();
  Mat3 rotation_variance = Mat3::Zero();

  Vec3 AngularVelocity(const SensorInputs& in, SensorNoise& noise) const {
    const Mat3 r = in.motion.frames[link].linear();
    return Noisy(r.transpose() * in.motion.angular_velocity[link], velocity_variance.diagonal(),
                 noise);
  }
  Vec3 AngularAcceleration(const SensorInputs& in, SensorNoise& noise) const {
    const Mat3 r = in.motion.frames[link].linear();
    return Noisy(r.transpose() * in.motion.angular_acceleration[link], accel_variance.diagonal(),
                 noise);
  }
  bool Apply(const std::string& key, const std::string& text, const RobotDesc& robot,
             std::string* error) {
    if (key == "link") return ReadSensorLink(text, robot, false, &link, error);
    if (key == "hasAngAccel") return ReadSensorBool(text, &has_accel, error);
    if (key == "hasAngVel") return ReadSensorBool(text, &has_velocity, error);
    if (key == "hasRotation") return ReadSensorBool(text, &has_rotation, error);
    if (key == "angAccelVariance") return ReadSensorMat3(text, &accel_variance, error);
    if (key == "angVelVariance") return ReadSensorMat3(text, &velocity_variance, error);
    if (key == "rotationVariance") return ReadSensorMat3(text, &rotation_variance, error);
    return false;
  }
};

const std::vector<SensorSettingSpec> kAccelerometerSpecs = {
    {"link", "0", "the link it sits on (name or index)"},
    {"Tsensor", "1 0 0 0 1 0 0 0 1 0 0 0", "its frame on the link"},
    {"hasAxis", "1 1 1", "which of its axes it measures"},
    {"accelVariance", "0 0 0", "noise variance per axis, (m/s²)²"}};

const std::vector<SensorSettingSpec> kGyroSpecs = {
    {"link", "0", "the link it sits on (name or index)"},
    {"hasAngAccel", "0", "measures angular acceleration"},
    {"hasAngVel", "0", "measures angular velocity"},
    {"hasRotation", "0", "measures the link's rotation"},
    {"angAccelVariance", "0 0 0 0 0 0 0 0 0", "noise variance (diagonal used), (rad/s²)²"},
    {"angVelVariance", "0 0 0 0 0 0 0 0 0", "noise variance (diagonal used), (rad/s)²"},
    {"rotationVariance", "0 0 0 0 0 0 0 0 0", "accepted, unused (as in Klamp't)"}};

class Accelerometer : public Sensor {
 public:
  explicit Accelerometer(const RobotDesc& robot) : robot_(robot) { measurements_.assign(3, 0.0); }
  const char* type() const override { return "Accelerometer"; }
  std::vector<SensorSettingSpec> SettingSpecs() const override { return kAccelerometerSpecs; }
  std::vector<std::string> MeasurementNames() const override { return AxisNames("accel"); }
  void Simulate(const SensorInputs& in) override {
    measurements_.clear();
    Append(&measurements_, part_.Measure(in, noise_));
  }
  int link() const override { return part_.link; }
  Pose frame() const override { return part_.tsensor; }
  // the measured specific force at its point
  void Draw(const std::vector<Pose>& frames, SensorDrawing* out) const override {
    if (measurements_.size() != 3) return;
    const Pose sensor = frames[part_.link] * part_.tsensor;
    const Vec3 f(measurements_[0], measurements_[1], measurements_[2]);
    out->arrows.push_back(
        {sensor.translation(), sensor.linear() * f, SensorDrawing::Quantity::kAcceleration});
  }

 protected:
  bool ApplySetting(const std::string& key, const std::string& text, std::string* error) override {
    return part_.Apply(key, text, robot_, error);
  }

 private:
  const RobotDesc& robot_;
  AccelerometerPart part_;
};

class TiltSensor : public Sensor {
 public:
  explicit TiltSensor(const RobotDesc& robot) : robot_(robot) { measurements_.assign(6, 0.0); }
  const char* type() const override { return "TiltSensor"; }
  std::vector<SensorSettingSpec> SettingSpecs() const override {
    return {{"link", "0", "the link it sits on (name or index)"},
            {"referenceDir", "0 0 1", "the world direction it measures against"},
            {"Rsensor", "1 0 0 0 1 0 0 0 1", "its axes on the link (row by row)"},
            {"hasAxis", "1 1 0", "which angles it measures"},
            {"resolution", "0 0 0", "quantisation step per axis (rad, rad/s)"},
            {"variance", "0 0 0", "noise variance per axis"},
            {"hasVelocity", "0", "accepted; the rates are always measured (as in Klamp't)"}};
  }
  std::vector<std::string> MeasurementNames() const override {
    std::vector<std::string> names = AxisNames("a");
    for (const std::string& n : AxisNames("w")) names.push_back(n);
    return names;
  }
  void Simulate(const SensorInputs& in) override {
    const Mat3 r = in.motion.frames[link_].linear() * rsensor_;
    const Vec3 d = r.transpose() * reference_.normalized();
    const Vec3 angles(std::asin(Clamp(d.y())), std::asin(Clamp(-d.x())), std::asin(Clamp(d.z())));
    const Vec3 rates = r.transpose() * in.motion.angular_velocity[link_];
    measurements_.assign(6, 0.0);
    for (int i = 0; i < 3; ++i) {
      if (!has_axis_[i]) continue;
      measurements_[i] = Discretize(angles[i], resolution_[i], variance_[i], noise_);
      measurements_[i + 3] = Discretize(rates[i], resolution_[i], variance_[i], noise_);
    }
  }
  int link() const override { return link_; }
  Pose frame() const override {
    Pose p = Pose::Identity();
    p.linear() = rsensor_;
    return p;
  }

 protected:
  bool ApplySetting(const std::string& key, const std::string& text, std::string* error) override {
    if (key == "link") return ReadSensorLink(text, robot_, false, &link_, error);
    if (key == "referenceDir") return ReadDirection(text, error);
    if (key == "Rsensor") return ReadSensorMat3(text, &rsensor_, error);
    if (key == "hasAxis") return ReadSensorBool3(text, &has_axis_, error);
    if (key == "resolution") return ReadSensorVec3(text, &resolution_, error);
    if (key == "variance") return ReadSensorVec3(text, &variance_, error);
    bool unused = false;
    return ReadSensorBool(text, &unused, error);
  }

 private:
  static double Clamp(double v) { return std::max(-1.0, std::min(1.0, v)); }
  bool ReadDirection(const std::string& text, std::string* error) {
    Vec3 d;
    if (!ReadSensorVec3(text, &d, error)) return false;
    if (d.norm() == 0.0) return *error = "referenceDir must not be zero", false;
    reference_ = d;
    return true;
  }
  const RobotDesc& robot_;
  int link_ = 0;
  Vec3 reference_ = Vec3::UnitZ();
  Mat3 rsensor_ = Mat3::Identity();
  std::array<bool, 3> has_axis_{true, true, false};
  Vec3 resolution_ = Vec3::Zero(), variance_ = Vec3::Zero();
};

class GyroSensor : public Sensor {
 public:
  explicit GyroSensor(const RobotDesc& robot) : robot_(robot) { Reset(); }
  const char* type() const override { return "GyroSensor"; }
  std::vector<SensorSettingSpec> SettingSpecs() const override { return kGyroSpecs; }
  std::vector<std::string> MeasurementNames() const override {
    std::vector<std::string> names = RotationNames();
    for (const std::string& n : AxisNames("angVel")) names.push_back(n);
    for (const std::string& n : AxisNames("angAccel")) names.push_back(n);
    return names;
  }
  void Simulate(const SensorInputs& in) override {
    if (part_.has_rotation) rotation_ = in.motion.frames[part_.link].linear();
    if (part_.has_velocity) velocity_ = part_.AngularVelocity(in, noise_);
    if (part_.has_accel) accel_ = part_.AngularAcceleration(in, noise_);
    measurements_.clear();
    AppendRotation(&measurements_, rotation_);
    Append(&measurements_, velocity_);
    Append(&measurements_, accel_);
  }
  void Reset() override {
    rotation_ = Mat3::Identity();
    velocity_ = accel_ = Vec3::Zero();
    measurements_.clear();
    AppendRotation(&measurements_, rotation_);
    measurements_.resize(15, 0.0);
  }
  int link() const override { return part_.link; }
  void SetInternalState(const std::vector<double>& state) override {
    (void)state;
    Unpack();
  }

 protected:
  bool ApplySetting(const std::string& key, const std::string& text, std::string* error) override {
    return part_.Apply(key, text, robot_, error);
  }

 private:
  // the held values come back from the measurements after a restore
  void Unpack() {
    if (measurements_.size() != 15) return;
    for (int i = 0; i < 9; ++i) rotation_(i / 3, i % 3) = measurements_[i];
    velocity_ = Vec3(measurements_[9], measurements_[10], measurements_[11]);
    accel_ = Vec3(measurements_[12], measurements_[13], measurements_[14]);
  }
  const RobotDesc& robot_;
  GyroPart part_;
  Mat3 rotation_ = Mat3::Identity();
  Vec3 velocity_ = Vec3::Zero(), accel_ = Vec3::Zero();
};

class ImuSensor : public Sensor {
 public:
  explicit ImuSensor(const RobotDesc& robot) : robot_(robot) { Reset(); }
  const char* type() const override { return "IMUSensor"; }
  std::vector<SensorSettingSpec> SettingSpecs() const override {
    std::vector<SensorSettingSpec> specs = kAccelerometerSpecs;
    specs.insert(specs.end(), kGyroSpecs.begin() + 1, kGyroSpecs.end());
    return specs;
  }
  std::vector<std::string> MeasurementNames() const override {
    std::vector<std::string> names;
    for (const char* prefix : {"accel", "vel", "trans", "angAccel", "angVel"}) {
      for (const std::string& n : AxisNames(prefix)) names.push_back(n);
    }
    for (const std::string& n : RotationNames()) names.push_back(n);
    return names;
  }
  void Simulate(const SensorInputs& in) override {
    const Pose sensor = in.motion.frames[accel_.link] * accel_.tsensor;
    const Vec3 a = sensor.linear() * accel_.Measure(in, noise_) + in.gravity;
    translation_ += velocity_ * last_dt_ + 0.5 * a * last_dt_ * last_dt_;
    velocity_ += a * last_dt_;
    acceleration_ = a;
    if (gyro_.has_accel) angular_accel_ = gyro_.AngularAcceleration(in, noise_);
    angular_velocity_ = gyro_.has_velocity ? gyro_.AngularVelocity(in, noise_)
                                           : Vec3(angular_velocity_ + angular_accel_ * last_dt_);
    rotation_ = gyro_.has_rotation
                    ? Mat3(in.motion.frames[gyro_.link].linear())
                    : Mat3(rotation_ * RotationFromMoment(angular_velocity_ * last_dt_));
    Pack();
  }
  void Advance(double dt) override { last_dt_ = dt; }
  void Reset() override {
    acceleration_ = velocity_ = translation_ = angular_accel_ = angular_velocity_ = Vec3::Zero();
    rotation_ = Mat3::Identity();
    last_dt_ = 0.0;
    Pack();
  }
  int link() const override { return accel_.link; }
  Pose frame() const override { return accel_.tsensor; }
  std::vector<double> InternalState() const override { return {last_dt_}; }
  void SetInternalState(const std::vector<double>& state) override {
    last_dt_ = state.empty() ? 0.0 : state[0];
    Unpack();
  }

 protected:
  bool ApplySetting(const std::string& key, const std::string& text, std::string* error) override {
    if (key == "link") {
      return accel_.Apply(key, text, robot_, error) && gyro_.Apply(key, text, robot_, error);
    }
    return accel_.Apply(key, text, robot_, error) || gyro_.Apply(key, text, robot_, error);
  }

 private:
  void Pack() {
    measurements_.clear();
    for (const Vec3* v :
         {&acceleration_, &velocity_, &translation_, &angular_accel_, &angular_velocity_}) {
      Append(&measurements_, *v);
    }
    AppendRotation(&measurements_, rotation_);
  }
  void Unpack() {
    if (measurements_.size() != 24) return;
    Vec3* parts[5] = {&acceleration_, &velocity_, &translation_, &angular_accel_,
                      &angular_velocity_};
    for (int p = 0; p < 5; ++p) *parts[p] = Eigen::Map<const Vec3>(&measurements_[3 * p]);
    for (int i = 0; i < 9; ++i) rotation_(i / 3, i % 3) = measurements_[15 + i];
  }
  const RobotDesc& robot_;
  AccelerometerPart accel_;
  GyroPart gyro_;
  Vec3 acceleration_, velocity_, translation_, angular_accel_, angular_velocity_;
  Mat3 rotation_ = Mat3::Identity();
  double last_dt_ = 0.0;
};

}  // namespace

std::unique_ptr<Sensor> MakeInertialSensor(const std::string& type, const RobotDesc& robot) {
  if (type == "Accelerometer") return std::make_unique<Accelerometer>(robot);
  if (type == "TiltSensor") return std::make_unique<TiltSensor>(robot);
  if (type == "GyroSensor") return std::make_unique<GyroSensor>(robot);
  if (type == "IMUSensor") return std::make_unique<ImuSensor>(robot);
  return nullptr;
}

}  // namespace lamina::core
