// SPDX-License-Identifier: MIT
// Reads contacts and contact forces out of a Simulator for the overlays.
#include "core/render/contact_markers.h"

#include "core/sim/simulator.h"

namespace lamina::core {

std::vector<ContactMarker> ContactMarkersFromSimulator(const Simulator& simulator) {
  std::vector<ContactMarker> markers;
  for (const ContactPair& pair : simulator.contact_pairs()) {
    const std::vector<FeedbackContact> feedback = simulator.GetContacts(pair.a, pair.b);
    if (!feedback.empty()) {
      const std::vector<Vec3> forces = simulator.GetContactForces(pair.a, pair.b);
      for (size_t i = 0; i < feedback.size(); ++i) {
        const Vec3 force = i < forces.size() ? forces[i] : Vec3::Zero();
        markers.push_back(
            {feedback[i].position, feedback[i].normal, force, feedback[i].penetrating});
      }
      continue;
    }
    for (const Contact& contact : pair.contacts) {
      markers.push_back({contact.position, contact.normal, Vec3::Zero(), contact.penetrating});
    }
  }
  return markers;
}

}  // namespace lamina::core
