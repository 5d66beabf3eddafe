// SPDX-License-Identifier: MIT
// Gravity's kick across a change of step (gravity_kick.h): (h0 + h)/2 over a step of h.
#include "core/sim/gravity_kick.h"

#include <gtest/gtest.h>

namespace lamina::core {
namespace {

TEST(GravityKickTest, ConstantStepOrNoPreviousStepIsUnscaled) {
  EXPECT_EQ(GravityKickScale(0.001, 0.001), 1.0);
  EXPECT_EQ(GravityKickScale(0.0, 0.001), 1.0);
  EXPECT_EQ(GravityKickScale(0.001, 0.0), 1.0);
}

TEST(GravityKickTest, KickSpansHalfOfEachNeighbouringStep) {
  // halved: (1 + 0.5)/2 ms of kick over a 0.5 ms step
  EXPECT_DOUBLE_EQ(GravityKickScale(0.001, 0.0005), 1.5);
  // back from 0.25 ms to 1 ms: (0.25 + 1)/2 ms over 1 ms
  EXPECT_DOUBLE_EQ(GravityKickScale(0.00025, 0.001), 0.625);
  // the kicks of a schedule add up to its time less half the first step's and the last's
  // difference: 1, 0.5, 0.25, 1 ms kick 1 + 0.75 + 0.375 + 0.625 = 2.75 ms over 2.75 ms
  const double kicks = 0.001 + 0.0005 * GravityKickScale(0.001, 0.0005) +
                       0.00025 * GravityKickScale(0.0005, 0.00025) +
                       0.001 * GravityKickScale(0.00025, 0.001);
  EXPECT_NEAR(kicks, 0.00275, 1e-18);
}

}  // namespace
}  // namespace lamina::core
