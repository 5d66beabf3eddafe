// SPDX-License-Identifier: MIT
#include "core/control/explicit_pd.h"

#include <cmath>

#include "core/math_types.h"

namespace lamina::core {

bool ExplicitPdStable(double kp, double kd, double inertia, double step) {
  if (kp == 0.0 && kd == 0.0) return true;
  if (!(inertia > 0.0) || !std::isfinite(inertia)) return inertia == kInf;  // (−∞: negative)
  const double a = kd * step / inertia;
  const double b = kp * step * step / inertia;
  return a < 2.0 && b < 4.0 - 2.0 * a;
}

}  // namespace lamina::core
