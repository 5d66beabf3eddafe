// SPDX-License-Identifier: MIT
#include "core/sim/body_table.h"

#include <cmath>

#include <ode/ode.h>

#include "core/sim/energy_guard.h"
#include "core/sim/ode_conversions.h"

namespace lamina::core {

namespace {

void AddForceAndTorque(dBodyID body, const Vec3& force, const Vec3& torque) {
  if (!force.isZero(0.0)) dBodyAddForce(body, force.x(), force.y(), force.z());
  if (!torque.isZero(0.0)) dBodyAddTorque(body, torque.x(), torque.y(), torque.z());
}

}  // namespace

void BodyTable::Reset(int count) {
  records_.assign(count, BodyRecord{});
  object_ids_.clear();
}

BodyRecord* BodyTable::Find(int id) {
  return id >= 0 && id < size() ? &records_[id] : nullptr;
}

const BodyRecord* BodyTable::Find(int id) const {
  return id >= 0 && id < size() ? &records_[id] : nullptr;
}

Pose BodyTable::GetPose(const BodyRecord& body) const {
  if (body.body == nullptr) return body.fixed_pose;
  Pose pose = Pose::Identity();
  pose.linear() = ToMat3(dBodyGetRotation(body.body)) * body.rotation_in_body;
  pose.translation() = ToVec3(dBodyGetPosition(body.body)) - pose.linear() * body.com;
  return pose;
}

void BodyTable::SetPose(const BodyRecord& body, const Pose& pose) const {
  if (body.body == nullptr) return;
  const Vec3 com_world = pose * body.com;
  dBodySetPosition(body.body, com_world.x(), com_world.y(), com_world.z());
  SetBodyRotation(body.body, pose.linear() * body.rotation_in_body.transpose());
}

Twist BodyTable::GetVelocity(const BodyRecord& body) const {
  if (body.body == nullptr) return {};
  const Vec3 angular = ToVec3(dBodyGetAngularVel(body.body));
  const Vec3 com_offset = GetPose(body).linear() * body.com;
  // v_origin = v_com - w x (com - origin)
  return {ToVec3(dBodyGetLinearVel(body.body)) - angular.cross(com_offset), angular};
}

void BodyTable::SetVelocity(const BodyRecord& body, const Twist& velocity) const {
  if (body.body == nullptr) return;
  const Vec3 com_offset = GetPose(body).linear() * body.com;
  const Vec3 com_velocity = velocity.linear + velocity.angular.cross(com_offset);
  dBodySetLinearVel(body.body, com_velocity.x(), com_velocity.y(), com_velocity.z());
  dBodySetAngularVel(body.body, velocity.angular.x(), velocity.angular.y(), velocity.angular.z());
}

BodyFrame BodyTable::FrameOf(int id) const {
  const dBodyID body = records_[id].body;
  if (body == nullptr) return BodyFrame{};
  return BodyFrame{ToMat3(dBodyGetRotation(body)), ToVec3(dBodyGetPosition(body))};
}

double BodyTable::KineticEnergy(const BodyRecord& body) const {
  const Mat3 R = ToMat3(dBodyGetRotation(body.body));
  return core::KineticEnergy(body.mass, R * body.inertia * R.transpose(),
                             ToVec3(dBodyGetLinearVel(body.body)),
                             ToVec3(dBodyGetAngularVel(body.body)));
}

std::vector<int> BodyTable::NonFiniteBodies() const {
  std::vector<int> ids;
  for (int id = 0; id < size(); ++id) {
    const BodyRecord& body = records_[id];
    if (body.body == nullptr || !body.owns_body) continue;
    const Vec3 p = ToVec3(dBodyGetPosition(body.body));
    const Vec3 v = ToVec3(dBodyGetLinearVel(body.body));
    const Vec3 w = ToVec3(dBodyGetAngularVel(body.body));
    if (!p.allFinite() || !v.allFinite() || !w.allFinite()) ids.push_back(id);
  }
  return ids;
}

bool BodyTable::StateIsFinite() const {
  for (const BodyRecord& body : records_) {
    if (body.body == nullptr) continue;
    const dReal* p = dBodyGetPosition(body.body);
    const dReal* v = dBodyGetLinearVel(body.body);
    const dReal* w = dBodyGetAngularVel(body.body);
    for (int k = 0; k < 3; ++k) {
      if (!std::isfinite(p[k]) || !std::isfinite(v[k]) || !std::isfinite(w[k])) return false;
    }
  }
  return true;
}

void BodyTable::ApplyForces() const {
  for (const BodyRecord& body : records_) {
    if (!body.moves_freely() || !dBodyIsEnabled(body.body)) continue;  // asleep
    AddForceAndTorque(body.body, body.force, body.torque);
    if (body.held.active) AddForceAndTorque(body.body, body.held.force, HeldTorque(body));
  }
}

void BodyTable::MarkKicked() {
  for (BodyRecord& body : records_) {
    body.kicked = body.moves_freely() && dBodyIsEnabled(body.body);
  }
}

void BodyTable::CancelExtraKick(const Vec3& extra) const {
  for (const BodyRecord& body : records_) {
    if (!body.owns_body || body.kicked || !body.moves_freely()) continue;
    if (!dBodyIsEnabled(body.body) || dBodyGetGravityMode(body.body) == 0) continue;
    dMass mass;
    dBodyGetMass(body.body, &mass);
    AddForceAndTorque(body.body, -mass.mass * extra, Vec3::Zero());
  }
}

Vec3 BodyTable::HeldTorque(const BodyRecord& body) const {
  if (!body.held.active || body.body == nullptr) return Vec3::Zero();
  Vec3 torque = body.held.torque;
  if (body.held.at_point) {
    const Vec3 point = GetPose(body) * body.held.local_point;
    torque += (point - ToVec3(dBodyGetPosition(body.body))).cross(body.held.force);
  }
  return torque;
}

void BodyTable::ClearCallForces() {
  for (BodyRecord& body : records_) {
    body.force.setZero();
    body.torque.setZero();
  }
}

}  // namespace lamina::core
