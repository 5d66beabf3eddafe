// SPDX-License-Identifier: MIT
// A robot's ODE joints as Newton solver rows (newton_solver.h): what getInfo2 of ODE 0.16 writes
// for a hinge (ode/src/joints/hinge.cpp: three ball rows, two rows keeping the axes aligned, and
// the stop row of dxJointLimitMotor::addLimot) and for an angular motor in user mode
// (amotor.cpp: one row per powered axis), so that the Newton solver and dWorldStep solve the
// same rows. Used by object_islands.cpp for the robots of ode_robot.h.
//
// Not replicated, all outside what OdeRobot builds (JointRows then returns false and the island
// stays with ODE's solver): a powered hinge (ODE's own hinge motor: OdeRobot drives its hinges
// through a separate angular motor), a hinge stop with bounce, a motor axis with stops or with
// CFM 0 (a hard row: the Newton solver's rows are soft), and every other joint type (sliders
// and linear motors among them).
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

/// The rows of `joint` (a hinge or a user-mode angular motor) between island bodies `ia` (its
/// first body) and `ib` (its second, -1 for the world) appended to `rows`. `hinge_axis2`: a
/// hinge's axis as ODE keeps it for its second body (in that body's axes; world axes without
/// one), which ODE's API does not return. World ERP/CFM are read from `world`; `step` in s.
/// Returns false, appending nothing, for a joint or a state outside what is replicated (above).
bool JointRows(dxJoint* joint, int ia, int ib, const Vec3& hinge_axis2, dxWorld* world, double step,
               std::vector<NewtonRow>* rows);

}  // namespace lamina::core
