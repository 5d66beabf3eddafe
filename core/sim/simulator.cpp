// SPDX-License-Identifier: MIT
#include "core/sim/simulator.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "core/contact/contact_clustering.h"
#include "core/contact/surface_blend.h"
#include "core/geometry/shrink.h"
#include "core/sim/energy_guard.h"
#include "core/sim/ode_conversions.h"
#include "core/sim/ode_handle.h"
#include "core/sim/ode_robot.h"
#include "core/sim/simulator_records.h"

namespace lamina::core {

namespace {

void RequireFinite(bool finite, const char* what) {
  if (!finite) throw std::invalid_argument(std::string(what) + " must be finite");
}

constexpr double kHardContactCfm = 1e-9;
// a pair whose layer moved less than this fraction of its thickness in a step has settled: no
// reason to retake the step
constexpr double kSettledLayerFraction = 0.1;
// a layer with less than this fraction of its thickness left is pressed through (resting on
// the geometry under it)
constexpr double kPressedThroughFraction = 0.01;
// contacts closer than this fraction of the pair's padding sum (or than kMinimumMergeRadius)
// count as one point: the same corner reported by both meshes. Merging farther apart points
// would move a pair's contacts by jumps as points enter and leave the layer, and a body resting
// on them could pick up energy from that.
constexpr double kMergeFraction = 0.05;
constexpr double kMinimumMergeRadius = 1e-4;
// a seed for ODE's random generator from the simulated time (a 64-bit mix of its bits)
unsigned long QuickStepSeed(double time) {
  uint64_t x = std::bit_cast<uint64_t>(time);
  x ^= x >> 33;
  x *= 0xff51afd7ed558ccdULL;
  x ^= x >> 33;
  return static_cast<unsigned long>(x);
}

// sliding slower than this keeps ODE's default friction directions (m/s)
constexpr double kSlidingSpeedThreshold = 1e-6;

void SetBodyRotation(dBodyID body, const Mat3& rotation) {
  const Eigen::Quaterniond q(rotation);
  const dQuaternion ode_q = {q.w(), q.x(), q.y(), q.z()};
  dBodySetQuaternion(body, ode_q);
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

bool BoundsOverlapInYZ(const Eigen::AlignedBox3d& a, const Eigen::AlignedBox3d& b) {
  return a.min().y() <= b.max().y() && b.min().y() <= a.max().y() && a.min().z() <= b.max().z() &&
         b.min().z() <= a.max().z();
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

/// ODE's force readout of one contact joint of the current step.
struct Simulator::JointFeedbackSlot {
  dJointFeedback ode{};
  dJointFeedback core{};  ///< the rigid-core joint under a soft contact (has_core)
  bool has_core = false;
  int record = -1;    ///< index in feedback_
  bool flip = false;  ///< the joint's first body is the record's second
  FeedbackContact contact;
};

Simulator::Simulator(const WorldDesc& world, const SolverSettings& solver) : Simulator(world) {
  SetSolver(solver);
}

Simulator::Simulator(const WorldDesc& world)
    : world_(world),
      ode_world_(nullptr, [](dxWorld* w) { dWorldDestroy(w); }),
      contact_group_(nullptr, [](dxJointGroup* g) { dJointGroupDestroy(g); }) {
  EnsureOdeInitialized();
  Build();
  ApplyInitialState();
}

Simulator::~Simulator() {
  TearDown();
}

// the ODE world, bodies, robots and controllers of world_ (at the initial state)
void Simulator::Build() {
  diagnostics_ = Diagnostics();
  ode_world_.reset(dWorldCreate());
  contact_group_.reset(dJointGroupCreate(0));
  dWorldSetERP(ode_world_.get(), world_.settings.erp);
  dWorldSetCFM(ode_world_.get(), world_.settings.cfm);
  dWorldSetAutoDisableFlag(ode_world_.get(), 0);
  SetGravity(world_.settings.gravity);
  BuildBodies();
  sleep_.assign(object_ids_.size(), ObjectSleep{});
  halted_ = false;
}

// everything Build made; the robots first (they destroy their own joints and bodies)
void Simulator::TearDown() {
  robots_.clear();
  controllers_.clear();
  robot_scratch_.clear();
  self_collision_pairs_.clear();
  bodies_.clear();
  object_ids_.clear();
  pairs_.clear();
  saved_pairs_.clear();
  candidates_.clear();
  saved_candidates_.clear();
  anchors_.clear();
  sleep_.clear();
  joint_feedback_.clear();
  contacts_current_ = false;
  contact_group_.reset();
  ode_world_.reset();
}

// MuJoCo's mj_recompile: a new simulation of world_ in the state `state` (time, bodies, robots,
// controllers, anchors, sleep); statistics and contact-feedback registrations are kept
void Simulator::RebuildWith(const SimState& state) {
  TearDown();
  Build();
  SetState(state);
}

int Simulator::body_count() const {
  return static_cast<int>(bodies_.size());
}

int Simulator::object_count() const {
  return static_cast<int>(object_ids_.size());
}

void Simulator::BuildBodies() {
  bodies_.resize(world_.IdCount());
  for (int id = 0; id < world_.IdCount(); ++id) {
    const WorldId resolved = world_.Resolve(id);
    BodyRecord& body = bodies_[id];
    body.kind = resolved.kind;
    if (resolved.kind == WorldId::Kind::kTerrain) {
      body.index = resolved.index;
      body.dynamic = false;
      RebuildCollisionGeometry(id);
    } else if (resolved.kind == WorldId::Kind::kRigidObject) {
      body.index = resolved.index;
      object_ids_.push_back(id);
      const RigidObjectDesc& object = world_.objects[body.index];
      body.body = dBodyCreate(ode_world_.get());
      // exact orientation update for the body's angular velocity (ODE's default is first order)
      dBodySetFiniteRotationMode(body.body, 1);
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
      body.mass = mass.mass;
      body.inertia << mass.I[0], mass.I[1], mass.I[2], mass.I[4], mass.I[5], mass.I[6], mass.I[8],
          mass.I[9], mass.I[10];
      RebuildCollisionGeometry(id);
    } else if (resolved.kind == WorldId::Kind::kRobot) {
      body.index = resolved.index;
      BuildRobot(resolved.index, id + 1);
    }
  }
}

void Simulator::RebuildCollisionGeometry(int id) {
  BodyRecord& body = bodies_[id];
  const GeometryDesc* desc = nullptr;
  if (body.kind == WorldId::Kind::kTerrain) desc = &world_.terrains[body.index].geometry;
  if (body.kind == WorldId::Kind::kRigidObject) desc = &world_.objects[body.index].geometry;
  const BodySimParams& sim = sim_params(id);
  if (body.kind == WorldId::Kind::kRobotLink) {
    body.geometry = LinkCollisionGeometry(body.index, body.link);
    if (body.geometry && body.body == nullptr) {
      body.bounds = WorldBounds(*body.geometry, body.fixed_pose, sim.padding);
    }
    contacts_current_ = false;
    return;
  }
  if (desc == nullptr) return;
  if (sim.preshrink != Preshrink::kNone && sim.padding > 0.0) {
    // shrunk geometries are the body's own: a shrunk mesh is new for every padding, so it cannot
    // be a key of the shared cache
    body.geometry = CollisionGeometry::Build(ShrinkGeometry(*desc, sim.padding, &diagnostics_));
  } else {
    body.geometry = geometry_cache_.Get(*desc);
  }
  if (body.geometry && body.kind == WorldId::Kind::kTerrain) {
    body.bounds = WorldBounds(*body.geometry, Pose::Identity(), sim.padding);
  }
  contacts_current_ = false;
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
  }
  anchors_.clear();
  for (int i = 0; i < static_cast<int>(sleep_.size()); ++i) {
    if (sleep_[i].asleep) SetObjectAsleep(i, false);
  }
  sleep_.assign(object_ids_.size(), ObjectSleep{});
  ForgetEnergies();
}

void Simulator::Reset() {
  if (halted_) {
    TearDown();
    Build();
  }
  time_ = 0.0;
  statistics_ = SimStatistics();
  for (BodyRecord& body : bodies_) {
    body.force.setZero();
    body.torque.setZero();
  }
  for (ContactFeedbackRecord& record : feedback_) record.BeginCall();
  ApplyInitialState();
}

void Simulator::SetSolver(const SolverSettings& solver) {
  world_.settings.solver = solver.type;
  world_.settings.quick_step_iterations = solver.quick_step_iterations;
}

void Simulator::ForgetEnergies() {
  for (BodyRecord& body : bodies_) body.energy = -1.0;
}

// ---- body access ------------------------------------------------------------------------

Simulator::BodyRecord* Simulator::record(int id) {
  return id >= 0 && id < body_count() ? &bodies_[id] : nullptr;
}

const Simulator::BodyRecord* Simulator::record(int id) const {
  return id >= 0 && id < body_count() ? &bodies_[id] : nullptr;
}

const BodySimParams& Simulator::sim_params(int id) const {
  const BodyRecord& body = bodies_[id];
  if (body.kind == WorldId::Kind::kRobotLink) return world_.robots[body.index].links[body.link].sim;
  return body.kind == WorldId::Kind::kTerrain ? world_.terrains[body.index].sim
                                              : world_.objects[body.index].sim;
}

BodySimParams* Simulator::mutable_sim_params(int id) {
  const BodyRecord* body = record(id);
  if (body == nullptr) return nullptr;
  if (body->kind == WorldId::Kind::kTerrain) return &world_.terrains[body->index].sim;
  if (body->kind == WorldId::Kind::kRigidObject) return &world_.objects[body->index].sim;
  if (body->kind == WorldId::Kind::kRobotLink) {
    return &world_.robots[body->index].links[body->link].sim;
  }
  return nullptr;
}

Pose Simulator::GetBodyPose(const BodyRecord& body) const {
  if (body.body == nullptr) return body.fixed_pose;
  Pose pose = Pose::Identity();
  pose.linear() = ToMat3(dBodyGetRotation(body.body)) * body.rotation_in_body;
  pose.translation() = ToVec3(dBodyGetPosition(body.body)) - pose.linear() * body.com;
  return pose;
}

void Simulator::SetBodyPose(const BodyRecord& body, const Pose& pose) {
  RequireFinite(pose.matrix().allFinite(), "a body pose");
  if (body.body == nullptr) return;
  contacts_current_ = false;
  const Vec3 com_world = pose * body.com;
  dBodySetPosition(body.body, com_world.x(), com_world.y(), com_world.z());
  SetBodyRotation(body.body, pose.linear() * body.rotation_in_body.transpose());
}

Twist Simulator::GetBodyVelocity(const BodyRecord& body) const {
  if (body.body == nullptr) return {};
  const Vec3 angular = ToVec3(dBodyGetAngularVel(body.body));
  const Vec3 com_offset = GetBodyPose(body).linear() * body.com;
  // v_origin = v_com - w x (com - origin)
  return {ToVec3(dBodyGetLinearVel(body.body)) - angular.cross(com_offset), angular};
}

void Simulator::SetBodyVelocity(const BodyRecord& body, const Twist& velocity) {
  RequireFinite(velocity.linear.allFinite() && velocity.angular.allFinite(), "a body velocity");
  if (body.body == nullptr) return;
  const Vec3 com_offset = GetBodyPose(body).linear() * body.com;
  const Vec3 com_velocity = velocity.linear + velocity.angular.cross(com_offset);
  dBodySetLinearVel(body.body, com_velocity.x(), com_velocity.y(), com_velocity.z());
  dBodySetAngularVel(body.body, velocity.angular.x(), velocity.angular.y(), velocity.angular.z());
}

Pose Simulator::GetObjectPose(int object) const {
  return GetBodyPose(bodies_[object_ids_[object]]);
}

void Simulator::SetObjectPose(int object, const Pose& pose) {
  SetBodyPose(bodies_[object_ids_[object]], pose);
  bodies_[object_ids_[object]].energy = -1.0;
  ForgetAnchors(&anchors_, object_ids_[object]);
  WakeBody(object_ids_[object]);
  WakeTouching(object_ids_[object]);
}

Twist Simulator::GetObjectVelocity(int object) const {
  return GetBodyVelocity(bodies_[object_ids_[object]]);
}

void Simulator::SetObjectVelocity(int object, const Twist& velocity) {
  SetBodyVelocity(bodies_[object_ids_[object]], velocity);
  bodies_[object_ids_[object]].energy = -1.0;
  WakeBody(object_ids_[object]);
}

bool Simulator::BodyEnabled(int id) const {
  const BodyRecord* body = record(id);
  return body != nullptr && body->enabled;
}

void Simulator::SetBodyEnabled(int id, bool enabled) {
  BodyRecord* body = record(id);
  if (body == nullptr || body->enabled == enabled) return;
  body->enabled = enabled;
  body->energy = -1.0;
  contacts_current_ = false;
  if (body->body == nullptr) return;
  if (enabled) {
    dBodyEnable(body->body);
    WakeBody(id);
  } else {
    dBodyDisable(body->body);
    WakeTouching(id);
  }
}

bool Simulator::BodyDynamic(int id) const {
  const BodyRecord* body = record(id);
  return body != nullptr && body->body != nullptr && body->dynamic;
}

void Simulator::SetBodyDynamic(int id, bool dynamic) {
  BodyRecord* body = record(id);
  if (body == nullptr || body->body == nullptr || body->dynamic == dynamic) return;
  body->dynamic = dynamic;
  body->energy = -1.0;
  contacts_current_ = false;  // which pairs may collide changed
  WakeBody(id);
  WakeTouching(id);
  if (dynamic) {
    dBodySetDynamic(body->body);
  } else {
    dBodySetKinematic(body->body);
  }
}

Pose Simulator::BodyPose(int id) const {
  const BodyRecord* body = record(id);
  return body != nullptr ? GetBodyPose(*body) : Pose::Identity();
}

void Simulator::SetBodyPose(int id, const Pose& pose) {
  BodyRecord* body = record(id);
  if (body == nullptr) return;
  SetBodyPose(*body, pose);
  body->energy = -1.0;
  ForgetAnchors(&anchors_, id);
  WakeBody(id);
  WakeTouching(id);
}

Twist Simulator::BodyVelocity(int id) const {
  const BodyRecord* body = record(id);
  return body != nullptr ? GetBodyVelocity(*body) : Twist{};
}

void Simulator::SetBodyVelocity(int id, const Twist& velocity) {
  BodyRecord* body = record(id);
  if (body == nullptr) return;
  SetBodyVelocity(*body, velocity);
  body->energy = -1.0;
  WakeBody(id);
}

void Simulator::AddBodyForce(int id, const Vec3& force, const Vec3& point) {
  RequireFinite(force.allFinite() && point.allFinite(), "an applied force");
  BodyRecord* body = record(id);
  if (body == nullptr || body->body == nullptr) return;
  const Vec3 com = ToVec3(dBodyGetPosition(body->body));
  body->force += force;
  body->torque += (point - com).cross(force);
  WakeBody(id);
}

void Simulator::AddBodyWrench(int id, const Vec3& force, const Vec3& torque) {
  RequireFinite(force.allFinite() && torque.allFinite(), "an applied wrench");
  BodyRecord* body = record(id);
  if (body == nullptr || body->body == nullptr) return;
  body->force += force;
  body->torque += torque;
  WakeBody(id);
}

void Simulator::UpdateWorld(WorldDesc* world) const {
  if (world->objects.size() != world_.objects.size() ||
      world->terrains.size() != world_.terrains.size()) {
    throw std::invalid_argument("UpdateWorld: the world does not match the simulated one");
  }
  world->settings = world_.settings;
  for (size_t t = 0; t < world_.terrains.size(); ++t)
    world->terrains[t].sim = world_.terrains[t].sim;
  for (int i = 0; i < object_count(); ++i) {
    RigidObjectDesc& object = world->objects[i];
    object.sim = world_.objects[i].sim;
    object.pose = GetObjectPose(i);
    object.initial_velocity = GetObjectVelocity(i);
  }
  UpdateWorldRobots(world);
}

// ---- state ------------------------------------------------------------------------------

SimState Simulator::GetState() const {
  SimState state;
  CaptureState(&state);
  return state;
}

void Simulator::CaptureState(SimState* state) const {
  CaptureBodyState(state, true);
}

void Simulator::CaptureBodyState(SimState* state, bool with_controllers) const {
  state->time = time_;
  state->objects.resize(object_ids_.size());
  for (size_t i = 0; i < object_ids_.size(); ++i) {
    state->objects[i] = ReadBodyState(bodies_[object_ids_[i]].body);
  }
  CaptureRobotState(state, with_controllers);
  state->anchors = anchors_;
  state->sleep = sleep_;
}

void Simulator::SetState(const SimState& state) {
  // ODE cannot be trusted after one of its errors: a stopped simulation is built anew
  if (halted_) RebuildWith(state);
  RestoreState(state);
  RestoreControllers(state);
  ForgetEnergies();
}

void Simulator::RestoreState(const SimState& state) {
  contacts_current_ = false;
  time_ = state.time;
  for (size_t i = 0; i < object_ids_.size() && i < state.objects.size(); ++i) {
    WriteBodyState(bodies_[object_ids_[i]].body, state.objects[i]);
  }
  RestoreRobotState(state);
  anchors_ = state.anchors;
  // a state from elsewhere (or taken with sleeping on while it is off now) wakes everything
  const bool usable = world_.settings.sleeping && state.sleep.size() == sleep_.size();
  for (size_t i = 0; i < sleep_.size(); ++i) {
    sleep_[i].idle_time = usable ? state.sleep[i].idle_time : 0.0;
    SetObjectAsleep(static_cast<int>(i), usable && state.sleep[i].asleep);
  }
}

// ---- stepping ---------------------------------------------------------------------------

StepStatus Simulator::Simulate(double dt) {
  if (halted_) return StepStatus::kError;
  Stopwatch total;
  const SimTimeSplit before = statistics_.time_split;
  for (ContactFeedbackRecord& record : feedback_) record.BeginCall();
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
  // applied forces last for one call
  for (BodyRecord& body : bodies_) {
    body.force.setZero();
    body.torque.setZero();
  }
  statistics_.worst_status = std::max(statistics_.worst_status, worst);
  SimTimeSplit& split = statistics_.time_split;
  const double measured = split.total() - before.total();
  split.other += std::max(0.0, total.Lap() - measured);
  return worst;
}

// one sub-step of length `step`; with adaptive stepping, a tentative step that uses up more
// than half of a boundary layer, or makes geometries interpenetrate, is undone and retaken in
// halves until it is acceptable or the step reaches settings.minimum_adaptive_step
StepStatus Simulator::Step(double step) {
  StepStatus status = StepStatus::kNormal;
  RunControllers(step);
  if (!contacts_current_) DetectContacts();
  MeasureUnknownEnergies();
  if (StopOverflowingBodies()) status = StepStatus::kUnstable;
  double remaining = step;
  double h = step;
  bool recovered = false;
  while (remaining > 0.0) {
    h = std::min(h, remaining);
    // reuses its storage: no allocation per sub-step; controllers only change after a step
    CaptureBodyState(&rollback_state_, false);
    const IntegrateResult result = Integrate(h);
    if (result == IntegrateResult::kOdeError) {
      // ODE's internal state cannot be trusted after one of its errors
      statistics_.worst_status = StepStatus::kError;
      halted_ = true;
      return StepStatus::kError;
    }
    if (result == IntegrateResult::kNonFinite) {
      // a step that blew up is undone once with the culprits stopped
      if (recovered || !RecoverFromFailedStep()) {
        statistics_.error = "a body state became non-finite at t = " + std::to_string(time_) + " s";
        statistics_.worst_status = StepStatus::kError;
        halted_ = true;
        return StepStatus::kError;
      }
      recovered = true;
      status = std::max(status, StepStatus::kUnstable);
      continue;
    }
    // keep the contacts of the state before the step in case it is rolled back
    std::swap(pairs_, saved_pairs_);
    std::swap(candidates_, saved_candidates_);
    DetectContacts();
    bool unreliable = false;
    if (world_.settings.adaptive_time_stepping && NeedsRollback(saved_pairs_, &unreliable) &&
        h / 2 >= world_.settings.minimum_adaptive_step) {
      RestoreState(rollback_state_);
      std::swap(pairs_, saved_pairs_);
      std::swap(candidates_, saved_candidates_);
      contacts_current_ = true;
      h /= 2;
      ++statistics_.rollbacks;
      status = std::max(status, StepStatus::kAdaptiveStep);
      continue;
    }
    if (unreliable) status = std::max(status, StepStatus::kContactUnreliable);
    if (CorrectInstabilities(h)) status = std::max(status, StepStatus::kUnstable);
    AcceptStep(h);
    remaining -= h;
  }
  return status;
}

void Simulator::AcceptStep(double step) {
  RecordAcceptedContacts();
  RecordFeedback(step);
  AcceptRobotStep(step);
  time_ += step;
  ++statistics_.steps;
  UpdateSleep(step);
}

// a step left some body with a non-finite state: go back to the state before it and stop the
// bodies that blew up (their velocities become zero); false if the state before was not finite
bool Simulator::RecoverFromFailedStep() {
  // blown up: non-finite after the step, or moving absurdly fast before it
  std::vector<bool> blown(object_ids_.size(), false);
  bool any = false;
  for (size_t i = 0; i < object_ids_.size(); ++i) {
    const dBodyID body = bodies_[object_ids_[i]].body;
    const Vec3 p = ToVec3(dBodyGetPosition(body));
    const Vec3 v = ToVec3(dBodyGetLinearVel(body));
    const Vec3 w = ToVec3(dBodyGetAngularVel(body));
    const BodyState& before = rollback_state_.objects[i];
    const double speed_squared =
        before.linear_velocity.squaredNorm() + before.angular_velocity.squaredNorm();
    blown[i] = !p.allFinite() || !v.allFinite() || !w.allFinite() || !std::isfinite(speed_squared);
    any = any || blown[i];
  }
  RestoreState(rollback_state_);
  if (!any || !StateIsFinite()) return false;
  for (size_t i = 0; i < object_ids_.size(); ++i) {
    if (!blown[i]) continue;
    BodyRecord& body = bodies_[object_ids_[i]];
    dBodySetLinearVel(body.body, 0, 0, 0);
    dBodySetAngularVel(body.body, 0, 0, 0);
    body.energy = 0.0;
    ++statistics_.instability_corrections;
  }
  contacts_current_ = true;  // positions are those of the contacts found before the step
  return true;
}

// the energy of a body whose state was just set is taken from the state it was given, so that the
// set itself is not mistaken for a blow-up while the step after it is still checked
void Simulator::MeasureUnknownEnergies() {
  for (BodyRecord& body : bodies_) {
    if (body.energy >= 0.0 || !body.moves_freely()) continue;
    body.energy = BodyKineticEnergy(body);
  }
}

// a body whose kinetic energy overflows a double would make ODE fail inside its step (and ODE
// cannot be trusted after that): it is stopped before the step instead
bool Simulator::StopOverflowingBodies() {
  bool stopped = false;
  for (BodyRecord& body : bodies_) {
    if (!body.moves_freely() || std::isfinite(body.energy)) continue;
    dBodySetLinearVel(body.body, 0, 0, 0);
    dBodySetAngularVel(body.body, 0, 0, 0);
    body.energy = 0.0;
    ++statistics_.instability_corrections;
    stopped = true;
  }
  return stopped;
}

double Simulator::BodyKineticEnergy(const BodyRecord& body) const {
  const Mat3 R = ToMat3(dBodyGetRotation(body.body));
  return KineticEnergy(body.mass, R * body.inertia * R.transpose(),
                       ToVec3(dBodyGetLinearVel(body.body)), ToVec3(dBodyGetAngularVel(body.body)));
}

// energy a body may gain from its contacts within one step without anything being wrong: the
// position correction of its deepest overlap (at most ERP = 1: speed depth / h) and the spring
// energy stored in a soft layer (½ k depth²)
double Simulator::ContactEnergyAllowance(int id, double step) const {
  double allowance = 0.0;
  const BodyRecord& body = bodies_[id];
  for (const ContactPair& pair : saved_pairs_) {
    if (pair.a != id && pair.b != id) continue;
    const double correction_speed = pair.max_depth / step;
    allowance += 0.5 * body.mass * correction_speed * correction_speed;
    allowance += 0.5 * body.mass * pair.anchor_speed * pair.anchor_speed;
    const double k =
        BlendSurfaces(sim_params(pair.a).surface, sim_params(pair.b).surface).stiffness;
    if (std::isfinite(k)) allowance += 0.5 * k * pair.max_depth * pair.max_depth;
  }
  return allowance;
}

bool Simulator::CorrectInstabilities(double step) {
  // bodies pushed by a kinematic body may gain any energy: leave them out of the check
  // scratch storage kept between steps: no allocation per sub-step
  std::vector<bool>& pushed = energy_scratch_.pushed;
  pushed.assign(bodies_.size(), false);
  for (const ContactPair& pair : saved_pairs_) {
    if (bodies_[pair.a].body && !bodies_[pair.a].dynamic) pushed[pair.b] = true;
    if (bodies_[pair.b].body && !bodies_[pair.b].dynamic) pushed[pair.a] = true;
  }
  std::vector<BodyEnergySample>& samples = energy_scratch_.samples;
  std::vector<int>& checked = energy_scratch_.checked;
  samples.clear();
  checked.clear();
  for (size_t i = 0; i < object_ids_.size(); ++i) {
    const int id = object_ids_[i];
    BodyRecord& body = bodies_[id];
    if (!body.moves_freely()) continue;
    const Vec3 v = ToVec3(dBodyGetLinearVel(body.body));
    const Vec3 w = ToVec3(dBodyGetAngularVel(body.body));
    const double energy = BodyKineticEnergy(body);
    const double before = body.energy;
    body.energy = energy;
    if (before < 0.0 || pushed[id]) continue;
    const BodyState& start = rollback_state_.objects[i];
    const Vec3 force = body.force + body.mass * world_.settings.gravity;
    samples.push_back({body.mass, before, energy,
                       ExternalWorkBound(force, body.torque, start.linear_velocity.norm(), v.norm(),
                                         start.angular_velocity.norm(), w.norm(), step) +
                           ContactEnergyAllowance(id, step)});
    checked.push_back(id);
  }
  const std::vector<double> scales = InstabilityScales(samples);
  for (size_t k = 0; k < scales.size(); ++k) {
    if (scales[k] >= 1.0) continue;
    BodyRecord& body = bodies_[checked[k]];
    const Vec3 v = scales[k] * ToVec3(dBodyGetLinearVel(body.body));
    const Vec3 w = scales[k] * ToVec3(dBodyGetAngularVel(body.body));
    dBodySetLinearVel(body.body, v.x(), v.y(), v.z());
    dBodySetAngularVel(body.body, w.x(), w.y(), w.z());
    body.energy *= scales[k] * scales[k];
    ++statistics_.instability_corrections;
  }
  return !scales.empty();
}

void Simulator::RecordAcceptedContacts() {
  int contacts = 0;
  for (const ContactPair& pair : pairs_) {
    statistics_.max_penetration = std::max(statistics_.max_penetration, pair.max_depth);
  }
  // the joints of the accepted step came from the contacts before it
  for (const ContactPair& pair : saved_pairs_) contacts += static_cast<int>(pair.contacts.size());
  statistics_.contact_joints += contacts;
  statistics_.max_contacts_in_step = std::max(statistics_.max_contacts_in_step, contacts);
}

// a tentative step is retaken in halves when it let a pair interpenetrate that had layer to
// spare before, or when it used up more than half of a pair's layer at once (more than half of
// what remained, and a noticeable part of the layer: noise at a settled contact is no reason)
bool Simulator::NeedsRollback(const std::vector<ContactPair>& before, bool* unreliable) const {
  bool rollback = false;
  for (const ContactPair& pair : pairs_) {
    const auto previous = std::find_if(before.begin(), before.end(), [&](const ContactPair& p) {
      return p.a == pair.a && p.b == pair.b;
    });
    const bool was_in_contact = previous != before.end();
    const double previous_depth = was_in_contact ? previous->max_depth : 0.0;
    const double previous_remaining = pair.tolerance - previous_depth;
    if (pair.penetrating) {
      *unreliable = true;
      // a new interpenetration through a layer that had room left is worth a smaller step; one
      // under a layer already pressed through (a soft layer resting on its core) or an old one
      // would roll back forever
      const bool had_room = previous_remaining > kPressedThroughFraction * pair.tolerance;
      if (!was_in_contact || (!previous->penetrating && had_room)) rollback = true;
      continue;
    }
    const double remaining = pair.tolerance - pair.max_depth;
    if (remaining < 0.5 * pair.tolerance && remaining < 0.5 * previous_remaining &&
        pair.max_depth - previous_depth > kSettledLayerFraction * pair.tolerance) {
      rollback = true;
    }
  }
  return rollback;
}

Simulator::IntegrateResult Simulator::Integrate(double step) {
  Stopwatch watch;
  IntegrateResult result = IntegrateResult::kOk;
  try {
    size_t feedback_slots = 0;
    if (!feedback_.empty()) {
      for (const ContactPair& pair : pairs_) {
        if (FindFeedback(pair.a, pair.b)) feedback_slots += pair.contacts.size();
      }
    }
    // sized before any joint points into it
    joint_feedback_.resize(feedback_slots);
    next_feedback_slot_ = 0;
    if (world_.settings.sleeping) WakeTouchedSleepers();
    UpdateFrictionAnchors(step);
    const Vec3* anchor_velocities = anchor_velocities_.data();
    for (const ContactPair& pair : pairs_) {
      // no joint ties a sleeper to what cannot wake it (ODE would enable it through the joint)
      if (!world_.settings.sleeping || !SleepsAgainstInert(pair))
        AddContactJoints(pair, anchor_velocities, step);
      anchor_velocities += pair.contacts.size();
    }
    joint_feedback_.resize(next_feedback_slot_);  // slots of pairs that made no joint
    ApplyAccumulatedForces();
    PrepareRobotsForStep(step);
    if (world_.settings.solver == SolverType::kQuickStep) {
      dWorldSetQuickStepNumIterations(ode_world_.get(), world_.settings.quick_step_iterations);
      // QuickStep shuffles its rows with ODE's process-wide random generator: seeded from the
      // state's time, the same state always takes the same step, whatever ran before
      dRandSetSeed(QuickStepSeed(time_));
      dWorldQuickStep(ode_world_.get(), step);
    } else {
      dWorldStep(ode_world_.get(), step);
    }
    dJointGroupEmpty(contact_group_.get());
  } catch (const std::exception& error) {
    dJointGroupEmpty(contact_group_.get());
    statistics_.error = error.what();
    result = IntegrateResult::kOdeError;
  }
  statistics_.time_split.solver += watch.Lap();
  contacts_current_ = false;
  if (result == IntegrateResult::kOk && !StateIsFinite()) result = IntegrateResult::kNonFinite;
  return result;
}

void Simulator::ApplyAccumulatedForces() {
  for (const BodyRecord& body : bodies_) {
    if (!body.moves_freely() || !dBodyIsEnabled(body.body)) continue;  // asleep
    if (!body.force.isZero(0.0)) {
      dBodyAddForce(body.body, body.force.x(), body.force.y(), body.force.z());
    }
    if (!body.torque.isZero(0.0)) {
      dBodyAddTorque(body.body, body.torque.x(), body.torque.y(), body.torque.z());
    }
  }
}

bool Simulator::StateIsFinite() const {
  for (const BodyRecord& body : bodies_) {
    if (body.body == nullptr) continue;
    const dReal* p = dBodyGetPosition(body.body);
    const dReal* v = dBodyGetLinearVel(body.body);
    const dReal* w = dBodyGetAngularVel(body.body);
    for (int k = 0; k < 3; ++k) {
      if (!std::isfinite(p[k]) || !std::isfinite(v[k]) || !std::isfinite(w[k])) return false;
    }
  }
  return true;
}

// ---- contacts ---------------------------------------------------------------------------

void Simulator::DetectContacts() {
  Stopwatch watch;
  pairs_.clear();
  FindCandidatePairs();
  statistics_.time_split.broad_phase += watch.Lap();
  for (const auto& [first, second] : candidates_) AddPairContacts(first, second);
  contacts_current_ = true;
}

bool Simulator::MayCollide(const BodyRecord& a, const BodyRecord& b) const {
  // static and kinematic bodies do not push each other
  if (!a.moves_freely() && !b.moves_freely()) return false;
  if (a.kind == WorldId::Kind::kRigidObject && b.kind == WorldId::Kind::kRigidObject) {
    return world_.settings.rigid_object_collisions;
  }
  if (a.kind == WorldId::Kind::kRobotLink && b.kind == WorldId::Kind::kRobotLink) {
    if (a.index != b.index) return world_.settings.robot_robot_collisions;
    // links welded into one body never push each other; other pairs when allowed
    if (a.body == b.body || !world_.settings.robot_self_collisions) return false;
    const std::vector<std::pair<int, int>>& allowed = self_collision_pairs_[a.index];
    return std::binary_search(allowed.begin(), allowed.end(),
                              std::make_pair(std::min(a.link, b.link), std::max(a.link, b.link)));
  }
  return true;
}

// sweep and prune along x over the padded bounds; candidates come out sorted by id pair, so the
// order of contact joints does not depend on where bodies are
void Simulator::FindCandidatePairs() {
  collidable_.clear();
  for (int id = 0; id < body_count(); ++id) {
    BodyRecord& body = bodies_[id];
    if (!body.geometry || !body.enabled) continue;
    if (body.body)
      body.bounds = WorldBounds(*body.geometry, GetBodyPose(body), sim_params(id).padding);
    if (body.bounds.isEmpty()) continue;
    collidable_.push_back(id);
  }
  std::sort(collidable_.begin(), collidable_.end(), [&](int a, int b) {
    const double ax = bodies_[a].bounds.min().x(), bx = bodies_[b].bounds.min().x();
    return ax != bx ? ax < bx : a < b;
  });
  candidates_.clear();
  for (size_t i = 0; i < collidable_.size(); ++i) {
    const BodyRecord& a = bodies_[collidable_[i]];
    for (size_t j = i + 1; j < collidable_.size(); ++j) {
      const BodyRecord& b = bodies_[collidable_[j]];
      if (b.bounds.min().x() > a.bounds.max().x()) break;
      if (!BoundsOverlapInYZ(a.bounds, b.bounds) || !MayCollide(a, b)) continue;
      candidates_.emplace_back(std::min(collidable_[i], collidable_[j]),
                               std::max(collidable_[i], collidable_[j]));
    }
  }
  std::sort(candidates_.begin(), candidates_.end());
}

void Simulator::AddPairContacts(int first, int second) {
  // a is a body that moves (ODE attaches contact joints to it); normals point into a
  int a = first, b = second;
  if (bodies_[a].body == nullptr) std::swap(a, b);
  const BodyRecord& body_a = bodies_[a];
  const BodyRecord& body_b = bodies_[b];
  const BodySimParams& sim_a = sim_params(a);
  const BodySimParams& sim_b = sim_params(b);
  Stopwatch watch;
  scratch_contacts_.clear();
  Collide(*body_a.geometry, GetBodyPose(body_a), sim_a.padding, *body_b.geometry,
          GetBodyPose(body_b), sim_b.padding, &scratch_contacts_);
  statistics_.time_split.contact_generation += watch.Lap();
  if (scratch_contacts_.empty()) return;
  ContactPair pair;
  pair.a = a;
  pair.b = b;
  pair.tolerance =
      sim_a.padding + body_a.geometry->margin() + sim_b.padding + body_b.geometry->margin();
  for (const Contact& contact : scratch_contacts_) {
    pair.max_depth = std::max(pair.max_depth, contact.depth);
    pair.penetrating = pair.penetrating || contact.penetrating;
  }
  MergeCoincidentContacts(std::max(kMergeFraction * pair.tolerance, kMinimumMergeRadius),
                          &scratch_contacts_);
  ClusterContacts(world_.settings.max_contacts, kDefaultClusterNormalScale, &scratch_contacts_);
  pair.contacts = scratch_contacts_;
  pairs_.push_back(std::move(pair));
  statistics_.time_split.clustering += watch.Lap();
}

// the depth that weighs a contact's share of its pair's stiffness: never quite zero, so that
// every contact of the pair keeps a finite law
double Simulator::ContactWeightDepth(const Contact& contact, const ContactPair& pair) {
  return std::max(contact.depth, 1e-6 * pair.tolerance + 1e-12);
}

// the world's ERP, limited so that an overlap of `depth` is pushed out at most at
// kMaxCorrectionSpeed
double Simulator::HardContactErp(double depth, double step) const {
  const double erp = world_.settings.erp;
  if (depth <= 0.0) return erp;
  return std::min(erp, world_.settings.max_correction_speed * step / depth);
}

BodyFrame Simulator::BodyFrameOf(int id) const {
  const dBodyID body = bodies_[id].body;
  if (body == nullptr) return BodyFrame{};
  return BodyFrame{ToMat3(dBodyGetRotation(body)), ToVec3(dBodyGetPosition(body))};
}

// the anchors of the pairs in contact now: a pair keeps its anchor while it sticks and gets a
// new one where it is when it starts touching, slides or rolls (friction_anchor.h); every
// contact gets the tangential velocity that takes back part of its drift
void Simulator::UpdateFrictionAnchors(double step) {
  next_anchors_.clear();
  anchor_velocities_.clear();
  for (ContactPair& pair : pairs_) {
    pair.anchor_speed = 0.0;
    if (pair.contacts.empty()) continue;
    const BodyFrame frame_a = BodyFrameOf(pair.a);
    const BodyFrame frame_b = BodyFrameOf(pair.b);
    const size_t first = anchor_velocities_.size();
    const FrictionAnchor* anchor = FindAnchor(anchors_, pair.a, pair.b);
    bool sticks =
        anchor != nullptr && AnchorRotation(*anchor, frame_a, frame_b) <= kAnchorMaxRotation;
    for (const Contact& contact : pair.contacts) {
      const Vec3 drift =
          sticks ? AnchorDrift(*anchor, frame_a, frame_b, contact.position, contact.normal)
                 : Vec3::Zero();
      sticks = sticks && drift.norm() <= world_.settings.friction_anchor_slip;
      anchor_velocities_.push_back(
          AnchorCorrectionVelocity(drift, step, world_.settings.friction_anchor_gain));
    }
    if (sticks) {
      next_anchors_.push_back(*anchor);
      for (size_t i = first; i < anchor_velocities_.size(); ++i) {
        pair.anchor_speed = std::max(pair.anchor_speed, anchor_velocities_[i].norm());
      }
    } else {
      next_anchors_.push_back(MakeAnchor(pair.a, pair.b, frame_a, frame_b));
      std::fill(anchor_velocities_.begin() + first, anchor_velocities_.end(), Vec3::Zero());
    }
  }
  // a pair that has no contact in this step but is still close keeps its anchor: contacts at
  // the edge of the layer come and go while a body stands
  const size_t in_contact = next_anchors_.size();
  SortAnchors(&next_anchors_);
  for (const FrictionAnchor& anchor : anchors_) {
    const std::pair<int, int> ids(std::min(anchor.a, anchor.b), std::max(anchor.a, anchor.b));
    if (std::binary_search(candidates_.begin(), candidates_.end(), ids) &&
        FindAnchor(next_anchors_, anchor.a, anchor.b) == nullptr) {
      next_anchors_.push_back(anchor);
    }
  }
  if (next_anchors_.size() > in_contact) SortAnchors(&next_anchors_);
  std::swap(anchors_, next_anchors_);
}

void Simulator::AddContactJoints(const ContactPair& pair, const Vec3* anchor_velocities,
                                 double step) {
  if (pair.contacts.empty()) return;
  dBodyID body_a = bodies_[pair.a].body;
  dBodyID body_b = bodies_[pair.b].body;
  const BlendedSurface surface =
      BlendSurfaces(sim_params(pair.a).surface, sim_params(pair.b).surface);
  // the pair pushes with k times its penetration (its deepest overlap) and damps with c, however
  // many points the clustering kept (Klamp't gives every point the full k and c): each contact
  // takes a share w_i/Σw of both by its pressure weight (depth², summed over a cluster's
  // members), so the pair's centre of pressure does not depend on the clustering, and a point
  // entering or leaving the layer at depth 0 changes nothing
  const double floor = ContactWeightDepth(Contact{}, pair);
  double weight_sum = 0.0, max_depth = 0.0;
  for (const Contact& contact : pair.contacts) {
    weight_sum += PressureWeight(contact, floor);
    max_depth = std::max(max_depth, ContactWeightDepth(contact, pair));
  }
  const SoftContactParams pair_soft = SoftContact(surface.stiffness, surface.damping, step);
  // a layer without stiffness or damping pushes with no force at all
  if (pair_soft.soft && !std::isfinite(pair_soft.cfm)) return;
  const ContactFeedbackRecord* record = feedback_.empty() ? nullptr : FindFeedback(pair.a, pair.b);
  for (const Contact& contact : pair.contacts) {
    const Vec3& anchor_velocity = *anchor_velocities++;
    // force share = k·d_max·share = k_i·d_i
    const double share = PressureWeight(contact, floor) / weight_sum;
    const SoftContactParams soft =
        pair_soft.soft
            ? SoftContact(surface.stiffness * max_depth * share / ContactWeightDepth(contact, pair),
                          surface.damping * share, step)
            : pair_soft;
    dContact joint{};
    joint.surface.mode = dContactApprox1;
    joint.surface.mu = std::isinf(surface.friction) ? dInfinity : surface.friction;
    if (soft.soft) {
      joint.surface.mode |= dContactSoftERP | dContactSoftCFM;
      joint.surface.soft_erp = soft.erp;
      joint.surface.soft_cfm = soft.cfm;
    }
    // a soft layer rebounds as its spring and damper make it; a restitution on top would
    // count the rebound twice (and pumps energy into a body rolling on a tessellated surface)
    if (surface.restitution > 0.0 && !soft.soft) {
      joint.surface.mode |= dContactBounce;
      joint.surface.bounce = surface.restitution;
      joint.surface.bounce_vel = world_.settings.bounce_velocity_threshold;
    }
    dVector3 velocity_a = {0, 0, 0}, velocity_b = {0, 0, 0};
    const Vec3& p = contact.position;
    if (body_a) dBodyGetPointVel(body_a, p.x(), p.y(), p.z(), velocity_a);
    if (body_b) dBodyGetPointVel(body_b, p.x(), p.y(), p.z(), velocity_b);
    const Vec3 relative = ToVec3(velocity_a) - ToVec3(velocity_b);
    const double normal_speed = relative.dot(contact.normal);
    if (!soft.soft) {
      // a hard contact corrects the layer overlap gently; at a bouncing impact not at all: the
      // velocity constraint with restitution sets the rebound, and correcting the overlap as
      // well would add energy (Klamp't's spheres bounce too high for this)
      const bool bouncing =
          surface.restitution > 0.0 && normal_speed < -world_.settings.bounce_velocity_threshold;
      joint.surface.mode |= dContactSoftERP | dContactSoftCFM;
      joint.surface.soft_erp = bouncing ? 0.0 : HardContactErp(contact.depth, step);
      joint.surface.soft_cfm = std::min(world_.settings.cfm, kHardContactCfm);
    }
    // the first friction direction opposes what friction has to take away, the sliding
    // velocity less the anchor's correction: ODE's per-axis friction becomes isotropic
    const Vec3 sliding = relative - normal_speed * contact.normal - anchor_velocity;
    Vec3 t1 = Vec3::Zero(), t2 = Vec3::Zero();
    if (sliding.norm() > kSlidingSpeedThreshold) {
      t1 = sliding.normalized();
      t2 = contact.normal.cross(t1);  // as ODE makes it
      joint.surface.mode |= dContactFDir1;
      joint.fdir1[0] = t1.x();
      joint.fdir1[1] = t1.y();
      joint.fdir1[2] = t1.z();
    } else if (!anchor_velocity.isZero(0.0)) {
      dVector3 n = {contact.normal.x(), contact.normal.y(), contact.normal.z()}, p1, p2;
      dPlaneSpace(n, p1, p2);  // ODE's own friction axes
      t1 = ToVec3(p1);
      t2 = ToVec3(p2);
    }
    if (!anchor_velocity.isZero(0.0)) {
      // ODE's friction rows ask (v_a - v_b)·t_i = motion_i
      joint.surface.mode |= dContactMotion1 | dContactMotion2;
      joint.surface.motion1 = anchor_velocity.dot(t1);
      joint.surface.motion2 = anchor_velocity.dot(t2);
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
    JointFeedbackSlot* slot =
        record != nullptr ? AttachFeedback(id, *record, pair, contact, surface.friction) : nullptr;
    if (soft.soft && contact.depth >= pair.tolerance) {
      AddCoreContactJoint(joint, pair.tolerance, step, body_a, body_b, slot);
    }
  }
}

// A soft layer that is pressed through rests on the rigid geometry under it: where the
// underlying geometries touch, a hard contact at the core's own depth (depth - padding sum)
// keeps them from passing through each other. Without it a layer too soft for its load would let
// the body sink through the floor. (ODE clamps a negative depth to 0, so a contact added
// before the cores touch would stop them early.)
void Simulator::AddCoreContactJoint(const dContact& soft_joint, double tolerance, double step,
                                    dBodyID body_a, dBodyID body_b, JointFeedbackSlot* slot) {
  dContact joint = soft_joint;
  joint.surface.mode = dContactApprox1 | dContactSoftERP | dContactSoftCFM;
  joint.surface.mode |=
      soft_joint.surface.mode & (dContactFDir1 | dContactMotion1 | dContactMotion2);
  joint.geom.depth = soft_joint.geom.depth - tolerance;
  joint.surface.soft_erp = HardContactErp(joint.geom.depth, step);
  joint.surface.soft_cfm = std::min(world_.settings.cfm, kHardContactCfm);
  dJointID id = dJointCreateContact(ode_world_.get(), contact_group_.get(), &joint);
  dJointAttach(id, body_a, body_b);
  if (slot != nullptr) {
    slot->has_core = true;
    dJointSetFeedback(id, &slot->core);
  }
}

// ---- contact feedback -------------------------------------------------------------------

Simulator::JointFeedbackSlot* Simulator::AttachFeedback(dJointID joint,
                                                        const ContactFeedbackRecord& record,
                                                        const ContactPair& pair,
                                                        const Contact& contact, double friction) {
  JointFeedbackSlot& slot = joint_feedback_[next_feedback_slot_++];
  slot.has_core = false;
  slot.record = static_cast<int>(&record - feedback_.data());
  // ODE reports the force on the joint's first body, pair.a; the record wants it on `first`
  slot.flip = pair.a != record.first;
  slot.contact.position = contact.position;
  slot.contact.normal = slot.flip ? Vec3(-contact.normal) : contact.normal;
  slot.contact.friction = friction;
  slot.contact.penetrating = contact.penetrating;
  dJointSetFeedback(joint, &slot.ode);
  return &slot;
}

void Simulator::RecordFeedback(double step) {
  if (feedback_.empty()) return;
  step_feedback_.resize(feedback_.size());
  for (std::vector<FeedbackContact>& contacts : step_feedback_) contacts.clear();
  for (JointFeedbackSlot& slot : joint_feedback_) {
    Vec3 force = ToVec3(slot.ode.f1);
    if (slot.has_core) force += ToVec3(slot.core.f1);
    slot.contact.force = slot.flip ? Vec3(-force) : force;
    step_feedback_[slot.record].push_back(slot.contact);
  }
  for (size_t r = 0; r < feedback_.size(); ++r) feedback_[r].AddSubStep(step, step_feedback_[r]);
}

ContactFeedbackRecord* Simulator::FindFeedback(int a, int b) {
  const int first = std::min(a, b), second = std::max(a, b);
  const auto found =
      std::lower_bound(feedback_.begin(), feedback_.end(), std::make_pair(first, second),
                       [](const ContactFeedbackRecord& r, const std::pair<int, int>& key) {
                         return std::make_pair(r.first, r.second) < key;
                       });
  if (found == feedback_.end() || found->first != first || found->second != second) return nullptr;
  return &*found;
}

void Simulator::EnableContactFeedback(int a, int b) {
  if (a == b || record(a) == nullptr || record(b) == nullptr) return;
  if (FindFeedback(a, b)) return;
  ContactFeedbackRecord entry;
  entry.first = std::min(a, b);
  entry.second = std::max(a, b);
  const auto at = std::lower_bound(
      feedback_.begin(), feedback_.end(), entry,
      [](const ContactFeedbackRecord& x, const ContactFeedbackRecord& y) {
        return std::make_pair(x.first, x.second) < std::make_pair(y.first, y.second);
      });
  feedback_.insert(at, entry);
}

std::vector<std::pair<int, int>> Simulator::ContactFeedbackPairs() const {
  std::vector<std::pair<int, int>> pairs;
  for (const ContactFeedbackRecord& r : feedback_) pairs.emplace_back(r.first, r.second);
  return pairs;
}

void Simulator::EnableContactFeedbackAll() {
  for (int a = 0; a < body_count(); ++a) {
    if (!bodies_[a].geometry) continue;
    for (int b = a + 1; b < body_count(); ++b) {
      if (bodies_[b].geometry && MayCollide(bodies_[a], bodies_[b])) EnableContactFeedback(a, b);
    }
  }
}

std::vector<const ContactFeedbackRecord*> Simulator::FeedbackRecords(int a, int b) const {
  std::vector<const ContactFeedbackRecord*> records;
  for (const ContactFeedbackRecord& r : feedback_) {
    const bool touches_a = r.first == a || r.second == a;
    if (touches_a && (b < 0 || r.first == b || r.second == b)) records.push_back(&r);
  }
  return records;
}

namespace {

// +1 when a is the record's first body (its forces are on a), -1 otherwise
double SignFor(const ContactFeedbackRecord& record, int a) {
  return record.first == a ? 1.0 : -1.0;
}

}  // namespace

bool Simulator::InContact(int a, int b) const {
  const std::vector<const ContactFeedbackRecord*> records = FeedbackRecords(a, b);
  if (!records.empty()) {
    return std::any_of(records.begin(), records.end(),
                       [](const ContactFeedbackRecord* r) { return r->in_contact; });
  }
  // without feedback: touching at the current state
  return std::any_of(pairs_.begin(), pairs_.end(), [&](const ContactPair& pair) {
    const bool touches_a = pair.a == a || pair.b == a;
    return touches_a && (b < 0 || pair.a == b || pair.b == b) && !pair.contacts.empty();
  });
}

bool Simulator::HadContact(int a, int b) const {
  for (const ContactFeedbackRecord* r : FeedbackRecords(a, b)) {
    if (r->contact_steps > 0) return true;
  }
  return false;
}

bool Simulator::HadSeparation(int a, int b) const {
  for (const ContactFeedbackRecord* r : FeedbackRecords(a, b)) {
    if (r->separation_steps > 0) return true;
  }
  return false;
}

bool Simulator::HadPenetration(int a, int b) const {
  for (const ContactFeedbackRecord* r : FeedbackRecords(a, b)) {
    if (r->penetration_steps > 0) return true;
  }
  return false;
}

std::vector<FeedbackContact> Simulator::GetContacts(int a, int b) const {
  std::vector<FeedbackContact> contacts;
  for (const ContactFeedbackRecord* r : FeedbackRecords(a, b)) {
    const double sign = SignFor(*r, a);
    for (FeedbackContact contact : r->contacts) {
      contact.normal *= sign;
      contact.force *= sign;
      contacts.push_back(contact);
    }
  }
  return contacts;
}

std::vector<Vec3> Simulator::GetContactForces(int a, int b) const {
  std::vector<Vec3> forces;
  for (const FeedbackContact& contact : GetContacts(a, b)) forces.push_back(contact.force);
  return forces;
}

Vec3 Simulator::ContactForce(int a, int b) const {
  Vec3 sum = Vec3::Zero();
  for (const ContactFeedbackRecord* r : FeedbackRecords(a, b))
    sum += SignFor(*r, a) * r->LastForce();
  return sum;
}

Vec3 Simulator::ContactTorque(int a, int b) const {
  Vec3 sum = Vec3::Zero();
  for (const ContactFeedbackRecord* r : FeedbackRecords(a, b))
    sum += SignFor(*r, a) * r->LastTorque();
  return sum;
}

Vec3 Simulator::MeanContactForce(int a, int b) const {
  Vec3 sum = Vec3::Zero();
  for (const ContactFeedbackRecord* r : FeedbackRecords(a, b))
    sum += SignFor(*r, a) * r->mean_force;
  return sum;
}

Vec3 Simulator::MeanContactTorque(int a, int b) const {
  Vec3 sum = Vec3::Zero();
  for (const ContactFeedbackRecord* r : FeedbackRecords(a, b))
    sum += SignFor(*r, a) * r->mean_torque;
  return sum;
}

}  // namespace lamina::core
