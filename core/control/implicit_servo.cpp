// SPDX-License-Identifier: MIT
// RobotController::ComputeImplicitServo: the stiff part of each PID actuator as a joint motor
// that the physics solver applies implicitly (ServoMotorCommand in robot_controller.h).
#include <algorithm>
#include <cmath>

#include "core/control/explicit_pd.h"
#include "core/control/robot_controller.h"

namespace lamina::core {

bool RobotController::ServoDriver(int d) const {
  const DriverDesc& driver = robot_->drivers[d];
  const ActuatorState& state = actuators_[d];
  // ODE bounds a motor by ±fmax: limits that do not straddle zero stay explicit
  return UsableDriver(d) && driver.type == DriverType::kNormal &&
         state.mode == ActuatorMode::kPid && (driver.servo_p > 0.0 || driver.servo_d > 0.0) &&
         driver.torque_min <= 0.0 && driver.torque_max >= 0.0;
}

bool RobotController::UnlimitedServo(int d) const {
  const DriverDesc& driver = robot_->drivers[d];
  return ServoDriver(d) && std::isinf(driver.torque_max) && std::isinf(driver.torque_min);
}

bool RobotController::HasUnlimitedServo() const {
  for (int d = 0; d < driver_count(); ++d) {
    if (UnlimitedServo(d)) return true;
  }
  return false;
}

void RobotController::DivergingServos(const VecX& link_inertias, double h,
                                      std::vector<char>* diverging) const {
  diverging->assign(driver_count(), 0);
  for (int d = 0; d < driver_count(); ++d) {
    if (!UnlimitedServo(d)) continue;
    const DriverDesc& driver = robot_->drivers[d];
    const int link = driver.links[0];
    if (link < 0 || link >= link_inertias.size()) continue;
    (*diverging)[d] = !ExplicitPdStable(driver.servo_p, driver.servo_d, link_inertias[link], h);
  }
}

void RobotController::ComputeImplicitServo(const VecX& q, const VecX& dq, double h,
                                           VecX* link_forces,
                                           std::vector<ServoMotorCommand>* motors,
                                           const std::vector<char>* only) const {
  motors->clear();
  if (!(h > 0.0)) {
    ComputeLinkForces(q, dq, link_forces);
    return;
  }
  // the servo drivers' whole law goes to their motors, so that the bound clamps the sum as the
  // explicit law does
  implicit_.assign(driver_count(), 0);
  for (int d = 0; d < driver_count(); ++d) {
    implicit_[d] = ServoDriver(d) && (only == nullptr || (*only)[d]);
  }
  AddDriverForces(q, dq, &implicit_, link_forces);
  if (q.size() != dof() || dq.size() != dof()) return;
  for (int d = 0; d < driver_count(); ++d) {
    if (!implicit_[d]) continue;
    const DriverDesc& driver = robot_->drivers[d];
    const ActuatorState& state = actuators_[d];
    // with unlimited torque, viscous joint friction is one more damper of the same row (solved
    // implicitly too); a limited actuator must not clamp the friction, which stays separate
    const bool unlimited = std::isinf(driver.torque_max) && std::isinf(driver.torque_min);
    const double viscous = unlimited ? std::max(0.0, driver.viscous_friction) : 0.0;
    const double stiffness = driver.servo_p * h + driver.servo_d + viscous;
    ServoMotorCommand motor;
    motor.link = driver.links[0];
    motor.includes_viscous = unlimited;
    motor.velocity =
        (driver.servo_p * PositionError(state, DriverValue(d, q)) + driver.servo_d * state.dq_des +
         driver.servo_i * state.i_term + state.torque) /
        stiffness;
    motor.cfm = 1.0 / stiffness;
    motor.fmax = std::min(driver.torque_max, -driver.torque_min);
    motors->push_back(motor);
  }
}

}  // namespace lamina::core
