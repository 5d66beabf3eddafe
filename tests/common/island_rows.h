// SPDX-License-Identifier: MIT
// Islands of bodies and ODE-style rows for the tests of the solvers that take them
// (core/sim/newton_solver.h, core/sim/direct_solver.h): 10 cm cubes under gravity, contacts
// with their friction rows, a face of four contacts.
#pragma once

#include <limits>
#include <vector>

#include <Eigen/LU>
#include <gtest/gtest.h>

#include "core/sim/newton_solver.h"

namespace lamina::test {

inline constexpr double kIslandGravity = 9.8;  ///< m/s², along −z

/// A 10 cm cube of `mass` starting at `start`, its free velocity after a step of gravity.
inline core::NewtonBody IslandBody(double mass, const core::Vec6& start, double step) {
  core::NewtonBody body;
  body.mass = mass;
  body.inertia = core::Mat3::Identity() * mass * 0.01 / 6.0;
  body.start = start;
  body.free_velocity = start;
  body.free_velocity(2) -= kIslandGravity * step;
  return body;
}

/// A normal row at `point_a` (relative to a's centre) pushing a up along z against b (or the
/// ground, -1) at b's `point_b`, then its two friction rows with coefficient mu.
inline void AddContact(std::vector<core::NewtonRow>* rows, int a, int b, const core::Vec3& point_a,
                       const core::Vec3& point_b, double mu, double cfm = 1e-9) {
  const core::Vec3 axes[3] = {core::Vec3::UnitZ(), core::Vec3::UnitX(), core::Vec3::UnitY()};
  const int normal = static_cast<int>(rows->size());
  for (int k = 0; k < 3; ++k) {
    core::NewtonRow row;
    row.a = a;
    row.b = b;
    row.ja << axes[k], point_a.cross(axes[k]);
    row.jb << -axes[k], -point_b.cross(axes[k]);
    row.cfm = k == 0 ? cfm : 1e-6;
    if (k > 0) {
      row.lo = -mu;
      row.hi = mu;
      row.normal = normal;
    }
    rows->push_back(row);
  }
}

/// The four corners of a 10 cm face under a (at −5 cm) over b's top face (at +5 cm).
inline void AddFace(std::vector<core::NewtonRow>* rows, int a, int b, double mu) {
  for (double x : {-0.05, 0.05}) {
    for (double y : {-0.05, 0.05}) AddContact(rows, a, b, {x, y, -0.05}, {x, y, 0.05}, mu);
  }
}

/// The sum of the normal rows' forces between a and b.
inline double NormalSum(const std::vector<core::NewtonRow>& rows, const core::NewtonResult& result,
                        int a, int b) {
  double sum = 0.0;
  for (size_t i = 0; i < rows.size(); ++i) {
    if (rows[i].normal < 0 && rows[i].lo == 0.0 && rows[i].a == a && rows[i].b == b) {
      sum += result.force[i];
    }
  }
  return sum;
}

/// A 2 kg box resting on the ground on four contacts at h = 10 ms, solved by `solver`: each row
/// asks v' = −cfm λ and m (v' + g h) = 4 h λ, so λ = m g h / (4 h + m cfm). Returns the result
/// (each solver adds its own checks).
template <typename Solver>
core::NewtonResult ExpectABoxOnTheGroundCarriesItsWeight(Solver* solver) {
  const double h = 0.01, m = 2.0, cfm = 1e-9;
  const std::vector<core::NewtonBody> bodies = {IslandBody(m, core::Vec6::Zero(), h)};
  std::vector<core::NewtonRow> rows;
  AddFace(&rows, 0, -1, 0.5);
  core::NewtonResult result;
  EXPECT_TRUE(solver->Solve(bodies, rows, h, {}, &result));
  if (!result.converged) return result;
  const double lambda = m * kIslandGravity * h / (4.0 * h + m * cfm);
  EXPECT_NEAR(NormalSum(rows, result, 0, -1), 4.0 * lambda, 1e-12 * lambda);
  EXPECT_NEAR(result.velocity[0](2), -cfm * lambda, 1e-15);
  EXPECT_LE(result.velocity[0].tail<3>().norm(), 1e-12);
  return result;
}

/// A 1000 kg box on a 1 kg one on the ground from rest, h = 10 ms: per contact λ0 (ground) and
/// λ1 (between), v0 = −cfm λ0, v1 = v0 − cfm λ1, m0 (v0 + g h) = 4 h (λ0 − λ1) and
/// m1 (v1 + g h) = 4 h λ1. Returns the result.
template <typename Solver>
core::NewtonResult ExpectAThousandToOneStackHolds(Solver* solver) {
  const double h = 0.01, m0 = 1.0, m1 = 1000.0, cfm = 1e-9;
  const std::vector<core::NewtonBody> bodies = {IslandBody(m0, core::Vec6::Zero(), h),
                                                IslandBody(m1, core::Vec6::Zero(), h)};
  std::vector<core::NewtonRow> rows;
  AddFace(&rows, 0, -1, 0.5);
  AddFace(&rows, 1, 0, 0.5);
  core::NewtonResult result;
  EXPECT_TRUE(solver->Solve(bodies, rows, h, {}, &result));
  if (!result.converged) return result;
  Eigen::Matrix2d a;
  a << 4.0 * h + m0 * cfm, -4.0 * h, m1 * cfm, 4.0 * h + m1 * cfm;
  const Eigen::Vector2d lambda =
      a.lu().solve(Eigen::Vector2d(m0 * kIslandGravity * h, m1 * kIslandGravity * h));
  EXPECT_NEAR(NormalSum(rows, result, 0, -1), 4.0 * lambda(0), 1e-9 * lambda(0));
  EXPECT_NEAR(NormalSum(rows, result, 1, 0), 4.0 * lambda(1), 1e-9 * lambda(1));
  EXPECT_NEAR(result.velocity[1](2), -cfm * (lambda(0) + lambda(1)), 1e-12);
  return result;
}

/// A 2 kg box sliding at 1 m/s along x on four contacts whose friction coefficient is infinite
/// (kFriction inf: no sliding), h = 10 ms: the solve settles and every contact point stops, to
/// the friction rows' give (cfm 1e-6 (m/s)/N times their force, at most m v / h = 200 N: 2e-4
/// m/s). The friction tips the box onto its front edge, so the back contacts carry no normal
/// force, where an infinite coefficient times 0 gave NaN bounds. Returns the result.
template <typename Solver>
core::NewtonResult ExpectASlidingBoxStopsOnInfiniteFriction(Solver* solver) {
  const double h = 0.01, m = 2.0;
  core::Vec6 start = core::Vec6::Zero();
  start(0) = 1.0;
  const std::vector<core::NewtonBody> bodies = {IslandBody(m, start, h)};
  std::vector<core::NewtonRow> rows;
  AddFace(&rows, 0, -1, std::numeric_limits<double>::infinity());
  core::NewtonResult result;
  EXPECT_TRUE(solver->Solve(bodies, rows, h, {}, &result));
  if (!result.converged) return result;
  EXPECT_TRUE(result.velocity[0].allFinite());
  for (double x : {-0.05, 0.05}) {
    for (double y : {-0.05, 0.05}) {
      const core::Vec3 arm(x, y, -0.05);
      const core::Vec3 point =
          result.velocity[0].head<3>() + result.velocity[0].tail<3>().cross(arm);
      EXPECT_LE(point.head<2>().norm(), 2e-4) << x << ", " << y;
    }
  }
  EXPECT_GT(result.velocity[0](4), 0.0);  // turning about +y: tipping forwards, onto x = +5 cm
  return result;
}

}  // namespace lamina::test
