// SPDX-License-Identifier: MIT
// Per-driver actuator emulation: the command state of one driver (off, torque, PID, locked
// velocity) and the control law that turns it into a clamped effort at the physics rate
// (Klamp't ActuatorCommand semantics, with the differences listed in docs/motion.md).
#pragma once

#include "core/model/world_desc.h"

namespace lamina::core {

/// What a driver is asked to do.
enum class ActuatorMode {
  kOff,             ///< no effort
  kTorque,          ///< apply `torque`, clamped to the driver's limits
  kPid,             ///< track (q_des, dq_des) with the PID law plus feed-forward `torque`
  kLockedVelocity,  ///< the simulator drives the joint motor at `desired_velocity` (max `torque`)
};

/// The command state of one driver. Units are the driver's: rad or m for q, N·m or N for efforts.
/// The gains are the driver's (DriverDesc::servo_p/i/d, read at every use): parameters, not
/// state, so that a gain edited live survives SetState and Reset (Klamp't's setPIDGains writes
/// the robot's drivers too).
struct ActuatorState {
  ActuatorMode mode = ActuatorMode::kPid;
  double q_des = 0;   ///< desired driver value
  double dq_des = 0;  ///< desired driver velocity, per s
  double i_term = 0;  ///< integral of the position error, rad·s (or m·s)
  /// Torque command (kTorque), PID feed-forward (kPid) or maximum motor effort (kLockedVelocity).
  double torque = 0;
  double desired_velocity = 0;  ///< kLockedVelocity only, per s
  /// Continuous revolute driver: errors are measured as the shortest angle (AngleDiff).
  bool relative_encoding = false;
};

/// True for a normal revolute driver whose range [q_min, q_max] is infinite or spans >= 2π
/// (Klamp't "relative encoding"). `revolute` says whether the driven link is revolute.
bool IsContinuousDriver(const DriverDesc& driver, bool revolute);

/// The initial state of a driver at value `q`: PID mode holding q, zero integral and
/// feed-forward; relative encoding per IsContinuousDriver.
ActuatorState InitialActuatorState(const DriverDesc& driver, bool revolute, double q);

/// The position error q_des − q; the shortest angle AngleDiff(q_des, q) for relative encoding.
double PositionError(const ActuatorState& state, double q);

/// The clamped effort of the driver at value q and velocity dq (N·m or N):
/// PID: servo_p·Δq + servo_d·(dq_des − dq) + servo_i·i_term + torque; torque mode: torque; both
/// clamped to [driver.torque_min, driver.torque_max] (read live). Off and locked velocity: 0. Never
/// changes the state (may be called again when the simulator retakes a step).
double ActuatorEffort(const ActuatorState& state, const DriverDesc& driver, double q, double dq);

/// Advances the state after an accepted physics step of `h` s ending at value q: PID mode adds
/// Δq·h to the integral with anti-windup (servo_i·i_term kept inside [torque_min, torque_max]);
/// locked velocity moves q_des by dq_des·h.
void IntegrateActuator(const DriverDesc& driver, double q, double h, ActuatorState* state);

}  // namespace lamina::core
