// SPDX-License-Identifier: MIT
// Moving between two robot configurations as Klamp't's RobotModel.interpolate and
// interpolateDeriv do, for the trajectories of the Python module (RobotTrajectory) and anyone
// else who blends configurations. Units are the links' own: rad for revolute, m for prismatic.
// Differences from Klamp't: Klamp't interpolates the rotation of a floating or ball-and-socket
// joint along the rotation's geodesic; here every value of such a joint is interpolated linearly
// (the same for the small steps between recorded milestones, not for large turns).
#pragma once

#include "core/math_types.h"
#include "core/model/world_desc.h"

namespace lamina::core {

/// The configuration a fraction `u` of the way from `a` to `b` (u = 0 gives a, u = 1 gives b):
/// a + u (b - a) per link, except on spin joints (unbounded revolute), which turn the short way
/// round and are returned wrapped into (-pi, pi] (Klamp't wraps them into [0, 2pi)). `a` and
/// `b` have robot.dof() entries.
VecX InterpolateConfig(const RobotDesc& robot, const VecX& a, const VecX& b, double u);

/// d/du of InterpolateConfig(robot, a, b, u): b - a, with spin joints' difference taken the
/// short way round (AngleDiff(b, a)).
VecX ConfigDifference(const RobotDesc& robot, const VecX& a, const VecX& b);

}  // namespace lamina::core
