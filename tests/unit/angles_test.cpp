// SPDX-License-Identifier: MIT
// Angle wrapping into (-pi, pi], shortest signed differences across the +-pi seam, and the
// Klamp't rule that shifts a revolute joint reading by 2 pi toward its limits.
#include "core/control/angles.h"

#include <cmath>

#include <gtest/gtest.h>

#include "core/math_types.h"

namespace lamina::core {
namespace {

constexpr double kTol = 1e-12;

TEST(AnglesTest, NormalizeAngleWrapsIntoHalfOpenInterval) {
  struct Case {
    double in, out;
  } cases[] = {{0, 0},
               {1, 1},
               {kPi, kPi},   // +pi stays
               {-kPi, kPi},  // -pi maps to +pi: the interval is (-pi, pi]
               {3 * kPi, kPi},
               {-3 * kPi, kPi},
               {2 * kPi, 0},
               {1.5 * kPi, -0.5 * kPi},
               {-1.5 * kPi, 0.5 * kPi},
               {7.0, 7.0 - 2 * kPi},
               {-100.0, -100.0 + 32 * kPi}};
  for (const Case& c : cases) {
    EXPECT_NEAR(NormalizeAngle(c.in), c.out, kTol) << "in " << c.in;
    EXPECT_GT(NormalizeAngle(c.in), -kPi);
    EXPECT_LE(NormalizeAngle(c.in), kPi);
  }
  EXPECT_TRUE(std::isnan(NormalizeAngle(std::nan(""))));
}

TEST(AnglesTest, AngleDiffIsTheShortestSignedRotation) {
  EXPECT_NEAR(AngleDiff(0.1, -0.1), 0.2, kTol);
  EXPECT_NEAR(AngleDiff(kPi - 0.1, -kPi + 0.1), -0.2, kTol);  // across the seam
  EXPECT_NEAR(AngleDiff(-kPi + 0.1, kPi - 0.1), 0.2, kTol);
  EXPECT_NEAR(AngleDiff(kPi, 0), kPi, kTol);
  EXPECT_NEAR(AngleDiff(0, kPi), kPi, kTol);  // exactly half a turn: +pi
  EXPECT_NEAR(AngleDiff(5 * kPi, 0), kPi, 1e-9);
  EXPECT_NEAR(AngleDiff(2.0, 2.0 + 4 * kPi), 0, 1e-12);
}

TEST(AnglesTest, ShiftIntoLimitsMovesByTwoPiOnlyWhenThatHelps) {
  // inside: unchanged
  EXPECT_EQ(ShiftIntoLimits(0.5, -1, 1), 0.5);
  // limits [0, 2pi): -0.5 reads as 2pi - 0.5
  EXPECT_NEAR(ShiftIntoLimits(-0.5, 0, 2 * kPi - 0.1), 2 * kPi - 0.5, kTol);
  // limits [-3.5, -2]: pi (+pi from the hinge) is -pi after shifting, inside
  EXPECT_NEAR(ShiftIntoLimits(kPi, -3.5, -2), -kPi, kTol);
  // outside after the shift too, but closer to the limits: shifted
  EXPECT_NEAR(ShiftIntoLimits(3.0, -2.5, 0.0), 3.0 - 2 * kPi, kTol);  // 3 -> -3.28 (0.78 off)
  // shifting would be farther outside: unchanged
  EXPECT_EQ(ShiftIntoLimits(1.2, -0.5, 1.0), 1.2);
  EXPECT_EQ(ShiftIntoLimits(-1.2, -1.0, 0.5), -1.2);
  // infinite limits: nothing violated
  EXPECT_EQ(ShiftIntoLimits(10.0, -kInf, kInf), 10.0);
}

}  // namespace
}  // namespace lamina::core
