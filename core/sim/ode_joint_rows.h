// SPDX-License-Identifier: MIT
// A robot's ODE joints as Newton solver rows (newton_solver.h): what getInfo2 of ODE 0.16 writes
// for a hinge (ode/src/joints/hinge.cpp: three ball rows, two rows keeping the axes aligned, and
// the stop row of dxJointLimitMotor::addLimot), a slider (slider.cpp: three rows keeping the
// bodies' rotations, two keeping the first body on the axis, the stop row), an angular motor in
// user mode (amotor.cpp) and a linear motor (lmotor.cpp: one row per powered axis), so that the
// Newton solver and dWorldStep solve the same rows. Used by object_islands.cpp for the robots of
// ode_robot.h.
//
// Not replicated, all outside what OdeRobot builds (JointRows then returns false and the island
// stays with ODE's solver): a powered hinge or slider (ODE's own joint motor: OdeRobot drives its
// joints through a separate motor joint), a stop with bounce, a motor axis with stops or with
// CFM 0 (a hard row: the Newton solver's rows are soft), a motor axis relative to the second body
// or the world, and every other joint type.
// One difference in what is read: ODE re-tests a hinge's stops only when one of them lies in
// [-π, π] and keeps the last result otherwise; here a hinge whose stops are both outside that
// range has no stop row (OdeRobot sets such stops to ±∞, where ODE's last result is "none" too).
//
// Units: m, rad, s; rows as in newton_solver.h (velocity rows in m/s or rad/s, forces in N or
// N·m); the joint's first body is its child link, the second its parent (null: the world).
#pragma once

#include <vector>

#include "core/math_types.h"
#include "core/sim/newton_solver.h"
#include "core/sim/ode_fwd.h"

namespace lamina::core {

/// What ODE keeps of a joint and its API does not return, recorded when the joint is built (as
/// ODE computes it then: ode/src/joints/joint.cpp setAxes, slider.cpp computeOffset and
/// computeInitialRelativeRotation).
struct JointFrame {
  /// hinge: its axis in the second body's axes (world axes without one)
  Vec3 axis2 = Vec3::UnitZ();
  /// slider: qrel, the first body's rotation relative to the second's (ODE's w, x, y, z: q1⁻¹ q2,
  /// or q1⁻¹ without a second body)
  Eigen::Vector4d relative = Eigen::Vector4d(1.0, 0.0, 0.0, 0.0);
  /// slider: the first body's centre in the second body's axes, from its centre (world without
  /// one)
  Vec3 offset = Vec3::Zero();
  /// linear motor: its axes in the first body's axes (all of OdeRobot's motor axes are the joint's)
  Vec3 axis1 = Vec3::UnitZ();
};

/// What ODE keeps of a hinge about `axis` (world) whose second body is `second` (null: the
/// world) when it is built: setAxes keeps the axis in the second body's axes, normalized (the
/// world's as given).
JointFrame OdeHingeFrame(dxBody* second, const Vec3& axis);
/// What ODE keeps of a slider (and its linear motor) from `first` to `second` (null: the world)
/// along `axis` (world) when it is built: slider.cpp computeInitialRelativeRotation and
/// computeOffset, the motor's axis in the first body's axes (lmotor.cpp).
JointFrame OdeSliderFrame(dxBody* first, dxBody* second, const Vec3& axis);

/// The rows of `joint` (a hinge, a slider, a user-mode angular motor or a linear motor) between
/// island bodies `ia` (its first body) and `ib` (its second, -1 for the world) appended to
/// `rows`. World ERP/CFM are read from `world`; `step` in s. Returns false, appending nothing,
/// for a joint or a state outside what is replicated (above). Without `tree_rows` a hinge or
/// slider gives only its stop row, not the five that hold it together (the Newton solver's
/// reduced step keeps those joints by its basis instead: reduced_basis.h).
bool JointRows(dxJoint* joint, int ia, int ib, const JointFrame& frame, dxWorld* world, double step,
               std::vector<NewtonRow>* rows, bool tree_rows = true);

}  // namespace lamina::core
