// SPDX-License-Identifier: MIT
// A box on an incline with Coulomb friction mu = 0.5 (tan(theta) = mu at 26.57 degrees): it
// sticks below that angle and slides with acceleration g (sin(theta) - mu cos(theta)) above it.
// The incline is a level plane under gravity tilted by theta (the same physics in the plane's
// frame), a box primitive and a box mesh; one run tilts the plane itself instead.
#include <cmath>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "core/geometry/tessellate.h"
#include "core/sim/simulator.h"
#include "tests/common/scene_builders.h"
#include "tests/common/test_support.h"

namespace lamina {
namespace {

using core::Vec3;

using test::kGravity;
constexpr double kMu = 0.5;
using test::kBoxSide;
constexpr double kObjectPadding = 0.0025;  // the plane terrain has none

double Radians(double degrees) {
  return degrees * core::kPi / 180.0;
}

// g (sin(theta) - mu cos(theta)): gravity along the slope minus kinetic friction mu N, N =
// m g cos(theta), per unit mass.
double SlidingAcceleration(double theta) {
  return kGravity * (std::sin(theta) - kMu * std::cos(theta));
}

enum class BoxShape { kPrimitive, kMesh };

// A 1 kg, 10 cm box resting (at the top of its padding) on the level plane z <= 0. Both
// surfaces have friction 0.5, so the blended (harmonic mean) friction is 0.5, and no
// restitution; both are rigid.
core::WorldDesc BoxOnPlane(BoxShape shape) {
  core::WorldDesc world;
  world.terrains.push_back(test::PlaneTerrain(kMu, 0.0));
  core::RigidObjectDesc box =
      test::BoxObject(kBoxSide, 1.0, Vec3(0, 0, 0.5 * kBoxSide + kObjectPadding));
  box.sim.padding = kObjectPadding;
  box.sim.surface = {0.0, kMu, core::kInf, core::kInf};
  if (shape == BoxShape::kMesh) {
    box.geometry.kind = core::GeometryKind::kMesh;
    box.geometry.mesh = std::make_shared<const core::TriangleMesh>(
        core::Tessellate(core::Primitive::Box(Vec3::Constant(kBoxSide))));
  }
  world.objects.push_back(box);
  return world;
}

// Gravity of a slope rising towards -x by theta, seen in the slope's frame: the box slides
// towards +x.
Vec3 TiltedGravity(double theta) {
  return kGravity * Vec3(std::sin(theta), 0.0, -std::cos(theta));
}

// Displacement along the slope (x) at times `times` (s, increasing) of the box on a slope of
// theta degrees.
std::vector<double> SlopeDisplacements(BoxShape shape, double theta_degrees,
                                       const std::vector<double>& times) {
  core::Simulator simulator(BoxOnPlane(shape));
  simulator.SetGravity(TiltedGravity(Radians(theta_degrees)));
  std::vector<double> out;
  for (double t : times) {
    simulator.Simulate(t - simulator.time());
    out.push_back(simulator.GetObjectPose(0).translation().x());
  }
  EXPECT_LT(simulator.statistics().worst_status, core::StepStatus::kUnstable)
      << simulator.statistics().error;
  // the box stays on the slope: no tipping (tan(theta) < 1 for a cube) and no bouncing off
  EXPECT_NEAR(simulator.GetObjectPose(0).translation().z(), 0.5 * kBoxSide + kObjectPadding, 1e-3);
  return out;
}

// Acceleration from the second difference of the displacement at t0, t0 + T, t0 + 2T (exact
// for uniformly accelerated motion, whatever the velocity at t0). The window starts at 0.5 s,
// well after the box settled into the layer and began to slide.
double MeasuredAcceleration(BoxShape shape, double theta_degrees) {
  const double t0 = 0.5, window = 0.75;
  const std::vector<double> x =
      SlopeDisplacements(shape, theta_degrees, {t0, t0 + window, t0 + 2 * window});
  return (x[2] - 2 * x[1] + x[0]) / (window * window);
}

double StuckDisplacement(BoxShape shape, double theta_degrees) {
  return std::abs(SlopeDisplacements(shape, theta_degrees, {2.0})[0]);
}

TEST(InclineTest, BoxSticksBelowTheFrictionAngle) {
  // tan(20 deg) = 0.36 and tan(25 deg) = 0.47 are below mu = 0.5: static friction holds the box
  // (the bar: less than 1 mm along the slope in 2 s)
  EXPECT_LT(StuckDisplacement(BoxShape::kPrimitive, 20.0), 1e-3);
  EXPECT_LT(StuckDisplacement(BoxShape::kPrimitive, 25.0), 1e-3);
}

TEST(InclineTest, BoxSlidesAboveTheFrictionAngleAtCoulombAcceleration) {
  // 30 deg: 9.8 (0.5 - 0.5 * 0.866) = 0.657 m/s^2; 35 deg: 9.8 (0.574 - 0.5 * 0.819) =
  // 1.607 m/s^2; within 2 %
  for (double theta : {30.0, 35.0}) {
    const double expected = SlidingAcceleration(Radians(theta));
    EXPECT_NEAR(MeasuredAcceleration(BoxShape::kPrimitive, theta), expected, 0.02 * expected)
        << theta << " degrees";
  }
}

TEST(InclineTest, MeshBoxSticksAndSlidesLikeThePrimitive) {
  // the same box as a 12-triangle mesh, held at its corners
  EXPECT_LT(StuckDisplacement(BoxShape::kMesh, 25.0), 1e-3);
  const double expected = SlidingAcceleration(Radians(35.0));
  EXPECT_NEAR(MeasuredAcceleration(BoxShape::kMesh, 35.0), expected, 0.02 * expected);
}

TEST(InclineTest, TiltedPlaneUnderVerticalGravityMatchesTiltedGravity) {
  // the plane itself rotated by 30 degrees about y (rising towards -x), the box resting on it
  // in the same attitude, gravity straight down: the box slides down along the plane's +x
  const double theta = Radians(30.0);
  core::WorldDesc world = BoxOnPlane(BoxShape::kPrimitive);
  const core::Pose tilt(Eigen::AngleAxisd(theta, Vec3::UnitY()));
  world.terrains[0].geometry.primitive = core::Primitive::Plane(tilt);
  core::RigidObjectDesc& box = world.objects[0];
  box.pose = tilt * box.pose;
  core::Simulator simulator(world);
  const Vec3 slope = tilt * Vec3::UnitX();  // downhill: its z component is -sin(theta)
  ASSERT_LT(slope.z(), 0.0);
  const double t0 = 0.5, window = 0.75;
  double x[3];
  for (int i = 0; i < 3; ++i) {
    simulator.Simulate(t0 + i * window - simulator.time());
    x[i] = slope.dot(simulator.GetObjectPose(0).translation());
  }
  ASSERT_LT(simulator.statistics().worst_status, core::StepStatus::kUnstable)
      << simulator.statistics().error;
  const double expected = SlidingAcceleration(theta);
  EXPECT_NEAR((x[2] - 2 * x[1] + x[0]) / (window * window), expected, 0.02 * expected);
}

}  // namespace
}  // namespace lamina
