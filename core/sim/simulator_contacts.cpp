// SPDX-License-Identifier: MIT
// The Simulator's contact joints (the rows of contact_rows.h made into ODE joints) and its
// contact-feedback registration and queries (contact_feedback.h has the sign convention).
#include <algorithm>

#include <ode/ode.h>

#include "core/contact/surface_blend.h"
#include "core/sim/contact_rows.h"
#include "core/sim/ode_conversions.h"
#include "core/sim/simulator.h"

namespace lamina::core {

namespace {

// a's velocity less b's at world point p
Vec3 RelativeVelocity(dBodyID a, dBodyID b, const Vec3& p) {
  dVector3 velocity_a = {0, 0, 0}, velocity_b = {0, 0, 0};
  if (a) dBodyGetPointVel(a, p.x(), p.y(), p.z(), velocity_a);
  if (b) dBodyGetPointVel(b, p.x(), p.y(), p.z(), velocity_b);
  return ToVec3(velocity_a) - ToVec3(velocity_b);
}

// a's angular velocity less b's (rad/s)
Vec3 RelativeAngularVelocity(dBodyID a, dBodyID b) {
  Vec3 relative = Vec3::Zero();
  if (a) relative += ToVec3(dBodyGetAngularVel(a));
  if (b) relative -= ToVec3(dBodyGetAngularVel(b));
  return relative;
}

RowSettings ContactRowSettings(const SimSettings& s) {
  return {s.erp, s.cfm, s.max_correction_speed, s.bounce_velocity_threshold};
}

}  // namespace

BlendedSurface Simulator::PairSurface(int a, int b) const {
  RequireBody(a);
  RequireBody(b);
  return BlendSurfaces(sim_params(a).surface, sim_params(b).surface);
}

PairLaw Simulator::PairContactLaw(const ContactPair& pair, double step) const {
  return MakePairLaw(pair, PairSurface(pair.a, pair.b), step);
}

void Simulator::AddContactJoints(const ContactPair& pair, const Vec3* anchor_velocities,
                                 double step) {
  if (pair.contacts.empty()) return;
  dBodyID body_a = bodies_[pair.a].body;
  dBodyID body_b = bodies_[pair.b].body;
  const PairLaw law = PairContactLaw(pair, step);
  if (!law.pushes) return;
  const ContactFeedbackRecord* record =
      feedback_.empty() ? nullptr : feedback_.Find(pair.a, pair.b);
  const RowSettings settings = ContactRowSettings(world_.settings);
  // the same for every contact of the pair; read only with rolling friction
  const Vec3 angular =
      law.surface.rolling > 0.0 ? RelativeAngularVelocity(body_a, body_b) : Vec3::Zero();
  for (const Contact& contact : pair.contacts) {
    const Vec3& anchor_velocity = *anchor_velocities++;
    const ContactRow row =
        MakeContactRow(contact, law, RelativeVelocity(body_a, body_b, contact.position),
                       anchor_velocity, step, settings, angular);
    const dContact joint = ToOdeContact(row, contact);
    dJointID id = dJointCreateContact(ode_world_.get(), contact_group_.get(), &joint);
    dJointAttach(id, body_a, body_b);
    FeedbackRecorder::Slot* slot =
        record ? feedback_.Attach(id, *record, pair.a, contact, row.mu) : nullptr;
    if (!row.core) continue;
    const dContact core = ToOdeContact(row, contact, true);
    dJointID core_id = dJointCreateContact(ode_world_.get(), contact_group_.get(), &core);
    dJointAttach(core_id, body_a, body_b);
    if (slot != nullptr) FeedbackRecorder::AttachCore(slot, core_id);
  }
}

// ---- feedback ---------------------------------------------------------------------------

void Simulator::EnableContactFeedback(int a, int b) {
  const BodyRecord* first = bodies_.Find(a);
  const BodyRecord* second = bodies_.Find(b);
  if (first == nullptr || second == nullptr) return;
  feedback_.Enable(a, b);
}

std::vector<std::pair<int, int>> Simulator::ContactFeedbackPairs() const {
  std::vector<std::pair<int, int>> pairs;
  for (const ContactFeedbackRecord& r : feedback_.records()) pairs.emplace_back(r.first, r.second);
  return pairs;
}

void Simulator::EnableContactFeedbackAll() {
  for (int a = 0; a < body_count(); ++a) {
    if (!bodies_[a].geometry) continue;
    for (int b = a + 1; b < body_count(); ++b) {
      if (bodies_[b].geometry && MayCollide(bodies_[a], bodies_[b])) feedback_.Enable(a, b);
    }
  }
}

bool Simulator::InContact(int a, int b) const {
  bool recorded = false, in_contact = false;
  feedback_.ForEach(a, b, [&](const ContactFeedbackRecord& r, double) {
    recorded = true;
    in_contact = in_contact || r.in_contact;
  });
  if (recorded) return in_contact;
  // without feedback: touching at the current state
  return std::any_of(
      contacts_.pairs().begin(), contacts_.pairs().end(), [&](const ContactPair& pair) {
        const bool touches_a = pair.a == a || pair.b == a;
        return touches_a && (b < 0 || pair.a == b || pair.b == b) && !pair.contacts.empty();
      });
}

bool Simulator::HadContact(int a, int b) const {
  bool any = false;
  feedback_.ForEach(
      a, b, [&](const ContactFeedbackRecord& r, double) { any = any || r.contact_steps > 0; });
  return any;
}

bool Simulator::HadSeparation(int a, int b) const {
  bool any = false;
  feedback_.ForEach(
      a, b, [&](const ContactFeedbackRecord& r, double) { any = any || r.separation_steps > 0; });
  return any;
}

bool Simulator::HadPenetration(int a, int b) const {
  bool any = false;
  feedback_.ForEach(
      a, b, [&](const ContactFeedbackRecord& r, double) { any = any || r.penetration_steps > 0; });
  return any;
}

std::vector<FeedbackContact> Simulator::GetContacts(int a, int b) const {
  std::vector<FeedbackContact> contacts;
  feedback_.ForEach(a, b, [&](const ContactFeedbackRecord& r, double sign) {
    for (FeedbackContact contact : r.contacts) {
      contact.normal *= sign;
      contact.force *= sign;
      contacts.push_back(contact);
    }
  });
  return contacts;
}

std::vector<Vec3> Simulator::GetContactForces(int a, int b) const {
  std::vector<Vec3> forces;
  for (const FeedbackContact& contact : GetContacts(a, b)) forces.push_back(contact.force);
  return forces;
}

Vec3 Simulator::ContactForce(int a, int b) const {
  Vec3 sum = Vec3::Zero();
  feedback_.ForEach(
      a, b, [&](const ContactFeedbackRecord& r, double sign) { sum += sign * r.LastForce(); });
  return sum;
}

Vec3 Simulator::ContactTorque(int a, int b) const {
  Vec3 sum = Vec3::Zero();
  feedback_.ForEach(
      a, b, [&](const ContactFeedbackRecord& r, double sign) { sum += sign * r.LastTorque(); });
  return sum;
}

Vec3 Simulator::MeanContactForce(int a, int b) const {
  Vec3 sum = Vec3::Zero();
  feedback_.ForEach(
      a, b, [&](const ContactFeedbackRecord& r, double sign) { sum += sign * r.mean_force; });
  return sum;
}

Vec3 Simulator::MeanContactTorque(int a, int b) const {
  Vec3 sum = Vec3::Zero();
  feedback_.ForEach(
      a, b, [&](const ContactFeedbackRecord& r, double sign) { sum += sign * r.mean_torque; });
  return sum;
}

}  // namespace lamina::core
