// SPDX-License-Identifier: MIT
// Surface blending (each rule with its inf/0 cases, symmetry) and the ODE soft-contact ERP/CFM,
// checked against a one-row re-derivation of ODE's constraint solve: the contact acts as the
// implicit spring-damper k x - c v, so a resting mass settles at x = m g / k.
#include "core/contact/surface_blend.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "tests/common/test_support.h"

namespace lamina::core {
namespace {

SurfaceDesc Surface(double restitution, double friction, double stiffness, double damping) {
  SurfaceDesc surface;
  surface.restitution = restitution;
  surface.friction = friction;
  surface.stiffness = stiffness;
  surface.damping = damping;
  return surface;
}

// Klamp't's defaults (klampt-internals.md §3.2): a robot link is rigid with friction 1, the
// default terrain soft and heavily damped with friction 0.5.
const SurfaceDesc kRobotLink = Surface(0.1, 1.0, kInf, kInf);
const SurfaceDesc kDefaultTerrain = Surface(0.1, 0.5, 8e5, 2e5);

TEST(SurfaceBlendTest, RestitutionIsTheArithmeticMean) {
  EXPECT_EQ(BlendSurfaces(Surface(0.25, 1, 1, 1), Surface(0.75, 1, 1, 1)).restitution, 0.5);
  EXPECT_EQ(BlendSurfaces(Surface(0.0, 1, 1, 1), Surface(1.0, 1, 1, 1)).restitution, 0.5);
  EXPECT_EQ(BlendSurfaces(kRobotLink, kDefaultTerrain).restitution, 0.1);
}

TEST(SurfaceBlendTest, FrictionIsTheHarmonicMeanWithoutPyramidFactor) {
  auto friction = [](double a, double b) {
    return BlendSurfaces(Surface(0, a, 1, 1), Surface(0, b, 1, 1)).friction;
  };
  // 2 * 1 * 0.5 / 1.5 = 2/3; Klamp't would give 0.707 * 2/3 = 0.471. Exact: the result is twice
  // a correctly rounded 1/3, and doubling commutes with rounding.
  EXPECT_EQ(BlendSurfaces(kRobotLink, kDefaultTerrain).friction, 2.0 / 3.0);
  EXPECT_EQ(friction(0.5, 0.5), 0.5);
  EXPECT_EQ(friction(0.0, 0.8), 0.0);
  EXPECT_EQ(friction(0.8, 0.0), 0.0);
  EXPECT_EQ(friction(0.0, 0.0), 0.0);
  EXPECT_EQ(friction(0.0, kInf), 0.0);
  EXPECT_EQ(friction(kInf, 0.3), 0.6);  // the limit of 2ab / (a + b) as a -> inf
  EXPECT_EQ(friction(0.3, kInf), 0.6);
  EXPECT_EQ(friction(kInf, kInf), kInf);
}

TEST(SurfaceBlendTest, StiffnessAndDampingActInSeries) {
  auto blend = [](double ka, double ca, double kb, double cb) {
    return BlendSurfaces(Surface(0, 1, ka, ca), Surface(0, 1, kb, cb));
  };
  // Two identical layers: half the stiffness, as two springs in series (the harmonic mean would
  // keep k). Two roundings (1/k, then the reciprocal of the sum): relative 1e-15.
  const BlendedSurface twins = blend(1e4, 300, 1e4, 300);
  EXPECT_NEAR(twins.stiffness, 5e3, 5e3 * 1e-15);
  EXPECT_NEAR(twins.damping, 150, 150 * 1e-15);
  const BlendedSurface mixed = blend(1e4, 100, 4e4, 300);
  EXPECT_NEAR(mixed.stiffness, 8e3, 8e3 * 1e-15);
  EXPECT_NEAR(mixed.damping, 75, 75 * 1e-15);
  // An infinite (rigid) side drops out exactly: a soft body on a rigid floor keeps its own law.
  const BlendedSurface on_rigid = blend(5e4, 10, kInf, kInf);
  EXPECT_EQ(on_rigid.stiffness, 5e4);
  EXPECT_EQ(on_rigid.damping, 10);
  const BlendedSurface link_on_terrain = BlendSurfaces(kRobotLink, kDefaultTerrain);
  EXPECT_EQ(link_on_terrain.stiffness, 8e5);
  EXPECT_EQ(link_on_terrain.damping, 2e5);
  const BlendedSurface rigid = blend(kInf, kInf, kInf, kInf);
  EXPECT_EQ(rigid.stiffness, kInf);
  EXPECT_EQ(rigid.damping, kInf);
  const BlendedSurface zero = blend(0, 0, 1e4, 100);
  EXPECT_EQ(zero.stiffness, 0.0);
  EXPECT_EQ(zero.damping, 0.0);
  const BlendedSurface zero_on_rigid = blend(0, 0, kInf, kInf);
  EXPECT_EQ(zero_on_rigid.stiffness, 0.0);
  EXPECT_EQ(zero_on_rigid.damping, 0.0);
}

// Lamina's rolling and spinning friction (m): off (0) by default, the harmonic mean like kFriction
TEST(SurfaceBlendTest, RollingAndSpinningFrictionAreHarmonicMeans) {
  auto resistance = [](double rolling_a, double spinning_a, double rolling_b, double spinning_b) {
    SurfaceDesc a, b;
    a.rolling_friction = rolling_a;
    a.spinning_friction = spinning_a;
    b.rolling_friction = rolling_b;
    b.spinning_friction = spinning_b;
    return BlendSurfaces(a, b);
  };
  const SurfaceDesc defaults;
  EXPECT_EQ(defaults.rolling_friction, 0.0);
  EXPECT_EQ(defaults.spinning_friction, 0.0);
  const BlendedSurface off = BlendSurfaces(kRobotLink, kDefaultTerrain);
  EXPECT_EQ(off.rolling, 0.0);
  EXPECT_EQ(off.spinning, 0.0);
  // 2 · 0.01 · 0.03 / 0.04 = 0.015; 2 · 0.002 · 0.006 / 0.008 = 0.003 (two roundings: 1e-15)
  const BlendedSurface mixed = resistance(0.01, 0.002, 0.03, 0.006);
  EXPECT_NEAR(mixed.rolling, 0.015, 0.015 * 1e-15);
  EXPECT_NEAR(mixed.spinning, 0.003, 0.003 * 1e-15);
  // equal sides keep their value (to the rounding of 1/x)
  EXPECT_NEAR(resistance(0.005, 0.005, 0.005, 0.005).rolling, 0.005, 0.005 * 1e-15);
  // one side without it turns it off for the pair, whatever the other side has
  EXPECT_EQ(resistance(0.0, 0.0, 0.02, 0.02).rolling, 0.0);
  EXPECT_EQ(resistance(0.02, 0.02, 0.0, 0.0).spinning, 0.0);
  EXPECT_EQ(resistance(0.02, 0.0, 0.02, 0.01).spinning, 0.0);
  // the two are blended independently
  const BlendedSurface rolling_only = resistance(0.004, 0.0, 0.004, 0.003);
  EXPECT_NEAR(rolling_only.rolling, 0.004, 0.004 * 1e-15);
  EXPECT_EQ(rolling_only.spinning, 0.0);
  // symmetric, bitwise
  for (double x : {0.0, 1e-4, 0.003, 0.01, 1.0 / 3.0}) {
    for (double y : {0.0, 2e-4, 0.007, 0.05, 2.0 / 3.0}) {
      const BlendedSurface ab = resistance(x, y, y, x);
      const BlendedSurface ba = resistance(y, x, x, y);
      EXPECT_EQ(std::bit_cast<std::uint64_t>(ab.rolling), std::bit_cast<std::uint64_t>(ba.rolling));
      EXPECT_EQ(std::bit_cast<std::uint64_t>(ab.spinning),
                std::bit_cast<std::uint64_t>(ba.spinning));
    }
  }
}

std::uint64_t Bits(double value) {
  return std::bit_cast<std::uint64_t>(value);
}

TEST(SurfaceBlendTest, BlendingIsSymmetricBitwise) {
  const std::vector<SurfaceDesc> surfaces = {kRobotLink,
                                             kDefaultTerrain,
                                             Surface(0.3, 0.7, 1234.5, 67.8),
                                             Surface(0, 0, 0, 0),
                                             Surface(1, kInf, 1e9, 0.1),
                                             Surface(0.1, 1.0 / 3.0, 3e5, kInf)};
  for (const SurfaceDesc& a : surfaces) {
    for (const SurfaceDesc& b : surfaces) {
      const BlendedSurface ab = BlendSurfaces(a, b);
      const BlendedSurface ba = BlendSurfaces(b, a);
      EXPECT_EQ(Bits(ab.restitution), Bits(ba.restitution));
      EXPECT_EQ(Bits(ab.friction), Bits(ba.friction));
      EXPECT_EQ(Bits(ab.stiffness), Bits(ba.stiffness));
      EXPECT_EQ(Bits(ab.damping), Bits(ba.damping));
    }
  }
}

TEST(SurfaceBlendTest, SoftContactParameters) {
  // h k = 10 exactly (1e-3 * 1e4 rounds to 10), so both are correctly rounded quotients.
  const SoftContactParams params = SoftContact(1e4, 100, 1e-3);
  EXPECT_TRUE(params.soft);
  EXPECT_EQ(params.erp, 10.0 / 110.0);
  EXPECT_EQ(params.cfm, 1.0 / 110.0);
  // No damping: a pure spring, full error reduction.
  const SoftContactParams spring = SoftContact(1e4, 0, 1e-3);
  EXPECT_TRUE(spring.soft);
  EXPECT_EQ(spring.erp, 1.0);
  EXPECT_EQ(spring.cfm, 1.0 / 10.0);
  // No stiffness: a pure damper, no error reduction.
  const SoftContactParams damper = SoftContact(0, 50, 1e-3);
  EXPECT_TRUE(damper.soft);
  EXPECT_EQ(damper.erp, 0.0);
  EXPECT_EQ(damper.cfm, 1.0 / 50.0);
  // Klamp't's worked default, robot link on the default terrain at 1 ms.
  const SoftContactParams terrain = SoftContact(8e5, 2e5, 1e-3);
  EXPECT_EQ(terrain.erp, 800.0 / 200800.0);
  EXPECT_EQ(terrain.cfm, 1.0 / 200800.0);
}

TEST(SurfaceBlendTest, RigidContactsAreHard) {
  EXPECT_FALSE(SoftContact(kInf, kInf, 1e-3).soft);
  EXPECT_FALSE(SoftContact(kInf, 100, 1e-3).soft);
  // A finite spring behind an infinite damper cannot move: rigid. Klamp't computes erp = h k /
  // inf = 0 and cfm = 0 here, a hard contact that never corrects penetration; Lamina uses the
  // world's ERP/CFM instead.
  const SoftContactParams stuck = SoftContact(1e4, kInf, 1e-3);
  EXPECT_FALSE(stuck.soft);
  EXPECT_EQ(stuck.erp, 0.0);
  EXPECT_EQ(stuck.cfm, 0.0);
}

TEST(SurfaceBlendTest, NeitherStiffnessNorDampingMeansNoForce) {
  const SoftContactParams none = SoftContact(0, 0, 1e-3);
  EXPECT_TRUE(none.soft);
  EXPECT_EQ(none.erp, 0.0);
  EXPECT_EQ(none.cfm, kInf);
}

// One step of ODE's solver for a single contact row between a body of mass m and a fixed floor.
// The ODE manual ("Soft constraint and constraint force mixing") gives the row's force λ
// (F = Jᵀ λ) as the solution of
//   (J M⁻¹ Jᵀ + CFM / h) λ = c / h,    c = ERP · depth / h,
// for a body at rest with no other force; with velocity v and external force f the right-hand
// side becomes c / h - J (v / h + M⁻¹ f) (ODE's step.cpp). Equivalently, the velocity after the
// step, v⁺ = v + h M⁻¹ (f + Jᵀ λ), satisfies J v⁺ = c - CFM λ. (The manual's statement
// "J v = c + CFM λ" has the sign of the mixing term flipped relative to its own solved form; the
// solved form is what ODE computes.) Here J = 1 (the row measures the separating velocity),
// M = m, and λ >= 0 (a contact only pushes).
struct RowStep {
  double force;     ///< λ, N
  double velocity;  ///< v⁺, m/s, positive = separating
};

RowStep StepContactRow(const SoftContactParams& params, double mass, double step, double depth,
                       double velocity, double external_force) {
  const double c = params.erp * depth / step;
  const double rhs = c / step - (velocity / step + external_force / mass);
  const double force = std::max(0.0, rhs / (1.0 / mass + params.cfm / step));
  return {force, velocity + step * (external_force + force) / mass};
}

// From J v⁺ = c - CFM λ: λ = (ERP x / h - v⁺) / CFM = (h k + c)(k x / (h k + c) - v⁺)
//   = k x - (h k + c) v⁺ = k (x - h v⁺) - c v⁺ = k x⁺ - c v⁺,
// with x⁺ = x - h v⁺ the depth after the step: the spring-damper force evaluated at the end of
// the step (implicit Euler). Held at depth x with zero velocity, λ = k x, so a mass m resting on
// the contact settles where k x = m g.
constexpr double kBlendMass = 2.0;  // kg
using test::kGravity;
constexpr double kStiffness = 1e4;   // N/m
constexpr double kDamping = 100;     // N·s/m
constexpr double kBlendStep = 1e-3;  // s
// A handful of roundings on quantities of order 1-100: relative 1e-12 leaves a wide margin.
constexpr double kBlendRelative = 1e-12;

TEST(SurfaceBlendTest, HeldContactPushesWithSpringForce) {
  const SoftContactParams params = SoftContact(kStiffness, kDamping, kBlendStep);
  const double weight = kBlendMass * kGravity;
  const double rest_depth = weight / kStiffness;  // 1.96 mm
  const RowStep held = StepContactRow(params, kBlendMass, kBlendStep, rest_depth, 0.0, -weight);
  EXPECT_NEAR(held.force, kStiffness * rest_depth, weight * kBlendRelative);
  EXPECT_NEAR(held.velocity, 0.0, 1e-15);  // stays at rest: the weight is exactly balanced
}

TEST(SurfaceBlendTest, MovingContactIsTheImplicitSpringDamper) {
  const SoftContactParams params = SoftContact(kStiffness, kDamping, kBlendStep);
  for (const double velocity : {-0.2, -0.01, 0.05}) {
    SCOPED_TRACE(velocity);
    const double depth = 3e-3;
    const RowStep step =
        StepContactRow(params, kBlendMass, kBlendStep, depth, velocity, -kBlendMass * kGravity);
    ASSERT_GT(step.force, 0.0);
    const double next_depth = depth - kBlendStep * step.velocity;
    EXPECT_NEAR(step.force, kStiffness * next_depth - kDamping * step.velocity,
                step.force * kBlendRelative);
  }
}

// Dropped onto the contact from rest at zero depth, the mass settles at m g / k. Damping ratio
// c / (2 sqrt(k m)) = 0.35, decay rate c / (2 m) = 25 /s: after 2 s the transient is ~e^-50.
TEST(SurfaceBlendTest, RestingMassSettlesAtWeightOverStiffness) {
  const SoftContactParams params = SoftContact(kStiffness, kDamping, kBlendStep);
  const double weight = kBlendMass * kGravity;
  double depth = 0.0;
  double velocity = 0.0;
  double force = 0.0;
  for (int i = 0; i < 2000; ++i) {
    const RowStep step = StepContactRow(params, kBlendMass, kBlendStep, depth, velocity, -weight);
    velocity = step.velocity;
    force = step.force;
    depth -= kBlendStep * velocity;
  }
  EXPECT_NEAR(depth, weight / kStiffness, weight / kStiffness * 1e-9);
  EXPECT_NEAR(force, weight, weight * 1e-9);
}

}  // namespace
}  // namespace lamina::core
