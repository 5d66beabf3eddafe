// SPDX-License-Identifier: MIT
// ODE's integration of one free rigid body over a step, for the bodies whose velocity Lamina's
// own solvers found (object_islands.h): their island is integrated here instead of in
// dWorldStep, which would make each of them an island of its own and cost about 2,000
// instructions a body in ODE's threading-job machinery (7 % of a 10-box stack's step).
//
// - FreeAngularVelocity: the angular velocity without the constraint rows, with ODE's implicit
//   gyroscopic term (Lacoursière 2006, as dxStepIsland_Stage0_Bodies in ode/src/step.cpp):
//   ω' = (I − h [L]×)⁻¹ L + h I⁻¹ τ with L = I ω. Unlike the explicit term −ω × I ω, it does not
//   pump energy into a body spinning about an intermediate axis.
// - StepFreeBody: ODE's dxStepBody (ode/src/util.cpp) for a body in finite rotation mode without
//   a finite-rotation axis (every Lamina body): the angular speed capped, x += h v, the rotation
//   by the quaternion of the finite rotation h ω applied on the left. The quaternion comes back
//   unnormalized, as dxStepBody has it before dNormalize4: dBodySetQuaternion normalizes it the
//   same way, so the pose is ODE's to the last bit.
// Units: SI; ω in rad/s, world axes; quaternions (w, x, y, z) as ODE's dQuaternion.
#pragma once

#include <array>

#include "core/math_types.h"

namespace lamina::core {

/// (w, x, y, z), ODE's order.
using OdeQuaternion = std::array<double, 4>;

/// The angular velocity after `step` seconds under the torque `torque` (N·m) alone, with ODE's
/// implicit gyroscopic term when `gyroscopic` (ODE's default for a body). `inertia`: about the
/// centre of mass, world axes (kg·m²).
Vec3 FreeAngularVelocity(const Mat3& inertia, const Vec3& omega, const Vec3& torque, double step,
                         bool gyroscopic);

struct FreeBodyPose {
  Vec3 position;           ///< of the centre of mass (m)
  OdeQuaternion rotation;  ///< unnormalized: dBodySetQuaternion normalizes it as ODE's step
  Vec3 omega;              ///< the angular velocity after the cap (rad/s)
};

/// dxStepBody: the pose after `step` seconds at the velocities `velocity` and `omega` from
/// `position` and the unit quaternion `rotation`; `max_angular_speed` as
/// dBodyGetMaxAngularSpeed (infinite: no cap).
FreeBodyPose StepFreeBody(const Vec3& position, const OdeQuaternion& rotation, const Vec3& velocity,
                          const Vec3& omega, double max_angular_speed, double step);

}  // namespace lamina::core
