// SPDX-License-Identifier: MIT
// Sensors of force: ContactSensor (a tactile patch on a link) and ForceTorqueSensor (at a
// link's joint).
//
// ContactSensor: the sum of the contact forces ON the link (N) at points inside the patch
// (patchMin ≤ x, y ≤ patchMax in the sensor frame Tsensor, |z| ≤ patchTolerance + the link's
// padding, since the boundary layer puts contact points up to the padding off the surface), in
// the sensor axes; z is the patch's outward normal, so a load pressing on the patch reads
// force_z < 0. `contact` is 1 when |force_z| > fSensitivity. Forces are weighted by Klamp't's
// edge falloff, noisy, quantised and clamped to ±fSaturation.
// ForceTorqueSensor: the wrench the link and everything it carries exert on its parent through
// its joint (Klamp't's sign), in the link frame (all six axes by default; Klamp't's default
// 0 0 0 read zero until set): force (N) and torque (N·m) about the link's
// origin (the joint; Klamp't takes it about the link's centre of mass). It is found by
// Newton–Euler on the subtree from the inputs (gravity, the accelerations since the previous
// sample and the last step's contacts): under a static load of mass m it reads m·g and the
// load's moment about the joint.
// Forces a user applies (mouse spring, held wrenches) are not inputs: they read as if the joint
// carried them.
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "core/sensors/sensor_text.h"
#include "core/sensors/sensor_types.h"

namespace lamina::core {

namespace {

bool InSubtree(const RobotDesc& robot, int k, int root) {
  for (int i = k; i >= 0; i = robot.links[i].parent) {
    if (i == root) return true;
  }
  return false;
}

class ContactSensor : public Sensor {
 public:
  explicit ContactSensor(const RobotDesc& robot) : robot_(robot) { Reset(); }
  const char* type() const override { return "ContactSensor"; }
  std::vector<SensorSettingSpec> SettingSpecs() const override {
    return {{"link", "0", "the link it sits on (name or index)"},
            {"Tsensor", "1 0 0 0 1 0 0 0 1 0 0 0", "the patch frame on the link: z out"},
            {"patchMin", "0 0", "the patch's lower x, y corner, m"},
            {"patchMax", "0 0", "the patch's upper x, y corner, m"},
            {"patchTolerance", "0.001", "distance off the patch plane that counts, m"},
            {"hasForce", "0 0 0", "which force axes it measures"},
            {"fResolution", "0 0 0", "quantisation step per axis, N"},
            {"fVariance", "0 0 0", "noise variance per axis, N²"},
            {"fSensitivity", "0", "|force_z| above which it reads contact, N"},
            {"fSaturation", "inf inf inf", "largest |force| per axis, N"},
            {"falloffCoefficient", "0", "exponent of the weight towards the patch edges"}};
  }
  std::vector<std::string> MeasurementNames() const override {
    std::vector<std::string> names = {"contact"};
    const char* axes[3] = {"force_x", "force_y", "force_z"};
    for (int i = 0; i < 3; ++i) {
      if (has_force_[i]) names.push_back(axes[i]);
    }
    return names;
  }
  void Simulate(const SensorInputs& in) override {
    const Pose sensor = in.motion.frames[link_] * tsensor_;
    const double tolerance = tolerance_ + robot_.links[link_].sim.padding;
    Vec3 force = Vec3::Zero();
    for (const LinkContact& c : in.contacts) {
      if (c.link != link_) continue;
      const Vec3 x = sensor.inverse() * c.position;
      if (!InPatch(x, tolerance)) continue;
      force += Weight(x) * (sensor.linear().transpose() * c.force);
    }
    measurements_ = {std::abs(force.z()) > sensitivity_ ? 1.0 : 0.0};
    for (int i = 0; i < 3; ++i) {
      if (!has_force_[i]) continue;
      const double f = Discretize(force[i], resolution_[i], variance_[i], noise_);
      measurements_.push_back(std::max(-saturation_[i], std::min(saturation_[i], f)));
    }
  }
  void Reset() override { measurements_.assign(MeasurementNames().size(), 0.0); }
  int link() const override { return link_; }
  Pose frame() const override { return tsensor_; }
  // the patch's edge (hot in contact) and the measured force at its centre
  void Draw(const std::vector<Pose>& frames, SensorDrawing* out) const override {
    const Pose sensor = frames[link_] * tsensor_;
    const bool hot = !measurements_.empty() && measurements_[0] != 0.0;
    const Vec3 c[4] = {sensor * Vec3(patch_min_.x(), patch_min_.y(), 0),
                       sensor * Vec3(patch_max_.x(), patch_min_.y(), 0),
                       sensor * Vec3(patch_max_.x(), patch_max_.y(), 0),
                       sensor * Vec3(patch_min_.x(), patch_max_.y(), 0)};
    for (int k = 0; k < 4; ++k) {
      out->segments.push_back(
          {c[k], c[(k + 1) % 4],
           hot ? SensorDrawing::Kind::kOutlineHot : SensorDrawing::Kind::kOutline});
    }
    Vec3 f = Vec3::Zero();
    for (int i = 0, m = 1; i < 3; ++i) {
      if (has_force_[i] && m < static_cast<int>(measurements_.size())) f[i] = measurements_[m++];
    }
    const Vec3 center = sensor * Vec3(0.5 * (patch_min_.x() + patch_max_.x()),
                                      0.5 * (patch_min_.y() + patch_max_.y()), 0);
    out->arrows.push_back({center, sensor.linear() * f, SensorDrawing::Quantity::kForce});
  }

 protected:
  bool ApplySetting(const std::string& key, const std::string& text, std::string* error) override {
    bool ok = false;
    if (key == "link")
      ok = ReadSensorLink(text, robot_, false, &link_, error);
    else if (key == "Tsensor")
      ok = ReadSensorPose(text, &tsensor_, error);
    else if (key == "patchMin")
      ok = ReadSensorVec2(text, &patch_min_, error);
    else if (key == "patchMax")
      ok = ReadSensorVec2(text, &patch_max_, error);
    else if (key == "patchTolerance")
      ok = ReadSensorDouble(text, &tolerance_, error);
    else if (key == "hasForce")
      ok = ReadSensorBool3(text, &has_force_, error);
    else if (key == "fResolution")
      ok = ReadSensorVec3(text, &resolution_, error);
    else if (key == "fVariance")
      ok = ReadSensorVec3(text, &variance_, error);
    else if (key == "fSensitivity")
      ok = ReadSensorDouble(text, &sensitivity_, error);
    else if (key == "fSaturation")
      ok = ReadSensorVec3(text, &saturation_, error);
    else
      ok = ReadSensorDouble(text, &falloff_, error);
    if (ok) Reset();
    return ok;
  }

 private:
  bool InPatch(const Vec3& x, double tolerance) const {
    return x.x() >= patch_min_.x() && x.x() <= patch_max_.x() && x.y() >= patch_min_.y() &&
           x.y() <= patch_max_.y() && std::abs(x.z()) <= tolerance;
  }
  // Klamp't's falloff: 1 at the centre, towards 0 at the corners
  double Weight(const Vec3& x) const {
    if (falloff_ <= 0.0) return 1.0;
    const Eigen::Vector2d c = 0.5 * (patch_min_ + patch_max_);
    const Eigen::Vector2d size = patch_max_ - patch_min_;
    const double area = size.x() * size.y();
    if (area <= 0.0) return 1.0;
    const double d = std::abs(4.0 * (x.x() - c.x()) * (x.y() - c.y())) / area;
    return std::pow(std::max(0.0, 1.0 - d), falloff_);
  }
  const RobotDesc& robot_;
  int link_ = 0;
  Pose tsensor_ = Pose::Identity();
  Eigen::Vector2d patch_min_ = Eigen::Vector2d::Zero(), patch_max_ = Eigen::Vector2d::Zero();
  double tolerance_ = 0.001, sensitivity_ = 0.0, falloff_ = 0.0;
  std::array<bool, 3> has_force_{false, false, false};
  Vec3 resolution_ = Vec3::Zero(), variance_ = Vec3::Zero();
  Vec3 saturation_ = Vec3::Constant(kInf);
};

// the wrench the subtree of `root` exerts on its parent: force (world) and moment about `o`
void SubtreeWrench(const SensorInputs& in, int root, const Vec3& o, Vec3* force, Vec3* moment) {
  const RobotDesc& robot = *in.robot;
  const LinkMotion& m = in.motion;
  *force = Vec3::Zero();
  *moment = Vec3::Zero();
  for (int k = root; k < robot.dof(); ++k) {
    if (!InSubtree(robot, k, root)) continue;
    const LinkDesc& link = robot.links[k];
    const Vec3 c = m.frames[k] * link.com;
    const Vec3 f = link.mass * (in.gravity - m.PointAcceleration(k, c));
    const Mat3 r = m.frames[k].linear();
    const Mat3 inertia = r * link.inertia * r.transpose();
    const Vec3& w = m.angular_velocity[k];
    *force += f;
    *moment += (c - o).cross(f) - inertia * m.angular_acceleration[k] - w.cross(inertia * w);
  }
  for (const LinkContact& c : in.contacts) {
    if (!InSubtree(robot, c.link, root)) continue;
    *force += c.force;
    *moment += (c.position - o).cross(c.force);
  }
}

class ForceTorqueSensor : public Sensor {
 public:
  explicit ForceTorqueSensor(const RobotDesc& robot) : robot_(robot) {
    measurements_.assign(6, 0.0);
  }
  const char* type() const override { return "ForceTorqueSensor"; }
  std::vector<SensorSettingSpec> SettingSpecs() const override {
    return {{"link", "0", "the link whose joint it measures (name or index)"},
            {"hasForce", "1 1 1", "which force axes it measures"},
            {"hasTorque", "1 1 1", "which torque axes it measures"},
            {"fVariance", "0 0 0", "noise variance per force axis, N²"},
            {"tVariance", "0 0 0", "noise variance per torque axis, (N·m)²"},
            {"localPos", "0 0 0", "accepted (older Klamp't files), unused"}};
  }
  std::vector<std::string> MeasurementNames() const override {
    return {"force_x", "force_y", "force_z", "torque_x", "torque_y", "torque_z"};
  }
  void Simulate(const SensorInputs& in) override {
    const Pose& frame = in.motion.frames[link_];
    Vec3 force, moment;
    SubtreeWrench(in, link_, frame.translation(), &force, &moment);
    const Vec3 f = frame.linear().transpose() * force;
    const Vec3 t = frame.linear().transpose() * moment;
    measurements_.assign(6, 0.0);
    for (int i = 0; i < 3; ++i) {
      if (has_force_[i]) measurements_[i] = Discretize(f[i], 0.0, f_variance_[i], noise_);
      if (has_torque_[i]) measurements_[i + 3] = Discretize(t[i], 0.0, t_variance_[i], noise_);
    }
  }
  int link() const override { return link_; }
  // the force and torque the link puts on its parent, at the joint
  void Draw(const std::vector<Pose>& frames, SensorDrawing* out) const override {
    if (measurements_.size() != 6) return;
    const Pose& frame = frames[link_];
    const Vec3 f(measurements_[0], measurements_[1], measurements_[2]);
    const Vec3 t(measurements_[3], measurements_[4], measurements_[5]);
    out->arrows.push_back(
        {frame.translation(), frame.linear() * f, SensorDrawing::Quantity::kForce});
    out->arrows.push_back(
        {frame.translation(), frame.linear() * t, SensorDrawing::Quantity::kTorque});
  }

 protected:
  bool ApplySetting(const std::string& key, const std::string& text, std::string* error) override {
    if (key == "link") return ReadSensorLink(text, robot_, false, &link_, error);
    if (key == "hasForce") return ReadSensorBool3(text, &has_force_, error);
    if (key == "hasTorque") return ReadSensorBool3(text, &has_torque_, error);
    if (key == "fVariance") return ReadSensorVec3(text, &f_variance_, error);
    if (key == "tVariance") return ReadSensorVec3(text, &t_variance_, error);
    Vec3 unused;
    return ReadSensorVec3(text, &unused, error);
  }

 private:
  const RobotDesc& robot_;
  int link_ = 0;
  std::array<bool, 3> has_force_{true, true, true}, has_torque_{true, true, true};
  Vec3 f_variance_ = Vec3::Zero(), t_variance_ = Vec3::Zero();
};

}  // namespace

std::unique_ptr<Sensor> MakeForceSensor(const std::string& type, const RobotDesc& robot) {
  if (type == "ContactSensor") return std::make_unique<ContactSensor>(robot);
  if (type == "ForceTorqueSensor") return std::make_unique<ForceTorqueSensor>(robot);
  return nullptr;
}

}  // namespace lamina::core
