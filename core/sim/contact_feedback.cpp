// SPDX-License-Identifier: MIT
#include "core/sim/contact_feedback.h"

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

}  // namespace lamina::core
