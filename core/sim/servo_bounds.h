// SPDX-License-Identifier: MIT
// Servo rows solved without their bound when the bound will not act. ODE's dWorldStep (a Dantzig
// LCP) factorizes every row whose bounds are infinite in one block and takes each bounded row in
// one pivot at a time, at a cost of order rows x (all rows)^2: on a humanoid the 30 servo rows,
// bounded by the torque limits, are pivoted one by one like its contacts. A servo whose force
// stays inside its limit gives exactly the same step without the bound, so the row goes unbounded
// when the force it would apply at the joint's current rate is well inside the limit, and the step
// is checked afterwards: ODE solves the row J v' = v_target - cfm lambda, so the force it applied
// is lambda = (v_target - rate after the step) / cfm. A row whose force came out beyond the limit
// is bounded again and the step retaken from its start (Simulator::TrySubStep), so a step is never
// accepted with a servo over its limit.
//
// Units: rates in rad/s (m/s for sliders), forces in N·m (N). Sign: the joint's own (the rate
// and force that increase q). Only the exact solver uses servo rows (QuickStep applies the PD
// law explicitly). Not in Klamp't, whose servos are explicit torques.
#pragma once

#include "core/control/robot_controller.h"

namespace lamina::core {

/// A row goes unbounded when the force it would apply at the current rate is below this
/// fraction of its limit: a load that doubles within one step is rare, and then costs a retake.
inline constexpr double kUnboundedServoFraction = 0.5;

/// The force the servo row of `motor` applied in a step that ended with the joint at
/// `rate_after`: (velocity - rate_after) / cfm.
double ServoRowForce(const ServoMotorCommand& motor, double rate_after);

/// Whether the row of `motor` may be solved without its (finite) bound at the joint rate
/// `rate_now`: the force at that rate is below kUnboundedServoFraction of the bound.
bool ServoMayGoUnbounded(const ServoMotorCommand& motor, double rate_now);

/// Whether an unbounded row's force after the step stayed within the bound (1e-9 relative slack
/// for the rounding of the solve); false for a non-finite rate.
bool ServoForceWithinBound(const ServoMotorCommand& motor, double rate_after);

}  // namespace lamina::core
