// SPDX-License-Identifier: MIT
// How far a friction bound moves from one round to the next when the direct solver's rounds
// (direct_solver.h) look for the bounds that agree with the normal forces they give. A friction
// row's bound b (N, or N·m for a rolling row) is μ|λ_n|, and λ_n is itself the answer of the LCP
// solved with the bounds of the round: the rounds look for the fixed point F(b) = b of that map.
//
// Rounds that set b to F(b) at once settle when F is flat, and swing for ever where a wheel's
// friction and normal force feed each other (ATHLETE on rough ground; F falling with a slope s of
// −6 to −100 there). Moving b halfway (Lamina before 2026-11-29) damps |s| < 3 only: 20 of 2119
// direct solves of ATHLETE on fractal terrain ran out of their budget and went back to dWorldStep,
// 59 of 5014 of HRP-2 on rough ground. Here b moves the secant step towards F(b) = b,
//   b' = b + w (F(b) − b), w = 1/(1 − s), s = (F(b) − F(b₀))/(b − b₀)
// from the last round's pair (b₀, F(b₀)), w within [1/1024, 1]; ½ while no slope is known (the
// first damped round, or b = b₀), or when s ≥ 1 (F rising as fast as b: no secant step towards the
// fixed point). On a straight F the secant step lands on the fixed point; on a steep bend it
// brackets it and closes in (1-D regula falsi). The fixed point, and so the answer, is the same.
// Units: those of the bound; w has none.
#pragma once

namespace lamina::core {

struct BoundSecant {
  double last_bound = 0.0;  ///< b₀ (valid once `known`)
  double last_value = 0.0;  ///< F(b₀)
  bool known = false;
};

/// The fraction w of the way from `bound` (b) to `value` (F(b)) the next round's bound moves;
/// records (b, F(b)) in `secant` for the next round.
double BoundStep(double bound, double value, BoundSecant* secant);

}  // namespace lamina::core
