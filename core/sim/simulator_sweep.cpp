// SPDX-License-Identifier: MIT
// The step's tunnelling check: a rigid object that moved further in one step than half its own
// thickness may have passed clean through something thin, ending with no contact at all (a
// 100 m/s ball crosses a 1 cm wall within one 10 ms step), which the contact-based rollback
// cannot see. For such a fast object a ray from its centre of mass before the step to its centre
// after is cast against every body it may collide with; a hit closer than the travel means its
// centre crossed a surface, and the step counts as one that interpenetrated: with adaptive
// stepping it is rolled back and retaken in halves (until the travel per step is below the
// thickness and the boundary layer catches the contact), and at the smallest step it is accepted
// with the status "contact unreliable". Robot links are not checked (they move by their joints
// and are rarely thin and fast). Klamp't has no such check: its balls tunnel silently.
#include <algorithm>
#include <cmath>

#include <ode/ode.h>

#include "core/contact/ray_cast.h"
#include "core/sim/simulator.h"

namespace lamina::core {

// the first body, besides `id`, that `id` may collide with and whose surface lies on the segment
// from `from` to `to`; true when there is one
bool Simulator::SegmentCrossesBody(int id, const Vec3& from, const Vec3& to) const {
  const double travel = (to - from).norm();
  const Vec3 direction = (to - from) / travel;
  const BodyRecord& moving = bodies_[id];
  for (int other = 0; other < body_count(); ++other) {
    const BodyRecord& body = bodies_[other];
    if (other == id || !body.geometry || !BodyEnabled(other) || !MayCollide(moving, body)) continue;
    if (RayCast(*body.geometry, BodyPose(other), from, direction, travel) < travel) return true;
  }
  return false;
}

bool Simulator::ObjectTunnelled() const {
  const std::vector<int>& ids = bodies_.object_ids();
  const SimState& start = guard_.rollback_state();
  for (size_t i = 0; i < ids.size() && i < start.objects.size(); ++i) {
    const BodyRecord& body = bodies_[ids[i]];
    if (!body.moves_freely() || !body.geometry) continue;
    const Vec3 from = start.objects[i].com_position;
    const dReal* p = dBodyGetPosition(body.body);
    const Vec3 to(p[0], p[1], p[2]);
    const double thickness = body.bounds.sizes().minCoeff();
    if ((to - from).norm() <= 0.5 * thickness) continue;
    if (SegmentCrossesBody(ids[i], from, to)) return true;
  }
  return false;
}

}  // namespace lamina::core
