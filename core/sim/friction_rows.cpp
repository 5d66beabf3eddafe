// SPDX-License-Identifier: MIT
#include "core/sim/friction_rows.h"

#include <cmath>

namespace lamina::core {

namespace {

// rounding of the LCP solve relative to the bound
constexpr double kFrictionBoundSlack = 1e-9;

double SlipSign(double x) {
  return x > 0.0 ? 1.0 : -1.0;
}

}  // namespace

double FrictionRowForce(double cfm, double rate) {
  return -rate / cfm;
}

FrictionRowMode ChooseFrictionRow(double fmax, double cfm, double rate_now) {
  if (!std::isfinite(fmax) || !(fmax > 0.0) || !(cfm > 0.0) || !std::isfinite(rate_now)) {
    return FrictionRowMode::kBounded;
  }
  const double force = std::abs(FrictionRowForce(cfm, rate_now));
  if (force < kUnboundedFrictionFraction * fmax) return FrictionRowMode::kUnbounded;
  if (force > kExplicitFrictionFactor * fmax) return FrictionRowMode::kExplicit;
  return FrictionRowMode::kBounded;
}

double ExplicitFrictionTorque(FrictionRowMode mode, double fmax, double rate_now) {
  return mode == FrictionRowMode::kExplicit ? -fmax * SlipSign(rate_now) : 0.0;
}

MergedRow MergeServoAndFrictionRows(double velocity, double servo_cfm, double friction_cfm) {
  const double sum = servo_cfm + friction_cfm;
  return {velocity * (friction_cfm / sum), servo_cfm * (friction_cfm / sum)};
}

bool FrictionGuessHeld(FrictionRowMode mode, double fmax, double cfm, double rate_now,
                       double rate_after) {
  if (mode == FrictionRowMode::kBounded) return true;
  if (!std::isfinite(rate_after)) return false;
  const double force = FrictionRowForce(cfm, rate_after);
  if (mode == FrictionRowMode::kUnbounded)
    return std::abs(force) <= fmax * (1.0 + kFrictionBoundSlack);
  // the bounded row applies −F·sign(rate_now) when its unbounded force is beyond F that way
  return -force * SlipSign(rate_now) >= fmax * (1.0 - kFrictionBoundSlack);
}

}  // namespace lamina::core
