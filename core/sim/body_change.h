// SPDX-License-Identifier: MIT
// The one rule for what a change of a body invalidates and wakes. Every setter of the simulator
// says what it changed (Simulator::BodyChanged(id, changes)); this table alone decides the rest,
// so that two setters that make the same change (a teleport by SetRobotConfig and by
// FakeSimulate, a pose set through SimBody and through an object index) can never disagree.
//
// | change    | contacts stale | energy forgotten | anchors dropped | wake body | wake touching |
// |-----------|:--:|:--:|:--:|:--:|:--:|
// | pose      | x | x | x | x | x |
// | velocity  |   | x |   | x |   |
// | shape     | x |   |   | x | x |
// | surface   |   |   |   | x | x |
// | enabled   | x | x |   | x |   |
// | disabled  | x | x |   |   | x |
// | kind      | x | x |   | x | x |
// | force     |   |   |   | x |   |
//
// Contacts are cached between steps (one detection serves the rollback test and the next step),
// so anything that moves, reshapes or re-filters a body makes them stale. A body's energy is the
// baseline of the instability check: a set velocity or pose is not a blow-up. A friction anchor
// remembers where a pair stuck: a teleported body's drift means nothing. What slept on a body
// that moved, reshaped or went away may have lost its support.
#pragma once

namespace lamina::core {

enum BodyChange : unsigned {
  kPoseChanged = 1u << 0,      ///< moved by hand (teleport, SetState of one body, FK)
  kVelocityChanged = 1u << 1,  ///< velocity set by hand
  kShapeChanged = 1u << 2,     ///< geometry or padding rebuilt
  kSurfaceChanged = 1u << 3,   ///< friction, restitution, stiffness or damping
  kEnabled = 1u << 4,          ///< takes part again
  kDisabled = 1u << 5,         ///< frozen, out of contact
  kKindChanged = 1u << 6,      ///< dynamic <-> kinematic
  kForceApplied = 1u << 7,     ///< an applied force or wrench, or a gravity change
};

struct ChangeEffects {
  bool contacts_stale = false;
  bool forget_energy = false;
  bool drop_anchors = false;
  bool wake_body = false;
  bool wake_touching = false;
  bool operator==(const ChangeEffects&) const = default;
};

/// What `changes` (BodyChange bits) require; the union over the bits.
constexpr ChangeEffects BodyChangeEffects(unsigned changes) {
  const auto any = [changes](unsigned bits) { return (changes & bits) != 0; };
  ChangeEffects e;
  e.contacts_stale = any(kPoseChanged | kShapeChanged | kEnabled | kDisabled | kKindChanged);
  e.forget_energy = any(kPoseChanged | kVelocityChanged | kEnabled | kDisabled | kKindChanged);
  e.drop_anchors = any(kPoseChanged);
  e.wake_body = any(kPoseChanged | kVelocityChanged | kShapeChanged | kSurfaceChanged | kEnabled |
                    kKindChanged | kForceApplied);
  e.wake_touching = any(kPoseChanged | kShapeChanged | kSurfaceChanged | kDisabled | kKindChanged);
  return e;
}

}  // namespace lamina::core
