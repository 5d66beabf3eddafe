// SPDX-License-Identifier: MIT
#include "core/sim/bound_secant.h"

#include <algorithm>

namespace lamina::core {

namespace {

constexpr double kPlainStep = 0.5;
constexpr double kSmallestStep = 1.0 / 1024.0;

}  // namespace

double BoundStep(double bound, double value, BoundSecant* secant) {
  double w = kPlainStep;
  const double moved = bound - secant->last_bound;
  if (secant->known && moved != 0.0) {
    const double slope = (value - secant->last_value) / moved;
    if (slope < 1.0) w = std::clamp(1.0 / (1.0 - slope), kSmallestStep, 1.0);
  }
  *secant = {bound, value, true};
  return w;
}

}  // namespace lamina::core
