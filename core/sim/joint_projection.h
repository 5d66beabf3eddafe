// SPDX-License-Identifier: MIT
// A body put back on its hinge or slider after a step that integrated every body on its own.
// The Newton solver's joint coordinates (reduced_basis.h) solve an island's velocities over its
// joints' rates, so every joint holds at the start of the step; the step then moves each body
// with its own velocity, which leaves a gap of order (ωh)²·r at a hinge. Placing the child at its
// joint coordinate from its parent, parents first, takes that gap back to rounding, and its
// velocity is made the one its parent and the joint's rate give at the new pose (what
// OdeRobot::ProjectOntoJoints does for a robot with its own kinematics; this is for the world's
// joints, which have none but ODE's).
//
// The joint coordinate is read from the poses as they are: a hinge's angle is the twist of the
// child's rotation about the axis relative to where it was built (the part of the rotation that
// is not about the axis is dropped), a slider's travel the child's centre along the axis (its
// rotation is set to the one it was built with, its offset across the axis dropped). Both are 0
// where the joint was built. Unlike ODE's dJointGetHingeAngle the angle is the child's relative
// to the parent whichever of the two is the joint's first body (right-handed about the axis).
//
// How far a joint is open (JointGap) is what the step guard watches (robot_guard.h for robots'
// joints, Simulator for the world's): a hinge's two copies of its axis point apart, or a slider's
// child off its line. A fixed joint is a slider along no axis (axis zero: it has no travel).
//
// Units: m, rad, s; centres of mass and velocities in world axes (BodyState), as ODE keeps them.
#pragma once

#include "core/math_types.h"
#include "core/sim/sim_state.h"

namespace lamina::core {

/// A hinge or slider seen from its parent body, as it was built (coordinate 0). The fixed world
/// as the parent is a body at the origin with the identity rotation, at rest.
struct JointPlacement {
  bool slider = false;
  Vec3 axis = Vec3::UnitZ();  ///< unit, in the parent's axes; zero for a fixed joint (a slider)
  /// hinge: a point of the axis in the parent's axes, from its centre of mass; slider: the
  /// child's centre of mass at travel 0, in the parent's axes from its centre of mass
  Vec3 parent_point = Vec3::Zero();
  /// hinge: the same point in the child's axes, from its centre of mass (slider: unused)
  Vec3 child_point = Vec3::Zero();
  /// the child's rotation in the parent's axes at coordinate 0
  Eigen::Quaterniond relative = Eigen::Quaterniond::Identity();
};

/// The placement of a joint built with the bodies at `parent` and `child`, about or along `axis`
/// (world, any length) through `point` (world; a hinge's).
JointPlacement MakeJointPlacement(const BodyState& parent, const BodyState& child, bool slider,
                                  const Vec3& axis, const Vec3& point);
/// A fixed joint's placement: a slider along no axis (coordinate always 0).
JointPlacement MakeFixedPlacement(const BodyState& parent, const BodyState& child);
/// The hinge's angle (rad, in (−π, π]) or the slider's travel (m) of `child` relative to `parent`.
double JointCoordinate(const JointPlacement& joint, const BodyState& parent,
                       const BodyState& child);
/// The joint's rate (rad/s or m/s): the child's angular velocity relative to the parent's along
/// the axis, or its centre's velocity relative to the parent's motion there, along the axis.
double JointRate(const JointPlacement& joint, const BodyState& parent, const BodyState& child);
/// The child on the joint at `coordinate`, moving with the parent and at `rate` along the joint.
BodyState PlaceOnJoint(const JointPlacement& joint, const BodyState& parent, double coordinate,
                       double rate);

/// The world point the parent carries: a hinge's axis point, or where a slider's child's centre of
/// mass is at travel 0 (a fixed joint's: where it is).
Vec3 JointParentPoint(const JointPlacement& joint, const BodyState& parent);

/// How far the joint is open (m): for a hinge the distance between its axis point carried by the
/// parent and by the child, for a slider the distance of the child's centre of mass from the line
/// the parent carries it along (the whole distance from where it was built, for a fixed joint).
/// The twist about the axis, and a slider's travel, do not count; nor does a tilt of the axes.
double JointGap(const JointPlacement& joint, const BodyState& parent, const BodyState& child);
/// The same gap as a vector (world, m): from the parent's point to the child's, less its part
/// along a slider's axis.
Vec3 JointGapVector(const JointPlacement& joint, const BodyState& parent, const BodyState& child);

/// How far a joint may be open before a step counts as having broken it or left it open (m):
/// max(1 cm, 10 % of `offset`, the distance from the parent's centre (or frame) to the child's).
/// A robot's joint uses its link's offset from its parent (robot_guard.h); a world joint the
/// distance between its bodies' centres of mass through the hinge's axis point.
double JointBreakGap(double offset);

}  // namespace lamina::core
