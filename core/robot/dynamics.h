// SPDX-License-Identifier: MIT
// Static dynamics of a RobotDesc: gravitational potential energy and the joint efforts that hold
// a configuration against gravity (the gradient of that energy).
#pragma once

#include "core/math_types.h"
#include "core/model/world_desc.h"

namespace lamina::core {

/// Gravitational potential energy −Σ_k m_k g·p_com_k (J) at configuration q (one entry per link),
/// for gravity `gravity` (m/s², e.g. (0, 0, −9.8)). Throws std::invalid_argument on a wrong size.
double PotentialEnergy(const RobotDesc& robot, const VecX& q, const Vec3& gravity);

/// The joint efforts (N·m for revolute, N for prismatic links) that balance gravity at q:
/// τ_i = −Σ_{k in subtree(i)} m_k g·∂p_com_k/∂q_i, the gradient of PotentialEnergy. One entry
/// per link. Throws std::invalid_argument on a wrong size.
VecX GravityTorques(const RobotDesc& robot, const VecX& q, const Vec3& gravity);

}  // namespace lamina::core
