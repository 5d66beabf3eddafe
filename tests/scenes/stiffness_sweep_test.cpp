// SPDX-License-Identifier: MIT
// Soft contact over six decades of stiffness: a 1 kg box (and a 1 kg sphere) dropped 1.5 cm
// onto a rigid plane, its surface k in {1e4 .. 1e9} N/m with critical or light damping, 1 ms
// steps for 2 s. The run stays stable, never gains energy, comes to rest, and rests at the
// spring's static depth m g / k inside the boundary layer.
#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "core/sim/simulator.h"
#include "tests/common/scene_builders.h"
#include "tests/common/test_support.h"

namespace lamina {
namespace {

using core::Vec3;

using test::kGravity;
constexpr double kBodyMass = 1.0;
constexpr double kBodySize = 0.1;       // box side; also the sphere's diameter
constexpr double kSweepPadding = 0.01;  // object padding; the rigid plane has none
constexpr double kDrop = 0.015;         // from the top of the layer

enum class Shape { kBox, kSphere };

struct SweepCase {
  Shape shape;
  double stiffness;  ///< N/m
  double damping;    ///< N·s/m
};

std::string Describe(const SweepCase& c) {
  return std::string(c.shape == Shape::kBox ? "box" : "sphere") +
         " k = " + std::to_string(c.stiffness) + " c = " + std::to_string(c.damping);
}

// Damping ratio zeta of a mass on the spring: c = 2 zeta sqrt(k m) (zeta = 1 is critical).
double Damping(double stiffness, double zeta) {
  return 2.0 * zeta * std::sqrt(stiffness * kBodyMass);
}

// What one run measured.
struct SweepRun {
  bool finite = true;
  core::StepStatus worst = core::StepStatus::kNormal;
  std::string error;
  double start_height = 0.0;   ///< body frame z at the start, m
  double highest_after = 0.0;  ///< highest body frame z after the first step, m
  double final_speed = 0.0;    ///< m/s
  double final_depth = 0.0;    ///< layer overlap at the end: padding - gap, m
};

SweepRun Run(const SweepCase& c) {
  core::WorldDesc world;
  // the plane is rigid, so the blended stiffness and damping are the body's own (series rule)
  world.terrains.push_back(test::PlaneTerrain(0.5, 0.0));
  const double half = 0.5 * kBodySize;
  const Vec3 start(0, 0, half + kSweepPadding + kDrop);
  core::RigidObjectDesc body = c.shape == Shape::kBox ? test::BoxObject(kBodySize, kBodyMass, start)
                                                      : test::SphereObject(half, kBodyMass, start);
  body.sim.padding = kSweepPadding;
  body.sim.surface = {0.0, 0.5, c.stiffness, c.damping};
  world.objects.push_back(body);
  world.settings.timestep = 0.001;

  core::Simulator simulator(world);
  SweepRun run;
  run.start_height = start.z();
  run.highest_after = -core::kInf;
  bool touched = false;
  for (int step = 0; step < 2000; ++step) {
    run.worst = std::max(run.worst, simulator.Simulate(0.001));
    const core::Pose pose = simulator.GetObjectPose(0);
    if (!pose.matrix().allFinite()) {
      run.finite = false;
      break;
    }
    // the rebounds: everything after the body first entered the layer
    touched = touched || pose.translation().z() < half + kSweepPadding;
    if (touched) run.highest_after = std::max(run.highest_after, pose.translation().z());
  }
  run.worst = std::max(run.worst, simulator.statistics().worst_status);
  run.error = simulator.statistics().error;
  run.final_speed = simulator.GetObjectVelocity(0).linear.norm();
  // the gap between the underlying geometry and the plane is z - half; the layer overlap is
  // the padding sum (with the layer-edge nanometre, core/contact/contact.h) minus that gap
  run.final_depth =
      kSweepPadding + core::kLayerEdgeSlack - (simulator.GetObjectPose(0).translation().z() - half);
  return run;
}

void ExpectStableSettledRun(const SweepCase& c) {
  SCOPED_TRACE(Describe(c));
  const SweepRun run = Run(c);
  ASSERT_TRUE(run.finite);
  EXPECT_LT(run.worst, core::StepStatus::kUnstable) << run.error;
  // no energy gain: after landing (restitution 0) the body never rebounds to where it was let go
  EXPECT_LT(run.highest_after, run.start_height);
  // at rest after 2 s: the slowest case, k = 1e4 critically damped, has a time constant of
  // 1 / sqrt(k / m) = 10 ms
  EXPECT_LT(run.final_speed, 1e-3);
  // Static depth: held at depth x the contact pushes with k x (docs/contact-model.md), and the
  // pair's total normal force is k x however many contact points carry it, so the body settles
  // where k x = m g: x = m g / k, from 0.98 mm (1e4) down to 9.8 nm (1e9), all inside the
  // 10 mm layer. Within 5 %.
  const double expected_depth = kBodyMass * kGravity / c.stiffness;
  ASSERT_LT(expected_depth, kSweepPadding);
  EXPECT_NEAR(run.final_depth, expected_depth, 0.05 * expected_depth);
}

constexpr double kStiffnesses[] = {1e4, 1e5, 1e6, 1e7, 1e8, 1e9};

TEST(StiffnessSweepTest, CriticallyDampedSphereSettlesAtStaticDepth) {
  // one contact point: the single point carries the whole k x
  for (double k : kStiffnesses) ExpectStableSettledRun({Shape::kSphere, k, Damping(k, 1.0)});
}

TEST(StiffnessSweepTest, CriticallyDampedBoxSettlesAtStaticDepth) {
  // four corner contacts share the pair's stiffness, so together they push k x
  for (double k : kStiffnesses) ExpectStableSettledRun({Shape::kBox, k, Damping(k, 1.0)});
}

TEST(StiffnessSweepTest, LightlyDampedContactStaysStableAndSettles) {
  // zeta = 0.05: the contact rings (decay rate zeta sqrt(k / m) = 15.8 /s at k = 1e5, i.e.
  // e^-31 over 2 s) but must not gain energy or blow up
  for (Shape shape : {Shape::kSphere, Shape::kBox}) {
    ExpectStableSettledRun({shape, 1e5, Damping(1e5, 0.05)});
  }
}

}  // namespace
}  // namespace lamina
