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

/// A grab in progress (Simulator::StartDrag).
struct DragState {
  bool active = false;
  int body = -1;                    ///< world id of the grabbed object or link
  Vec3 local_point = Vec3::Zero();  ///< grabbed point in the body's frame
  Vec3 target = Vec3::Zero();       ///< world, as last set
  double effective_mass = 0.0;      ///< kg at the grabbed point
  DragSpringSettings settings;
  DragSpring spring;
  Vec3 force = Vec3::Zero();  ///< on the body in the last step (N, world)
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
