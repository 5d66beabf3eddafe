// SPDX-License-Identifier: MIT
// Sleeping rigid objects (Simulator::SetSleeping): idle time, islands of touching objects that
// fall asleep together, waking.
#include <algorithm>
#include <numeric>

#include "core/sim/ode_conversions.h"
#include "core/sim/simulator.h"
#include "core/sim/simulator_records.h"

namespace lamina::core {

namespace {

int IslandRoot(std::vector<int>& parent, int i) {
  while (parent[i] != i) {
    parent[i] = parent[parent[i]];
    i = parent[i];
  }
  return i;
}

constexpr WorldId::Kind kObject = WorldId::Kind::kRigidObject;

double Speed(dBodyID body) {
  return std::max(ToVec3(dBodyGetLinearVel(body)).norm(), ToVec3(dBodyGetAngularVel(body)).norm());
}

// a kinematic body carries what it touches whenever it moves at all
bool KinematicMoves(dBodyID body) {
  return Speed(body) > 0.0;
}

}  // namespace

void Simulator::SetSleeping(bool on) {
  world_.settings.sleeping = on;
  if (on) return;
  for (int i = 0; i < object_count(); ++i) {
    sleep_[i].idle_time = 0.0;
    if (sleep_[i].asleep) SetObjectAsleep(i, false);
  }
}

bool Simulator::ObjectAsleep(int object) const {
  return object >= 0 && object < static_cast<int>(sleep_.size()) && sleep_[object].asleep;
}

int Simulator::SleepingObjectCount() const {
  return static_cast<int>(std::count_if(sleep_.begin(), sleep_.end(),
                                        [](const ObjectSleep& sleep) { return sleep.asleep; }));
}

void Simulator::SetObjectAsleep(int object, bool asleep) {
  sleep_[object].asleep = asleep;
  BodyRecord& body = bodies_[object_ids_[object]];
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

// a setter, an applied force or a surface edit reached body `id`
void Simulator::WakeBody(int id) {
  const BodyRecord* body = record(id);
  if (body == nullptr || body->kind != kObject || sleep_.empty()) return;
  sleep_[body->index].idle_time = 0.0;
  if (sleep_[body->index].asleep) SetObjectAsleep(body->index, false);
}

// body `id` moved, changed shape or went away: what sleeps on it may have lost its support
void Simulator::WakeTouching(int id) {
  for (const ContactPair& pair : pairs_) {
    if (pair.contacts.empty() || (pair.a != id && pair.b != id)) continue;
    const BodyRecord& other = bodies_[pair.a == id ? pair.b : pair.a];
    if (other.kind != kObject || !sleep_[other.index].asleep) continue;
    sleep_[other.index].idle_time = 0.0;
    SetObjectAsleep(other.index, false);
  }
}

// what keeps the objects it touches awake: an awake dynamic object, a robot link, a kinematic
// body that moves at all; static, disabled and sleeping bodies and standing kinematic ones do not
bool Simulator::KeepsTouchedAwake(const BodyRecord& body) const {
  if (body.body == nullptr || !body.enabled) return false;
  if (!body.dynamic) return KinematicMoves(body.body);
  return body.kind != kObject || !sleep_[body.index].asleep;
}

// a pair of a sleeper and something that cannot wake it (no contact joint for it: ODE would
// enable the sleeper through the joint)
bool Simulator::SleepsAgainstInert(const ContactPair& pair) const {
  const auto asleep = [&](const BodyRecord& body) {
    return body.kind == kObject && sleep_[body.index].asleep;
  };
  const BodyRecord& a = bodies_[pair.a];
  const BodyRecord& b = bodies_[pair.b];
  return (asleep(a) && !KeepsTouchedAwake(b)) || (asleep(b) && !KeepsTouchedAwake(a));
}

// before a step: a sleeping object touched by something that keeps it awake wakes, and so does
// everything asleep that touches it (its idle time stays, so that the island can fall asleep
// again together)
void Simulator::WakeTouchedSleepers() {
  bool changed = true;
  while (changed) {
    changed = false;
    for (const ContactPair& pair : pairs_) {
      if (pair.contacts.empty()) continue;
      for (const auto& [sleeper, other] : {std::pair(pair.a, pair.b), std::pair(pair.b, pair.a)}) {
        const BodyRecord& body = bodies_[sleeper];
        if (body.kind != kObject || !sleep_[body.index].asleep) continue;
        if (!KeepsTouchedAwake(bodies_[other])) continue;
        SetObjectAsleep(body.index, false);
        changed = true;
      }
    }
  }
}

// after an accepted step: idle times, then every island of touching objects whose members have
// all been idle for sleep_time, and that touches no robot and no moving kinematic body, sleeps
void Simulator::UpdateSleep(double step) {
  if (!world_.settings.sleeping) return;
  const int count = object_count();
  for (int i = 0; i < count; ++i) {
    const BodyRecord& body = bodies_[object_ids_[i]];
    // ODE itself enables a disabled body that a joint ties to an enabled one
    if (sleep_[i].asleep && body.moves_freely() && dBodyIsEnabled(body.body)) {
      sleep_[i].asleep = false;
      sleep_[i].idle_time = 0.0;
    }
    if (!body.moves_freely() || sleep_[i].asleep) continue;
    sleep_[i].idle_time =
        Speed(body.body) < world_.settings.sleep_speed ? sleep_[i].idle_time + step : 0.0;
  }
  std::vector<int>& parent = sleep_islands_;
  parent.resize(count);
  std::iota(parent.begin(), parent.end(), 0);
  // a body pushed by an applied force stays awake while the force lasts
  std::vector<char>& ready = sleep_ready_;
  ready.assign(count, 0);
  for (int i = 0; i < count; ++i) {
    const BodyRecord& body = bodies_[object_ids_[i]];
    ready[i] = body.moves_freely() && sleep_[i].idle_time >= world_.settings.sleep_time &&
               body.force.isZero(0.0) && body.torque.isZero(0.0);
  }
  for (const ContactPair& pair : pairs_) {
    if (pair.contacts.empty()) continue;
    const BodyRecord& a = bodies_[pair.a];
    const BodyRecord& b = bodies_[pair.b];
    const bool a_free = a.kind == kObject && a.moves_freely();
    const bool b_free = b.kind == kObject && b.moves_freely();
    if (a_free && b_free) {
      parent[IslandRoot(parent, a.index)] = IslandRoot(parent, b.index);
      continue;
    }
    // a robot link, or a kinematic body on the move, keeps what it touches awake
    if (a_free && KeepsTouchedAwake(b)) ready[a.index] = 0;
    if (b_free && KeepsTouchedAwake(a)) ready[b.index] = 0;
  }
  std::vector<char>& island_ready = island_ready_;
  island_ready.assign(count, 1);
  for (int i = 0; i < count; ++i) {
    if (!ready[i]) island_ready[IslandRoot(parent, i)] = 0;
  }
  for (int i = 0; i < count; ++i) {
    if (ready[i] && island_ready[IslandRoot(parent, i)] && !sleep_[i].asleep) {
      SetObjectAsleep(i, true);
    }
  }
}

}  // namespace lamina::core
