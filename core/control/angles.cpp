// SPDX-License-Identifier: MIT
// Angle wrapping and the joint-reading shift (see angles.h).
#include "core/control/angles.h"

#include <cmath>

#include "core/math_types.h"

namespace lamina::core {
namespace {

// How far `q` lies outside [q_min, q_max] (0 inside).
double LimitViolation(double q, double q_min, double q_max) {
  if (q > q_max) return q - q_max;
  if (q < q_min) return q_min - q;
  return 0.0;
}

}  // namespace

double NormalizeAngle(double angle) {
  if (!std::isfinite(angle)) return angle;
  double wrapped = std::fmod(angle, kTwoPi);  // in (-2pi, 2pi), sign of angle
  if (wrapped <= -kPi) wrapped += kTwoPi;
  if (wrapped > kPi) wrapped -= kTwoPi;
  return wrapped;
}

double AngleDiff(double a, double b) {
  return NormalizeAngle(a - b);
}

double ShiftIntoLimits(double q, double q_min, double q_max) {
  const double violation = LimitViolation(q, q_min, q_max);
  if (violation == 0.0) return q;
  const double shifted = q > q_max ? q - kTwoPi : q + kTwoPi;
  return LimitViolation(shifted, q_min, q_max) < violation ? shifted : q;
}

}  // namespace lamina::core
