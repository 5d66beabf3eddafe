// SPDX-License-Identifier: MIT
// The Simulator's contact joints (the rows of contact_rows.h made into ODE joints) and its
// contact-feedback registration and queries (contact_feedback.h has the sign convention).
#include <algorithm>

#include <ode/ode.h>

#include "core/contact/surface_blend.h"
#include "core/sim/contact_rows.h"
#include "core/sim/ode_conversions.h"
#include "core/sim/ode_robot.h"
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

// 1/m of the ODE body that carries `body` when it moves (kg⁻¹; 0: static or kinematic)
double InverseMass(const BodyRecord& body) {
  if (!body.moves_freely()) return 0.0;
  dMass mass;
  dBodyGetMass(body.body, &mass);
  return mass.mass > 0.0 ? 1.0 / mass.mass : 0.0;
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
  PairLaw law = MakePairLaw(pair, PairSurface(pair.a, pair.b), step);
  if (law.surface.restitution > 0.0) {  // (only bouncing rows read it)
    law.inverse_mass = InverseMass(bodies_[pair.a]) + InverseMass(bodies_[pair.b]);
  }
  return law;
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
  // solver "newton": the joints of an object island are kept for its solve (object_islands.h)
  const int free_a = IslandBody(pair.a);
  const int free_b = IslandBody(pair.b);
  const bool keep = islands_active_ && (free_a >= 0 || free_b >= 0) &&
                    islands_.Takes(free_a >= 0 ? free_a : free_b);
  // the joint in ODE, or null when kept
  auto make = [&](const dContact& joint) -> dJointID {
    if (keep) return nullptr;
    dJointID id = dJointCreateContact(ode_world_.get(), contact_group_.get(), &joint);
    dJointAttach(id, body_a, body_b);
    return id;
  };
  auto kept_feedback = [&](FeedbackRecorder::Slot* slot, bool core) {
    return slot != nullptr ? FeedbackRecorder::Feedback(slot, core) : nullptr;
  };
  for (const Contact& contact : pair.contacts) {
    const Vec3& anchor_velocity = *anchor_velocities++;
    const ContactRow row =
        MakeContactRow(contact, law, RelativeVelocity(body_a, body_b, contact.position),
                       anchor_velocity, step, settings, angular);
    const dContact joint = ToOdeContact(row, contact);
    dJointID id = make(joint);
    FeedbackRecorder::Slot* slot =
        record ? feedback_.Attach(id, *record, pair.a, contact, row.mu) : nullptr;
    if (keep) islands_.Keep(joint, free_a, free_b, body_a, body_b, kept_feedback(slot, false));
    if (!row.core) continue;
    const dContact core = ToOdeContact(row, contact, true);
    dJointID core_id = make(core);
    if (keep) islands_.Keep(core, free_a, free_b, body_a, body_b, kept_feedback(slot, true));
    if (slot != nullptr && !keep) FeedbackRecorder::AttachCore(slot, core_id);
  }
}

int Simulator::IslandBody(int id) const {
  const BodyRecord& record = bodies_[id];
  if (!record.moves_freely() || !dBodyIsEnabled(record.body)) return -1;
  if (record.kind != WorldId::Kind::kRobotLink) return id;
  return world_.RobotLinkId(record.index, robots_[record.index]->link(record.link).carrier);
}

// A robot goes to the Newton solver (its joints and motors kept: object_islands.h) when every
// body moves freely and is awake, none is dragged, and its bodies carry no joint but its own (a
// world joint keeps it with ODE's solver).
bool Simulator::RobotForIslands(int robot) {
  const OdeRobot& sim_robot = *robots_[robot];
  const int first = world_.RobotLinkId(robot, 0);
  std::vector<int>& count = robot_scratch_[robot].joint_count;
  count.assign(sim_robot.dof(), 0);
  for (int l = 0; l < sim_robot.dof(); ++l) {
    const OdeRobot::Link& link = sim_robot.link(l);
    if (link.kind != OdeRobot::LinkKind::kBody) continue;
    if (IslandBody(first + l) < 0 || (drag_.active && drag_.body == first + l)) return false;
    if (link.joint == nullptr) continue;
    count[link.carrier] += 2;  // the joint and its motor, on the link's body and the parent's
    const int parent = world_.robots[robot].links[l].parent;
    if (parent >= 0 && sim_robot.link(parent).body != nullptr)
      count[sim_robot.link(parent).carrier] += 2;
  }
  for (int l = 0; l < sim_robot.dof(); ++l) {
    const OdeRobot::Link& link = sim_robot.link(l);
    if (link.owns_body && dBodyGetNumJoints(link.body) != count[l]) return false;
  }
  return true;
}

int Simulator::OwnBodies(int robot) const {
  int bodies = 0;
  for (int l = 0; l < robots_[robot]->dof(); ++l) bodies += robots_[robot]->link(l).owns_body;
  return bodies;
}

// every link before its parent, so that the island's matrix stays narrow (object_islands.h)
void Simulator::KeepRobotJoints(int robot) {
  const OdeRobot& sim_robot = *robots_[robot];
  const int first = world_.RobotLinkId(robot, 0);
  for (int l : sim_robot.children_first()) {
    const OdeRobot::Link& link = sim_robot.link(l);
    if (link.joint == nullptr) continue;
    const int parent = world_.robots[robot].links[l].parent;
    const int b = parent >= 0 && sim_robot.link(parent).body != nullptr
                      ? first + sim_robot.link(parent).carrier
                      : -1;
    islands_.KeepJoint(link.joint, first + l, b, link.frame);
    islands_.KeepJoint(link.servo, first + l, b, link.frame);
  }
}

// robots that cannot go to the Newton solver, bodies held by a persistent ODE joint (world
// joints) and the dragged body stay with ODE's solver, and so does every island they are in; a
// free body touching a sleeping one too (ODE would wake it through the joint). The exact solver
// takes its large robots (direct_solver.h) and, with newton_objects_, its islands of free
// objects (object_islands.h decides by their contacts); a free object touching one of its
// robots leaves that island to dWorldStep.
void Simulator::PrepareObjectIslands(bool exact) {
  islands_.Begin(bodies_.size(), exact, direct_robots_ ? direct_min_bodies_ : 0,
                 newton_objects_ ? kNewtonObjectContacts : 0);
  islands_.SetReducedRobots(world_.settings.joint_coordinates);
  std::vector<int>& kept = island_joint_count_;
  kept.assign(static_cast<size_t>(bodies_.size()), 0);
  if (!exact && world_.settings.joint_coordinates) KeepWorldJoints(&kept);
  for (int r = 0; r < robot_count(); ++r) {
    if (RobotForIslands(r) && (!exact || (direct_robots_ && OwnBodies(r) >= direct_min_bodies_))) {
      KeepRobotJoints(r);
      continue;
    }
    const int first = world_.RobotLinkId(r, 0);
    for (int l = 0; l < robots_[r]->dof(); ++l) {
      const int id = IslandBody(first + l);
      if (id >= 0) islands_.MarkOde(id);
    }
  }
  for (int id = 0; id < bodies_.size(); ++id) {
    const BodyRecord& record = bodies_[id];
    if (record.body == nullptr || record.kind == WorldId::Kind::kRobotLink) continue;
    if ((exact && !newton_objects_) || !record.is_object() ||
        dBodyGetNumJoints(record.body) > kept[id] || (drag_.active && drag_.body == id)) {
      islands_.MarkOde(id);
    }
  }
  for (const ContactPair& pair : contacts_.pairs()) {
    const int a = IslandBody(pair.a), b = IslandBody(pair.b);
    if (a >= 0 && b >= 0) {
      islands_.Link(a, b);
      if (exact && IsRobotLink(a) != IsRobotLink(b)) islands_.MarkOde(a);
    } else if ((a >= 0) != (b >= 0)) {
      const BodyRecord& other = bodies_[a >= 0 ? pair.b : pair.a];
      if (other.body != nullptr && !dBodyIsEnabled(other.body)) islands_.MarkOde(a >= 0 ? a : b);
    }
  }
}

// a world joint's world id of its first and second body (-1: the world), or false when it is
// not a hinge or slider without friction between free rigid objects (or one and the world)
bool Simulator::WorldJointIslandBodies(int joint, int* a, int* b) const {
  const WorldJointDesc& desc = world_.joints[static_cast<size_t>(joint)];
  dJointID ode = world_joints_.ode_joint(joint);
  if (ode == nullptr || desc.type == WorldJointType::kFixed || desc.friction > 0.0 ||
      dJointGetBody(ode, 0) == nullptr) {
    return false;
  }
  int ids[2] = {-1, -1};
  for (size_t i = 0; i < desc.bodies.size() && i < 2; ++i) {
    const WorldJointBody& body = desc.bodies[i];
    if (body.kind == WorldId::Kind::kTerrain) continue;
    if (body.kind != WorldId::Kind::kRigidObject) return false;
    ids[i] = IslandBody(world_.ObjectId(body.index));
    if (ids[i] < 0) return false;
  }
  *a = ids[0];
  *b = ids[1];
  return *a >= 0;
}

void Simulator::KeepWorldJoints(std::vector<int>* kept) {
  for (int j = 0; j < world_joints_.size(); ++j) {
    int a = -1, b = -1;
    if (!WorldJointIslandBodies(j, &a, &b)) continue;
    islands_.KeepJoint(world_joints_.ode_joint(j), a, b, world_joints_.frame(j));
    ++(*kept)[static_cast<size_t>(a)];
    if (b >= 0) ++(*kept)[static_cast<size_t>(b)];
  }
}

bool Simulator::IsRobotLink(int id) const {
  return bodies_[id].kind == WorldId::Kind::kRobotLink;
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
