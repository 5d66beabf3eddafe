// SPDX-License-Identifier: MIT
// RobotController (see robot_controller.h): driver mapping, actuator forces, scheduling and the
// Klamp't command set on top of MotionQueue.
#include "core/control/robot_controller.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <regex>
#include <utility>

#include "core/robot/dynamics.h"
#include "core/robot/kinematics.h"

namespace lamina::core {
namespace {

// Accumulated periods (0.01 + 0.01 + ...) drift by ulps; a run that is due "now" must not slip.
constexpr double kControlTimeTolerance = 1e-9;  // s

bool AllFinite(const VecX& v) {
  return v.allFinite();
}

bool IsFloatingJoint(JointType type) {
  return type == JointType::kFloating || type == JointType::kFloatingPlanar ||
         type == JointType::kBallAndSocket;
}

// The first of an affine driver's links with a nonzero scale, or -1 (none: the driver is unusable).
int AffineReadIndex(const DriverDesc& driver) {
  for (size_t j = 0; j < driver.links.size() && j < driver.affine_scale.size(); ++j) {
    if (driver.affine_scale[j] != 0) return static_cast<int>(j);
  }
  return -1;
}

double AffineOffset(const DriverDesc& driver, size_t j) {
  return j < driver.affine_offset.size() ? driver.affine_offset[j] : 0.0;
}

bool IsDescendantOrSelf(const RobotDesc& robot, int k, int i) {
  for (int link = k; link >= 0; link = robot.links[link].parent) {
    if (link == i) return true;
  }
  return false;
}

// Effective inertia about link i's joint of the subtree at configuration q (kg·m² or kg).
double EffectiveInertia(const RobotDesc& robot, const std::vector<Pose>& frames, int i) {
  const LinkDesc& link = robot.links[i];
  const Vec3 axis = (frames[i].linear() * link.axis).normalized();
  double inertia = 0;
  for (int k = i; k < robot.dof(); ++k) {
    if (!IsDescendantOrSelf(robot, k, i)) continue;
    const LinkDesc& body = robot.links[k];
    if (link.axis_type == LinkJointAxis::kPrismatic) {
      inertia += body.mass;
      continue;
    }
    const Mat3 rotation = frames[k].linear();
    const Vec3 lever = axis.cross(frames[k] * body.com - frames[i].translation());
    inertia += axis.dot(rotation * body.inertia * rotation.transpose() * axis) +
               body.mass * lever.squaredNorm();
  }
  return inertia;
}

double RampAcceleration(const RobotDesc& robot, const std::vector<Pose>& frames, int i) {
  const LinkDesc& link = robot.links[i];
  if (std::isfinite(link.acceleration_max)) return link.acceleration_max;
  if (!std::isfinite(link.torque_max)) return kDefaultAccelerationMax;
  const double inertia = EffectiveInertia(robot, frames, i);
  if (!(inertia > 0) || !std::isfinite(inertia)) return kDefaultAccelerationMax;
  return std::abs(link.torque_max) / inertia;
}

VecX ClampIntoLimits(const VecX& q, const JointLimits& limits) {
  return q.cwiseMax(limits.q_min).cwiseMin(limits.q_max);
}

}  // namespace

JointLimits LinkRampLimits(const RobotDesc& robot) {
  const int n = robot.dof();
  JointLimits limits = JointLimits::Unbounded(n);
  const std::vector<Pose> frames = LinkTransforms(robot, robot.InitialConfig());
  for (int i = 0; i < n; ++i) {
    const LinkDesc& link = robot.links[i];
    limits.q_min[i] = std::min(link.q_min, link.q_max);
    limits.q_max[i] = link.q_max;
    limits.velocity_max[i] = std::max(0.0, std::min(link.velocity_max, -link.velocity_min));
    limits.acceleration_max[i] = std::max(0.0, RampAcceleration(robot, frames, i));
  }
  return limits;
}

double ControlPeriodFromProperty(const std::string& xml) {
  std::smatch match;
  static const std::regex kTimeStep(R"re(timeStep\s*=\s*["']([^"']+)["'])re", std::regex::icase);
  static const std::regex kRate(R"re(\brate\s*=\s*["']([^"']+)["'])re", std::regex::icase);
  if (std::regex_search(xml, match, kTimeStep)) {
    const double step = std::strtod(match[1].str().c_str(), nullptr);
    if (step > 0 && std::isfinite(step)) return step;
  }
  if (std::regex_search(xml, match, kRate)) {
    const double rate = std::strtod(match[1].str().c_str(), nullptr);
    if (rate > 0 && std::isfinite(rate)) return 1.0 / rate;
  }
  return 0;
}

RobotController::RobotController(const RobotDesc& robot)
    : RobotController(std::make_shared<RobotDesc>(robot)) {}

RobotController::RobotController(std::shared_ptr<RobotDesc> robot)
    : owned_(std::move(robot)), robot_(owned_.get()) {
  Initialize();
}

RobotController RobotController::ViewOf(RobotDesc* robot) {
  return RobotController(robot);
}

RobotController::RobotController(RobotDesc* robot) : robot_(robot) {
  Initialize();
}

void RobotController::Initialize() {
  const RobotDesc& robot = *robot_;
  limits_ = LinkRampLimits(robot);
  queue_ = MotionQueue(limits_);
  sensed_q_ = robot.InitialConfig();
  sensed_dq_ = robot.InitialVelocity();
  for (const JointDesc& joint : robot.joints) floating_base_ |= IsFloatingJoint(joint.type);
  actuators_.reserve(robot.drivers.size());
  for (int d = 0; d < driver_count(); ++d) {
    const DriverDesc& driver = robot.drivers[d];
    const bool revolute =
        UsableDriver(d) && robot.links[driver.links[0]].axis_type == LinkJointAxis::kRevolute;
    const double q = UsableDriver(d) ? DriverValue(d, sensed_q_) : 0.0;
    actuators_.push_back(InitialActuatorState(driver, revolute, q));
  }
  driven_.assign(robot.links.size(), false);
  for (const DriverDesc& driver : robot.drivers) {
    for (const int link : driver.links) {
      if (link >= 0 && link < dof()) driven_[link] = true;
    }
  }
  const auto property = robot.properties.find("controller");
  if (property != robot.properties.end()) {
    const double period = ControlPeriodFromProperty(property->second);
    if (period > 0) control_period_ = period;
  }
}

bool RobotController::UsableDriver(int d) const {
  const DriverDesc& driver = robot_->drivers[d];
  if (driver.links.empty()) return false;
  for (int link : driver.links) {
    if (link < 0 || link >= dof()) return false;
  }
  if (driver.type == DriverType::kAffine) return AffineReadIndex(driver) >= 0;
  return true;
}

// ---- mapping -----------------------------------------------------------------------------

namespace {

// An affine driver's value from its links: the v whose line q_j = o_j + s_j v is nearest to them
// (least squares), Σ s_j (q_j − o_j) / Σ s_j²; with `velocity` the same for dq (no offsets).
// The PID then acts along the scale vector s and the transmission correction, orthogonal to s,
// on the rest: a load on any of the links is shared as the model says, whatever the links'
// order. Klamp't averages (q_j − o_j)/s_j (the same for scales of equal size); reading the first
// link alone, as Lamina did, left a loaded second link 4.5·τ/kP off (docs/motion.md).
double AffineProjection(const DriverDesc& driver, const VecX& values, bool velocity) {
  double along = 0.0, norm = 0.0;
  for (size_t j = 0; j < driver.links.size() && j < driver.affine_scale.size(); ++j) {
    const double s = driver.affine_scale[j];
    along += s * (values[driver.links[j]] - (velocity ? 0.0 : AffineOffset(driver, j)));
    norm += s * s;
  }
  return along / norm;  // norm > 0: UsableDriver requires a nonzero scale
}

}  // namespace

double RobotController::DriverValue(int d, const VecX& q) const {
  if (!UsableDriver(d)) return 0;
  const DriverDesc& driver = robot_->drivers[d];
  if (driver.type != DriverType::kAffine) return q[driver.links[0]];
  return AffineProjection(driver, q, false);
}

double RobotController::DriverVelocity(int d, const VecX& dq) const {
  if (!UsableDriver(d)) return 0;
  const DriverDesc& driver = robot_->drivers[d];
  if (driver.type != DriverType::kAffine) return dq[driver.links[0]];
  return AffineProjection(driver, dq, true);
}

VecX RobotController::DriverValues(const VecX& q) const {
  VecX values(driver_count());
  for (int d = 0; d < driver_count(); ++d) values[d] = DriverValue(d, q);
  return values;
}

VecX RobotController::DriverVelocities(const VecX& dq) const {
  VecX values(driver_count());
  for (int d = 0; d < driver_count(); ++d) values[d] = DriverVelocity(d, dq);
  return values;
}

VecX RobotController::LinkValuesFromDrivers(const VecX& driver_values, const VecX& base,
                                            bool velocity) const {
  VecX out = base;
  for (int d = 0; d < driver_count() && d < driver_values.size(); ++d) {
    if (!UsableDriver(d)) continue;
    const DriverDesc& driver = robot_->drivers[d];
    if (driver.type != DriverType::kAffine) {
      out[driver.links[0]] = driver_values[d];
      continue;
    }
    for (size_t j = 0; j < driver.links.size() && j < driver.affine_scale.size(); ++j) {
      const double offset = velocity ? 0.0 : AffineOffset(driver, j);
      out[driver.links[j]] = offset + driver.affine_scale[j] * driver_values[d];
    }
  }
  return out;
}

VecX RobotController::DriverForcesFromLinks(const VecX& link_forces) const {
  VecX forces = VecX::Zero(driver_count());
  for (int d = 0; d < driver_count(); ++d) {
    if (!UsableDriver(d)) continue;
    const DriverDesc& driver = robot_->drivers[d];
    if (driver.type != DriverType::kAffine) {
      forces[d] = link_forces[driver.links[0]];
      continue;
    }
    for (size_t j = 0; j < driver.links.size() && j < driver.affine_scale.size(); ++j) {
      forces[d] += driver.affine_scale[j] * link_forces[driver.links[j]];
    }
  }
  return forces;
}

// ---- physics rate ------------------------------------------------------------------------

VecX RobotController::DriverEfforts(const VecX& q, const VecX& dq) const {
  VecX efforts = VecX::Zero(driver_count());
  if (q.size() != dof() || dq.size() != dof()) return efforts;
  for (int d = 0; d < driver_count(); ++d) {
    if (!UsableDriver(d)) continue;
    efforts[d] =
        ActuatorEffort(actuators_[d], robot_->drivers[d], DriverValue(d, q), DriverVelocity(d, dq));
  }
  return efforts;
}

void RobotController::ComputeLinkForces(const VecX& q, const VecX& dq, VecX* link_forces) const {
  AddDriverForces(q, dq, nullptr, link_forces);
}

void RobotController::AddDriverForces(const VecX& q, const VecX& dq, const std::vector<char>* skip,
                                      VecX* link_forces) const {
  link_forces->setZero(dof());
  if (q.size() != dof() || dq.size() != dof()) return;
  for (int d = 0; d < driver_count(); ++d) {
    if (!UsableDriver(d) || (skip && (*skip)[d])) continue;
    const DriverDesc& driver = robot_->drivers[d];
    const double effort =
        ActuatorEffort(actuators_[d], driver, DriverValue(d, q), DriverVelocity(d, dq));
    if (driver.type != DriverType::kAffine) {
      (*link_forces)[driver.links[0]] += effort;
      continue;
    }
    for (size_t j = 0; j < driver.links.size() && j < driver.affine_scale.size(); ++j) {
      (*link_forces)[driver.links[j]] += driver.affine_scale[j] * effort;
    }
    if (actuators_[d].mode == ActuatorMode::kPid) AddAffineCorrection(d, q, dq, link_forces);
  }
}

// Klamp't's transmission term: a stiff coupling e_j = 0.25·kp·(q_des_j − q_j) +
// 0.001·kp·(dq_des_j − dq_j) that keeps the linked joints on the affine line, projected
// orthogonal to the scale vector (so it does no work along the driver) and capped in norm at
// 10·max torque_max of the links (when finite).
void RobotController::AddAffineCorrection(int d, const VecX& q, const VecX& dq,
                                          VecX* link_forces) const {
  const DriverDesc& driver = robot_->drivers[d];
  const ActuatorState& state = actuators_[d];
  const size_t n = std::min(driver.links.size(), driver.affine_scale.size());
  VecX scale(static_cast<Eigen::Index>(n)), correction(static_cast<Eigen::Index>(n));
  double cap = 0;
  for (size_t j = 0; j < n; ++j) {
    const int link = driver.links[j];
    const double q_des = AffineOffset(driver, j) + driver.affine_scale[j] * state.q_des;
    const double dq_des = driver.affine_scale[j] * state.dq_des;
    scale[j] = driver.affine_scale[j];
    correction[j] =
        0.25 * driver.servo_p * (q_des - q[link]) + 0.001 * driver.servo_p * (dq_des - dq[link]);
    cap = std::max(cap, std::abs(robot_->links[link].torque_max));
  }
  correction -= scale * (scale.dot(correction) / scale.squaredNorm());
  cap *= 10;
  const double norm = correction.norm();
  if (std::isfinite(cap) && norm > cap) correction *= cap / norm;
  if (!correction.allFinite()) return;
  for (size_t j = 0; j < n; ++j) (*link_forces)[driver.links[j]] += correction[j];
}

void RobotController::AcceptStep(const VecX& q, double h) {
  if (q.size() != dof() || !(h >= 0)) return;
  for (int d = 0; d < driver_count(); ++d) {
    if (UsableDriver(d))
      IntegrateActuator(robot_->drivers[d], DriverValue(d, q), h, &actuators_[d]);
  }
}

// ---- control rate ------------------------------------------------------------------------

bool RobotController::SetControlPeriod(double period) {
  if (!(period > 0) || !std::isfinite(period)) {
    return Fail("SetControlPeriod: period must be > 0 s");
  }
  control_period_ = period;
  return Succeed();
}

bool RobotController::ControlDue(double time) const {
  return next_control_time_ <= time + kControlTimeTolerance;
}

void RobotController::SetGravityCompensation(bool on) {
  gravity_compensation_ = on;
}

bool RobotController::Update(double time, const VecX& sensed_q, const VecX& sensed_dq) {
  if (!std::isfinite(time)) return Fail("Update: time is not finite");
  if (!CheckLinkVector(sensed_q, "Update", "sensed_q") ||
      !CheckLinkVector(sensed_dq, "Update", "sensed_dq")) {
    return false;
  }
  sensed_q_ = sensed_q;
  sensed_dq_ = sensed_dq;
  if (queue_.empty()) queue_.SetConstant(ClampIntoLimits(sensed_q_, limits_));
  queue_.Advance(control_period_);
  if (!manual_) SetTargetsFromQueue();
  next_control_time_ += control_period_;
  return Succeed();
}

// Klamp't's path controller ends in SetPIDCommand: every driver goes (back) to PID mode with the
// queue's targets, its integral kept and its feed-forward replaced (gravity or 0).
void RobotController::SetTargetsFromQueue() {
  VecX q, dq;
  queue_.Config(&q);
  queue_.Velocity(&dq);
  const bool feed_forward = gravity_compensation_ && !floating_base_;
  const VecX torque_ff =
      feed_forward ? DriverForcesFromLinks(GravityTorques(*robot_, sensed_q_, gravity_)) : VecX();
  for (int d = 0; d < driver_count(); ++d) {
    if (!UsableDriver(d)) continue;
    ActuatorState& state = actuators_[d];
    state.mode = ActuatorMode::kPid;
    state.q_des = DriverValue(d, q);
    state.dq_des = DriverVelocity(d, dq);
    state.torque = feed_forward ? torque_ff[d] : 0.0;
  }
}

// ---- commands ----------------------------------------------------------------------------

bool RobotController::CheckLinkVector(const VecX& v, const char* command, const char* name) {
  if (v.size() != dof()) {
    return Fail(std::string(command) + ": " + name + " has " + std::to_string(v.size()) +
                " entries, the robot has " + std::to_string(dof()) + " links");
  }
  if (!AllFinite(v)) return Fail(std::string(command) + ": " + name + " is not finite");
  return true;
}

bool RobotController::ToDriverSpace(const VecX& v, bool velocity, const char* command,
                                    const char* name, VecX* out) {
  if (!AllFinite(v)) return Fail(std::string(command) + ": " + name + " is not finite");
  if (v.size() == dof()) {
    *out = velocity ? DriverVelocities(v) : DriverValues(v);
  } else if (v.size() == driver_count()) {
    *out = v;
  } else {
    return Fail(std::string(command) + ": " + name + " has " + std::to_string(v.size()) +
                " entries; expected " + std::to_string(dof()) + " (links) or " +
                std::to_string(driver_count()) + " (drivers)");
  }
  return true;
}

bool RobotController::ToDriverForces(const VecX& torque, const char* command, VecX* out) {
  if (!AllFinite(torque)) return Fail(std::string(command) + ": torque is not finite");
  if (torque.size() == dof()) {
    *out = DriverForcesFromLinks(torque);
  } else if (torque.size() == driver_count()) {
    *out = torque;
  } else {
    return Fail(std::string(command) + ": torque has " + std::to_string(torque.size()) +
                " entries; expected " + std::to_string(dof()) + " (links) or " +
                std::to_string(driver_count()) + " (drivers)");
  }
  return true;
}

bool RobotController::SetPIDCommand(const VecX& q, const VecX& dq) {
  return SetPIDCommand(q, dq, VecX::Zero(driver_count()));
}

bool RobotController::SetPIDCommand(const VecX& q, const VecX& dq, const VecX& torque_ff) {
  VecX q_des, dq_des, ff;
  if (!ToDriverSpace(q, false, "SetPIDCommand", "q", &q_des) ||
      !ToDriverSpace(dq, true, "SetPIDCommand", "dq", &dq_des) ||
      !ToDriverForces(torque_ff, "SetPIDCommand", &ff)) {
    return false;
  }
  for (int d = 0; d < driver_count(); ++d) {
    ActuatorState& state = actuators_[d];
    state.mode = ActuatorMode::kPid;
    state.q_des = q_des[d];
    state.dq_des = dq_des[d];
    state.torque = ff[d];
  }
  manual_ = true;
  return Succeed();
}

bool RobotController::SetPIDGains(const VecX& kp, const VecX& ki, const VecX& kd) {
  const Eigen::Index n = driver_count();
  if (kp.size() != n || ki.size() != n || kd.size() != n) {
    return Fail("SetPIDGains: gains must have " + std::to_string(n) + " entries (drivers)");
  }
  if (!AllFinite(kp) || !AllFinite(ki) || !AllFinite(kd) || (kp.array() < 0).any() ||
      (ki.array() < 0).any() || (kd.array() < 0).any()) {
    return Fail("SetPIDGains: gains must be finite and >= 0");
  }
  for (int d = 0; d < driver_count(); ++d) {
    robot_->drivers[d].servo_p = kp[d];
    robot_->drivers[d].servo_i = ki[d];
    robot_->drivers[d].servo_d = kd[d];
  }
  return Succeed();
}

void RobotController::GetPIDGains(VecX* kp, VecX* ki, VecX* kd) const {
  kp->resize(driver_count());
  ki->resize(driver_count());
  kd->resize(driver_count());
  for (int d = 0; d < driver_count(); ++d) {
    (*kp)[d] = robot_->drivers[d].servo_p;
    (*ki)[d] = robot_->drivers[d].servo_i;
    (*kd)[d] = robot_->drivers[d].servo_d;
  }
}

bool RobotController::SetTorque(const VecX& torque) {
  VecX commanded;
  if (!ToDriverForces(torque, "SetTorque", &commanded)) return false;
  for (int d = 0; d < driver_count(); ++d) {
    actuators_[d].mode = ActuatorMode::kTorque;
    actuators_[d].torque = commanded[d];
  }
  manual_ = true;
  return Succeed();
}

VecX RobotController::CommandedTorques() const {
  VecX torques(driver_count());
  for (int d = 0; d < driver_count(); ++d) torques[d] = actuators_[d].torque;
  return torques;
}

bool RobotController::AllPid() const {
  return std::all_of(actuators_.begin(), actuators_.end(),
                     [](const ActuatorState& a) { return a.mode == ActuatorMode::kPid; });
}

// Klamp't EnablePathControl: restart the queue from the current command when it is empty or
// the manual override was on, then hand control back to the queue.
void RobotController::EnablePathControl() {
  if (queue_.empty() || manual_) {
    queue_.SetConstant(AllPid() ? CommandedLinkConfig() : ClampIntoLimits(sensed_q_, limits_));
  }
  manual_ = false;
}

template <typename Command>
bool RobotController::QueueCommand(const char* command, Command&& run) {
  MotionQueue backup = queue_;
  const bool manual = manual_;
  EnablePathControl();
  if (!run()) {
    const std::string reason = queue_.last_error();
    queue_ = std::move(backup);
    manual_ = manual;
    return Fail(std::string(command) + ": " + reason);
  }
  return Succeed();
}

bool RobotController::SetVelocity(const VecX& dq, double duration) {
  if (!CheckLinkVector(dq, "SetVelocity", "dq")) return false;
  if (!(duration >= 0) || !std::isfinite(duration)) {
    return Fail("SetVelocity: duration must be finite and >= 0 s");
  }
  return QueueCommand("SetVelocity",
                      [&] { return queue_.SetConstantVelocity(dq, queue_.time() + duration); });
}

VecX RobotController::HoldUndriven(const VecX& q, bool velocity) const {
  VecX held = q;
  const VecX end = queue_.EndConfig();
  for (int i = 0; i < held.size() && i < dof(); ++i) {
    if (!driven_[i]) held[i] = velocity ? 0.0 : end[i];
  }
  return held;
}

bool RobotController::SetMilestone(const VecX& q) {
  if (!CheckLinkVector(q, "SetMilestone", "q")) return false;
  return QueueCommand("SetMilestone", [&] {
    queue_.Cut();
    return queue_.AppendRamp(HoldUndriven(q, false));
  });
}

bool RobotController::SetMilestone(const VecX& q, const VecX& dq) {
  if (!CheckLinkVector(q, "SetMilestone", "q") || !CheckLinkVector(dq, "SetMilestone", "dq")) {
    return false;
  }
  return QueueCommand("SetMilestone", [&] {
    queue_.Cut();
    return queue_.AppendRamp(HoldUndriven(q, false), HoldUndriven(dq, true));
  });
}

bool RobotController::AddMilestone(const VecX& q) {
  if (!CheckLinkVector(q, "AddMilestone", "q")) return false;
  return QueueCommand("AddMilestone", [&] { return queue_.AppendRamp(HoldUndriven(q, false)); });
}

bool RobotController::AddMilestone(const VecX& q, const VecX& dq) {
  if (!CheckLinkVector(q, "AddMilestone", "q") || !CheckLinkVector(dq, "AddMilestone", "dq")) {
    return false;
  }
  return QueueCommand("AddMilestone", [&] {
    return queue_.AppendRamp(HoldUndriven(q, false), HoldUndriven(dq, true));
  });
}

bool RobotController::AddMilestoneLinear(const VecX& q) {
  if (!CheckLinkVector(q, "AddMilestoneLinear", "q")) return false;
  return QueueCommand("AddMilestoneLinear",
                      [&] { return queue_.AppendLinearRamp(HoldUndriven(q, false)); });
}

bool RobotController::SetLinear(const VecX& q, double duration) {
  if (!CheckLinkVector(q, "SetLinear", "q")) return false;
  return QueueCommand("SetLinear", [&] {
    queue_.Cut();
    return queue_.AppendLinear(q, duration);
  });
}

bool RobotController::AddLinear(const VecX& q, double duration) {
  if (!CheckLinkVector(q, "AddLinear", "q")) return false;
  return QueueCommand("AddLinear", [&] { return queue_.AppendLinear(q, duration); });
}

bool RobotController::SetCubic(const VecX& q, const VecX& dq, double duration) {
  if (!CheckLinkVector(q, "SetCubic", "q") || !CheckLinkVector(dq, "SetCubic", "dq")) {
    return false;
  }
  return QueueCommand("SetCubic", [&] {
    queue_.Cut();
    return queue_.AppendCubic(q, dq, duration);
  });
}

bool RobotController::AddCubic(const VecX& q, const VecX& dq, double duration) {
  if (!CheckLinkVector(q, "AddCubic", "q") || !CheckLinkVector(dq, "AddCubic", "dq")) {
    return false;
  }
  return QueueCommand("AddCubic", [&] { return queue_.AppendCubic(q, dq, duration); });
}

VecX RobotController::CommandedLinkConfig() const {
  VecX q_des(driver_count());
  for (int d = 0; d < driver_count(); ++d) {
    q_des[d] = actuators_[d].mode == ActuatorMode::kPid ||
                       actuators_[d].mode == ActuatorMode::kLockedVelocity
                   ? actuators_[d].q_des
                   : DriverValue(d, sensed_q_);
  }
  return LinkValuesFromDrivers(q_des, sensed_q_, false);
}

bool RobotController::GetCommandedConfig(VecX* q) const {
  if (!AllPid()) return false;
  *q = CommandedLinkConfig();
  return true;
}

bool RobotController::GetCommandedVelocity(VecX* dq) const {
  if (!AllPid()) return false;
  VecX dq_des(driver_count());
  for (int d = 0; d < driver_count(); ++d) dq_des[d] = actuators_[d].dq_des;
  *dq = LinkValuesFromDrivers(dq_des, sensed_dq_, true);
  return true;
}

// ---- limits and state --------------------------------------------------------------------

bool RobotController::SetLimits(const JointLimits& limits) {
  if (!queue_.SetLimits(limits)) return Fail(queue_.last_error());
  limits_ = limits;
  return Succeed();
}

RobotControllerState RobotController::GetState() const {
  RobotControllerState state;
  state.actuators = actuators_;
  state.queue = queue_;
  state.next_control_time = next_control_time_;
  state.sensed_q = sensed_q_;
  state.sensed_dq = sensed_dq_;
  state.manual = manual_;
  return state;
}

bool RobotController::SetState(const RobotControllerState& state) {
  if (static_cast<int>(state.actuators.size()) != driver_count() || state.queue.dof() != dof() ||
      state.sensed_q.size() != dof() || state.sensed_dq.size() != dof()) {
    return Fail("SetState: the state is for a different robot");
  }
  actuators_ = state.actuators;
  queue_ = state.queue;
  queue_.SetLimits(limits_);  // the limits are settings, not state
  next_control_time_ = state.next_control_time;
  sensed_q_ = state.sensed_q;
  sensed_dq_ = state.sensed_dq;
  manual_ = state.manual;
  return Succeed();
}

bool RobotController::Fail(std::string message) {
  last_error_ = std::move(message);
  return false;
}

bool RobotController::Succeed() {
  last_error_.clear();
  return true;
}

}  // namespace lamina::core
