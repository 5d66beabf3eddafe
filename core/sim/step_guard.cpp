// SPDX-License-Identifier: MIT
#include "core/sim/step_guard.h"

#include <algorithm>
#include <cmath>

#include <ode/ode.h>

#include "core/sim/ode_conversions.h"

namespace lamina::core {

namespace {

bool BodyFinite(dBodyID body) {
  return ToVec3(dBodyGetPosition(body)).allFinite() &&
         ToVec3(dBodyGetLinearVel(body)).allFinite() &&
         ToVec3(dBodyGetAngularVel(body)).allFinite();
}

std::pair<int, int> Key(const ContactPair& pair) {
  return {std::min(pair.a, pair.b), std::max(pair.a, pair.b)};
}

// the rules of one pair given the same pair before the step (null: it was not in contact)
bool PairNeedsRollback(const ContactPair& pair, const ContactPair* previous, bool* unreliable) {
  const double previous_depth = previous ? previous->max_depth : 0.0;
  const double previous_remaining = pair.tolerance - previous_depth;
  if (pair.penetrating) {
    *unreliable = true;
    const bool had_room = previous_remaining > kPressedThroughFraction * pair.tolerance;
    return previous == nullptr || (!previous->penetrating && had_room);
  }
  const double remaining = pair.tolerance - pair.max_depth;
  return remaining < 0.5 * pair.tolerance && remaining < 0.5 * previous_remaining &&
         pair.max_depth - previous_depth > kSettledLayerFraction * pair.tolerance;
}

}  // namespace

bool NeedsRollback(const std::vector<ContactPair>& before, const std::vector<ContactPair>& after,
                   bool* unreliable) {
  bool rollback = false;
  auto previous = before.begin();
  for (const ContactPair& pair : after) {
    while (previous != before.end() && Key(*previous) < Key(pair)) ++previous;
    const bool same = previous != before.end() && previous->a == pair.a && previous->b == pair.b;
    rollback = PairNeedsRollback(pair, same ? &*previous : nullptr, unreliable) || rollback;
  }
  return rollback;
}

namespace {

void AddPairAllowance(const ContactPair& pair, double mass, double k, double step,
                      double* allowance) {
  const double correction_speed = pair.max_depth / step;
  *allowance += 0.5 * mass * correction_speed * correction_speed;
  *allowance += 0.5 * mass * pair.anchor_speed * pair.anchor_speed;
  if (std::isfinite(k)) *allowance += 0.5 * k * pair.max_depth * pair.max_depth;
}

}  // namespace

// (a body's sum in the pairs' order, as one pass per body had it: the same to the last bit, in
// time linear in the pairs rather than bodies × pairs: on the 210-box pyramid, about 400 pairs,
// 84,000 pair visits a step before)
void ContactEnergyAllowances(const std::vector<ContactPair>& pairs,
                             const std::vector<double>& masses, const PairStiffness& stiffness,
                             double step, std::vector<double>* allowances) {
  allowances->assign(masses.size(), 0.0);
  for (const ContactPair& pair : pairs) {
    const double k = stiffness(pair);
    AddPairAllowance(pair, masses[pair.a], k, step, &(*allowances)[pair.a]);
    AddPairAllowance(pair, masses[pair.b], k, step, &(*allowances)[pair.b]);
  }
}

void StepGuard::MeasureUnknownEnergies(BodyTable* bodies) {
  for (BodyRecord& body : *bodies) {
    if (body.energy >= 0.0 || !body.moves_freely()) continue;
    body.energy = bodies->KineticEnergy(body);
  }
}

int StepGuard::StopOverflowingBodies(BodyTable* bodies, std::vector<int>* ids) {
  int stopped = 0;
  for (int id = 0; id < bodies->size(); ++id) {
    BodyRecord& body = (*bodies)[id];
    if (!body.moves_freely() || std::isfinite(body.energy)) continue;
    dBodySetLinearVel(body.body, 0, 0, 0);
    dBodySetAngularVel(body.body, 0, 0, 0);
    body.energy = 0.0;
    ++stopped;
    if (ids) ids->push_back(id);
  }
  return stopped;
}

// per body id: a rigid object non-finite after the step, or moving absurdly fast before it; every
// link of a robot one of whose links is non-finite after the step (robot_guard.h)
std::vector<char> StepGuard::BlownUp(const BodyTable& bodies) const {
  std::vector<char> blown(bodies.size(), 0);
  const std::vector<int>& ids = bodies.object_ids();
  for (size_t i = 0; i < ids.size(); ++i) {
    const BodyState& start = rollback_state_.objects[i];
    const double speed_squared =
        start.linear_velocity.squaredNorm() + start.angular_velocity.squaredNorm();
    blown[ids[i]] = !BodyFinite(bodies[ids[i]].body) || !std::isfinite(speed_squared);
  }
  std::vector<int> robots;  // robots with a non-finite link
  for (const BodyRecord& body : bodies) {
    if (body.kind == WorldId::Kind::kRobotLink && body.body && !BodyFinite(body.body)) {
      robots.push_back(body.index);
    }
  }
  for (int id = 0; id < bodies.size(); ++id) {
    const BodyRecord& body = bodies[id];
    if (body.kind != WorldId::Kind::kRobotLink || !body.body || !body.owns_body) continue;
    if (std::find(robots.begin(), robots.end(), body.index) != robots.end()) blown[id] = 1;
  }
  return blown;
}

// bodies pushed by a kinematic body, and the body on the mouse spring (an implicit constraint
// driven by the user), may gain any energy: they are left out of the check
void StepGuard::MarkPushed(const BodyTable& bodies, const std::vector<ContactPair>& before) {
  std::vector<char>& pushed = scratch_.pushed;
  pushed.assign(bodies.size(), 0);
  for (int id = 0; id < bodies.size(); ++id) pushed[id] = bodies[id].dragged ? 1 : 0;
  for (const ContactPair& pair : before) {
    if (bodies[pair.a].body && !bodies[pair.a].dynamic) pushed[pair.b] = 1;
    if (bodies[pair.b].body && !bodies[pair.b].dynamic) pushed[pair.a] = 1;
  }
}

void StepGuard::CollectSamples(BodyTable* bodies, const std::vector<ContactPair>& before,
                               const PairStiffness& stiffness, const Vec3& gravity, double step) {
  MarkPushed(*bodies, before);
  scratch_.samples.clear();
  scratch_.checked.clear();
  scratch_.masses.resize(bodies->size());
  for (int id = 0; id < bodies->size(); ++id) scratch_.masses[id] = (*bodies)[id].mass;
  ContactEnergyAllowances(before, scratch_.masses, stiffness, step, &scratch_.allowances);
  const std::vector<int>& ids = bodies->object_ids();
  for (size_t i = 0; i < ids.size(); ++i) {
    BodyRecord& body = (*bodies)[ids[i]];
    if (!body.moves_freely()) continue;
    const Vec3 v = ToVec3(dBodyGetLinearVel(body.body));
    const Vec3 w = ToVec3(dBodyGetAngularVel(body.body));
    const double energy = bodies->KineticEnergy(body);
    const double energy_before = body.energy;
    body.energy = energy;
    if (energy_before < 0.0 || scratch_.pushed[ids[i]]) continue;
    const BodyState& start = rollback_state_.objects[i];
    const Vec3 force = body.force + body.held.force + body.mass * gravity;
    const Vec3 torque = body.torque + bodies->HeldTorque(body);
    const double work = ExternalWorkBound(force, torque, start.linear_velocity.norm(), v.norm(),
                                          start.angular_velocity.norm(), w.norm(), step);
    scratch_.samples.push_back(
        {body.mass, energy_before, energy, work + scratch_.allowances[ids[i]]});
    scratch_.checked.push_back(ids[i]);
  }
}

int StepGuard::RecoverFromFailedStep(BodyTable* bodies,
                                     const std::function<void(const SimState&)>& restore,
                                     std::vector<int>* stopped_ids) {
  const std::vector<char> blown = BlownUp(*bodies);
  restore(rollback_state_);
  const int stopped = static_cast<int>(std::count(blown.begin(), blown.end(), 1));
  if (stopped == 0 || !bodies->StateIsFinite()) return -1;
  for (int id = 0; id < bodies->size(); ++id) {
    if (!blown[id]) continue;
    BodyRecord& body = (*bodies)[id];
    dBodySetLinearVel(body.body, 0, 0, 0);
    dBodySetAngularVel(body.body, 0, 0, 0);
    body.energy = 0.0;
    if (stopped_ids) stopped_ids->push_back(id);
  }
  return stopped;
}

int StepGuard::CorrectInstabilities(BodyTable* bodies, const std::vector<ContactPair>& before,
                                    const PairStiffness& stiffness, const Vec3& gravity,
                                    double step, std::vector<int>* ids) {
  CollectSamples(bodies, before, stiffness, gravity, step);
  const std::vector<double> scales = InstabilityScales(scratch_.samples);
  int corrected = 0;
  for (size_t k = 0; k < scales.size(); ++k) {
    if (scales[k] >= 1.0) continue;
    BodyRecord& body = (*bodies)[scratch_.checked[k]];
    const Vec3 v = scales[k] * ToVec3(dBodyGetLinearVel(body.body));
    const Vec3 w = scales[k] * ToVec3(dBodyGetAngularVel(body.body));
    dBodySetLinearVel(body.body, v.x(), v.y(), v.z());
    dBodySetAngularVel(body.body, w.x(), w.y(), w.z());
    body.energy *= scales[k] * scales[k];
    ++corrected;
    if (ids) ids->push_back(scratch_.checked[k]);
  }
  return corrected;
}

}  // namespace lamina::core
