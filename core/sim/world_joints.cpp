// SPDX-License-Identifier: MIT
#include "core/sim/world_joints.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <ode/ode.h>

#include "core/sim/ode_conversions.h"

namespace lamina::core {

namespace {

// ODE's parameters of a hinge or slider: its limits and its friction motor
void SetLimitsAndFriction(dJointID joint, const WorldJointDesc& desc) {
  const auto set = desc.type == WorldJointType::kHinge ? dJointSetHingeParam : dJointSetSliderParam;
  if (std::isfinite(desc.min)) set(joint, dParamLoStop, desc.min);
  if (std::isfinite(desc.max)) set(joint, dParamHiStop, desc.max);
  set(joint, dParamBounce, 0.0);
  set(joint, dParamVel, 0.0);
  set(joint, dParamFMax, desc.friction);
}

dJointID MakeJoint(dWorldID world, const WorldJointDesc& desc, dBodyID a, dBodyID b) {
  switch (desc.type) {
    case WorldJointType::kFixed: {
      dJointID joint = dJointCreateFixed(world, nullptr);
      dJointAttach(joint, a, b);
      dJointSetFixed(joint);
      return joint;
    }
    case WorldJointType::kHinge: {
      dJointID joint = dJointCreateHinge(world, nullptr);
      dJointAttach(joint, a, b);
      dJointSetHingeAnchor(joint, desc.point.x(), desc.point.y(), desc.point.z());
      dJointSetHingeAxis(joint, desc.axis.x(), desc.axis.y(), desc.axis.z());
      SetLimitsAndFriction(joint, desc);
      return joint;
    }
    case WorldJointType::kSlider: {
      dJointID joint = dJointCreateSlider(world, nullptr);
      dJointAttach(joint, a, b);
      dJointSetSliderAxis(joint, desc.axis.x(), desc.axis.y(), desc.axis.z());
      SetLimitsAndFriction(joint, desc);
      return joint;
    }
  }
  return nullptr;
}

// the distance from the parent's centre of mass to the child's as built, through a hinge's axis
// point; from the world (no parent body), the child's distance from the hinge's point (0 for a
// slider or a fixed joint)
double BuiltOffset(const JointPlacement& child_of_second, bool second_moves) {
  const double from_parent = second_moves ? child_of_second.parent_point.norm() : 0.0;
  return child_of_second.slider ? from_parent : from_parent + child_of_second.child_point.norm();
}

}  // namespace

void OdeWorldJoints::Build(dxWorld* ode_world, const WorldDesc& world, const BodyOf& body_of,
                           Diagnostics& diagnostics) {
  Clear();
  for (size_t j = 0; j < world.joints.size(); ++j) {
    const WorldJointDesc& desc = world.joints[j];
    // as given: ODE measures the first body relative to the second (a null first body is the
    // world, and ODE flips its readings to keep that meaning)
    dBodyID a = body_of(desc.bodies[0]);
    dBodyID b = desc.bodies.size() > 1 ? body_of(desc.bodies[1]) : nullptr;
    types_.push_back(desc.type);
    if (a == nullptr && b == nullptr) {
      diagnostics.Warning({world.source_path, 0, 0},
                          "joint " + std::to_string(j) + " (" + WorldJointTypeName(desc.type) +
                              ") holds nothing that moves; it is left out");
      joints_.push_back(nullptr);
      frames_.emplace_back();
      placements_.emplace_back();
      break_gaps_.push_back(kInf);
      continue;
    }
    joints_.push_back(MakeJoint(ode_world, desc, a, b));
    Record(joints_.back(), desc);
  }
}

// what the Newton solver's rows (JointFrame) and the placement after a step in joint
// coordinates need of a hinge or slider whose first body moves, with the bodies as built
void OdeWorldJoints::Record(dJointID joint, const WorldJointDesc& desc) {
  frames_.emplace_back();
  placements_.emplace_back();
  break_gaps_.push_back(kInf);
  const bool slider = desc.type == WorldJointType::kSlider;
  dBodyID first = dJointGetBody(joint, 0), second = dJointGetBody(joint, 1);
  if (first == nullptr) return;
  const BodyState a = ReadBodyState(first);
  const BodyState b = second != nullptr ? ReadBodyState(second) : BodyState{};
  Placements& both = placements_.back();
  if (desc.type == WorldJointType::kFixed) {
    both.first_child = MakeFixedPlacement(b, a);
  } else {
    frames_.back() =
        slider ? OdeSliderFrame(first, second, desc.axis) : OdeHingeFrame(second, desc.axis);
    both.first_child = MakeJointPlacement(b, a, slider, desc.axis, desc.point);
    both.second_child = MakeJointPlacement(a, b, slider, desc.axis, desc.point);
  }
  break_gaps_.back() = JointBreakGap(BuiltOffset(both.first_child, second != nullptr));
}

int OdeWorldJoints::IndexOf(const dxJoint* joint) const {
  for (size_t j = 0; j < joints_.size(); ++j) {
    if (joints_[j] == joint) return static_cast<int>(j);
  }
  return -1;
}

void OdeWorldJoints::Clear() {
  for (dJointID joint : joints_) {
    if (joint != nullptr) dJointDestroy(joint);
  }
  joints_.clear();
  types_.clear();
  frames_.clear();
  placements_.clear();
  break_gaps_.clear();
}

double OdeWorldJoints::Position(int joint) const {
  dJointID j = joints_.at(static_cast<size_t>(joint));
  if (j == nullptr) return 0.0;
  if (types_[joint] == WorldJointType::kHinge) return dJointGetHingeAngle(j);
  if (types_[joint] == WorldJointType::kSlider) return dJointGetSliderPosition(j);
  return 0.0;
}

double OdeWorldJoints::Gap(int joint) const {
  dJointID j = joints_.at(static_cast<size_t>(joint));
  if (j == nullptr || dJointGetBody(j, 0) == nullptr) return 0.0;
  if (types_[joint] == WorldJointType::kHinge) {
    // the axis point as each body carries it (ODE keeps both): JointGap's hinge gap, from the
    // rotation matrices ODE already has
    dVector3 first, second;
    dJointGetHingeAnchor(j, first);
    dJointGetHingeAnchor2(j, second);
    return dCalcPointsDistance3(first, second);
  }
  dBodyID second = dJointGetBody(j, 1);
  return JointGap(placements_[joint].first_child,
                  second != nullptr ? ReadBodyState(second) : BodyState{},
                  ReadBodyState(dJointGetBody(j, 0)));
}

bool OdeWorldJoints::AnyOpen(double* largest) const {
  bool open = false;
  for (int j = 0; j < size(); ++j) {
    const double gap = Gap(j);
    open = open || gap > break_gaps_[j];
    if (largest) *largest = std::max(*largest, gap);
  }
  return open;
}

double OdeWorldJoints::Rate(int joint) const {
  dJointID j = joints_.at(static_cast<size_t>(joint));
  if (j == nullptr) return 0.0;
  if (types_[joint] == WorldJointType::kHinge) return dJointGetHingeAngleRate(j);
  if (types_[joint] == WorldJointType::kSlider) return dJointGetSliderPositionRate(j);
  return 0.0;
}

}  // namespace lamina::core
