// SPDX-License-Identifier: MIT
// The Simulator's interaction primitives (interaction.h has the laws): the mouse spring as an
// implicit ODE ball joint to the target, rebuilt every physics step, and kinematic targets.
#include <cmath>
#include <stdexcept>

#include <ode/ode.h>

#include "core/robot/dynamics.h"
#include "core/sim/body_change.h"
#include "core/sim/ode_conversions.h"
#include "core/sim/ode_robot.h"
#include "core/sim/simulator.h"

namespace lamina::core {

/// The spring's joint of the current step and ODE's readout of its force.
struct OdeDragJoint {
  dJointFeedback feedback{};
  bool attached = false;  ///< a joint was made in the step being taken
};

OdeDragJoint* NewOdeDragJoint() {
  return new OdeDragJoint();
}

void DeleteOdeDragJoint(OdeDragJoint* joint) {
  delete joint;
}

namespace {

// Lie-group logarithm of a rotation as an angular displacement (rad, world)
Vec3 RotationBetween(const Mat3& from, const Mat3& to) {
  return MomentFromRotation(to * from.transpose());
}

// world axis i of the turn drag's angular motor: a stop at 0 with the body at −turn_i, which
// its ERP drives back to 0 (ODE's stop row: J ω = −(ERP / h) angle)
void SetTurnRow(dJointID joint, int i, double turn_i, double erp, double cfm) {
  const Vec3 axis = Vec3::Unit(i);
  dJointSetAMotorAxis(joint, i, 0, axis.x(), axis.y(), axis.z());  // 0: world axes
  dJointSetAMotorAngle(joint, i, -turn_i);
  const int group = dParamGroup * i;
  dJointSetAMotorParam(joint, dParamLoStop + group, 0.0);  // lo = hi: a bilateral row
  dJointSetAMotorParam(joint, dParamHiStop + group, 0.0);
  dJointSetAMotorParam(joint, dParamStopERP + group, erp);
  dJointSetAMotorParam(joint, dParamStopCFM + group, cfm);
}

}  // namespace

// ---- the mouse spring -------------------------------------------------------------------

std::vector<bool> Simulator::FreeJoints(int robot) const {
  const OdeRobot& ode = *robots_[robot];
  std::vector<bool> free(ode.dof());
  for (int l = 0; l < ode.dof(); ++l) free[l] = ode.DofFree(l);
  return free;
}

double Simulator::EffectiveMassAt(int id, const Vec3& point) const {
  const BodyRecord& body = bodies_[id];
  if (body.kind == WorldId::Kind::kRobotLink) {
    return core::EffectiveMassAt(world_.robots[body.index], GetRobotConfig(body.index),
                                 FreeJoints(body.index), body.link, point);
  }
  const Mat3 rotation = ToMat3(dBodyGetRotation(body.body));
  const Vec3 com = ToVec3(dBodyGetPosition(body.body));
  return RigidEffectiveMass(body.mass, rotation * body.inertia * rotation.transpose(), point - com);
}

bool Simulator::CanGrab(int id) const {
  const BodyRecord* body = bodies_.Find(id);
  return body != nullptr && body->body != nullptr && body->enabled && body->dynamic;
}

bool Simulator::StartDrag(int id, const Vec3& point, const DragSpringSettings& settings) {
  if (!point.allFinite()) throw std::invalid_argument("a drag point must be finite");
  if (auto error = CheckDragSpringSettings(settings)) throw std::invalid_argument(*error);
  if (!CanGrab(id)) return false;
  const double mass = EffectiveMassAt(id, point);
  if (!(mass > 0.0) || !std::isfinite(mass)) return false;
  EndDrag();
  drag_.active = true;
  drag_.body = id;
  drag_.local_point = bodies_.GetPose(bodies_[id]).inverse() * point;
  drag_.target = point;
  drag_.effective_mass = mass;
  drag_.settings = settings;
  drag_.spring = MakeDragSpring(mass, world_.settings.gravity.norm(), settings);
  for (int shared : SharingBody(id)) bodies_[shared].dragged = true;
  BodyChanged(id, kForceApplied);
  return true;
}

void Simulator::SetDragTarget(const Vec3& target) {
  if (!target.allFinite()) throw std::invalid_argument("a drag target must be finite");
  if (!drag_.active) return;
  drag_.target = target;
  BodyChanged(drag_.body, kForceApplied);
}

void Simulator::EndDrag() {
  if (drag_.active && drag_.body < bodies_.size()) {
    for (int shared : SharingBody(drag_.body)) bodies_[shared].dragged = false;
    BodyChanged(drag_.body, kForceApplied);  // what hung still on the spring falls now
  }
  drag_ = DragState{};
}

// ---- the turn drag ----------------------------------------------------------------------

double Simulator::EffectiveInertiaOf(int id) const {
  const BodyRecord& body = bodies_[id];
  if (body.kind == WorldId::Kind::kRobotLink) {
    return core::EffectiveInertiaOf(world_.robots[body.index], GetRobotConfig(body.index),
                                    FreeJoints(body.index), body.link);
  }
  return RigidEffectiveInertia(body.inertia);
}

// the turn spring of body `id` into `drag`; false for a body that cannot turn
bool Simulator::TurnSpringOf(int id, const DragSpringSettings& settings, DragState* drag) const {
  const double inertia = EffectiveInertiaOf(id);
  const double mass = bodies_[id].mass;
  if (!(inertia > 0.0) || !std::isfinite(inertia) || !(mass > 0.0)) return false;
  drag->effective_inertia = inertia;
  drag->turn_spring = MakeTurnSpring(inertia, mass, world_.settings.gravity.norm(), settings);
  return true;
}

bool Simulator::StartRotateDrag(int id, const DragSpringSettings& settings) {
  if (auto error = CheckDragSpringSettings(settings)) throw std::invalid_argument(*error);
  if (!CanGrab(id)) return false;
  DragState drag;
  if (!TurnSpringOf(id, settings, &drag)) return false;
  EndDrag();
  drag.active = true;
  drag.rotating = true;
  drag.body = id;
  drag.target_rotation = bodies_.GetPose(bodies_[id]).linear();
  drag.settings = settings;
  drag_ = drag;
  for (int shared : SharingBody(id)) bodies_[shared].dragged = true;
  BodyChanged(id, kForceApplied);
  return true;
}

void Simulator::SetDragTargetOrientation(const Mat3& rotation) {
  if (!rotation.allFinite() || !IsRotation(rotation)) {
    throw std::invalid_argument("a drag target orientation must be a rotation matrix");
  }
  if (!drag_.active || !drag_.rotating) return;
  drag_.target_rotation = rotation;
  BodyChanged(drag_.body, kForceApplied);
}

// the angular motor that turns the body: three world axes, each a bilateral stop at the
// displacement's component with the spring's k and c as stop ERP/CFM (interaction.h)
void Simulator::AddTurnJoint(double step) {
  const BodyRecord& body = bodies_[drag_.body];
  const Vec3 turn = CappedTurn(bodies_.GetPose(body).linear(), drag_.target_rotation, kMaxDragTurn);
  const Vec3 omega = ToVec3(dBodyGetAngularVel(body.body));
  const double scale = TurnScale(drag_.turn_spring, turn, omega, step);
  const double k = scale * drag_.turn_spring.stiffness;
  const double c = scale * drag_.turn_spring.damping;
  dJointID joint = dJointCreateAMotor(ode_world_.get(), contact_group_.get());
  dJointAttach(joint, body.body, nullptr);
  dJointSetAMotorMode(joint, dAMotorUser);
  dJointSetAMotorNumAxes(joint, 3);
  for (int i = 0; i < 3; ++i) {
    SetTurnRow(joint, i, turn[i], step * k / (step * k + c), 1.0 / (step * k + c));
  }
  dJointSetFeedback(joint, &drag_joint_->feedback);
  drag_joint_->attached = true;
}

// after a rebuild the grabbed body's mass may be another: the spring follows it
void Simulator::RescaleDrag() {
  if (drag_.rotating) {
    if (!TurnSpringOf(drag_.body, drag_.settings, &drag_)) {
      EndDrag();
      return;
    }
    for (int shared : SharingBody(drag_.body)) bodies_[shared].dragged = true;
    return;
  }
  const BodyRecord& body = bodies_[drag_.body];
  const double mass = EffectiveMassAt(drag_.body, bodies_.GetPose(body) * drag_.local_point);
  if (!(mass > 0.0) || !std::isfinite(mass)) {
    EndDrag();
    return;
  }
  drag_.effective_mass = mass;
  drag_.spring = MakeDragSpring(mass, world_.settings.gravity.norm(), drag_.settings);
  for (int shared : SharingBody(drag_.body)) bodies_[shared].dragged = true;
}

// the ball joint from the grabbed point to the (capped) target for a step of h, its k and c
// scaled to keep the force under the cap (interaction.h)
void Simulator::AddDragJoint(double step) {
  drag_joint_->attached = false;
  if (!drag_.active) return;
  const BodyRecord& body = bodies_[drag_.body];
  if (!body.moves_freely() || !dBodyIsEnabled(body.body)) return;
  if (drag_.rotating) {
    AddTurnJoint(step);
    return;
  }
  const Vec3 point = bodies_.GetPose(body) * drag_.local_point;
  const Vec3 target = CapStretch(point, drag_.target, drag_.settings.max_stretch);
  dVector3 velocity;
  dBodyGetPointVel(body.body, point.x(), point.y(), point.z(), velocity);
  const double scale =
      DragScale(drag_.spring, target - point, ToVec3(velocity), world_.settings.gravity, step);
  const double k = scale * drag_.spring.stiffness;
  const double c = scale * drag_.spring.damping;
  dJointID joint = dJointCreateBall(ode_world_.get(), contact_group_.get());
  dJointAttach(joint, body.body, nullptr);
  dJointSetBallAnchor(joint, point.x(), point.y(), point.z());
  dJointSetBallAnchor2(joint, target.x(), target.y(), target.z());
  dJointSetBallParam(joint, dParamERP, step * k / (step * k + c));
  dJointSetBallParam(joint, dParamCFM, 1.0 / (step * k + c));
  dJointSetFeedback(joint, &drag_joint_->feedback);
  drag_joint_->attached = true;
}

// ---- kinematic targets ------------------------------------------------------------------

bool Simulator::SetKinematicTarget(int id, const Pose& target, double duration) {
  if (!target.matrix().allFinite() || !IsRotation(target.linear()) || !std::isfinite(duration) ||
      duration < 0.0) {
    throw std::invalid_argument("a kinematic target needs a rigid pose and duration >= 0");
  }
  BodyRecord& body = RequireBody(id);
  if (body.body == nullptr || !body.enabled) return false;
  const bool first = targets_.count(id) == 0;
  KinematicTarget& move = targets_[id];
  if (first) move.was_dynamic = body.dynamic;
  if (body.dynamic) SetBodyDynamic(id, false);
  const double time = std::max(duration, world_.settings.timestep);
  const Pose now = bodies_.GetPose(body);
  move.target = target;
  move.duration = time;
  move.remaining = time;
  move.standing = 0.0;
  move.com_velocity = (target * body.com - now * body.com) / time;
  move.angular_velocity = RotationBetween(now.linear(), target.linear()) / time;
  return true;
}

void Simulator::ReleaseKinematicTarget(int id) {
  const auto found = targets_.find(id);
  if (found == targets_.end()) return;
  const KinematicTarget move = found->second;
  targets_.erase(found);
  BodyRecord& body = RequireBody(id);
  if (move.was_dynamic) SetBodyDynamic(id, true);
  // thrown with the velocity of its last move, unless it has stood still longer than that took;
  // a body that was kinematic before stays so, standing
  const bool moving = move.was_dynamic && move.standing <= move.duration;
  const Vec3 linear = moving ? move.com_velocity : Vec3::Zero();
  const Vec3 angular = moving ? move.angular_velocity : Vec3::Zero();
  dBodySetLinearVel(body.body, linear.x(), linear.y(), linear.z());
  dBodySetAngularVel(body.body, angular.x(), angular.y(), angular.z());
  BodyChanged(id, kVelocityChanged);
}

// each moving target's body gets the velocity of its move for this step, or in the step that
// ends the move the one that lands exactly on the target; an arrived body stands
void Simulator::MoveKinematicTargets(double step) {
  for (auto& [id, move] : targets_) {
    const BodyRecord& body = bodies_[id];
    Vec3 linear = Vec3::Zero(), angular = Vec3::Zero();
    if (move.remaining > step * (1 + 1e-9)) {
      linear = move.com_velocity;
      angular = move.angular_velocity;
    } else if (move.remaining > 0.0) {
      const Pose now = bodies_.GetPose(body);
      linear = (move.target * body.com - now * body.com) / step;
      angular = RotationBetween(now.linear(), move.target.linear()) / step;
    }
    dBodySetLinearVel(body.body, linear.x(), linear.y(), linear.z());
    dBodySetAngularVel(body.body, angular.x(), angular.y(), angular.z());
  }
}

void Simulator::AcceptInteraction(double step) {
  for (auto& [id, move] : targets_) {
    if (move.remaining == 0.0) move.standing += step;
    move.remaining = std::max(0.0, move.remaining - step);
  }
  if (!drag_.active || !drag_joint_->attached) return;
  if (drag_.rotating) {
    drag_.torque = ToVec3(drag_joint_->feedback.t1);
  } else {
    drag_.force = ToVec3(drag_joint_->feedback.f1);
  }
}

void Simulator::ClearInteraction() {
  for (const auto& [id, move] : targets_) {
    if (move.was_dynamic) SetBodyDynamic(id, true);
  }
  targets_.clear();
  EndDrag();
  ClearAppliedWrenches();
}

}  // namespace lamina::core
