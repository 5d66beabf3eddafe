// SPDX-License-Identifier: MIT
// Klamp't's heavyblocktest.xml (a 0.4 m block on a 0.1 m block on a slab, all rigid) at mass
// ratios of 100:1 (as written) and 1000:1: the light block must carry the heavy one without
// being squeezed out sideways, and the layers must hold the weight. Runs 5 s of simulated time
// per ratio (label "physics").
#include <string>

#include <gtest/gtest.h>

#include "core/sim/simulator.h"
#include "tests/common/test_support.h"

namespace lamina {
namespace {

using core::Vec3;

// The world with the top block's mass set to `ratio` times the bottom one's, its inertia
// scaled with it (same shape, uniform density).
core::WorldDesc HeavyBlockWorld(double ratio) {
  test::LoadedWorld loaded;
  test::LoadWorld(test::WorldsPath("klampt/simulation_test_worlds/heavyblocktest.xml"), &loaded);
  EXPECT_TRUE(loaded.ok) << loaded.diagnostics.FormatAll();
  core::WorldDesc world = loaded.world;
  EXPECT_EQ(world.objects.size(), 2u);
  if (world.objects.size() != 2) return world;
  core::RigidObjectDesc& light = world.objects[0];
  core::RigidObjectDesc& heavy = world.objects[1];
  const double mass = ratio * light.mass;
  heavy.inertia *= mass / heavy.mass;
  heavy.mass = mass;
  return world;
}

void ExpectBlocksStayPut(double ratio) {
  SCOPED_TRACE("mass ratio " + std::to_string(ratio));
  const core::WorldDesc world = HeavyBlockWorld(ratio);
  ASSERT_EQ(world.objects.size(), 2u);
  core::Simulator simulator(world);
  simulator.Simulate(5.0);
  ASSERT_LT(simulator.statistics().worst_status, core::StepStatus::kUnstable)
      << simulator.statistics().error;
  // the bar: lateral drift < 5 mm (Klamp't squeezes the 1 kg block out by 0.40 m at
  // 100:1)
  for (int i = 0; i < simulator.object_count(); ++i) {
    const Vec3 drift =
        simulator.GetObjectPose(i).translation() - world.objects[i].pose.translation();
    EXPECT_LT(drift.head<2>().norm(), 5e-3) << world.objects[i].name;
  }
  // penetration stays within the boundary layer: every pair here (slab-block, block-block)
  // has paddings of 2.5 mm on each side, 5 mm in all
  const double padding_sum =
      world.objects[0].sim.padding + world.objects[1].sim.padding + core::kLayerEdgeSlack;
  EXPECT_LT(simulator.statistics().max_penetration, padding_sum);
  // the bar: no instability correction (Klamp't fires them here)
  EXPECT_EQ(simulator.statistics().instability_corrections, 0);
  // the stack stands: the light block's centre 0.05 m (half its side) plus at most the 5 mm
  // layer above the slab's top (z = 0), the heavy one's 0.2 m above the light block's top
  const double light_z = simulator.GetObjectPose(0).translation().z();
  const double heavy_z = simulator.GetObjectPose(1).translation().z();
  EXPECT_GT(light_z, 0.05);
  EXPECT_LT(light_z, 0.05 + padding_sum);
  EXPECT_GT(heavy_z - light_z, 0.05 + 0.2);
  EXPECT_LT(heavy_z - light_z, 0.05 + 0.2 + padding_sum);
  EXPECT_LT(simulator.GetObjectVelocity(1).linear.norm(), 1e-3);
}

TEST(HeavyBlockRatioTest, HundredToOneAsWritten) {
  ExpectBlocksStayPut(100.0);
}

TEST(HeavyBlockRatioTest, ThousandToOne) {
  ExpectBlocksStayPut(1000.0);
}

}  // namespace
}  // namespace lamina
