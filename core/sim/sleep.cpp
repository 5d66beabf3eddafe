// SPDX-License-Identifier: MIT
#include "core/sim/sleep.h"

#include <algorithm>
#include <numeric>

#include <ode/ode.h>

#include "core/sim/ode_conversions.h"

namespace lamina::core {

namespace {

int IslandRoot(std::vector<int>& parent, int i) {
  while (parent[i] != i) {
    parent[i] = parent[parent[i]];
    i = parent[i];
  }
  return i;
}

double Speed(dxBody* body) {
  return std::max(ToVec3(dBodyGetLinearVel(body)).norm(), ToVec3(dBodyGetAngularVel(body)).norm());
}

bool Pushed(const BodyRecord& body) {
  return !body.force.isZero(0.0) || !body.torque.isZero(0.0) || body.held.active || body.dragged;
}

}  // namespace

void IslandsReady(int count, const std::vector<std::pair<int, int>>& links,
                  std::vector<char>* ready, std::vector<int>* parent) {
  parent->resize(count);
  std::iota(parent->begin(), parent->end(), 0);
  for (const auto& [a, b] : links) (*parent)[IslandRoot(*parent, a)] = IslandRoot(*parent, b);
  std::vector<char> island_ready(count, 1);
  for (int i = 0; i < count; ++i) {
    if (!(*ready)[i]) island_ready[IslandRoot(*parent, i)] = 0;
  }
  for (int i = 0; i < count; ++i) {
    (*ready)[i] = (*ready)[i] && island_ready[IslandRoot(*parent, i)];
  }
}

bool SleepTracker::asleep(int object) const {
  return object >= 0 && object < static_cast<int>(states_.size()) && states_[object].asleep;
}

int SleepTracker::asleep_count() const {
  return static_cast<int>(
      std::count_if(states_.begin(), states_.end(), [](const ObjectSleep& s) { return s.asleep; }));
}

void SleepTracker::SetAsleep(BodyTable* bodies, int object, bool asleep) {
  states_[object].asleep = asleep;
  BodyRecord& body = (*bodies)[bodies->object_ids()[object]];
  if (body.body == nullptr || !body.enabled) return;
  if (asleep) {
    dBodySetLinearVel(body.body, 0, 0, 0);
    dBodySetAngularVel(body.body, 0, 0, 0);
    dBodySetForce(body.body, 0, 0, 0);
    dBodySetTorque(body.body, 0, 0, 0);
    dBodyDisable(body.body);
    body.energy = 0.0;
  } else {
    dBodyEnable(body.body);
  }
}

void SleepTracker::Restore(BodyTable* bodies, const std::vector<ObjectSleep>& states, bool usable) {
  usable = usable && states.size() == states_.size();
  for (size_t i = 0; i < states_.size(); ++i) {
    states_[i].idle_time = usable ? states[i].idle_time : 0.0;
    SetAsleep(bodies, static_cast<int>(i), usable && states[i].asleep);
  }
}

void SleepTracker::WakeAll(BodyTable* bodies) {
  for (size_t i = 0; i < states_.size(); ++i) {
    states_[i].idle_time = 0.0;
    if (states_[i].asleep) SetAsleep(bodies, static_cast<int>(i), false);
  }
}

void SleepTracker::Wake(BodyTable* bodies, int id) {
  const BodyRecord* body = bodies->Find(id);
  if (body == nullptr || !body->is_object() || states_.empty()) return;
  states_[body->index].idle_time = 0.0;
  if (states_[body->index].asleep) SetAsleep(bodies, body->index, false);
}

void SleepTracker::WakeTouching(BodyTable* bodies, const std::vector<ContactPair>& pairs, int id) {
  for (const ContactPair& pair : pairs) {
    if (pair.contacts.empty() || (pair.a != id && pair.b != id)) continue;
    const BodyRecord& other = (*bodies)[pair.a == id ? pair.b : pair.a];
    if (!ObjectAsleep(other)) continue;
    states_[other.index].idle_time = 0.0;
    SetAsleep(bodies, other.index, false);
  }
}

bool SleepTracker::ObjectAsleep(const BodyRecord& body) const {
  return body.is_object() && states_[body.index].asleep;
}

bool SleepTracker::KeepsTouchedAwake(const BodyRecord& body) const {
  if (body.body == nullptr || !body.enabled) return false;
  if (!body.dynamic) return Speed(body.body) > 0.0;
  return !ObjectAsleep(body);
}

bool SleepTracker::SleepsAgainstInert(const BodyTable& bodies, const ContactPair& pair) const {
  const BodyRecord& a = bodies[pair.a];
  const BodyRecord& b = bodies[pair.b];
  return (ObjectAsleep(a) && !KeepsTouchedAwake(b)) || (ObjectAsleep(b) && !KeepsTouchedAwake(a));
}

void SleepTracker::WakeTouchedSleepers(BodyTable* bodies, const std::vector<ContactPair>& pairs) {
  bool changed = true;
  while (changed) {
    changed = false;
    for (const ContactPair& pair : pairs) {
      if (pair.contacts.empty()) continue;
      for (const auto& [sleeper, other] : {std::pair(pair.a, pair.b), std::pair(pair.b, pair.a)}) {
        const BodyRecord& body = (*bodies)[sleeper];
        if (!ObjectAsleep(body) || !KeepsTouchedAwake((*bodies)[other])) continue;
        SetAsleep(bodies, body.index, false);
        changed = true;
      }
    }
  }
}

void SleepTracker::UpdateIdleTimes(BodyTable* bodies, double step, double sleep_speed) {
  const std::vector<int>& ids = bodies->object_ids();
  for (size_t i = 0; i < ids.size(); ++i) {
    const BodyRecord& body = (*bodies)[ids[i]];
    ObjectSleep& sleep = states_[i];
    // ODE itself enables a disabled body that a joint ties to an enabled one
    if (sleep.asleep && body.moves_freely() && dBodyIsEnabled(body.body)) {
      sleep.asleep = false;
      sleep.idle_time = 0.0;
    }
    if (!body.moves_freely() || sleep.asleep) continue;
    sleep.idle_time = Speed(body.body) < sleep_speed ? sleep.idle_time + step : 0.0;
  }
}

// ready_: idle long enough and not pushed; links_: touching free objects
void SleepTracker::MarkReady(const BodyTable& bodies, const std::vector<ContactPair>& pairs,
                             double sleep_time) {
  const std::vector<int>& ids = bodies.object_ids();
  ready_.assign(ids.size(), 0);
  for (size_t i = 0; i < ids.size(); ++i) {
    const BodyRecord& body = bodies[ids[i]];
    ready_[i] = body.moves_freely() && states_[i].idle_time >= sleep_time && !Pushed(body);
  }
  links_.clear();
  for (const ContactPair& pair : pairs) {
    if (pair.contacts.empty()) continue;
    const BodyRecord& a = bodies[pair.a];
    const BodyRecord& b = bodies[pair.b];
    const bool a_free = a.is_object() && a.moves_freely();
    const bool b_free = b.is_object() && b.moves_freely();
    if (a_free && b_free) {
      links_.emplace_back(a.index, b.index);
      continue;
    }
    // a robot link, or a kinematic body on the move, keeps what it touches awake
    if (a_free && KeepsTouchedAwake(b)) ready_[a.index] = 0;
    if (b_free && KeepsTouchedAwake(a)) ready_[b.index] = 0;
  }
}

void SleepTracker::Update(BodyTable* bodies, const std::vector<ContactPair>& pairs, double step,
                          double sleep_speed, double sleep_time) {
  UpdateIdleTimes(bodies, step, sleep_speed);
  MarkReady(*bodies, pairs, sleep_time);
  const int count = static_cast<int>(states_.size());
  IslandsReady(count, links_, &ready_, &parent_);
  for (int i = 0; i < count; ++i) {
    if (ready_[i] && !states_[i].asleep) SetAsleep(bodies, i, true);
  }
}

}  // namespace lamina::core
