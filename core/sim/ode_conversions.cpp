// SPDX-License-Identifier: MIT
#include "core/sim/ode_conversions.h"

#include <algorithm>

namespace lamina::core {

void SetBodyRotation(dBodyID body, const Mat3& rotation) {
  const Eigen::Quaterniond q(rotation);
  const dQuaternion ode_q = {q.w(), q.x(), q.y(), q.z()};
  dBodySetQuaternion(body, ode_q);
}

BodyState ReadBodyState(dBodyID body) {
  const dReal* q = dBodyGetQuaternion(body);
  return {ToVec3(dBodyGetPosition(body)), Eigen::Quaterniond(q[0], q[1], q[2], q[3]),
          ToVec3(dBodyGetLinearVel(body)), ToVec3(dBodyGetAngularVel(body))};
}

void WriteBodyState(dBodyID body, const BodyState& state) {
  dBodySetPosition(body, state.com_position.x(), state.com_position.y(), state.com_position.z());
  const dQuaternion q = {state.orientation.w(), state.orientation.x(), state.orientation.y(),
                         state.orientation.z()};
  dBodySetQuaternion(body, q);
  // dBodySetQuaternion normalizes, which can change the last bit of a quaternion a step left
  // normalized: write ODE's own q exactly and derive its rotation as a step does (dQtoR)
  dReal* stored = const_cast<dReal*>(dBodyGetQuaternion(body));
  std::copy(q, q + 4, stored);
  dQtoR(stored, const_cast<dReal*>(dBodyGetRotation(body)));
  dBodySetLinearVel(body, state.linear_velocity.x(), state.linear_velocity.y(),
                    state.linear_velocity.z());
  dBodySetAngularVel(body, state.angular_velocity.x(), state.angular_velocity.y(),
                     state.angular_velocity.z());
}

}  // namespace lamina::core
