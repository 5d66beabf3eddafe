// SPDX-License-Identifier: MIT
// What the mouse tools call: a spring that pulls a grabbed point towards a target, and kinematic
// targets that move a body along with the mouse. The pure parts are here; the simulator applies
// them every physics step (simulator_interaction.cpp), so nothing depends on how Simulate is
// chunked.
//
// The mouse spring is solved implicitly by ODE, not applied as an explicit force: a ball joint
// between the grabbed point and the target with the spring's stiffness k and damping c as its
// ERP = h k / (h k + c) and CFM = 1 / (h k + c) (the ODE manual's spring-damper), so a stiff
// spring on a light link cannot blow up. The other end is the target point, fixed in the world
// during a step (ODE's ball joint to the static world, its second anchor moved by the caller: the
// kinematic anchor). Damping acts on the grabbed point's world velocity, as in MuJoCo, Gazebo and
// Drake. The spring is scaled by the effective mass at the grabbed point, m = 3 / trace(J M⁻¹ Jᵀ)
// (MuJoCo's mjv_initPerturb; J the point's Jacobian), so that a finger link and a torso, a 0.1 kg
// and a 100 kg box, respond alike: k = m (2π f)², c = 2 ζ m (2π f), critically damped by default
// (MuJoCo's √k·m is ζ = 0.5 and Gazebo's translation ζ = 0.25 for all that their docs say). The
// pull is capped twice: the target is held at most max_stretch from the point (Drake's
// displacement cap, against tunnelling when the cursor is flung away), and the force at
// max_force_per_weight m |g|: before each step k and c are scaled so that the implicit force
// bound k |e| + (k h + c) |v + h g| stays under the cap (DragScale). For a body moved only by the
// spring, gravity and passive contacts the force then never exceeds the cap (the implicit
// response to an SPD effective mass only shrinks it). Klamp't's SimTest uses a fixed 10 N/m
// spring with no damping (a 10 kg link barely moves while a 50 g object oscillates).
//
// The turn drag (MuJoCo simulate's Ctrl+drag rotate) is the mouse spring's rotational
// counterpart: a spring that turns the grabbed body towards a target orientation R_t with the
// torque τ = k_r θ â − c_r ω (θ â = log(R_t Rᵀ), the angular displacement from the body's frame R
// to the target, world; ω its angular velocity). It is implicit too: an ODE angular motor in user
// mode with three world axes, each a bilateral stop at angle −θ âᵢ whose stop ERP/CFM are k_r and
// c_r as above, so ODE solves τ = k_r θ â − (k_r h + c_r) ω⁺ against the body's full inertia.
// k_r = I (2π f)², c_r = 2 ζ I (2π f) with I the rotational effective inertia, MuJoCo's
// 1 / body_invweight0[rot] made like the effective mass: I = 3 / trace(J_ω M⁻¹ J_ωᵀ) (J_ω the
// body's angular Jacobian), i.e. 3 / trace(I_com⁻¹) for a free body (independent of its
// orientation, so it is computed once per grab) and the articulated value for a robot link (3x
// the inertia about the hinge for a link turned by one revolute joint, as for the effective mass).
// About a principal axis with inertia I_a the turn then has natural frequency f √(I / I_a): exact
// for a body with equal principal inertias. Two caps, as for the point: the displacement is held
// within kMaxDragTurn = π/2 of the body (past π the logarithm's axis flips, so a target dragged
// beyond half a turn would turn the body back the other way), and the torque at
// max_force_per_weight m |g| √(I / m) = max_force_per_weight |g| √(m I) (the force cap acting at
// the radius of gyration): before each step k_r and c_r are scaled so that the implicit torque
// bound k_r |θ| + (k_r h + c_r) |ω| stays under it (TurnScale). For a free body turned only by the
// spring (no contacts) the torque then never exceeds the cap. MuJoCo applies its rotational
// perturbation as an explicit torque; Klamp't has none.
//
// A kinematic target (Box2D's b2Body_SetTargetTransform) makes a body kinematic and gives it the
// constant velocity that reaches the target frame after the given time, landing exactly on it in
// the step that ends the move; a kinematic body pushes what it meets as if it had infinite mass
// and carries what rests on it by friction (its friction anchors stay: nothing teleports). On
// release it becomes dynamic with the velocity it last moved at, so a throw works (unless it has
// stood still on its target for longer than its last move took: then it is released at rest).
#pragma once

#include <optional>
#include <string>

#include "core/math_types.h"
#include "core/model/world_desc.h"
#include "core/sim/ode_fwd.h"

namespace lamina::core {

struct DragSpringSettings {
  double frequency = 5.0;              ///< Hz: natural frequency of the grabbed point on its mass
  double damping_ratio = 1.0;          ///< 1: critically damped
  double max_force_per_weight = 20.0;  ///< force cap in multiples of m_eff |g| (g = 9.81 if 0)
  double max_stretch = 0.5;            ///< m: farthest the target is held from the grabbed point
};

/// None when every field is finite and positive (the damping ratio may be 0); otherwise what is
/// wrong.
std::optional<std::string> CheckDragSpringSettings(const DragSpringSettings& settings);

/// The spring of a grab with effective mass `mass` (kg): stiffness (N/m), damping (N·s/m) and
/// force cap (N) for gravity magnitude `gravity` (m/s²).
struct DragSpring {
  double stiffness = 0.0;
  double damping = 0.0;
  double max_force = 0.0;
};
DragSpring MakeDragSpring(double mass, double gravity, const DragSpringSettings& settings);

/// The scale (<= 1) of k and c for one step of `h` s that keeps the implicit force bound
/// k |stretch| + (k h + c) |velocity + h gravity| under the cap. `stretch` is target − point
/// (already capped), `velocity` the point's (m/s).
double DragScale(const DragSpring& spring, const Vec3& stretch, const Vec3& velocity,
                 const Vec3& gravity, double h);

/// `target` moved towards `point` so that it is at most `max_stretch` away.
Vec3 CapStretch(const Vec3& point, const Vec3& target, double max_stretch);

/// MuJoCo's effective mass of a free rigid body at a point `r` (world) from its centre of mass:
/// 3 / trace(I/m + [r]× I⁻¹ [r]×ᵀ), `inertia` about the COM in world axes.
double RigidEffectiveMass(double mass, const Mat3& inertia, const Vec3& r);

/// The largest angular displacement the turn drag's spring is given (rad).
inline constexpr double kMaxDragTurn = kPi / 2;

/// The rotational spring of a turn drag: stiffness (N·m/rad), damping (N·m·s/rad) and torque
/// cap (N·m).
struct TurnSpring {
  double stiffness = 0.0;
  double damping = 0.0;
  double max_torque = 0.0;
};
/// The turn spring of a body of mass `mass` (kg) and rotational effective inertia `inertia`
/// (kg·m²) for gravity magnitude `gravity` (m/s², 9.81 if 0): k_r = I (2π f)²,
/// c_r = 2 ζ I (2π f), cap max_force_per_weight |g| √(m I).
TurnSpring MakeTurnSpring(double inertia, double mass, double gravity,
                          const DragSpringSettings& settings);
/// The scale (<= 1) of k_r and c_r for a step of `h` s that keeps k_r |turn| + (k_r h + c_r) |ω|
/// under the cap; `turn` is θ â (rad, capped), `angular_velocity` ω (rad/s).
double TurnScale(const TurnSpring& spring, const Vec3& turn, const Vec3& angular_velocity,
                 double h);
/// θ â = log(to fromᵀ) (rad, world), shortened to at most `max_turn`.
Vec3 CappedTurn(const Mat3& from, const Mat3& to, double max_turn);
/// The rotational effective inertia of a free rigid body, 3 / trace(I⁻¹), `inertia` about its
/// centre of mass (any axes: the trace does not depend on them).
double RigidEffectiveInertia(const Mat3& inertia);

/// A grab in progress (Simulator::StartDrag, or StartRotateDrag for a turn drag).
struct DragState {
  bool active = false;
  int body = -1;                    ///< world id of the grabbed object or link
  Vec3 local_point = Vec3::Zero();  ///< grabbed point in the body's frame
  Vec3 target = Vec3::Zero();       ///< world, as last set
  double effective_mass = 0.0;      ///< kg at the grabbed point
  DragSpringSettings settings;
  DragSpring spring;
  Vec3 force = Vec3::Zero();  ///< on the body in the last step (N, world); 0 for a turn drag
  bool rotating = false;      ///< a turn drag: the rotational spring instead of the point's
  Mat3 target_rotation = Mat3::Identity();  ///< the body frame's target orientation, world
  double effective_inertia = 0.0;           ///< kg·m², rotational (turn drag)
  TurnSpring turn_spring;
  Vec3 torque = Vec3::Zero();  ///< of the turn spring on the body in the last step (N·m, world)
};

/// The ODE side of the mouse spring (its force readout), kept out of this header.
struct OdeDragJoint;
OdeDragJoint* NewOdeDragJoint();
void DeleteOdeDragJoint(OdeDragJoint* joint);

/// A body moving to a kinematic target (Simulator::SetKinematicTarget).
struct KinematicTarget {
  Pose target = Pose::Identity();        ///< the body frame's goal in the world
  double duration = 0.0;                 ///< s the move was given
  double remaining = 0.0;                ///< s of simulated time left to reach it (0: arrived)
  double standing = 0.0;                 ///< s since it arrived
  Vec3 com_velocity = Vec3::Zero();      ///< the move's constant velocity of the COM (m/s)
  Vec3 angular_velocity = Vec3::Zero();  ///< rad/s, world
  bool was_dynamic = true;               ///< restored on release
};

}  // namespace lamina::core
