// SPDX-License-Identifier: MIT
#include "core/sim/contact_feedback.h"

#include <algorithm>

#include <ode/ode.h>

namespace lamina::core {

void ContactFeedbackRecord::BeginCall() {
  contacts.clear();
  in_contact = false;
  contact_steps = 0;
  separation_steps = 0;
  penetration_steps = 0;
  mean_force.setZero();
  mean_torque.setZero();
  accumulated_time = 0.0;
}

void ContactFeedbackRecord::AddSubStep(double step,
                                       const std::vector<FeedbackContact>& step_contacts) {
  contacts = step_contacts;
  in_contact = !contacts.empty();
  if (in_contact) {
    ++contact_steps;
  } else {
    ++separation_steps;
  }
  for (const FeedbackContact& contact : contacts) {
    if (contact.penetrating) {
      ++penetration_steps;
      break;
    }
  }
  // running time-weighted means; sub-steps without contact count as zero force
  accumulated_time += step;
  if (accumulated_time <= 0.0) return;
  const double weight = step / accumulated_time;
  mean_force += weight * (LastForce() - mean_force);
  mean_torque += weight * (LastTorque() - mean_torque);
}

Vec3 ContactFeedbackRecord::LastForce() const {
  Vec3 force = Vec3::Zero();
  for (const FeedbackContact& contact : contacts) force += contact.force;
  return force;
}

Vec3 ContactFeedbackRecord::LastTorque() const {
  Vec3 torque = Vec3::Zero();
  for (const FeedbackContact& contact : contacts) torque += contact.position.cross(contact.force);
  return torque;
}

namespace {

bool RecordBefore(const ContactFeedbackRecord& r, const std::pair<int, int>& key) {
  return std::make_pair(r.first, r.second) < key;
}

Vec3 ForceOf(const dJointFeedback& feedback) {
  return {feedback.f1[0], feedback.f1[1], feedback.f1[2]};
}

}  // namespace

struct FeedbackRecorder::Slot {
  dJointFeedback ode{};
  dJointFeedback core{};  ///< the rigid-core joint under a soft contact (has_core)
  bool has_core = false;
  int record = -1;    ///< index in records()
  bool flip = false;  ///< the joint's first body is the record's second
  FeedbackContact contact;
};

FeedbackRecorder::FeedbackRecorder() = default;
FeedbackRecorder::~FeedbackRecorder() = default;
FeedbackRecorder::FeedbackRecorder(FeedbackRecorder&&) noexcept = default;
FeedbackRecorder& FeedbackRecorder::operator=(FeedbackRecorder&&) noexcept = default;

void FeedbackRecorder::Enable(int a, int b) {
  if (a == b || Find(a, b) != nullptr) return;
  const std::pair<int, int> key(std::min(a, b), std::max(a, b));
  ContactFeedbackRecord entry;
  entry.first = key.first;
  entry.second = key.second;
  records_.insert(std::lower_bound(records_.begin(), records_.end(), key, RecordBefore), entry);
}

const ContactFeedbackRecord* FeedbackRecorder::Find(int a, int b) const {
  const std::pair<int, int> key(std::min(a, b), std::max(a, b));
  const auto found = std::lower_bound(records_.begin(), records_.end(), key, RecordBefore);
  if (found == records_.end() || found->first != key.first || found->second != key.second) {
    return nullptr;
  }
  return &*found;
}

void FeedbackRecorder::BeginCall() {
  for (ContactFeedbackRecord& record : records_) record.BeginCall();
}

void FeedbackRecorder::ReserveSlots(size_t contacts) {
  slots_.resize(contacts);
  used_slots_ = 0;
}

FeedbackRecorder::Slot* FeedbackRecorder::Attach(dxJoint* joint,
                                                 const ContactFeedbackRecord& record,
                                                 int joint_first_body, const Contact& contact,
                                                 double friction) {
  Slot& slot = slots_[used_slots_++];
  slot.has_core = false;
  slot.record = static_cast<int>(&record - records_.data());
  // ODE reports the force on the joint's first body; the record wants it on `first`
  slot.flip = joint_first_body != record.first;
  slot.contact.position = contact.position;
  slot.contact.normal = slot.flip ? Vec3(-contact.normal) : contact.normal;
  slot.contact.friction = friction;
  slot.contact.penetrating = contact.penetrating;
  if (joint != nullptr) dJointSetFeedback(joint, &slot.ode);
  return &slot;
}

dJointFeedback* FeedbackRecorder::Feedback(Slot* slot, bool core) {
  if (!core) return &slot->ode;
  slot->has_core = true;
  return &slot->core;
}

void FeedbackRecorder::AttachCore(Slot* slot, dxJoint* core_joint) {
  slot->has_core = true;
  dJointSetFeedback(core_joint, &slot->core);
}

void FeedbackRecorder::RecordStep(double step) {
  if (records_.empty()) return;
  step_contacts_.resize(records_.size());
  for (std::vector<FeedbackContact>& contacts : step_contacts_) contacts.clear();
  for (size_t i = 0; i < used_slots_; ++i) {
    Slot& slot = slots_[i];
    Vec3 force = ForceOf(slot.ode);
    if (slot.has_core) force += ForceOf(slot.core);
    slot.contact.force = slot.flip ? Vec3(-force) : force;
    step_contacts_[slot.record].push_back(slot.contact);
  }
  for (size_t r = 0; r < records_.size(); ++r) records_[r].AddSubStep(step, step_contacts_[r]);
}

}  // namespace lamina::core
