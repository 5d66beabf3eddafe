// SPDX-License-Identifier: MIT
// Klamp't's simulation test worlds, run as they are, against the bars: the 10-box stack
// stands, the 100 kg block does not squeeze out the 1 kg one, fast drops do not tunnel. These run
// seconds of simulated time each (label "physics").
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "core/geometry/shrink.h"
#include "core/io/world_file.h"
#include "core/sim/simulator.h"
#include "tests/common/test_support.h"

namespace lamina {
namespace {

using core::Vec3;

// the gravity of Klamp't's worlds (m/s²)
constexpr double kGravityForWorlds = 9.8;

core::WorldDesc LoadTestWorld(const std::string& name) {
  return test::LoadShippedWorld("klampt/simulation_test_worlds/" + name);
}

TEST(KlamptWorldsTest, StackOfTenBoxesStandsTenSeconds) {
  const core::WorldDesc world = LoadTestWorld("stacktest.xml");
  core::Simulator simulator(world);
  simulator.Simulate(10.0);
  ASSERT_NE(simulator.statistics().worst_status, core::StepStatus::kError)
      << simulator.statistics().error;
  // the bar: top drift < 1 mm (Klamp't drifts 12 mm); every box stays within 1 mm
  // sideways of where it started
  for (int i = 0; i < simulator.object_count(); ++i) {
    const Vec3 start = world.objects[i].pose.translation();
    const Vec3 end = simulator.GetObjectPose(i).translation();
    EXPECT_LT((end - start).head<2>().norm(), 1e-3) << world.objects[i].name;
  }
  // each box rests on the one below: centres 0.1 m apart plus at most the 2 mm padding sum (and
  // the layer-edge nanometre, core/contact/contact.h)
  for (int i = 1; i < simulator.object_count(); ++i) {
    const double gap = simulator.GetObjectPose(i).translation().z() -
                       simulator.GetObjectPose(i - 1).translation().z();
    EXPECT_GT(gap, 0.1) << world.objects[i].name;
    EXPECT_LT(gap, 0.1 + 0.002 + core::kLayerEdgeSlack) << world.objects[i].name;
  }
}

TEST(KlamptWorldsTest, HeavyBlockDoesNotSqueezeOutTheLightOne) {
  const core::WorldDesc world = LoadTestWorld("heavyblocktest.xml");
  core::Simulator simulator(world);
  simulator.Simulate(5.0);
  ASSERT_NE(simulator.statistics().worst_status, core::StepStatus::kError);
  // the bar: lateral drift < 5 mm (Klamp't squeezes the 1 kg block out by 0.40 m)
  for (int i = 0; i < simulator.object_count(); ++i) {
    const Vec3 drift =
        simulator.GetObjectPose(i).translation() - world.objects[i].pose.translation();
    EXPECT_LT(drift.head<2>().norm(), 5e-3) << world.objects[i].name;
  }
  // penetration stays within the boundary layer (paddings of 2.5 mm on each side)
  EXPECT_LT(simulator.statistics().max_penetration, 0.005);
  // the bar: no instability correction (Klamp't fires them here)
  EXPECT_EQ(simulator.statistics().instability_corrections, 0);
  // the 1 kg block still sits on the slab under the 100 kg block: 0.05 m half side + padding
  EXPECT_NEAR(simulator.GetObjectPose(0).translation().z(), 0.05 + 0.005, 1e-3);
}

TEST(KlamptWorldsTest, FastDropsDoNotTunnel) {
  const core::WorldDesc world = LoadTestWorld("fastdroptest.xml");
  core::Simulator simulator(world);
  double lowest_over_slab = 1e9;
  for (int step = 0; step < 3000; ++step) {
    simulator.Simulate(0.001);
    for (int i = 0; i < simulator.object_count(); ++i) {
      const Vec3 p = simulator.GetObjectPose(i).translation();
      // over the 4 m x 4 m slab whose top is z = 0 (the box centre is 0.05 m inside its box)
      if (std::abs(p.x()) < 1.9 && std::abs(p.y()) < 1.9) {
        lowest_over_slab = std::min(lowest_over_slab, p.z());
      }
    }
  }
  ASSERT_NE(simulator.statistics().worst_status, core::StepStatus::kError);
  // a 0.1 m box centre never gets below the slab's top while over it (no tunnelling)
  EXPECT_GT(lowest_over_slab, 0.0);
  // rollbacks are how adaptive stepping catches the impacts at 14 and 17 m/s
  EXPECT_GT(simulator.statistics().rollbacks, 0);
  // the box dropped flat from 10 m bounces (restitution 0.45) and comes to rest on the slab
  simulator.Simulate(7.0);
  EXPECT_NEAR(simulator.GetObjectPose(0).translation().z(), 0.05 + 0.002, 1e-3);
}

// stiffness_test.xml: nine tessellated balls (1 kg, radius 0.1 m, preshrunk under a 0.04 m
// padding) with stiffness 50, 500 or 5000 N/m and damping 1..100 N·s/m, and one rigid ball,
// dropped from 1 m onto a rigid slab
// Kinetic plus potential energy of object `i` (J), gravity along -z.
double MechanicalEnergy(const core::Simulator& simulator, const core::RigidObjectDesc& object,
                        int i) {
  const core::Pose pose = simulator.GetObjectPose(i);
  const core::Twist twist = simulator.GetObjectVelocity(i);
  const core::Mat3 inertia = pose.linear() * object.inertia * pose.linear().transpose();
  const Vec3 com_velocity = twist.linear + twist.angular.cross(pose.linear() * object.com);
  return 0.5 * object.mass * com_velocity.squaredNorm() +
         0.5 * twist.angular.dot(inertia * twist.angular) +
         object.mass * kGravityForWorlds * (pose * object.com).z();
}

TEST(KlamptWorldsTest, SoftBallsSettleAtTheirPredictedPenetration) {
  const core::WorldDesc world = LoadTestWorld("stiffness_test.xml");
  core::Simulator simulator(world);
  const int rigid = static_cast<int>(world.objects.size()) - 1;
  ASSERT_EQ(world.objects[rigid].name, "ball_rigid");
  simulator.Simulate(2.0);
  // the rigid tessellated ball lands exactly on its pole vertex, an unstable balance of the
  // padded polyhedron (the vertex stands 0.2 mm higher than the faces around it); symmetric
  // contacts hold it there (within 0.1 mm at 2 s) until rounding errors have grown (about 3 s)
  EXPECT_LT((simulator.GetObjectPose(rigid).translation() - world.objects[rigid].pose.translation())
                .head<2>()
                .norm(),
            1e-4);
  const double rigid_energy = MechanicalEnergy(simulator, world.objects[rigid], rigid);
  simulator.Simulate(3.0);
  ASSERT_NE(simulator.statistics().worst_status, core::StepStatus::kError);
  EXPECT_EQ(simulator.statistics().instability_corrections, 0);
  for (int i = 0; i < simulator.object_count(); ++i) {
    const core::RigidObjectDesc& ball = world.objects[i];
    SCOPED_TRACE(ball.name);
    const Vec3 position = simulator.GetObjectPose(i).translation();
    // preshrunk: the padded surface is about the original sphere; exactly, the layer just
    // touches the slab when the centre is the padding above the shrunk mesh's lowest vertex
    // (vertices move slightly more than the padding where faces meet at an angle)
    const core::GeometryDesc shrunk =
        core::ShrinkGeometry(ball.geometry, ball.sim.padding, nullptr);
    double lowest = 0.0;
    for (const Vec3& vertex : shrunk.mesh->vertices) {
      lowest = std::min(lowest, (shrunk.Matrix() * vertex).z());
    }
    const double penetration = ball.sim.padding - lowest - position.z();
    const double k = ball.sim.surface.stiffness;  // the slab is rigid: the blend keeps k
    if (std::isfinite(k)) {
      // m g / k, or the whole 0.04 m layer when it cannot carry the ball (k = 50 needs 0.196 m):
      // then the ball rests on its rigid core
      const double predicted = std::min(kGravityForWorlds / k, ball.sim.padding);
      EXPECT_NEAR(penetration, predicted, 0.05 * predicted);
      // the bar: < 5 mm sideways (Klamp't: up to 0.68 m)
      EXPECT_LT((position - ball.pose.translation()).head<2>().norm(), 5e-3);
    } else {
      // off its vertex the rigid ball rolls like the 960-facet polyhedron it is: no energy
      // gained (1 mJ allows for the hard contacts' layer correction); its hard contacts keep
      // it on the outside of its 4 cm layer (measured within 1 mm), far from its core
      EXPECT_LT(MechanicalEnergy(simulator, ball, i), rigid_energy + 1e-3);
      EXPECT_LT(penetration, 0.25 * ball.sim.padding);
    }
  }
}

// bounce_test.xml: ten spheres (five from sphere.geom, a primitive, five from sphere.off, a mesh)
// with restitution 1, 0.75, 0.5, 0.25 and 0 dropped from 2 m onto a slab of restitution 0.5
TEST(KlamptWorldsTest, SpheresReboundToRestitutionSquaredTimesTheDrop) {
  const core::WorldDesc world = LoadTestWorld("bounce_test.xml");
  core::Simulator simulator(world);
  const int n = simulator.object_count();
  std::vector<double> apex(n, 0.0);
  std::vector<bool> rising(n, false), landed_again(n, false);
  for (int step = 0; step < 2500; ++step) {
    simulator.Simulate(0.001);
    for (int i = 0; i < n; ++i) {
      const double z = simulator.GetObjectPose(i).translation().z();
      const double vz = simulator.GetObjectVelocity(i).linear.z();
      if (vz > 0.0 && !landed_again[i]) rising[i] = true;
      if (rising[i] && vz < 0.0) landed_again[i] = true;  // past the first apex
      if (rising[i] && !landed_again[i]) apex[i] = std::max(apex[i], z);
    }
  }
  ASSERT_NE(simulator.statistics().worst_status, core::StepStatus::kError);
  const double terrain_restitution = world.terrains[0].sim.surface.restitution;
  for (int i = 0; i < n; ++i) {
    const core::RigidObjectDesc& sphere = world.objects[i];
    // the padded surfaces touch when the centre is at radius + both paddings
    const double rest = 0.1 + sphere.sim.padding + world.terrains[0].sim.padding;
    const double drop = sphere.pose.translation().z() - rest;
    const double e = (sphere.sim.surface.restitution + terrain_restitution) / 2;
    const double expected = e * e * drop;
    const double rebound = rising[i] ? apex[i] - rest : 0.0;
    // the bar: e² h within 5 % for every sphere (Klamp't: 0.51 m for e = 0.375 and 0.25)
    EXPECT_NEAR(rebound, expected, 0.05 * expected + 1e-3) << sphere.name << " e = " << e;
  }
}

}  // namespace
}  // namespace lamina
