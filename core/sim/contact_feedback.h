// SPDX-License-Identifier: MIT
// Contact feedback between two bodies: which contacts acted, with what forces, over the sub-steps
// of the last Simulate call. Recorded only for pairs that asked for it.
//
// Sign convention (one for everything): a record belongs to the pair (first, second) with
// first < second (world ids). Normals point into `first` and forces are the forces ON `first`
// (exerted by `second`). Queries for (a, b) with a > b swap the roles: normals and forces are
// negated, so asking for (b, a) gives exactly the negatives of (a, b).
#pragma once

#include <vector>

#include "core/contact/contact.h"
#include "core/math_types.h"
#include "core/sim/ode_fwd.h"

namespace lamina::core {

/// One contact that acted during a sub-step.
struct FeedbackContact {
  Vec3 position = Vec3::Zero();  ///< world, m
  Vec3 normal = Vec3::UnitZ();   ///< unit, into the record's first body
  double friction = 0.0;         ///< blended Coulomb friction coefficient
  Vec3 force = Vec3::Zero();     ///< on the first body, N, world
  bool penetrating = false;      ///< the underlying geometries interpenetrate here
};

/// What the pair did during the sub-steps of the last Simulate call.
struct ContactFeedbackRecord {
  int first = -1;                         ///< world id, first < second
  int second = -1;                        ///< world id
  std::vector<FeedbackContact> contacts;  ///< the last sub-step's contacts and forces
  bool in_contact = false;                ///< contacts acted in the last sub-step
  int contact_steps = 0;                  ///< sub-steps with contact, last Simulate call
  int separation_steps = 0;               ///< sub-steps without contact, last Simulate call
  int penetration_steps = 0;              ///< sub-steps with interpenetration, last call
  Vec3 mean_force = Vec3::Zero();         ///< on first, averaged over the call's time (N)
  Vec3 mean_torque = Vec3::Zero();        ///< on first about the world origin, time average (N·m)
  double accumulated_time = 0.0;          ///< s of sub-steps averaged so far in this call

  /// Forgets the last call (Simulate starts every call with this).
  void BeginCall();
  /// Adds one accepted sub-step of length `step` whose contacts were `contacts`.
  void AddSubStep(double step, const std::vector<FeedbackContact>& step_contacts);
  /// Sum of the last sub-step's forces on first (N).
  Vec3 LastForce() const;
  /// Sum of the last sub-step's torques on first about the world origin (N·m).
  Vec3 LastTorque() const;
};

/// The contact feedback of a simulation: the records of the pairs that asked for it (sorted by
/// (first, second)), and ODE's force readout of this step's contact joints, turned into the
/// records' contacts after every accepted step. ForEach visits records without allocating.
class FeedbackRecorder {
 public:
  bool empty() const { return records_.empty(); }
  const std::vector<ContactFeedbackRecord>& records() const { return records_; }
  /// Starts recording the pair (a, b) (a != b; nothing when it is recorded already).
  void Enable(int a, int b);
  /// The record of the pair (a, b) in either order, or null.
  const ContactFeedbackRecord* Find(int a, int b) const;
  /// Every record forgets the last Simulate call.
  void BeginCall();
  /// Puts back records saved from records() (the accuracy meter's probe steps record nothing);
  /// the pairs must be the same.
  void RestoreRecords(std::vector<ContactFeedbackRecord> records) { records_ = std::move(records); }

  FeedbackRecorder();
  ~FeedbackRecorder();
  FeedbackRecorder(FeedbackRecorder&&) noexcept;
  FeedbackRecorder& operator=(FeedbackRecorder&&) noexcept;
  /// ODE's readout of one contact joint of the current step (contact_feedback.cpp).
  struct Slot;
  /// Before a step's joints are made: `contacts` slots at most (joints point into them, so they
  /// must not move while the step is built).
  void ReserveSlots(size_t contacts);
  /// A slot for a new contact joint of `pair`'s `contact` under `record` (Find's result); a
  /// null `joint` is one the Newton solver keeps (it fills Feedback(slot, false)).
  Slot* Attach(dxJoint* joint, const ContactFeedbackRecord& record, int joint_first_body,
               const Contact& contact, double friction);
  /// The slot's force record of its joint (`core`: of its rigid-core joint, which it then has).
  static dJointFeedback* Feedback(Slot* slot, bool core);
  /// The rigid-core joint of a soft contact reports into the same slot.
  static void AttachCore(Slot* slot, dxJoint* core_joint);
  /// After the step: the slots' forces become the records' last sub-step of length `step`.
  void RecordStep(double step);

  /// Calls f(record, sign) for every record touching a (and b, unless b < 0); sign is +1 when a is
  /// the record's first body (its forces are on a), -1 otherwise.
  template <typename F>
  void ForEach(int a, int b, const F& f) const {
    for (const ContactFeedbackRecord& r : records_) {
      const bool touches_a = r.first == a || r.second == a;
      if (touches_a && (b < 0 || r.first == b || r.second == b)) f(r, r.first == a ? 1.0 : -1.0);
    }
  }

 private:
  std::vector<ContactFeedbackRecord> records_;
  std::vector<std::vector<FeedbackContact>> step_contacts_;  ///< per record, one step
  std::vector<Slot> slots_;
  size_t used_slots_ = 0;
};

}  // namespace lamina::core
