// SPDX-License-Identifier: MIT
// Islands of bodies and ODE-style rows for the tests of the solvers that take them
// (core/sim/newton_solver.h, core/sim/direct_solver.h): 10 cm cubes under gravity, contacts
// with their friction rows, a face of four contacts.
#pragma once

#include <vector>

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

}  // namespace lamina::test
