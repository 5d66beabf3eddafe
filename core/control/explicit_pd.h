// SPDX-License-Identifier: MIT
// Whether a PD law applied explicitly holds a joint at a given step. Klamp't (and Lamina under
// QuickStep) applies a PID actuator's effort τ = kP·e − kD·q̇ computed at the start of the step,
// and ODE integrates it with symplectic Euler (v += h·τ/m, then q += h·v). For a joint of inertia m
// on its own, the error e and rate v after the step are the linear map
//
//   [e']   [1 − b    h·(1 − a)] [e]        a = kD·h/m,  b = kP·h²/m,
//   [v'] = [−b/h     1 − a    ] [v],
//
// with determinant 1 − a and trace 2 − a − b. Its eigenvalues stay inside the unit circle (Jury's
// conditions) exactly when a < 2 and b < 4 − 2a; with kD = 0 it is the undamped symplectic
// oscillator, bounded for b < 4 (ω·h < 2). Outside, the error grows by a factor |λ| > 1 every
// step: an actuator with a torque limit chatters at its limit (Klamp't's robots do: ATHLETE's
// light links have a ≈ 5), one without a limit diverges to infinity (worlds/accuracy/
// gripper_pad.xml at 10 ms: a = b = 5, the pad at 1e125 m within 1.5 s).
//
// Units: kP in N·m/rad (N/m), kD in N·m·s/rad (N·s/m), m in kg·m² (kg), h in s.
#pragma once

namespace lamina::core {

/// True when the explicit PD law with gains `kp`, `kd` (≥ 0) holds a joint of inertia `inertia`
/// at step `step` (the conditions above). An infinite inertia (a joint that moves nothing) holds;
/// a zero, negative or NaN one does not, unless both gains are 0.
bool ExplicitPdStable(double kp, double kd, double inertia, double step);

}  // namespace lamina::core
