// SPDX-License-Identifier: MIT
// Conversions between ODE's body data and core types, shared by the simulator's source files.
#pragma once

#include <ode/ode.h>

#include "core/math_types.h"
#include "core/sim/sim_state.h"

namespace lamina::core {

/// An ODE vector (dBodyGetPosition and the like) as a Vec3. (Inline: the solvers' row building
/// calls these for every row.)
inline Vec3 ToVec3(const dReal* v) {
  return {v[0], v[1], v[2]};
}
/// An ODE 3x4 rotation (dBodyGetRotation) as a Mat3.
inline Mat3 ToMat3(const dReal* r) {
  Mat3 m;
  m << r[0], r[1], r[2], r[4], r[5], r[6], r[8], r[9], r[10];
  return m;
}
/// Sets the ODE body's orientation to `rotation` (through its quaternion, as ODE keeps it).
void SetBodyRotation(dBodyID body, const Mat3& rotation);
/// The body's state as ODE holds it (at its centre of mass).
BodyState ReadBodyState(dBodyID body);
/// Sets position, orientation and velocities exactly (bit for bit what ReadBodyState gave).
void WriteBodyState(dBodyID body, const BodyState& state);

}  // namespace lamina::core
