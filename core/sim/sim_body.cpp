// SPDX-License-Identifier: MIT
// SimBody: the per-body handle of a Simulator (declared in simulator.h, which it needs whole).
#include "core/sim/simulator.h"

namespace lamina::core {

bool SimBody::valid() const {
  const BodyRecord* body = simulator_->bodies_.Find(id_);
  return body != nullptr && body->kind != WorldId::Kind::kRobot;
}

void SimBody::Enable(bool enabled) {
  simulator_->SetBodyEnabled(id_, enabled);
}

bool SimBody::enabled() const {
  return simulator_->BodyEnabled(id_);
}

void SimBody::EnableDynamics(bool dynamic) {
  simulator_->SetBodyDynamic(id_, dynamic);
}

bool SimBody::dynamics_enabled() const {
  return simulator_->BodyDynamic(id_);
}

Pose SimBody::GetTransform() const {
  return simulator_->BodyPose(id_);
}

void SimBody::SetTransform(const Pose& pose) {
  simulator_->SetBodyPose(id_, pose);
}

Twist SimBody::GetVelocity() const {
  return simulator_->BodyVelocity(id_);
}

void SimBody::SetVelocity(const Twist& velocity) {
  simulator_->SetBodyVelocity(id_, velocity);
}

SurfaceDesc SimBody::GetSurface() const {
  simulator_->RequireBody(id_);
  return simulator_->sim_params(id_).surface;
}

void SimBody::SetSurface(const SurfaceDesc& surface) {
  simulator_->SetBodySurface(id_, surface);
}

double SimBody::GetPadding() const {
  simulator_->RequireBody(id_);
  return simulator_->sim_params(id_).padding;
}

void SimBody::SetPadding(double padding) {
  simulator_->SetBodyPadding(id_, padding);
}

void SimBody::ApplyForceAtPoint(const Vec3& force, const Vec3& point) {
  simulator_->AddBodyForce(id_, force, point);
}

void SimBody::ApplyForceAtLocalPoint(const Vec3& force, const Vec3& point) {
  simulator_->AddBodyForce(id_, force, GetTransform() * point);
}

void SimBody::ApplyWrench(const Vec3& force, const Vec3& torque) {
  simulator_->AddBodyWrench(id_, force, torque);
}

}  // namespace lamina::core
