// SPDX-License-Identifier: MIT
// The Simulator's bodies: building them, access by world id and by object index, the setters,
// forces that last one call and forces that are held, the one change rule (BodyChanged), the
// initial state and UpdateWorld. Unknown ids and indices throw std::out_of_range (programmer
// errors); non-finite values std::invalid_argument.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <ode/ode.h>

#include "core/geometry/shrink.h"
#include "core/sim/body_change.h"
#include "core/sim/ode_conversions.h"
#include "core/sim/ode_robot.h"
#include "core/sim/simulator.h"

namespace lamina::core {

namespace {

void RequireFinite(bool finite, const char* what) {
  if (!finite) throw std::invalid_argument(std::string(what) + " must be finite");
}

}  // namespace

// ---- building ---------------------------------------------------------------------------

void Simulator::BuildBodies() {
  bodies_.Reset(world_.IdCount());
  for (int id = 0; id < world_.IdCount(); ++id) {
    const WorldId resolved = world_.Resolve(id);
    BodyRecord& body = bodies_[id];
    body.kind = resolved.kind;
    body.index = resolved.index;
    if (resolved.kind == WorldId::Kind::kTerrain) {
      body.dynamic = false;
      RebuildCollisionGeometry(id);
    } else if (resolved.kind == WorldId::Kind::kRigidObject) {
      BuildObject(id, resolved.index);
    } else if (resolved.kind == WorldId::Kind::kRobot) {
      BuildRobot(resolved.index, id + 1);
    }
  }
}

void Simulator::BuildObject(int id, int object) {
  BodyRecord& body = bodies_[id];
  bodies_.AddObject(id);
  const RigidObjectDesc& desc = world_.objects[object];
  body.body = dBodyCreate(ode_world_.get());
  // exact orientation update for the body's angular velocity (ODE's default is first order)
  dBodySetFiniteRotationMode(body.body, 1);
  body.com = desc.com;
  dMass mass;
  const Mat3& I = desc.inertia;
  dMassSetParameters(&mass, desc.mass, 0, 0, 0, I(0, 0), I(1, 1), I(2, 2), I(0, 1), I(0, 2),
                     I(1, 2));
  if (!dMassCheck(&mass)) {
    // ODE rejects zero mass or an invalid inertia; keep the body usable and tiny
    dMassSetSphereTotal(&mass, std::max(desc.mass, 1e-3), 0.01);
    diagnostics_.Note({world_.source_path, 0, 0},
                      "object '" + desc.name +
                          "': ODE cannot simulate its mass and inertia; simulated as a sphere of " +
                          std::to_string(mass.mass) + " kg and 1 cm radius");
  }
  dBodySetMass(body.body, &mass);
  body.mass = mass.mass;
  body.inertia << mass.I[0], mass.I[1], mass.I[2], mass.I[4], mass.I[5], mass.I[6], mass.I[8],
      mass.I[9], mass.I[10];
  RebuildCollisionGeometry(id);
}

void Simulator::RebuildCollisionGeometry(int id) {
  BodyRecord& body = bodies_[id];
  const BodySimParams& sim = sim_params(id);
  if (body.kind == WorldId::Kind::kRobotLink) {
    body.geometry = LinkCollisionGeometry(body.index, body.link);
    if (body.geometry && body.body == nullptr) {
      body.bounds = WorldBounds(*body.geometry, body.fixed_pose, sim.padding);
    }
    return;
  }
  const bool terrain = body.kind == WorldId::Kind::kTerrain;
  if (!terrain && body.kind != WorldId::Kind::kRigidObject) return;
  const GeometryDesc& desc =
      terrain ? world_.terrains[body.index].geometry : world_.objects[body.index].geometry;
  if (sim.preshrink != Preshrink::kNone && sim.padding > 0.0) {
    // shrunk geometries are the body's own: a shrunk mesh is new for every padding, so it cannot
    // be a key of the shared cache
    body.geometry = CollisionGeometry::Build(ShrinkGeometry(desc, sim.padding, &diagnostics_));
  } else {
    body.geometry = geometry_cache_.Get(desc);
  }
  if (body.geometry && terrain) {
    body.bounds = WorldBounds(*body.geometry, Pose::Identity(), sim.padding);
  }
}

// the world-level joints, built with every body at its initial pose (where they read 0)
void Simulator::BuildWorldJoints() {
  if (world_.joints.empty()) return;
  for (int i = 0; i < object_count(); ++i) {
    SetBodyPose(bodies_.object_ids()[i], world_.objects[i].pose);
  }
  for (int r = 0; r < robot_count(); ++r) robots_[r]->SetConfig(world_.robots[r].InitialConfig());
  const auto body_of = [this](const WorldJointBody& body) -> dxBody* {
    switch (body.kind) {
      case WorldId::Kind::kRigidObject:
        return bodies_[world_.ObjectId(body.index)].body;
      case WorldId::Kind::kRobotLink:
        return bodies_[world_.RobotLinkId(body.index, body.link)].body;
      default:
        return nullptr;  // a terrain: the world
    }
  };
  world_joints_.Build(ode_world_.get(), world_, body_of, diagnostics_);
}

void Simulator::ApplyInitialState() {
  for (int i = 0; i < object_count(); ++i) {
    SetObjectPose(i, world_.objects[i].pose);
    SetObjectVelocity(i, world_.objects[i].initial_velocity);
  }
  for (int r = 0; r < robot_count(); ++r) {
    const RobotDesc& robot = world_.robots[r];
    SetRobotConfig(r, robot.InitialConfig());
    SetRobotVelocity(r, robot.InitialVelocity());
    controllers_[r] = RobotController::ViewOf(&world_.robots[r]);
    controllers_[r].SetGravity(world_.settings.gravity);
    if (r < static_cast<int>(sensors_.size())) sensors_[r].Reset();
  }
  anchors_.Clear();
  sleep_.WakeAll(&bodies_);
  sleep_.Reset(object_count());
  contacts_.Invalidate();
  for (BodyRecord& body : bodies_) body.energy = -1.0;
}

// ---- the one change rule ----------------------------------------------------------------

void Simulator::BodyChanged(int id, unsigned changes) {
  const ChangeEffects effects = BodyChangeEffects(changes);
  if (effects.contacts_stale) contacts_.Invalidate();
  if (effects.forget_energy) bodies_[id].energy = -1.0;
  if (effects.drop_anchors) anchors_.Forget(id);
  if (effects.wake_body) sleep_.Wake(&bodies_, id);
  if (effects.wake_touching) sleep_.WakeTouching(&bodies_, contacts_.pairs(), id);
}

// ---- access -----------------------------------------------------------------------------

const BodySimParams& Simulator::sim_params(int id) const {
  const BodyRecord& body = bodies_[id];
  if (body.kind == WorldId::Kind::kRobotLink) return world_.robots[body.index].links[body.link].sim;
  return body.kind == WorldId::Kind::kTerrain ? world_.terrains[body.index].sim
                                              : world_.objects[body.index].sim;
}

BodyRecord& Simulator::RequireObject(int object) {
  return const_cast<BodyRecord&>(std::as_const(*this).RequireObject(object));
}

const BodyRecord& Simulator::RequireObject(int object) const {
  if (object < 0 || object >= object_count()) {
    throw std::out_of_range("object " + std::to_string(object) + ": the world has " +
                            std::to_string(object_count()) + " objects");
  }
  return bodies_[bodies_.object_ids()[object]];
}

// the record of a terrain, object or link; out_of_range otherwise
BodyRecord& Simulator::RequireBody(int id) {
  BodyRecord* body = bodies_.Find(id);
  if (body == nullptr || body->kind == WorldId::Kind::kRobot) {
    throw std::out_of_range("body id " + std::to_string(id) + " is not a terrain, object or link");
  }
  return *body;
}

const BodyRecord& Simulator::RequireBody(int id) const {
  return const_cast<Simulator*>(this)->RequireBody(id);
}

Pose Simulator::GetObjectPose(int object) const {
  return bodies_.GetPose(RequireObject(object));
}

void Simulator::SetObjectPose(int object, const Pose& pose) {
  RequireObject(object);
  SetBodyPose(bodies_.object_ids()[object], pose);
}

Twist Simulator::GetObjectVelocity(int object) const {
  return bodies_.GetVelocity(RequireObject(object));
}

void Simulator::SetObjectVelocity(int object, const Twist& velocity) {
  RequireObject(object);
  SetBodyVelocity(bodies_.object_ids()[object], velocity);
}

bool Simulator::BodyEnabled(int id) const {
  return RequireBody(id).enabled;
}

// the records carried by id's ODE body: id itself, and the links welded into one body with it
std::vector<int> Simulator::SharingBody(int id) const {
  const BodyRecord& body = bodies_[id];
  if (body.body == nullptr) return {id};
  std::vector<int> ids;
  for (int other = 0; other < bodies_.size(); ++other) {
    if (bodies_[other].body == body.body) ids.push_back(other);
  }
  return ids;
}

void Simulator::SetBodyEnabled(int id, bool enabled) {
  BodyRecord& body = RequireBody(id);
  if (body.enabled == enabled) return;
  if (body.body != nullptr) (enabled ? dBodyEnable : dBodyDisable)(body.body);
  for (int shared : SharingBody(id)) {
    bodies_[shared].enabled = enabled;
    BodyChanged(shared, enabled ? kEnabled : kDisabled);
  }
}

bool Simulator::BodyDynamic(int id) const {
  const BodyRecord& body = RequireBody(id);
  return body.body != nullptr && body.dynamic;
}

void Simulator::SetBodyDynamic(int id, bool dynamic) {
  BodyRecord& body = RequireBody(id);
  if (body.body == nullptr || body.dynamic == dynamic) return;
  (dynamic ? dBodySetDynamic : dBodySetKinematic)(body.body);
  for (int shared : SharingBody(id)) {
    bodies_[shared].dynamic = dynamic;
    BodyChanged(shared, kKindChanged);
  }
}

Pose Simulator::BodyPose(int id) const {
  return bodies_.GetPose(RequireBody(id));
}

void Simulator::SetBodyPose(int id, const Pose& pose) {
  RequireFinite(pose.matrix().allFinite(), "a body pose");
  if (!IsRotation(pose.linear())) throw std::invalid_argument("a body pose must be rigid");
  const BodyRecord& body = RequireBody(id);
  if (body.body == nullptr) return;
  bodies_.SetPose(body, pose);
  BodyChanged(id, kPoseChanged);
}

Twist Simulator::BodyVelocity(int id) const {
  return bodies_.GetVelocity(RequireBody(id));
}

void Simulator::SetBodyVelocity(int id, const Twist& velocity) {
  RequireFinite(velocity.linear.allFinite() && velocity.angular.allFinite(), "a body velocity");
  const BodyRecord& body = RequireBody(id);
  if (body.body == nullptr) return;
  bodies_.SetVelocity(body, velocity);
  BodyChanged(id, kVelocityChanged);
}

// ---- forces -----------------------------------------------------------------------------

void Simulator::AddBodyForce(int id, const Vec3& force, const Vec3& point) {
  RequireFinite(force.allFinite() && point.allFinite(), "an applied force");
  BodyRecord& body = RequireBody(id);
  if (body.body == nullptr) return;
  body.force += force;
  body.torque += (point - ToVec3(dBodyGetPosition(body.body))).cross(force);
  BodyChanged(id, kForceApplied);
}

void Simulator::AddBodyWrench(int id, const Vec3& force, const Vec3& torque) {
  RequireFinite(force.allFinite() && torque.allFinite(), "an applied wrench");
  BodyRecord& body = RequireBody(id);
  if (body.body == nullptr) return;
  body.force += force;
  body.torque += torque;
  BodyChanged(id, kForceApplied);
}

void Simulator::SetAppliedWrench(int id, const Vec3& force, const Vec3& torque) {
  RequireFinite(force.allFinite() && torque.allFinite(), "a held wrench");
  BodyRecord& body = RequireBody(id);
  if (body.body == nullptr) return;
  body.held = HeldWrench{force, torque, Vec3::Zero(), false, true};
  BodyChanged(id, kForceApplied);
}

void Simulator::SetAppliedForceAtLocalPoint(int id, const Vec3& force, const Vec3& local_point) {
  RequireFinite(force.allFinite() && local_point.allFinite(), "a held force");
  BodyRecord& body = RequireBody(id);
  if (body.body == nullptr) return;
  body.held = HeldWrench{force, Vec3::Zero(), local_point, true, true};
  BodyChanged(id, kForceApplied);
}

void Simulator::ClearAppliedWrench(int id) {
  RequireBody(id).held = HeldWrench{};
}

void Simulator::ClearAppliedWrenches() {
  for (BodyRecord& body : bodies_) body.held = HeldWrench{};
}

// ---- energies and UpdateWorld -----------------------------------------------------------

double Simulator::KineticEnergy() const {
  double energy = 0.0;
  for (const BodyRecord& body : bodies_) {
    if (body.moves_freely() && body.owns_body) energy += bodies_.KineticEnergy(body);
  }
  return energy;
}

double Simulator::PotentialEnergy() const {
  double energy = 0.0;
  for (const BodyRecord& body : bodies_) {
    if (body.body == nullptr || !body.owns_body) continue;
    energy -= body.mass * world_.settings.gravity.dot(ToVec3(dBodyGetPosition(body.body)));
  }
  return energy;
}

namespace {

// every element of the simulated world, for UpdateWorld
std::vector<ElementIndex> Elements(const WorldDesc& world) {
  std::vector<ElementIndex> elements = {ElementIndex::Settings()};
  for (int t = 0; t < static_cast<int>(world.terrains.size()); ++t) {
    elements.push_back(ElementIndex::Terrain(t));
  }
  for (int o = 0; o < static_cast<int>(world.objects.size()); ++o) {
    elements.push_back(ElementIndex::Object(o));
  }
  for (size_t r = 0; r < world.robots.size(); ++r) {
    const int robot = static_cast<int>(r);
    for (int l = 0; l < world.robots[r].dof(); ++l)
      elements.push_back(ElementIndex::Link(robot, l));
    for (size_t d = 0; d < world.robots[r].drivers.size(); ++d) {
      elements.push_back(ElementIndex::Driver(robot, static_cast<int>(d)));
    }
  }
  return elements;
}

bool SameStructure(const WorldDesc& a, const WorldDesc& b) {
  if (a.terrains.size() != b.terrains.size() || a.objects.size() != b.objects.size() ||
      a.robots.size() != b.robots.size()) {
    return false;
  }
  for (size_t r = 0; r < a.robots.size(); ++r) {
    if (a.robots[r].dof() != b.robots[r].dof() ||
        a.robots[r].drivers.size() != b.robots[r].drivers.size()) {
      return false;
    }
  }
  return true;
}

}  // namespace

// every row of the parameter table but the initial conditions, then the initial conditions from
// the current state: "every live edit" by construction
void Simulator::UpdateWorld(WorldDesc* world) const {
  if (!SameStructure(*world, world_)) {
    throw std::invalid_argument("UpdateWorld: the world does not match the simulated one");
  }
  for (const ElementIndex& element : Elements(world_)) {
    for (const ParamSpec* spec : ParamsOf(element.kind)) {
      if (spec->apply != ParamApply::kOnReset)
        spec->set(world, element, spec->get(world_, element));
    }
  }
  for (int i = 0; i < object_count(); ++i) {
    world->objects[i].pose = GetObjectPose(i);
    world->objects[i].initial_velocity = GetObjectVelocity(i);
  }
  for (int r = 0; r < robot_count(); ++r) {
    world->robots[r].config = GetRobotConfig(r);
    world->robots[r].velocity = GetRobotVelocity(r);
  }
}

}  // namespace lamina::core
