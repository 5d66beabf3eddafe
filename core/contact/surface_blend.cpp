// SPDX-License-Identifier: MIT
// Blending two contact surfaces and the ODE soft-contact parameters (see surface_blend.h).
#include "core/contact/surface_blend.h"

#include <cmath>

namespace lamina::core {
namespace {

/// Two springs (or dampers) in series: 1 / (1/a + 1/b). An infinite side is returned exactly as
/// the other one (1 / (1/b) can be an ulp off b); a zero side gives 1 / inf = 0.
double SeriesCombination(double a, double b) {
  if (std::isinf(a)) return b;
  if (std::isinf(b)) return a;
  return 1.0 / (1.0 / a + 1.0 / b);
}

}  // namespace

BlendedSurface BlendSurfaces(const SurfaceDesc& a, const SurfaceDesc& b) {
  BlendedSurface blended;
  blended.restitution = 0.5 * (a.restitution + b.restitution);
  // The harmonic mean is twice the series combination: 2 / (1/μa + 1/μb).
  blended.friction = 2.0 * SeriesCombination(a.friction, b.friction);
  blended.rolling = 2.0 * SeriesCombination(a.rolling_friction, b.rolling_friction);
  blended.spinning = 2.0 * SeriesCombination(a.spinning_friction, b.spinning_friction);
  blended.stiffness = SeriesCombination(a.stiffness, b.stiffness);
  blended.damping = SeriesCombination(a.damping, b.damping);
  return blended;
}

SoftContactParams SoftContact(double stiffness, double damping, double step) {
  if (std::isinf(stiffness) || std::isinf(damping)) return {0.0, 0.0, false};
  const double denominator = step * stiffness + damping;
  if (denominator == 0.0) return {0.0, kInf, true};
  return {step * stiffness / denominator, 1.0 / denominator, true};
}

}  // namespace lamina::core
