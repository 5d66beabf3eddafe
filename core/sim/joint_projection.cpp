// SPDX-License-Identifier: MIT
#include "core/sim/joint_projection.h"

#include <algorithm>
#include <cmath>

namespace lamina::core {

namespace {

Vec3 WorldAxis(const JointPlacement& joint, const BodyState& parent) {
  return parent.orientation * joint.axis;
}

}  // namespace

Vec3 JointParentPoint(const JointPlacement& joint, const BodyState& parent) {
  return parent.com_position + parent.orientation * joint.parent_point;
}

JointPlacement MakeJointPlacement(const BodyState& parent, const BodyState& child, bool slider,
                                  const Vec3& axis, const Vec3& point) {
  JointPlacement joint;
  joint.slider = slider;
  const Eigen::Quaterniond to_parent = parent.orientation.conjugate();
  joint.axis = (to_parent * axis).normalized();
  joint.relative = (to_parent * child.orientation).normalized();
  if (slider) {
    joint.parent_point = to_parent * (child.com_position - parent.com_position);
  } else {
    joint.parent_point = to_parent * (point - parent.com_position);
    joint.child_point = child.orientation.conjugate() * (point - child.com_position);
  }
  return joint;
}

JointPlacement MakeFixedPlacement(const BodyState& parent, const BodyState& child) {
  JointPlacement joint = MakeJointPlacement(parent, child, true, Vec3::UnitZ(), Vec3::Zero());
  joint.axis = Vec3::Zero();
  return joint;
}

double JointCoordinate(const JointPlacement& joint, const BodyState& parent,
                       const BodyState& child) {
  if (joint.slider) {
    return (child.com_position - JointParentPoint(joint, parent)).dot(WorldAxis(joint, parent));
  }
  // the rotation since the build, in the parent's axes, and its twist about the axis
  const Eigen::Quaterniond turn =
      parent.orientation.conjugate() * child.orientation * joint.relative.conjugate();
  double angle = 2.0 * std::atan2(turn.vec().dot(joint.axis), turn.w());
  if (angle > M_PI) angle -= 2.0 * M_PI;
  if (angle <= -M_PI) angle += 2.0 * M_PI;
  return angle;
}

double JointRate(const JointPlacement& joint, const BodyState& parent, const BodyState& child) {
  const Vec3 axis = WorldAxis(joint, parent);
  if (!joint.slider) return (child.angular_velocity - parent.angular_velocity).dot(axis);
  const Vec3 carried = parent.linear_velocity +
                       parent.angular_velocity.cross(child.com_position - parent.com_position);
  return (child.linear_velocity - carried).dot(axis);
}

BodyState PlaceOnJoint(const JointPlacement& joint, const BodyState& parent, double coordinate,
                       double rate) {
  const Vec3 axis = WorldAxis(joint, parent);
  BodyState child;
  child.angular_velocity = parent.angular_velocity;
  if (joint.slider) {
    child.orientation = parent.orientation * joint.relative;
    child.com_position = JointParentPoint(joint, parent) + coordinate * axis;
    child.linear_velocity =
        parent.linear_velocity +
        parent.angular_velocity.cross(child.com_position - parent.com_position) + rate * axis;
    return child;
  }
  const Eigen::Quaterniond twist(Eigen::AngleAxisd(coordinate, joint.axis));
  child.orientation = (parent.orientation * twist * joint.relative).normalized();
  const Vec3 pivot = JointParentPoint(joint, parent);
  child.com_position = pivot - child.orientation * joint.child_point;
  child.angular_velocity += rate * axis;
  child.linear_velocity = parent.linear_velocity +
                          parent.angular_velocity.cross(pivot - parent.com_position) +
                          child.angular_velocity.cross(child.com_position - pivot);
  return child;
}

Vec3 JointGapVector(const JointPlacement& joint, const BodyState& parent, const BodyState& child) {
  if (!joint.slider) {
    const Vec3 carried = child.com_position + child.orientation * joint.child_point;
    return carried - JointParentPoint(joint, parent);
  }
  const Vec3 axis = WorldAxis(joint, parent);
  Vec3 off = child.com_position - JointParentPoint(joint, parent);
  off -= off.dot(axis) * axis;
  return off;
}

double JointGap(const JointPlacement& joint, const BodyState& parent, const BodyState& child) {
  return JointGapVector(joint, parent, child).norm();
}

double JointBreakGap(double offset) {
  constexpr double kFloor = 0.01;    // m
  constexpr double kFraction = 0.1;  // of the offset
  return std::max(kFloor, kFraction * offset);
}

}  // namespace lamina::core
