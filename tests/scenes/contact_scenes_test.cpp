// SPDX-License-Identifier: MIT
// Contact scenes with analytic answers: a box resting on a plane, Coulomb sliding distance along
// an axis and diagonally (isotropic friction), restitution bounce height, and determinism with
// contacts.
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "core/sim/friction_anchor.h"
#include "core/sim/simulator.h"
#include "tests/common/scene_builders.h"
#include "tests/common/test_support.h"

namespace lamina {
namespace {

using core::Vec3;

using test::kGravity;

using test::BoxObject;
using test::PlaneTerrain;

TEST(RestingBoxTest, RestsOnItsBoundaryLayerWithoutDrift) {
  core::WorldDesc world;
  world.terrains.push_back(PlaneTerrain(0.5, 0.0));
  core::RigidObjectDesc box = BoxObject(0.2, 1.0, Vec3(0, 0, 0.11));
  box.sim.surface.restitution = 0.0;
  world.objects.push_back(box);
  core::Simulator simulator(world);
  simulator.Simulate(3.0);
  ASSERT_NE(simulator.statistics().worst_status, core::StepStatus::kError)
      << simulator.statistics().error;
  const core::Pose pose = simulator.GetObjectPose(0);
  // the padded surfaces touch: centre at half the side plus the 2.5 mm padding; hard contact
  // with ERP 0.95 leaves a residual overlap of a fraction of a millimetre
  EXPECT_NEAR(pose.translation().z(), 0.1 + 0.0025, 5e-4);
  EXPECT_NEAR(pose.translation().head<2>().norm(), 0.0, 1e-6);
  EXPECT_NEAR(simulator.GetObjectVelocity(0).linear.norm(), 0.0, 1e-3);
  // a box resting on its face is held by its four corners
  EXPECT_GE(simulator.statistics().max_contacts_in_step, 4);
}

// a 1 kg box launched at speed v along `direction` on a plane with friction mu (both surfaces
// mu, so the harmonic mean is mu) stops after v^2 / (2 mu g)
double SlideDistance(const Vec3& direction, double speed, double mu) {
  core::WorldDesc world;
  world.terrains.push_back(PlaneTerrain(mu, 0.0));
  core::RigidObjectDesc box = BoxObject(0.1, 1.0, Vec3(0, 0, 0.0525));
  box.sim.surface = {0.0, mu, core::kInf, core::kInf};
  box.initial_velocity.linear = direction.normalized() * speed;
  world.objects.push_back(box);
  core::Simulator simulator(world);
  double farthest = 0.0;
  for (int i = 0; i < 150; ++i) {
    simulator.Simulate(0.01);
    farthest = std::max(farthest, simulator.GetObjectPose(0).translation().head<2>().norm());
  }
  const double distance = simulator.GetObjectPose(0).translation().head<2>().norm();
  // once it stops, its friction anchor takes back at most the drift allowed while sticking
  EXPECT_GE(distance, farthest - core::SimSettings{}.friction_anchor_slip);
  return distance;
}

TEST(SlidingTest, StopsAtCoulombDistanceAlongAnAxisAndDiagonally) {
  const double mu = 0.5, speed = 1.0;
  const double expected = speed * speed / (2 * mu * kGravity);
  // the bound: within 2 % along an axis and at 45 degrees (isotropy)
  EXPECT_NEAR(SlideDistance(Vec3(1, 0, 0), speed, mu), expected, 0.02 * expected);
  EXPECT_NEAR(SlideDistance(Vec3(1, 1, 0), speed, mu), expected, 0.02 * expected);
}

TEST(BounceTest, SphereReboundsToRestitutionSquaredTimesHeight) {
  const double restitution = 0.5, drop = 1.0, radius = 0.1;
  core::WorldDesc world;
  world.terrains.push_back(PlaneTerrain(0.5, restitution));
  core::RigidObjectDesc ball = BoxObject(0.1, 1.0, Vec3(0, 0, radius + 0.0025 + drop));
  ball.geometry.primitive = core::Primitive::Sphere(radius);
  ball.inertia = core::Mat3::Identity() * (0.4 * radius * radius);
  ball.sim.surface.restitution = restitution;
  world.objects.push_back(ball);
  core::Simulator simulator(world);
  double apex = 0.0;
  bool bounced = false;
  for (int i = 0; i < 1500; ++i) {
    simulator.Simulate(0.001);
    // height of the padded surface above the plane
    const double z = simulator.GetObjectPose(0).translation().z() - radius - ball.sim.padding;
    const double vz = simulator.GetObjectVelocity(0).linear.z();
    if (vz > 0) bounced = true;
    if (bounced) apex = std::max(apex, z);
  }
  ASSERT_TRUE(bounced) << simulator.statistics().error;
  // e^2 h within 5 % (the bound for bounce_test.xml)
  EXPECT_NEAR(apex, restitution * restitution * drop, 0.05 * restitution * restitution * drop);
}

// restitution 1 from 2 m: adaptive stepping halves the step at every impact (the ball moves 6 mm
// a step, more than its 2.5 mm layer) and returns to 1 ms after it. With gravity's kick spanning
// half of each neighbouring step (gravity_kick.h) the fourth apex is the first's within 1e-4 of
// the drop (kicks of g·h lost about 2·g·h/v of the energy at each bounce: docs/simulator.md).
TEST(BounceTest, ElasticBallRisesBackThroughHalvedSteps) {
  const double drop = 2.0, radius = 0.1;
  core::WorldDesc world;
  world.terrains.push_back(PlaneTerrain(0.5, 1.0));
  core::RigidObjectDesc ball = test::SphereObject(radius, 1.0, Vec3(0, 0, radius + 0.0025 + drop));
  ball.sim.surface.restitution = 1.0;
  world.objects.push_back(ball);
  core::Simulator simulator(world);
  std::vector<double> apexes;
  double previous_vz = 0.0;
  for (int i = 0; i < 5500; ++i) {
    simulator.Simulate(0.001);
    const double z = simulator.GetObjectPose(0).translation().z();
    const double vz = simulator.GetObjectVelocity(0).linear.z();
    if (previous_vz > 0.0 && vz <= 0.0) apexes.push_back(z);
    previous_vz = vz;
  }
  ASSERT_EQ(apexes.size(), 4u) << simulator.statistics().error;
  EXPECT_GE(simulator.statistics().rollbacks, 4);  // at least one per bounce
  EXPECT_NEAR(apexes.back(), apexes.front(), 1e-4 * drop);
}

TEST(DeterminismTest, SameContactSceneTwiceIsBitIdentical) {
  core::WorldDesc world;
  world.terrains.push_back(PlaneTerrain(0.5, 0.2));
  core::RigidObjectDesc box = BoxObject(0.2, 1.0, Vec3(0, 0, 0.5));
  box.pose.linear() = core::RotationFromRollPitchYaw(0.3, 0.2, 0.1);
  box.initial_velocity.linear = Vec3(0.5, 0.1, 0);
  world.objects.push_back(box);
  core::Simulator first(world), second(world);
  first.Simulate(1.0);
  second.Simulate(1.0);
  EXPECT_EQ(first.GetState(), second.GetState());
  // restoring a mid-run state reproduces the rest of the run exactly
  core::Simulator replay(world);
  replay.Simulate(0.4);
  const core::SimState middle = replay.GetState();
  replay.Simulate(0.6);
  const core::SimState end = replay.GetState();
  replay.SetState(middle);
  replay.Simulate(0.6);
  EXPECT_EQ(replay.GetState(), end);
}

// QuickStep shuffles its rows with ODE's process-wide random generator: a run must not depend on
// what ran before it in the process, and a restored state must replay exactly
TEST(DeterminismTest, QuickStepRunsDoNotDependOnEarlierRuns) {
  core::WorldDesc world;
  world.terrains.push_back(PlaneTerrain(0.5, 0.2));
  for (int i = 0; i < 3; ++i) {
    core::RigidObjectDesc box = BoxObject(0.2, 1.0, Vec3(0.05 * i, 0, 0.15 + 0.25 * i));
    box.pose.linear() = core::RotationFromRollPitchYaw(0.3 * i, 0.2, 0.1);
    world.objects.push_back(box);
  }
  const core::SolverSettings quick{core::SolverType::kQuickStep, 10};
  core::Simulator first(world, quick);
  first.Simulate(0.5);
  first.Simulate(0.5);
  core::Simulator second(world, quick);
  second.Simulate(0.5);
  const core::SimState middle = second.GetState();
  second.Simulate(0.5);
  EXPECT_EQ(first.GetState(), second.GetState());
  second.SetState(middle);
  second.Simulate(0.5);
  EXPECT_EQ(first.GetState(), second.GetState());
}

// a box held by static friction on a 20 degree slope (gravity tilted, mu 0.5), under QuickStep
// with few iterations, so that its friction anchor has drift to take back: the anchors are part of
// the state, and a replay without them goes elsewhere
TEST(DeterminismTest, SetStateRestoresFrictionAnchors) {
  core::WorldDesc world;
  world.terrains.push_back(PlaneTerrain(0.5, 0.0));
  core::RigidObjectDesc box = BoxObject(0.1, 1.0, Vec3(0, 0, 0.0525));
  box.sim.surface = {0.0, 0.5, core::kInf, core::kInf};
  world.objects.push_back(box);
  const double theta = 20.0 * core::kPi / 180.0;
  core::Simulator replay(world, {core::SolverType::kQuickStep, 3});
  replay.SetGravity(kGravity * Vec3(std::sin(theta), 0.0, -std::cos(theta)));
  replay.Simulate(0.5);
  const core::SimState middle = replay.GetState();
  ASSERT_EQ(middle.anchors.size(), 1u);
  replay.Simulate(0.5);
  const core::SimState end = replay.GetState();
  replay.SetState(middle);
  replay.Simulate(0.5);
  EXPECT_EQ(replay.GetState(), end);
  core::SimState forgotten = middle;
  forgotten.anchors.clear();
  replay.SetState(forgotten);
  replay.Simulate(0.5);
  EXPECT_NE(replay.GetState().objects, end.objects);
  // static friction holds the box: three iterations leave it jittering by a few micrometres about
  // its anchor, it does not creep down the slope
  EXPECT_LT(std::abs(end.objects[0].com_position.x() - middle.objects[0].com_position.x()), 2e-5);
}

}  // namespace
}  // namespace lamina
