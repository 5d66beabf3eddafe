// SPDX-License-Identifier: MIT
#include "core/sim/servo_bounds.h"

#include <cmath>

namespace lamina::core {

namespace {

// rounding of the LCP solve relative to the bound
constexpr double kServoBoundSlack = 1e-9;

}  // namespace

double ServoRowForce(const ServoMotorCommand& motor, double rate_after) {
  return (motor.velocity - rate_after) / motor.cfm;
}

bool ServoMayGoUnbounded(const ServoMotorCommand& motor, double rate_now) {
  if (!std::isfinite(motor.fmax) || !(motor.fmax > 0.0) || !(motor.cfm > 0.0)) return false;
  return std::abs(ServoRowForce(motor, rate_now)) < kUnboundedServoFraction * motor.fmax;
}

bool ServoForceWithinBound(const ServoMotorCommand& motor, double rate_after) {
  return std::abs(ServoRowForce(motor, rate_after)) <= motor.fmax * (1.0 + kServoBoundSlack);
}

}  // namespace lamina::core
