// SPDX-License-Identifier: MIT
// Kept triangle-pair candidates (core/contact/near_pair_cache.h) in whole simulations: a run that
// reuses them is bitwise the run that searches the mesh hierarchies every step, and on resting
// contact it searches in few steps.
#include <string>

#include <gtest/gtest.h>

#include "core/sim/simulator.h"
#include "tests/common/test_support.h"

namespace lamina {
namespace {

struct Counts {
  long long searches = 0, reused = 0;
};

Counts RunBothWays(const std::string& world_file, core::SolverType solver, double duration) {
  const core::WorldDesc world = test::LoadShippedWorld(world_file);
  core::Simulator reusing(world, {solver, 20});
  core::Simulator searching(world, {solver, 20});
  searching.SetReuseContactPairs(false);
  for (double t = 0.0; t < duration - 1e-9; t += 0.05) {
    reusing.Simulate(0.05);
    searching.Simulate(0.05);
    EXPECT_TRUE(reusing.GetState() == searching.GetState()) << world_file << " at " << t + 0.05;
  }
  EXPECT_EQ(searching.ContactPairSearches() + searching.ContactPairReuses(), 0);
  return {reusing.ContactPairSearches(), reusing.ContactPairReuses()};
}

TEST(ContactPairReuseTest, HumanoidOnRoughGroundRunsBitwiseTheSame) {
  // HRP-2's soles (meshes) landing and standing on fractal terrain, exact solver
  const Counts counts = RunBothWays("examples/hrp2_rough.xml", core::SolverType::kStep, 0.3);
  EXPECT_GT(counts.reused, 20 * counts.searches);
  EXPECT_GT(counts.searches, 0);
}

TEST(ContactPairReuseTest, BallsOnAStiffnessRangeRunBitwiseTheSame) {
  // stiffness_test.xml's 960-triangle balls dropping onto their blocks (they land after about
  // 0.4 s) and sinking into their layers
  const Counts counts = RunBothWays("klampt/simulation_test_worlds/stiffness_test.xml",
                                    core::SolverType::kNewton, 0.6);
  EXPECT_GT(counts.reused, 20 * counts.searches);
  EXPECT_GT(counts.searches, 0);
}

TEST(ContactPairReuseTest, WheelsLandingOnFractalTerrainRunBitwiseTheSame) {
  // ATHLETE's six wheels landing on fractal terrain: they move fast enough to search again in
  // many steps, and the Newton solver takes the island
  const Counts counts = RunBothWays("klampt/athlete_fractal_1.xml", core::SolverType::kNewton, 0.3);
  EXPECT_GT(counts.searches, 500);
  EXPECT_GT(counts.reused, counts.searches);
}

}  // namespace
}  // namespace lamina
