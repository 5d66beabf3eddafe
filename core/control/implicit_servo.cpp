// SPDX-License-Identifier: MIT
// RobotController::ComputeImplicitServo: the stiff part of each PID actuator as a joint motor
// that the physics solver applies implicitly (ServoMotorCommand in robot_controller.h).
#include <algorithm>
#include <cmath>

#include "core/control/robot_controller.h"

namespace lamina::core {

void RobotController::ComputeImplicitServo(const VecX& q, const VecX& dq, double h,
                                           VecX* link_forces,
                                           std::vector<ServoMotorCommand>* motors) const {
  ComputeLinkForces(q, dq, link_forces);
  motors->clear();
  if (q.size() != dof() || dq.size() != dof() || !(h > 0.0)) return;
  for (int d = 0; d < driver_count(); ++d) {
    const DriverDesc& driver = drivers_[d];
    const ActuatorState& state = actuators_[d];
    if (!UsableDriver(d) || driver.type != DriverType::kNormal) continue;
    if (state.mode != ActuatorMode::kPid || (state.kp <= 0.0 && state.kd <= 0.0)) continue;
    // ODE bounds a motor by ±fmax: limits that do not straddle zero stay explicit
    if (!(driver.torque_min <= 0.0 && driver.torque_max >= 0.0)) continue;
    const int link = driver.links[0];
    const double value = DriverValue(d, q);
    // the whole law goes to the motor, so that its bound clamps the sum as the explicit law does
    (*link_forces)[link] -= ActuatorEffort(state, driver, value, DriverVelocity(d, dq));
    // with unlimited torque, viscous joint friction is one more damper of the same row (solved
    // implicitly too); a limited actuator must not clamp the friction, which stays separate
    const bool unlimited = std::isinf(driver.torque_max) && std::isinf(driver.torque_min);
    const double viscous = unlimited ? std::max(0.0, driver.viscous_friction) : 0.0;
    const double stiffness = state.kp * h + state.kd + viscous;
    ServoMotorCommand motor;
    motor.link = link;
    motor.includes_viscous = unlimited;
    motor.velocity = (state.kp * PositionError(state, value) + state.kd * state.dq_des +
                      state.ki * state.i_term + state.torque) /
                     stiffness;
    motor.cfm = 1.0 / stiffness;
    motor.fmax = std::min(driver.torque_max, -driver.torque_min);
    motors->push_back(motor);
  }
}

}  // namespace lamina::core
