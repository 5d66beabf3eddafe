// SPDX-License-Identifier: MIT
// Dynamics of a RobotDesc: gravitational potential energy, the joint efforts that hold a
// configuration against gravity (the gradient of that energy), the joint-space mass matrix and
// the effective mass at a point (what the mouse spring scales with).
#pragma once

#include <vector>

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

/// The joint-space mass matrix M(q) over the joints with free[i] set (one per link; a welded
/// link's joint does not move): M = Σ_k J_v,kᵀ m_k J_v,k + J_ω,kᵀ I_k J_ω,k, with J_v,k and J_ω,k
/// the Jacobians of link k's centre of mass and rotation over its ancestors' free joints
/// (revolute: axis a_i through the joint's origin; prismatic: a_i). Rows and columns of joints
/// that are not free are zero.
MatX MassMatrix(const RobotDesc& robot, const VecX& q, const std::vector<bool>& free);

/// MuJoCo's effective mass at `point` (world) of link `link`: 3 / trace(J M⁻¹ Jᵀ) with J the
/// point's Jacobian over the free joints. A point that no free joint moves has infinite
/// effective mass. (A point that only one joint moves has 3x its scalar inertia there: the
/// definition averages over the three directions, as MuJoCo does.)
double EffectiveMassAt(const RobotDesc& robot, const VecX& q, const std::vector<bool>& free,
                       int link, const Vec3& point);

/// The rotational counterpart (MuJoCo's 1 / body_invweight0[rot]): 3 / trace(J_ω M⁻¹ J_ωᵀ) with
/// J_ω link `link`'s angular Jacobian over the free joints (kg·m²). A link that no free revolute
/// joint turns has infinite effective inertia; one turned by a single hinge has 3x its inertia
/// about the hinge.
double EffectiveInertiaOf(const RobotDesc& robot, const VecX& q, const std::vector<bool>& free,
                          int link);

/// The inertia each free joint moves when every other free joint moves freely too: 1 / (M⁻¹)_ii
/// over the free joints (kg·m² for revolute, kg for prismatic links; the smallest inertia the
/// joint can meet, so the one a joint's explicit PD law must be stable for: explicit_pd.h);
/// infinite for a joint that is not free or moves no mass. One entry per link.
VecX JointInertias(const RobotDesc& robot, const VecX& q, const std::vector<bool>& free);

}  // namespace lamina::core
