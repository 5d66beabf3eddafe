// SPDX-License-Identifier: MIT
// Angle arithmetic for revolute joints: wrapping to (-pi, pi], shortest signed differences and
// the Klamp't rule for reading a wrapped joint angle back into the joint's limits.
#pragma once

namespace lamina::core {

/// `angle` (rad) wrapped into (-pi, pi]. Non-finite input is returned unchanged.
double NormalizeAngle(double angle);

/// The shortest signed rotation from `b` to `a` (rad), i.e. a - b wrapped into (-pi, pi].
double AngleDiff(double a, double b);

/// A revolute joint reading `q` (rad) made consistent with the limits [q_min, q_max]: when q is
/// outside, q - 2pi (if q > q_max) or q + 2pi (if q < q_min) is returned instead when the shifted
/// value is inside the limits or violates them by less than q does. Otherwise q is unchanged.
double ShiftIntoLimits(double q, double q_min, double q_max);

}  // namespace lamina::core
