// SPDX-License-Identifier: MIT
// The secant step of the direct solver's friction rounds (core/sim/bound_secant.h) on maps F(b)
// whose fixed point is known.
#include "core/sim/bound_secant.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include <gtest/gtest.h>

namespace lamina::core {
namespace {

using BoundMap = std::function<double(double)>;

// rounds of b ← b + w (F(b) − b) from b = 0 until |F(b) − b| ≤ 1e-9 |b|: the number of rounds
// taken, or -1 after `most`; `plain` keeps w at ½ (the rule bound_secant.h replaces)
int Rounds(const BoundMap& map, bool plain, int most, double* bound) {
  BoundSecant secant;
  double b = 0.0;
  for (int round = 1; round <= most; ++round) {
    const double value = map(b);
    if (std::abs(value - b) <= 1e-9 * std::abs(b)) {
      *bound = b;
      return round;
    }
    const double w = plain ? 0.5 : BoundStep(b, value, &secant);
    b += w * (value - b);
  }
  *bound = b;
  return -1;
}

// A wheel whose normal force falls steeply as its friction grows: μ|λ_n| = 1.9 N up to a bound
// of 0.4 N, 0 from 0.495 N, slope −20 between. Its fixed point is 9.9/21 N. Halfway steps swing
// between two bounds for ever (|1 + ½(s − 1)| = 9.5 > 1); secant steps settle (measured: in 7
// rounds).
TEST(BoundSecantTest, SettlesWhereHalfwayStepsSwingForEver) {
  const BoundMap steep = [](double b) { return std::clamp(1.9 - 20.0 * (b - 0.4), 0.0, 1.9); };
  double bound = 0.0;
  EXPECT_EQ(Rounds(steep, true, 500, &bound), -1);
  const int rounds = Rounds(steep, false, 500, &bound);
  EXPECT_GT(rounds, 0);
  EXPECT_LE(rounds, 10);
  EXPECT_NEAR(bound, 9.9 / 21.0, 1e-9);
}

// On a straight map the second step lands on the fixed point; the first is the plain ½.
TEST(BoundSecantTest, LandsOnAStraightMapsFixedPointInOneSecantStep) {
  BoundSecant secant;
  EXPECT_EQ(BoundStep(0.0, 2.0, &secant), 0.5);  // F(b) = 2 − 3b; b* = 0.5
  const double b = 1.0;                          // ½ of the way from 0 to F(0) = 2
  const double w = BoundStep(b, 2.0 - 3.0 * b, &secant);
  EXPECT_DOUBLE_EQ(w, 0.25);                  // 1/(1 − s), s = −3
  EXPECT_DOUBLE_EQ(b + w * (-1.0 - b), 0.5);  // onto b*
}

// A map rising as fast as b gives no secant step: the plain ½ again; a flat one the whole step;
// a cliff the smallest.
TEST(BoundSecantTest, KeepsTheHalfStepWithoutASlopeTowardsTheFixedPoint) {
  BoundSecant secant;
  BoundStep(1.0, 2.0, &secant);
  EXPECT_EQ(BoundStep(2.0, 3.5, &secant), 0.5);  // s = 1.5
  EXPECT_EQ(BoundStep(2.0, 3.0, &secant), 0.5);  // b did not move
  BoundStep(1.0, 3.0, &secant);
  EXPECT_EQ(BoundStep(2.0, 3.0, &secant), 1.0);  // s = 0
  BoundStep(0.0, 1e3, &secant);
  EXPECT_EQ(BoundStep(1e-9, 0.0, &secant), 1.0 / 1024.0);  // s = −1e12: the smallest step
}

}  // namespace
}  // namespace lamina::core
