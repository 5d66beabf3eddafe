// SPDX-License-Identifier: MIT
// Per-DOF limits that bound generated motions: position range, speed and acceleration.
#pragma once

#include <string>

#include "core/math_types.h"

namespace lamina::core {

/// Limits of a robot's DOFs, all vectors of the same length (one entry per DOF). Infinite
/// entries mean "unbounded"; velocity and acceleration maxima must be >= 0 (0 freezes the DOF).
struct JointLimits {
  VecX q_min;             ///< rad or m
  VecX q_max;             ///< rad or m, >= q_min
  VecX velocity_max;      ///< rad/s or m/s
  VecX acceleration_max;  ///< rad/s^2 or m/s^2

  int dof() const { return static_cast<int>(q_min.size()); }

  /// `dof` DOFs with no position bounds and the given speed and acceleration maxima.
  static JointLimits Unbounded(int dof, double velocity_max = kInf, double acceleration_max = kInf);

  /// True when every vector has `dof` entries, no entry is NaN, q_min <= q_max and the maxima
  /// are >= 0. Otherwise false with the reason in `*error` (when not null).
  bool IsValid(int dof, std::string* error) const;
};

}  // namespace lamina::core
