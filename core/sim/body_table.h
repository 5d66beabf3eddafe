// SPDX-License-Identifier: MIT
// The simulator's bodies by Klamp't world id (terrains, rigid objects, robots and their links):
// what each id is, its ODE body (if it moves), its collision geometry and padded bounds, its
// mass, the forces applied to it, and the conversions between its frame and ODE's centre of mass.
//
// Frames: a record's frame is the object or link frame; ODE holds the carrying body at its centre
// of mass, `com` (in the record's frame) away, with axes rotated by `rotation_in_body` (a link
// welded into its parent's body). Velocities are of the record frame's origin, world axes.
// What a change of a body invalidates elsewhere (contacts, energies, anchors, sleep) is decided by
// BodyChangeEffects (body_change.h), not here.
#pragma once

#include <memory>
#include <vector>

#include "core/contact/collision_geometry.h"
#include "core/math_types.h"
#include "core/model/world_desc.h"
#include "core/sim/friction_anchor.h"
#include "core/sim/ode_fwd.h"

namespace lamina::core {

/// A force that lasts until it is changed or cleared, whatever the Simulate chunking (MuJoCo's
/// xfrc_applied): at the centre of mass with a torque, or at a point fixed in the body.
struct HeldWrench {
  Vec3 force = Vec3::Zero();        ///< N, world
  Vec3 torque = Vec3::Zero();       ///< N·m, world (besides the force's own moment)
  Vec3 local_point = Vec3::Zero();  ///< where the force acts, body frame (at_point)
  bool at_point = false;            ///< false: the force acts at the centre of mass
  bool active = false;
};

struct BodyRecord {
  WorldId::Kind kind = WorldId::Kind::kInvalid;
  int index = -1;          ///< terrain, object or robot index
  int link = -1;           ///< robot links
  dxBody* body = nullptr;  ///< null for static bodies (terrains, fixed bases) and ids without one
  bool owns_body = true;   ///< false for a link merged into its parent's body
  Mat3 rotation_in_body = Mat3::Identity();  ///< this record's frame in the ODE body's axes
  Pose fixed_pose = Pose::Identity();        ///< frame of a static body (no ODE body)
  std::shared_ptr<const CollisionGeometry> geometry;
  Vec3 com = Vec3::Zero();  ///< the ODE body's centre of mass in this record's frame
  double mass = 0.0;
  Mat3 inertia = Mat3::Zero();  ///< about the COM, body axes
  bool enabled = true;
  bool dynamic = true;         ///< false: kinematic
  Vec3 force = Vec3::Zero();   ///< world, at the COM, for the sub-steps of the next Simulate
  Vec3 torque = Vec3::Zero();  ///< world
  HeldWrench held;             ///< lasts across Simulate calls
  bool dragged = false;        ///< held by the mouse spring (kept awake, out of the energy check)
  Eigen::AlignedBox3d bounds;  ///< padded world bounds
  double energy = -1.0;        ///< kinetic energy after the last accepted step; < 0 unknown
  /// moved freely and awake in the last accepted step: took gravity's kick (gravity_kick.h)
  bool kicked = false;

  bool moves_freely() const { return body != nullptr && enabled && dynamic; }
  bool is_object() const { return kind == WorldId::Kind::kRigidObject; }
};

class BodyTable {
 public:
  void Reset(int count);
  int size() const { return static_cast<int>(records_.size()); }
  BodyRecord& operator[](int id) { return records_[id]; }
  const BodyRecord& operator[](int id) const { return records_[id]; }
  /// The record of `id`, or null for an id out of range.
  BodyRecord* Find(int id);
  const BodyRecord* Find(int id) const;
  std::vector<BodyRecord>::iterator begin() { return records_.begin(); }
  std::vector<BodyRecord>::iterator end() { return records_.end(); }
  std::vector<BodyRecord>::const_iterator begin() const { return records_.begin(); }
  std::vector<BodyRecord>::const_iterator end() const { return records_.end(); }

  /// World ids of the rigid objects, by object index.
  const std::vector<int>& object_ids() const { return object_ids_; }
  void AddObject(int id) { object_ids_.push_back(id); }

  /// The record's frame in the world (static bodies: their fixed pose).
  Pose GetPose(const BodyRecord& body) const;
  /// Places the carrying ODE body so that the record's frame is at `pose` (static: nothing).
  void SetPose(const BodyRecord& body, const Pose& pose) const;
  Twist GetVelocity(const BodyRecord& body) const;
  void SetVelocity(const BodyRecord& body, const Twist& velocity) const;
  /// The ODE body's frame (at the centre of mass); identity for a static body.
  BodyFrame FrameOf(int id) const;
  /// ½ m v² + ½ ωᵀ I ω of the ODE body (J).
  double KineticEnergy(const BodyRecord& body) const;
  /// Every ODE body's position and velocities are finite.
  bool StateIsFinite() const;
  /// The world ids of the bodies whose position or velocities are not finite (for a merged
  /// link: the link that owns the ODE body).
  std::vector<int> NonFiniteBodies() const;
  /// Adds this step's forces to the ODE bodies: the one-call forces and the held wrenches of
  /// every awake, freely moving body.
  void ApplyForces() const;
  /// Sets every record's `kicked` from whether its body moves freely and is awake now.
  void MarkKicked();
  /// Adds −m·`extra` to each body that moves freely and is awake now but was not kicked in the
  /// last step: gravity's scaled kick (gravity_kick.h) starts from the plain one there.
  void CancelExtraKick(const Vec3& extra) const;
  /// The one-call forces end (Simulate calls this at the end of every call).
  void ClearCallForces();
  /// The torque of body's held wrench about its centre of mass (its own torque plus the moment
  /// of a force held at a point), N·m, world.
  Vec3 HeldTorque(const BodyRecord& body) const;

 private:
  std::vector<BodyRecord> records_;
  std::vector<int> object_ids_;
};

}  // namespace lamina::core
