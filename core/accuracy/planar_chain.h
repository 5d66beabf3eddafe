// SPDX-License-Identifier: MIT
// The reference answer of the linked-pendulum scenes (numerics §6 scene 2: double pendulum and
// 10-link chain): a planar chain of rigid links on parallel hinges, the first hung from a fixed
// pivot, integrated in its generalized coordinates (one angle per link) by classical RK4 at a
// fine fixed step. Lamina simulates the same chain in maximal coordinates (6 per body, hinges as
// constraints), so the two share no code or formulation: agreement is a cross-check.
//
// Link k has mass m_k, moment of inertia I_k about its centre of mass (about the hinge axis),
// its centre of mass c_k from its own hinge, and L_k from its hinge to the next link's hinge; the
// centre of mass lies on the line between the two hinges (for the last link: along its own
// direction). θ_k is the angle of link k from the down direction, positive towards
// side = axis × down (right-handed about the hinge axis). With ℓ_ki = L_i (i < k), c_k (i = k),
// 0 (i > k), and B_ij = Σ_{k ≥ max(i,j)} m_k·ℓ_ki·ℓ_kj, Lagrange's equations are
//   Σ_j (B_ij·cos(θ_i − θ_j) + δ_ij·I_i)·θ̈_j = −Σ_j B_ij·sin(θ_i − θ_j)·θ̇_j² − g·sin θ_i·Σ_k
//   m_k·ℓ_ki.
// Units: kg, m, s, rad.
#pragma once

#include <string>
#include <vector>

#include "core/math_types.h"
#include "core/model/world_desc.h"

namespace lamina::core {

struct PlanarLink {
  double mass = 0.0;     ///< kg
  double inertia = 0.0;  ///< about the centre of mass and the hinge axis, kg·m²
  double com = 0.0;      ///< c: hinge to centre of mass, m
  double length = 0.0;   ///< L: hinge to the next hinge, m (unused for the last link)
};

/// Angles and angular velocities of the links (rad, rad/s), one entry per link.
struct PlanarChainState {
  Eigen::VectorXd angle, rate;
};

/// What the equations above hold constant while the links are: B and the gravity levers.
struct PlanarChainConstants {
  Eigen::MatrixXd coupling;  ///< B (kg·m²)
  Eigen::VectorXd lever;     ///< per angle i, Σ_k m_k·ℓ_ki (kg·m)
};

struct PlanarChain {
  std::vector<PlanarLink> links;
  double g = 9.8;  ///< m/s²

  PlanarChainConstants Constants() const;
  /// θ̈ of the equations above.
  Eigen::VectorXd Accelerations(const PlanarChainState& state) const;
  /// The same with the constants computed once (Constants()).
  Eigen::VectorXd Accelerations(const PlanarChainState& state,
                                const PlanarChainConstants& constants) const;
  /// Kinetic plus potential energy (J; potential 0 at the pivot's height).
  double Energy(const PlanarChainState& state) const;
  /// The centres of mass in the plane, (down, side) coordinates from the pivot (m).
  std::vector<Eigen::Vector2d> Centres(const Eigen::VectorXd& angle) const;
};

/// A RK4 solution sampled at a fixed step; State(t) interpolates between samples by cubic
/// Hermite on the angles (error O(step⁴), like the integration).
class PlanarChainTrajectory {
 public:
  PlanarChainTrajectory(PlanarChain chain, const PlanarChainState& start, double duration,
                        double step);
  /// The state at time t ∈ [0, duration] (s); clamped outside.
  PlanarChainState State(double t) const;
  const PlanarChain& chain() const { return chain_; }

 private:
  PlanarChain chain_;
  PlanarChainConstants constants_;
  double step_;
  std::vector<PlanarChainState> samples_;
  std::vector<Eigen::VectorXd> accelerations_;
};

/// One RK4 step of `step` seconds (`constants`: chain.Constants()).
PlanarChainState Rk4Step(const PlanarChain& chain, const PlanarChainConstants& constants,
                         const PlanarChainState& state, double step);

/// A world's chain of hinges as a planar chain, with what maps it back to the world: the hinge
/// axis, the pivot, the plane's down and side directions and each centre's constant offset along
/// the axis.
struct WorldPlanarChain {
  PlanarChain chain;
  PlanarChainState start;
  Vec3 pivot = Vec3::Zero(), axis = Vec3::UnitY(), down = -Vec3::UnitZ(), side = Vec3::UnitX();
  std::vector<double> offsets;  ///< each centre of mass along the axis, m

  /// Centre of mass of link k (world, m) for the angles.
  std::vector<Vec3> Centres(const Eigen::VectorXd& angle) const;
};

/// Reads joint k as the hinge holding object k (and object k − 1 for k > 0; joint 0 holds object
/// 0 to the world); every hinge axis parallel, every link's centre on the line of its hinges.
/// Returns "" on success, otherwise what does not fit (e.g. "joint 1 is not a hinge").
std::string ReadPlanarChain(const WorldDesc& world, WorldPlanarChain* out);

}  // namespace lamina::core
