// SPDX-License-Identifier: MIT
// Sleeping rigid objects (SimSettings::sleeping, off by default as in ODE, Klamp't and MuJoCo): an
// object idle (slower than sleepSpeed, linear m/s and angular rad/s) for sleepTime, together with
// every free object it touches (its island), leaves the steps until something wakes it.
//
// Rules (one place each):
// - KeepsTouchedAwake: an awake dynamic object, a robot link, or a kinematic body that moves at
//   all keeps what it touches awake; static, disabled and sleeping bodies and standing kinematic
//   ones do not;
// - a sleeper touched by something that keeps it awake wakes, and so does everything asleep that
//   touches it (WakeTouchedSleepers, before a step); its idle time stays, so the island can fall
//   asleep again together;
// - no contact joint ties a sleeper to something inert (ODE would enable it through the joint);
// - an island sleeps when all its members are ready: idle long enough, not pushed by an applied
//   force, a held wrench or the mouse spring, not touching a robot or a moving kinematic body
//   (IslandsReady, pure);
// - Wake (a setter, a force or an edit reached the body) and WakeTouching (the body moved,
//   reshaped or went away: what sleeps on it may have lost its support) come from the simulator's
//   one change rule (body_change.h).
// A sleeper's ODE body is disabled with zero velocity and no force. Sleep is part of SimState.
#pragma once

#include <utility>
#include <vector>

#include "core/sim/body_table.h"
#include "core/sim/contact_set.h"
#include "core/sim/sim_state.h"

namespace lamina::core {

/// Union-find over `count` objects joined by `links` (object index pairs): ready[i] stays set only
/// when every object of i's island is ready. `parent` is scratch.
void IslandsReady(int count, const std::vector<std::pair<int, int>>& links,
                  std::vector<char>* ready, std::vector<int>* parent);

class SleepTracker {
 public:
  /// One idle, awake state per object.
  void Reset(int objects) { states_.assign(objects, ObjectSleep{}); }
  const std::vector<ObjectSleep>& states() const { return states_; }
  bool asleep(int object) const;
  int asleep_count() const;

  /// Restores `states` (from a SimState); with `usable` false (sleeping off, or a state of
  /// another size) everything wakes instead.
  void Restore(BodyTable* bodies, const std::vector<ObjectSleep>& states, bool usable);
  void WakeAll(BodyTable* bodies);
  /// A setter, an applied force or an edit reached body `id`.
  void Wake(BodyTable* bodies, int id);
  /// Body `id` moved, changed shape or went away: what sleeps against it wakes.
  void WakeTouching(BodyTable* bodies, const std::vector<ContactPair>& pairs, int id);
  /// Before a step (rules above).
  void WakeTouchedSleepers(BodyTable* bodies, const std::vector<ContactPair>& pairs);
  /// A pair of a sleeper and something that cannot wake it: it gets no contact joint.
  bool SleepsAgainstInert(const BodyTable& bodies, const ContactPair& pair) const;
  /// After an accepted step of `step` s: idle times, then the islands that are ready sleep.
  void Update(BodyTable* bodies, const std::vector<ContactPair>& pairs, double step,
              double sleep_speed, double sleep_time);

 private:
  bool KeepsTouchedAwake(const BodyRecord& body) const;
  bool ObjectAsleep(const BodyRecord& body) const;
  void SetAsleep(BodyTable* bodies, int object, bool asleep);
  void UpdateIdleTimes(BodyTable* bodies, double step, double sleep_speed);
  void MarkReady(const BodyTable& bodies, const std::vector<ContactPair>& pairs, double sleep_time);

  std::vector<ObjectSleep> states_;  ///< per rigid object
  std::vector<char> ready_;          ///< scratch of Update
  std::vector<int> parent_;          ///< scratch of Update
  std::vector<std::pair<int, int>> links_;
};

}  // namespace lamina::core
