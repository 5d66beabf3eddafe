// SPDX-License-Identifier: MIT
// The instability check: kinetic energy, the work bound, and which bodies get slowed.
#include "core/sim/energy_guard.h"

#include <cmath>

#include <gtest/gtest.h>

namespace lamina::core {
namespace {

TEST(EnergyGuardTest, KineticEnergyHasTheHalf) {
  const Mat3 inertia = Vec3(1.0, 2.0, 3.0).asDiagonal();
  // ½·2·(3² + 4²) + ½·(1·1² + 2·0 + 3·2²) = 25 + 6.5
  EXPECT_DOUBLE_EQ(KineticEnergy(2.0, inertia, Vec3(3, 4, 0), Vec3(1, 0, 2)), 31.5);
}

TEST(EnergyGuardTest, WorkBoundUsesTheFasterEnd) {
  // 0.01 s·(5 N·max(1, 3) m/s + 2 N·m·max(4, 0) rad/s)
  EXPECT_DOUBLE_EQ(ExternalWorkBound(Vec3(3, 4, 0), Vec3(0, 0, 2), 1, 3, 4, 0, 0.01),
                   0.01 * (15 + 8));
}

TEST(EnergyGuardTest, ImpactHandingMomentumToALightBodyIsStable) {
  // a 100 kg block at 1 m/s stops a 1 kg one... and the light one leaves at up to 2 m/s:
  // it alone gains 2 J (over its 1 J/kg allowance), but the total energy does not grow
  const std::vector<BodyEnergySample> bodies = {{100.0, 50.0, 48.0, 0.0}, {1.0, 0.0, 2.0, 0.0}};
  EXPECT_TRUE(InstabilityScales(bodies).empty());
}

TEST(EnergyGuardTest, GainBeyondTheAllowanceIsScaledToPostCorrection) {
  InstabilitySettings settings;
  // allowance 1.5·10 + 1·2 + 3 = 20 J; the body jumped to 500 J
  const std::vector<BodyEnergySample> bodies = {{2.0, 10.0, 500.0, 3.0}, {1.0, 5.0, 5.0, 0.0}};
  const std::vector<double> scales = InstabilityScales(bodies, settings);
  ASSERT_EQ(scales.size(), 2u);
  EXPECT_DOUBLE_EQ(scales[0], std::sqrt(settings.post_correction * 20.0 / 500.0));
  EXPECT_DOUBLE_EQ(scales[1], 1.0);  // the quiet body is left alone
}

TEST(EnergyGuardTest, OnlyTheBodiesOverTheirAllowanceAreSlowed) {
  // each body just within its own allowance (1.5·0 + 1·1 = 1 J), the total too: stable
  std::vector<BodyEnergySample> bodies(3, {1.0, 0.0, 0.99, 0.0});
  EXPECT_TRUE(InstabilityScales(bodies).empty());
  bodies[1].energy_after = 1.5;
  const std::vector<double> scales = InstabilityScales(bodies);
  // total 3.48 > 3: the body over its own allowance is slowed to 0.8 J
  ASSERT_EQ(scales.size(), 3u);
  EXPECT_DOUBLE_EQ(scales[1], std::sqrt(0.8 * 1.0 / 1.5));
  EXPECT_DOUBLE_EQ(scales[0], 1.0);
}

}  // namespace
}  // namespace lamina::core
