// SPDX-License-Identifier: MIT
// The explicit PD law's stability (core/control/explicit_pd.h) against the law itself: on a grid
// of gains the predicate says "holds" exactly where 2000 steps of v += h·(−kP·e − kD·v)/m,
// e += h·v from e = 1 stay bounded, and the gripper pad's gains at 1 and 10 ms fall on either side.
#include "core/control/explicit_pd.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

namespace lamina::core {
namespace {

// the largest |e| over 2000 explicit steps from e = 1 at rest
double LargestError(double kp, double kd, double m, double h) {
  double e = 1.0, v = 0.0, largest = 1.0;
  for (int k = 0; k < 2000 && largest < 1e6; ++k) {
    v += h * (-kp * e - kd * v) / m;
    e += h * v;
    largest = std::max(largest, std::abs(e));
  }
  return largest;
}

TEST(ExplicitPdTest, HoldsExactlyWhereTheLawStaysBounded) {
  const double m = 0.5, h = 0.01;
  int checked = 0;
  // a = kD·h/m and b = kP·h²/m on a grid that keeps clear of the boundary (where growth is slow)
  for (double a = 0.05; a < 3.0; a += 0.1) {
    for (double b = 0.05; b < 6.0; b += 0.1) {
      if (std::abs(b - (4.0 - 2.0 * a)) < 0.15 || std::abs(a - 2.0) < 0.15) continue;
      const double kd = a * m / h, kp = b * m / (h * h);
      const bool bounded = LargestError(kp, kd, m, h) < 1e3;
      EXPECT_EQ(ExplicitPdStable(kp, kd, m, h), bounded) << "a " << a << " b " << b;
      ++checked;
    }
  }
  EXPECT_GT(checked, 1000);
}

TEST(ExplicitPdTest, TheGripperPadDivergesAtTenMillisecondsOnly) {
  // servoP 1e4 N/m, servoD 100 N·s/m on the 0.2 kg pad (worlds/accuracy/gripper_pad.rob)
  EXPECT_TRUE(ExplicitPdStable(1e4, 100.0, 0.2, 0.001));  // a = 0.5, b = 0.05
  EXPECT_FALSE(ExplicitPdStable(1e4, 100.0, 0.2, 0.01));  // a = b = 5
  EXPECT_TRUE(ExplicitPdStable(1e4, 100.0, std::numeric_limits<double>::infinity(), 0.01));
  EXPECT_FALSE(ExplicitPdStable(1e4, 0.0, 0.0, 0.01));
  EXPECT_FALSE(ExplicitPdStable(1e4, 0.0, -std::numeric_limits<double>::infinity(), 0.01));
  EXPECT_TRUE(ExplicitPdStable(0.0, 0.0, 0.0, 0.01));  // no law at all
}

}  // namespace
}  // namespace lamina::core
