// SPDX-License-Identifier: MIT
#include "core/sim/simulator.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/contact/contact_clustering.h"
#include "core/contact/surface_blend.h"
#include "core/sim/ode_handle.h"

namespace lamina::core {

namespace {

// contacts closing slower than this do not bounce, so resting bodies do not chatter (m/s)
constexpr double kBounceVelocityThreshold = 0.01;
// contacts closer than this (or than the pair's padding sum) count as one point (m)
constexpr double kMinimumMergeRadius = 1e-4;
// sliding slower than this keeps ODE's default friction directions (m/s)
constexpr double kSlidingSpeedThreshold = 1e-6;

Vec3 ToVec3(const dReal* v) {
  return {v[0], v[1], v[2]};
}

Mat3 ToMat3(const dReal* r) {
  Mat3 m;
  m << r[0], r[1], r[2], r[4], r[5], r[6], r[8], r[9], r[10];
  return m;
}

void SetBodyRotation(dBodyID body, const Mat3& rotation) {
  const Eigen::Quaterniond q(rotation);
  const dQuaternion ode_q = {q.w(), q.x(), q.y(), q.z()};
  dBodySetQuaternion(body, ode_q);
}

bool AabbsOverlap(const Eigen::AlignedBox3d& a, const Eigen::AlignedBox3d& b) {
  return !a.isEmpty() && !b.isEmpty() && a.intersects(b);
}

// bounds of `geometry` at `pose`, grown by `padding` on every side
Eigen::AlignedBox3d WorldBounds(const CollisionGeometry& geometry, const Pose& pose,
                                double padding) {
  const Eigen::AlignedBox3d& local = geometry.local_bounds();
  Eigen::AlignedBox3d world;
  if (local.isEmpty()) return world;
  if (!local.min().allFinite() || !local.max().allFinite()) {
    return Eigen::AlignedBox3d(Vec3::Constant(-kInf), Vec3::Constant(kInf));
  }
  for (int corner = 0; corner < 8; ++corner) {
    world.extend(pose * local.corner(static_cast<Eigen::AlignedBox3d::CornerType>(corner)));
  }
  const double grow = padding + geometry.margin();
  world.min().array() -= grow;
  world.max().array() += grow;
  return world;
}

}  // namespace

const char* StepStatusName(StepStatus status) {
  switch (status) {
    case StepStatus::kNormal:
      return "normal";
    case StepStatus::kAdaptiveStep:
      return "adaptive step";
    case StepStatus::kContactUnreliable:
      return "contact unreliable";
    case StepStatus::kUnstable:
      return "unstable";
    case StepStatus::kError:
      return "error";
  }
  return "error";
}

struct Simulator::ObjectBody {
  dBodyID body = nullptr;
  std::shared_ptr<const CollisionGeometry> geometry;
  Vec3 com = Vec3::Zero();     ///< in the object frame
  Eigen::AlignedBox3d bounds;  ///< padded world bounds, refreshed every sub-step
};

struct Simulator::TerrainBody {
  std::shared_ptr<const CollisionGeometry> geometry;
  Eigen::AlignedBox3d bounds;  ///< padded world bounds
};

Simulator::Simulator(const WorldDesc& world, SolverSettings solver)
    : world_(world),
      solver_(solver),
      ode_world_(nullptr, [](dxWorld* w) { dWorldDestroy(w); }),
      contact_group_(nullptr, [](dxJointGroup* g) { dJointGroupDestroy(g); }) {
  EnsureOdeInitialized();
  ode_world_.reset(dWorldCreate());
  contact_group_.reset(dJointGroupCreate(0));
  dWorldSetERP(ode_world_.get(), world_.settings.erp);
  dWorldSetCFM(ode_world_.get(), world_.settings.cfm);
  dWorldSetAutoDisableFlag(ode_world_.get(), 0);
  SetGravity(world_.settings.gravity);
  BuildBodies();
  ApplyInitialState();
}

Simulator::~Simulator() = default;

int Simulator::object_count() const {
  return static_cast<int>(objects_.size());
}

void Simulator::BuildBodies() {
  for (const TerrainDesc& terrain : world_.terrains) {
    TerrainBody body;
    body.geometry = geometry_cache_.Get(terrain.geometry);
    if (body.geometry) {
      body.bounds = WorldBounds(*body.geometry, Pose::Identity(), terrain.sim.padding);
    }
    terrains_.push_back(std::move(body));
  }
  for (const RigidObjectDesc& object : world_.objects) {
    ObjectBody body;
    body.body = dBodyCreate(ode_world_.get());
    // exact orientation update for the body's angular velocity (ODE's default is first order)
    dBodySetFiniteRotationMode(body.body, 1);
    body.geometry = geometry_cache_.Get(object.geometry);
    body.com = object.com;
    dMass mass;
    const Mat3& I = object.inertia;
    dMassSetParameters(&mass, object.mass, 0, 0, 0, I(0, 0), I(1, 1), I(2, 2), I(0, 1), I(0, 2),
                       I(1, 2));
    if (!dMassCheck(&mass)) {
      // ODE rejects zero mass or an invalid inertia; keep the body usable and tiny
      dMassSetSphereTotal(&mass, std::max(object.mass, 1e-3), 0.01);
    }
    dBodySetMass(body.body, &mass);
    objects_.push_back(std::move(body));
  }
}

void Simulator::ApplyInitialState() {
  for (int i = 0; i < object_count(); ++i) {
    SetObjectPose(i, world_.objects[i].pose);
    SetObjectVelocity(i, world_.objects[i].initial_velocity);
  }
}

void Simulator::Reset() {
  time_ = 0.0;
  statistics_ = SimStatistics();
  ApplyInitialState();
}

void Simulator::SetSimStep(double step) {
  if (step > 0.0 && std::isfinite(step)) world_.settings.timestep = step;
}

void Simulator::SetGravity(const Vec3& gravity) {
  world_.settings.gravity = gravity;
  dWorldSetGravity(ode_world_.get(), gravity.x(), gravity.y(), gravity.z());
}

Pose Simulator::GetObjectPose(int object) const {
  const ObjectBody& body = objects_[object];
  Pose pose = Pose::Identity();
  pose.linear() = ToMat3(dBodyGetRotation(body.body));
  pose.translation() = ToVec3(dBodyGetPosition(body.body)) - pose.linear() * body.com;
  return pose;
}

void Simulator::SetObjectPose(int object, const Pose& pose) {
  contacts_current_ = false;
  const ObjectBody& body = objects_[object];
  const Vec3 com_world = pose * body.com;
  dBodySetPosition(body.body, com_world.x(), com_world.y(), com_world.z());
  SetBodyRotation(body.body, pose.linear());
}

Twist Simulator::GetObjectVelocity(int object) const {
  const ObjectBody& body = objects_[object];
  const Vec3 angular = ToVec3(dBodyGetAngularVel(body.body));
  const Vec3 com_offset = GetObjectPose(object).linear() * body.com;
  // v_origin = v_com - w x (com - origin)
  return {ToVec3(dBodyGetLinearVel(body.body)) - angular.cross(com_offset), angular};
}

void Simulator::SetObjectVelocity(int object, const Twist& velocity) {
  const ObjectBody& body = objects_[object];
  const Vec3 com_offset = GetObjectPose(object).linear() * body.com;
  const Vec3 com_velocity = velocity.linear + velocity.angular.cross(com_offset);
  dBodySetLinearVel(body.body, com_velocity.x(), com_velocity.y(), com_velocity.z());
  dBodySetAngularVel(body.body, velocity.angular.x(), velocity.angular.y(), velocity.angular.z());
}

SimState Simulator::GetState() const {
  SimState state;
  CaptureState(&state);
  return state;
}

void Simulator::CaptureState(SimState* state) const {
  state->time = time_;
  state->objects.resize(objects_.size());
  for (size_t i = 0; i < objects_.size(); ++i) {
    const dBodyID body = objects_[i].body;
    const dReal* q = dBodyGetQuaternion(body);
    state->objects[i] = {ToVec3(dBodyGetPosition(body)), Eigen::Quaterniond(q[0], q[1], q[2], q[3]),
                         ToVec3(dBodyGetLinearVel(body)), ToVec3(dBodyGetAngularVel(body))};
  }
}

void Simulator::SetState(const SimState& state) {
  contacts_current_ = false;
  time_ = state.time;
  for (size_t i = 0; i < objects_.size() && i < state.objects.size(); ++i) {
    const BodyState& s = state.objects[i];
    dBodyID body = objects_[i].body;
    dBodySetPosition(body, s.com_position.x(), s.com_position.y(), s.com_position.z());
    const dQuaternion q = {s.orientation.w(), s.orientation.x(), s.orientation.y(),
                           s.orientation.z()};
    dBodySetQuaternion(body, q);
    dBodySetLinearVel(body, s.linear_velocity.x(), s.linear_velocity.y(), s.linear_velocity.z());
    dBodySetAngularVel(body, s.angular_velocity.x(), s.angular_velocity.y(),
                       s.angular_velocity.z());
  }
}

StepStatus Simulator::Simulate(double dt) {
  if (statistics_.worst_status == StepStatus::kError) return StepStatus::kError;
  StepStatus worst = StepStatus::kNormal;
  double remaining = dt;
  while (remaining > 0.0) {
    // the last sub-step absorbs a remainder smaller than a part per million of a step
    const double step =
        remaining < world_.settings.timestep * (1 + 1e-6) ? remaining : world_.settings.timestep;
    const StepStatus status = Step(step);
    worst = std::max(worst, status);
    if (status == StepStatus::kError) break;
    remaining -= step;
  }
  statistics_.worst_status = std::max(statistics_.worst_status, worst);
  return worst;
}

// one sub-step of length `step`; with adaptive stepping, a tentative step that uses up more
// than half of a boundary layer, or makes geometries interpenetrate, is undone and retaken in
// halves until it is acceptable or the step reaches kMinimumAdaptiveStep
StepStatus Simulator::Step(double step) {
  StepStatus status = StepStatus::kNormal;
  if (!contacts_current_) DetectContacts();
  double remaining = step;
  double h = step;
  while (remaining > 0.0) {
    h = std::min(h, remaining);
    CaptureState(&rollback_state_);  // reuses its storage: no allocation per sub-step
    if (!Integrate(h)) return StepStatus::kError;
    // keep the contacts of the state before the step in case it is rolled back
    std::swap(pairs_, saved_pairs_);
    DetectContacts();
    bool unreliable = false;
    if (world_.settings.adaptive_time_stepping && NeedsRollback(saved_pairs_, &unreliable) &&
        h / 2 >= kMinimumAdaptiveStep) {
      SetState(rollback_state_);
      std::swap(pairs_, saved_pairs_);
      contacts_current_ = true;
      h /= 2;
      ++statistics_.rollbacks;
      status = std::max(status, StepStatus::kAdaptiveStep);
      continue;
    }
    if (unreliable) status = std::max(status, StepStatus::kContactUnreliable);
    RecordAcceptedContacts();
    time_ += h;
    remaining -= h;
    ++statistics_.steps;
  }
  return status;
}

void Simulator::RecordAcceptedContacts() {
  int contacts = 0;
  for (const ContactPair& pair : pairs_) {
    contacts += static_cast<int>(pair.contacts.size());
    statistics_.max_penetration = std::max(statistics_.max_penetration, pair.max_depth);
  }
  statistics_.max_contacts_in_step = std::max(statistics_.max_contacts_in_step, contacts);
}

bool Simulator::NeedsRollback(const std::vector<ContactPair>& before, bool* unreliable) const {
  bool rollback = false;
  for (const ContactPair& pair : pairs_) {
    const auto previous = std::find_if(before.begin(), before.end(), [&](const ContactPair& p) {
      return p.a == pair.a && p.b == pair.b;
    });
    const bool was_in_contact = previous != before.end();
    if (pair.penetrating) {
      *unreliable = true;
      // a new interpenetration is worth a smaller step; an old one would roll back forever
      if (!was_in_contact || !previous->penetrating) rollback = true;
      continue;
    }
    const double remaining = pair.tolerance - pair.max_depth;
    const double previous_remaining =
        was_in_contact ? previous->tolerance - previous->max_depth : pair.tolerance;
    if (remaining < 0.5 * pair.tolerance && remaining < 0.5 * previous_remaining) rollback = true;
  }
  return rollback;
}

bool Simulator::Integrate(double step) {
  try {
    for (const ContactPair& pair : pairs_) AddContactJoints(pair, step);
    if (solver_.type == SolverType::kQuickStep) {
      dWorldSetQuickStepNumIterations(ode_world_.get(), solver_.quick_step_iterations);
      dWorldQuickStep(ode_world_.get(), step);
    } else {
      dWorldStep(ode_world_.get(), step);
    }
    dJointGroupEmpty(contact_group_.get());
  } catch (const std::exception& error) {
    dJointGroupEmpty(contact_group_.get());
    statistics_.error = error.what();
    statistics_.worst_status = StepStatus::kError;
    return false;
  }
  contacts_current_ = false;
  if (!StateIsFinite()) {
    statistics_.error = "a body state became non-finite at t = " + std::to_string(time_) + " s";
    statistics_.worst_status = StepStatus::kError;
    return false;
  }
  return true;
}

bool Simulator::StateIsFinite() const {
  for (const ObjectBody& object : objects_) {
    const dReal* p = dBodyGetPosition(object.body);
    const dReal* v = dBodyGetLinearVel(object.body);
    const dReal* w = dBodyGetAngularVel(object.body);
    for (int k = 0; k < 3; ++k) {
      if (!std::isfinite(p[k]) || !std::isfinite(v[k]) || !std::isfinite(w[k])) return false;
    }
  }
  return true;
}

void Simulator::DetectContacts() {
  pairs_.clear();
  for (int i = 0; i < object_count(); ++i) {
    ObjectBody& object = objects_[i];
    if (!object.geometry) continue;
    object.bounds = WorldBounds(*object.geometry, GetObjectPose(i), world_.objects[i].sim.padding);
  }
  for (int i = 0; i < object_count(); ++i) {
    const ObjectBody& a = objects_[i];
    if (!a.geometry) continue;
    const Pose X_Wa = GetObjectPose(i);
    for (int t = 0; t < static_cast<int>(terrains_.size()); ++t) {
      const TerrainBody& terrain = terrains_[t];
      if (!terrain.geometry || !AabbsOverlap(a.bounds, terrain.bounds)) continue;
      AddPairContacts(i, -1 - t, *a.geometry, X_Wa, *terrain.geometry, Pose::Identity());
    }
    if (!world_.settings.rigid_object_collisions) continue;
    for (int j = i + 1; j < object_count(); ++j) {
      const ObjectBody& b = objects_[j];
      if (!b.geometry || !AabbsOverlap(a.bounds, b.bounds)) continue;
      AddPairContacts(i, j, *a.geometry, X_Wa, *b.geometry, GetObjectPose(j));
    }
  }
  contacts_current_ = true;
}

void Simulator::AddPairContacts(int a, int b, const CollisionGeometry& geometry_a, const Pose& X_Wa,
                                const CollisionGeometry& geometry_b, const Pose& X_Wb) {
  const BodySimParams& sim_a = world_.objects[a].sim;
  const BodySimParams& sim_b = b >= 0 ? world_.objects[b].sim : world_.terrains[-1 - b].sim;
  scratch_contacts_.clear();
  Collide(geometry_a, X_Wa, sim_a.padding, geometry_b, X_Wb, sim_b.padding, &scratch_contacts_);
  if (scratch_contacts_.empty()) return;
  ContactPair pair;
  pair.a = a;
  pair.b = b;
  pair.tolerance = sim_a.padding + geometry_a.margin() + sim_b.padding + geometry_b.margin();
  for (const Contact& contact : scratch_contacts_) {
    pair.max_depth = std::max(pair.max_depth, contact.depth);
    pair.penetrating = pair.penetrating || contact.penetrating;
  }
  MergeCoincidentContacts(std::max(pair.tolerance, kMinimumMergeRadius), &scratch_contacts_);
  ClusterContacts(world_.settings.max_contacts, kDefaultClusterNormalScale, &scratch_contacts_);
  pair.contacts = scratch_contacts_;
  pairs_.push_back(std::move(pair));
}

void Simulator::AddContactJoints(const ContactPair& pair, double step) {
  dBodyID body_a = objects_[pair.a].body;
  dBodyID body_b = pair.b >= 0 ? objects_[pair.b].body : nullptr;
  const SurfaceDesc& surface_b =
      pair.b >= 0 ? world_.objects[pair.b].sim.surface : world_.terrains[-1 - pair.b].sim.surface;
  const BlendedSurface surface = BlendSurfaces(world_.objects[pair.a].sim.surface, surface_b);
  const SoftContactParams soft = SoftContact(surface.stiffness, surface.damping, step);
  // a layer without stiffness or damping pushes with no force at all
  if (soft.soft && !std::isfinite(soft.cfm)) return;
  for (const Contact& contact : pair.contacts) {
    dContact joint{};
    joint.surface.mode = dContactApprox1;
    joint.surface.mu = std::isinf(surface.friction) ? dInfinity : surface.friction;
    if (soft.soft) {
      joint.surface.mode |= dContactSoftERP | dContactSoftCFM;
      joint.surface.soft_erp = soft.erp;
      joint.surface.soft_cfm = soft.cfm;
    }
    if (surface.restitution > 0.0) {
      joint.surface.mode |= dContactBounce;
      joint.surface.bounce = surface.restitution;
      joint.surface.bounce_vel = kBounceVelocityThreshold;
    }
    dVector3 velocity_a = {0, 0, 0}, velocity_b = {0, 0, 0};
    const Vec3& p = contact.position;
    if (body_a) dBodyGetPointVel(body_a, p.x(), p.y(), p.z(), velocity_a);
    if (body_b) dBodyGetPointVel(body_b, p.x(), p.y(), p.z(), velocity_b);
    const Vec3 relative = ToVec3(velocity_a) - ToVec3(velocity_b);
    const double normal_speed = relative.dot(contact.normal);
    if (!soft.soft && surface.restitution > 0.0 && normal_speed < -kBounceVelocityThreshold) {
      // a bouncing impact: the velocity constraint with restitution sets the rebound; correcting
      // the layer overlap as well would add energy (Klamp't's spheres bounce too high for this)
      joint.surface.mode |= dContactSoftERP;
      joint.surface.soft_erp = 0.0;
    }
    // friction along the sliding direction makes ODE's per-axis friction isotropic
    const Vec3 sliding = relative - normal_speed * contact.normal;
    if (sliding.norm() > kSlidingSpeedThreshold) {
      const Vec3 direction = sliding.normalized();
      joint.surface.mode |= dContactFDir1;
      joint.fdir1[0] = direction.x();
      joint.fdir1[1] = direction.y();
      joint.fdir1[2] = direction.z();
    }
    joint.geom.pos[0] = p.x();
    joint.geom.pos[1] = p.y();
    joint.geom.pos[2] = p.z();
    joint.geom.normal[0] = contact.normal.x();
    joint.geom.normal[1] = contact.normal.y();
    joint.geom.normal[2] = contact.normal.z();
    joint.geom.depth = contact.depth;
    dJointID id = dJointCreateContact(ode_world_.get(), contact_group_.get(), &joint);
    dJointAttach(id, body_a, body_b);
  }
}

}  // namespace lamina::core
