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

#include "core/math_types.h"

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

}  // namespace lamina::core
