// SPDX-License-Identifier: MIT
#include "core/sim/gravity_kick.h"

namespace lamina::core {

double GravityKickScale(double previous, double step) {
  if (previous <= 0.0 || step <= 0.0 || previous == step) return 1.0;
  return (previous + step) / (2.0 * step);
}

}  // namespace lamina::core
