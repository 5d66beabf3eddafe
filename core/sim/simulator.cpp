// SPDX-License-Identifier: MIT
// The Simulator's orchestration: building and rebuilding, the state, and the step as a list of
// named stages. The stages' data live in their units (simulator.h lists them).
#include "core/sim/simulator.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <mutex>
#include <stdexcept>

#include <ode/ode.h>

#include "core/sim/contact_readout.h"
#include "core/sim/gravity_kick.h"
#include "core/sim/ode_conversions.h"
#include "core/sim/ode_handle.h"
#include "core/sim/ode_robot.h"

namespace lamina::core {

namespace {

// a seed for ODE's random generator from the simulated time (a 64-bit mix of its bits)
unsigned long QuickStepSeed(double time) {
  uint64_t x = std::bit_cast<uint64_t>(time);
  x ^= x >> 33;
  x *= 0xff51afd7ed558ccdULL;
  x ^= x >> 33;
  return static_cast<unsigned long>(x);
}

// guards ODE's process-wide random generator, which dWorldQuickStep draws from
std::mutex& QuickStepMutex() {
  static std::mutex mutex;
  return mutex;
}

// a remainder within this fraction of a step counts as a whole step (Simulate)
constexpr double kStepGridTolerance = 1e-6;

// finite, with a unit quaternion (ODE's own are unit to rounding)
bool IsFinite(const BodyState& body) {
  return body.com_position.allFinite() && body.orientation.coeffs().allFinite() &&
         std::abs(body.orientation.norm() - 1.0) < 1e-6 && body.linear_velocity.allFinite() &&
         body.angular_velocity.allFinite();
}

bool IsFinite(const SimState& state) {
  const auto finite = [](const std::vector<BodyState>& bodies) {
    return std::all_of(bodies.begin(), bodies.end(),
                       [](const BodyState& b) { return IsFinite(b); });
  };
  return std::isfinite(state.time) && finite(state.objects) &&
         std::all_of(state.robots.begin(), state.robots.end(),
                     [&](const RobotSimState& robot) { return finite(robot.bodies); });
}

}  // namespace

Simulator::Simulator(const WorldDesc& world, const SolverSettings& solver) : Simulator(world) {
  SetSolver(solver);
}

Simulator::Simulator(const WorldDesc& world)
    : world_(world), drag_joint_(NewOdeDragJoint(), DeleteOdeDragJoint) {
  EnsureOdeInitialized();
  Build();
  // made once: callers may hold references to them, and rebuilds keep their settings
  for (RobotDesc& robot : world_.robots) controllers_.push_back(RobotController::ViewOf(&robot));
  BuildSensors();
  ApplyInitialState();
}

Simulator::~Simulator() {
  TearDown();
}

// the ODE world, bodies, robots and controllers of world_ (at the initial state)
void Simulator::Build() {
  diagnostics_ = Diagnostics();
  ode_world_ = CreateOdeWorld();
  contact_group_.reset(dJointGroupCreate(0));
  dWorldSetERP(ode_world_.get(), world_.settings.erp);
  dWorldSetCFM(ode_world_.get(), world_.settings.cfm);
  dWorldSetAutoDisableFlag(ode_world_.get(), 0);
  const Vec3& g = world_.settings.gravity;
  dWorldSetGravity(ode_world_.get(), g.x(), g.y(), g.z());
  BuildBodies();
  sleep_.Reset(object_count());
  BuildWorldJoints();
  halted_ = false;
}

// everything Build made; the robots first (they destroy their own joints and bodies)
void Simulator::TearDown() {
  world_joints_.Clear();
  targets_.clear();
  drag_ = DragState{};
  robots_.clear();
  robot_scratch_.clear();
  self_collision_pairs_.clear();
  bodies_.Reset(0);
  contacts_.Clear();
  anchors_.Clear();
  sleep_.Reset(0);
  contact_group_.reset();
  ode_world_.reset();
}

// MuJoCo's mj_recompile: a new simulation of world_ in the state `state` (time, bodies, robots,
// controllers, anchors, sleep); what is not state is kept too: statistics, observers, feedback
// registrations, the controllers and their settings, bodies disabled or kinematic, held wrenches,
// the drag and kinematic targets
void Simulator::RebuildWith(const SimState& state) {
  const std::map<int, KinematicTarget> targets = targets_;
  const DragState drag = drag_;
  BuildKeepingFlags();
  targets_ = targets;
  drag_ = drag;
  SetState(state);
}

// TearDown and Build, with every body's enabled and kinematic flags and held wrench kept
void Simulator::BuildKeepingFlags() {
  const std::vector<BodyRecord> before(bodies_.begin(), bodies_.end());
  TearDown();
  Build();
  for (int id = 0; id < bodies_.size() && id < static_cast<int>(before.size()); ++id) {
    BodyRecord& body = bodies_[id];
    if (body.kind != before[id].kind) continue;
    body.held = before[id].held;
    if (body.enabled != before[id].enabled) SetBodyEnabled(id, before[id].enabled);
    if (body.body && body.dynamic != before[id].dynamic) SetBodyDynamic(id, before[id].dynamic);
  }
}

void Simulator::Rebuild() {
  // a stopped simulation's bodies are garbage: it is rebuilt at the last state that was good
  if (halted_) {
    RebuildWith(last_good_);
    return;
  }
  const std::vector<RobotPlacement> placements = RobotPlacements();
  RebuildWith(GetState());
  KeepRobotPlacements(placements);
  if (drag_.active) RescaleDrag();
}

// every robot's configuration, velocity and link frames
std::vector<Simulator::RobotPlacement> Simulator::RobotPlacements() const {
  std::vector<RobotPlacement> placements;
  for (int r = 0; r < robot_count(); ++r) {
    RobotPlacement placement{GetRobotConfig(r), GetRobotVelocity(r), {}};
    const int first = world_.RobotLinkId(r, 0);
    for (int l = 0; l < robots_[r]->dof(); ++l) {
      placement.frames.push_back(bodies_.GetPose(bodies_[first + l]));
    }
    placements.push_back(std::move(placement));
  }
  return placements;
}

// a robot whose bodies, restored after a rebuild, no longer put its links where they were (a
// link's mass properties moved its body's centre of mass) or no longer read its configuration
// (a joint built at another reference counts other turns) is placed again by its configuration
void Simulator::KeepRobotPlacements(const std::vector<RobotPlacement>& placements) {
  const std::vector<RobotPlacement> now = RobotPlacements();
  for (int r = 0; r < robot_count() && r < static_cast<int>(placements.size()); ++r) {
    bool moved = now[r].q != placements[r].q;
    for (size_t l = 0; l < now[r].frames.size() && !moved; ++l) {
      moved = !now[r].frames[l].isApprox(placements[r].frames[l], 1e-12);
    }
    if (!moved) continue;
    SetRobotConfig(r, placements[r].q);
    SetRobotVelocity(r, placements[r].dq);
  }
}

void Simulator::Reset() {
  if (halted_) BuildKeepingFlags();
  time_ = 0.0;
  last_step_ = 0.0;
  statistics_ = SimStatistics();
  meter_.Reset();
  ClearInteraction();
  bodies_.ClearCallForces();
  feedback_.BeginCall();
  ApplyInitialState();
}

int Simulator::AddStepObserver(StepObserver observer) {
  observers_.emplace_back(next_observer_, std::move(observer));
  return next_observer_++;
}

// an observer removed while observers are called is only emptied then (DispatchStep erases it)
void Simulator::RemoveStepObserver(int id) {
  for (auto& [observer_id, observer] : observers_) {
    if (observer_id == id) observer = nullptr;
  }
  if (!dispatching_) std::erase_if(observers_, [](const auto& entry) { return !entry.second; });
}

// by index: an observer may add or remove observers (one added now is called from the next step)
void Simulator::DispatchStep(const StepEvent& event) {
  dispatching_ = true;
  const size_t count = observers_.size();
  for (size_t i = 0; i < count; ++i) {
    if (observers_[i].second) observers_[i].second(event);
  }
  dispatching_ = false;
  std::erase_if(observers_, [](const auto& entry) { return !entry.second; });
}

void Simulator::MirrorStep(double h, int contact_joints, const std::vector<ContactPair>& contacts) {
  if (!(h > 0.0) || !std::isfinite(h))
    throw std::invalid_argument("Simulator::MirrorStep: step " + std::to_string(h) +
                                " s is not > 0 and finite");
  time_ += h;
  const std::vector<int> none;
  const StepEvent event{*this, time_, h, 0u, contact_joints, 0, 0, none, contacts, feedback_};
  AccumulateStep(event, &statistics_);
  if (!observers_.empty()) DispatchStep(event);
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
  state->last_step = last_step_;
  const std::vector<int>& ids = bodies_.object_ids();
  state->objects.resize(ids.size());
  for (size_t i = 0; i < ids.size(); ++i) state->objects[i] = ReadBodyState(bodies_[ids[i]].body);
  CaptureRobotState(state, with_controllers);
  state->anchors = anchors_.anchors();
  state->sleep = sleep_.states();
}

void Simulator::SetState(const SimState& state) {
  if (!IsFinite(state)) {
    throw std::invalid_argument("SetState: the state is not finite or has a non-unit quaternion");
  }
  // ODE cannot be trusted after one of its errors: a stopped simulation is built anew
  if (halted_) {
    RebuildWith(state);
    return;
  }
  contacts_.Invalidate();
  RestoreState(state);
  bodies_.MarkKicked();  // (as in the run the state came from)
  RestoreControllers(state);
  for (BodyRecord& body : bodies_) body.energy = -1.0;
}

// the bodies, robots, anchors and sleep of `state`; what depends on them is the caller's
void Simulator::RestoreState(const SimState& state) {
  time_ = state.time;
  last_step_ = state.last_step;
  const std::vector<int>& ids = bodies_.object_ids();
  for (size_t i = 0; i < ids.size() && i < state.objects.size(); ++i) {
    WriteBodyState(bodies_[ids[i]].body, state.objects[i]);
  }
  RestoreRobotState(state);
  anchors_.Restore(state.anchors);
  sleep_.Restore(&bodies_, state.sleep, world_.settings.sleeping);
}

// ---- stepping ---------------------------------------------------------------------------

StepStatus Simulator::Simulate(double dt) {
  if (!std::isfinite(dt) || dt < 0.0) {
    throw std::invalid_argument("Simulate: dt must be finite and >= 0, got " + std::to_string(dt));
  }
  if (halted_) return StepStatus::kError;
  Stopwatch total;
  const SimTimeSplit before = statistics_.time_split;
  feedback_.BeginCall();
  StepStatus worst = StepStatus::kNormal;
  const double largest = world_.settings.timestep;
  double remaining = dt;
  while (remaining > 0.0) {
    // steps on the grid of whole steps, whatever the chunking of the calls
    const double step = remaining < largest * (1 - kStepGridTolerance) ? remaining : largest;
    if (meter_on_ && meter_.Due()) SampleStepError(step);
    if (meter_on_) {
      Stopwatch stepping;
      worst = std::max(worst, Step(step));
      meter_.AddSteppingTime(stepping.Lap());
    } else {
      worst = std::max(worst, Step(step));
    }
    if (worst == StepStatus::kError) break;
    remaining -= step;
    if (remaining < largest * kStepGridTolerance) remaining = 0.0;
  }
  bodies_.ClearCallForces();  // applied forces (not held wrenches) last for one call
  SimTimeSplit& split = statistics_.time_split;
  const double measured = split.total() - before.total();
  split.other += std::max(0.0, total.Lap() - measured);
  return worst;
}

// one step of length `step`; with adaptive stepping, a tentative sub-step that uses up more than
// half of a boundary layer, or makes geometries interpenetrate, is undone and retaken in halves
// until it is acceptable or it reaches settings.minimum_adaptive_step (step_guard.h)
StepStatus Simulator::Step(double step) {
  StepProgress progress;
  RunControllers(step);
  if (!contacts_.current()) DetectContacts();
  StepGuard::MeasureUnknownEnergies(&bodies_);
  if (const int stopped = StepGuard::StopOverflowingBodies(&bodies_, &progress.corrected_bodies)) {
    progress.flags |= kStepOverflowStop;
    progress.corrections += stopped;
  }
  StepStatus worst = StepStatus::kNormal;
  double remaining = step;
  double h = step;
  bool recovered = false;
  while (remaining > 0.0) {
    h = std::min(h, remaining);
    // halves of halves do not add up exactly: a sub-step that would leave a rounding sliver
    // (1e-19 s was seen) takes it along instead
    if (remaining - h <= step * kStepGridTolerance) h = remaining;
    const SubStep result = TrySubStep(&h, &progress, &recovered);
    if (result == SubStep::kError) return StepStatus::kError;
    if (result == SubStep::kRetake) continue;
    worst = std::max(worst, AcceptStep(h, &progress));
    remaining -= h;
  }
  return worst;
}

// one tentative sub-step of *h: accepted, to be retaken (*h halved after a rollback), or an error
Simulator::SubStep Simulator::TrySubStep(double* h, StepProgress* progress, bool* recovered) {
  CaptureBodyState(&guard_.rollback_state(), false);  // reuses its storage
  MeasureRobotJointGapsBefore();
  const IntegrateResult result = Integrate(*h);
  if (result == IntegrateResult::kOdeError) {
    const std::vector<int> blown = bodies_.NonFiniteBodies();
    if (!blown.empty()) statistics_.error += " (non-finite: " + BodiesText(world_, blown) + ")";
    return Halt("");
  }
  if (result == IntegrateResult::kNonFinite) {
    const std::vector<int> blown = bodies_.NonFiniteBodies();  // (before the state is restored)
    // a step that blew up is undone once with the culprits stopped
    const int stopped = *recovered ? -1
                                   : guard_.RecoverFromFailedStep(
                                         &bodies_, [this](const SimState& s) { RestoreState(s); },
                                         &progress->corrected_bodies);
    if (stopped < 0) {
      const std::string in = blown.empty() ? "" : " in " + BodiesText(world_, blown);
      return Halt("a body state became non-finite" + in + " at t = " + std::to_string(time_) +
                  " s");
    }
    *recovered = true;
    progress->flags |= kStepRecovered;
    progress->corrections += stopped;
    return SubStep::kRetake;
  }
  // a servo row solved without its bound that went over it, or a friction row whose guessed
  // answer did not hold: bounded, the sub-step is retaken
  const bool servo_overrun = BoundOverrunServos();
  if (FrictionGuessesFailed() || servo_overrun) {
    RestoreState(guard_.rollback_state());
    return SubStep::kRetake;
  }
  // a robot whose joints came apart is put back and stopped (simulator_robots.cpp)
  if (const int stopped = StopBrokenRobots(&progress->corrected_bodies)) {
    progress->flags |= kStepCorrected;
    progress->corrections += stopped;
  }
  contacts_.KeepForRollback();
  DetectContacts();
  bool unreliable = false;
  bool rollback = NeedsRollback(contacts_.before(), contacts_.pairs(), &unreliable);
  if (ObjectTunnelled()) rollback = unreliable = true;  // simulator_sweep.cpp
  if (world_.settings.adaptive_time_stepping && rollback &&
      *h / 2 >= world_.settings.minimum_adaptive_step) {
    RestoreState(guard_.rollback_state());
    contacts_.Rollback();
    *h /= 2;
    ++progress->rollbacks;
    progress->flags |= kStepRetaken;
    return SubStep::kRetake;
  }
  if (unreliable || islands_unconverged_) progress->flags |= kStepUnreliable;
  const int corrected = guard_.CorrectInstabilities(
      &bodies_, contacts_.before(),
      [this](const ContactPair& pair) { return PairSurface(pair.a, pair.b).stiffness; },
      KickGravity(*h), *h, &progress->corrected_bodies);
  if (corrected > 0) {
    progress->flags |= kStepCorrected;
    progress->corrections += corrected;
  }
  if (JointsOpen(&progress->joint_gap)) progress->flags |= kStepJointOpen;
  return SubStep::kAccepted;
}

Simulator::SubStep Simulator::Halt(const std::string& error) {
  last_good_ = guard_.rollback_state();  // the start of the step that failed
  for (int r = 0; r < robot_count(); ++r) {
    last_good_.robots[r].controller = controllers_[r].GetState();
    last_good_.robots[r].sensors = sensors_[r].GetState();
    last_good_.robots[r].friction_holdoff = robot_scratch_[r].friction_holdoff;
  }
  if (!error.empty()) statistics_.error = error;
  statistics_.worst_status = StepStatus::kError;
  halted_ = true;
  return SubStep::kError;
}

Simulator::IntegrateResult Simulator::Integrate(double step) {
  Stopwatch watch;
  IntegrateResult result = IntegrateResult::kOk;
  try {
    // gravity's kick across a change of step (the Newton islands read ODE's gravity too)
    const Vec3 gravity = KickGravity(step);
    dWorldSetGravity(ode_world_.get(), gravity.x(), gravity.y(), gravity.z());
    BuildConstraints(step);
    PrepareJointStabilization();
    islands_.SetAside();  // (the bodies of the islands Lamina solved: StepSetAside steps them)
    if (world_.settings.solver == SolverType::kQuickStep) {
      dWorldSetQuickStepNumIterations(ode_world_.get(), world_.settings.quick_step_iterations);
      // QuickStep shuffles its rows with ODE's process-wide random generator: seeded from the
      // state's time, the same state always takes the same step, whatever ran before. The seed
      // and the step are one critical section: simulators stepping in other threads (batch
      // runs) share the generator, so their quick steps take turns
      std::lock_guard<std::mutex> lock(QuickStepMutex());
      dRandSetSeed(QuickStepSeed(time_));
      dWorldQuickStep(ode_world_.get(), step);
    } else {
      dWorldStep(ode_world_.get(), step);
    }
    islands_.StepSetAside(step);
  } catch (const std::exception& error) {
    statistics_.error = error.what();
    result = IntegrateResult::kOdeError;
    MarkOdeWorldFailed(ode_world_.get());
  }
  const Vec3& gravity = world_.settings.gravity;
  dWorldSetGravity(ode_world_.get(), gravity.x(), gravity.y(), gravity.z());
  islands_.Restore();  // the robot joints the Newton solver took, back in ODE
  if (result == IntegrateResult::kOk && islands_active_) {
    ProjectReducedRobots();
    ProjectReducedWorldJoints();
  }
  if (result == IntegrateResult::kOk) StabilizeWorldJoints(step);
  dJointGroupEmpty(contact_group_.get());
  statistics_.time_split.solver += watch.Lap();
  if (result == IntegrateResult::kOk && !bodies_.StateIsFinite()) {
    result = IntegrateResult::kNonFinite;
  }
  return result;
}

// the meter's probe steps are the plain ones it compares (error_meter.h)
Vec3 Simulator::KickGravity(double step) const {
  const double scale = probing_ ? 1.0 : GravityKickScale(last_step_, step);
  return scale * world_.settings.gravity;
}

// the robots the Newton solver took in their joint coordinates: their bodies back on their joints
// (the step integrated each body on its own: object_islands.h)
void Simulator::ProjectReducedRobots() {
  for (int r = 0; r < robot_count(); ++r) {
    OdeRobot& robot = *robots_[r];
    for (int l = 0; l < robot.dof(); ++l) {
      if (robot.link(l).joint == nullptr) continue;
      if (islands_.SolvedReduced(robot.link(l).joint)) robot.ProjectOntoJoints();
      break;
    }
  }
}

// the world's hinges and sliders the Newton solver took in joint coordinates: each child back on
// its joint from its parent, parents first (joint_projection.h; its coordinate and rate as the
// step left them)
void Simulator::ProjectReducedWorldJoints() {
  if (world_joints_.size() == 0) return;
  for (const ObjectIslands::TreeJoint& tree_joint : islands_.reduced_tree()) {
    const int j = world_joints_.IndexOf(tree_joint.joint);
    if (j < 0) continue;
    dJointID joint = world_joints_.ode_joint(j);
    dBodyID child = dJointGetBody(joint, tree_joint.first_is_child ? 0 : 1);
    dBodyID parent = dJointGetBody(joint, tree_joint.first_is_child ? 1 : 0);
    const BodyState from = parent != nullptr ? ReadBodyState(parent) : BodyState{};
    const BodyState now = ReadBodyState(child);
    const JointPlacement& placement = world_joints_.placement(j, tree_joint.first_is_child);
    WriteBodyState(child, PlaceOnJoint(placement, from, JointCoordinate(placement, from, now),
                                       JointRate(placement, from, now)));
  }
}

// everything ODE solves in the step: kinematic motion, contact rows (with the friction anchors),
// forces, the mouse spring, the robots' motors, stops and friction
void Simulator::BuildConstraints(double step) {
  islands_unconverged_ = false;
  MoveKinematicTargets(step);
  size_t recorded = 0;
  if (!feedback_.empty()) {
    for (const ContactPair& pair : contacts_.pairs()) {
      if (feedback_.Find(pair.a, pair.b)) recorded += pair.contacts.size();
    }
  }
  feedback_.ReserveSlots(recorded);  // joints point into the slots: sized before any exists
  const SimSettings& s = world_.settings;
  if (s.sleeping) sleep_.WakeTouchedSleepers(&bodies_, contacts_.pairs());
  anchors_.Update(&contacts_.mutable_pairs(), contacts_.candidates(), bodies_, step,
                  s.friction_anchor_gain, s.friction_anchor_slip);
  const Vec3* anchor_velocities = anchors_.velocities().data();
  const bool newton = s.solver == SolverType::kNewton;
  // the exact solver takes its large robots' islands (a Newton step, then the direct solve:
  // direct_solver.h) and its object islands of many contacts (Newton's method: object_islands.h)
  const auto touches_object = [&](const ContactPair& pair) {
    return bodies_[pair.a].is_object() || bodies_[pair.b].is_object();
  };
  bool exact_islands =
      s.solver == SolverType::kStep && newton_objects_ &&
      std::any_of(contacts_.pairs().begin(), contacts_.pairs().end(), touches_object);
  for (int r = 0; r < robot_count() && s.solver == SolverType::kStep && direct_robots_; ++r) {
    exact_islands = exact_islands || OwnBodies(r) >= direct_min_bodies_;
  }
  islands_active_ = newton || exact_islands;
  if (islands_active_) PrepareObjectIslands(!newton);
  for (const ContactPair& pair : contacts_.pairs()) {
    // no joint ties a sleeper to what cannot wake it (ODE would enable it through the joint)
    if (!s.sleeping || !sleep_.SleepsAgainstInert(bodies_, pair)) {
      AddContactJoints(pair, anchor_velocities, step);
    }
    anchor_velocities += pair.contacts.size();
  }
  bodies_.ApplyForces();
  // (after the sleepers woke: they start from the plain kick too)
  const Vec3 extra_gravity = KickGravity(step) - s.gravity;
  if (!extra_gravity.isZero(0.0)) bodies_.CancelExtraKick(extra_gravity);
  AddDragJoint(step);
  PrepareRobotsForStep(step);
  if (islands_active_) {
    const ObjectIslands::Statistics before = islands_.statistics();
    islands_.Solve(ode_world_.get(), contact_group_.get(), step);
    const ObjectIslands::Statistics& after = islands_.statistics();
    statistics_.direct_islands += after.direct_islands - before.direct_islands;
    statistics_.direct_fallbacks += after.direct_fallbacks - before.direct_fallbacks;
    statistics_.newton_islands += after.newton_islands - before.newton_islands;
    statistics_.newton_fallbacks += after.newton_fallbacks - before.newton_fallbacks;
    statistics_.newton_unconverged += after.unconverged - before.unconverged;
    islands_unconverged_ = after.unconverged > before.unconverged;
    statistics_.newton_iterations += after.iterations - before.iterations;
    statistics_.newton_factorizations += after.factorizations - before.factorizations;
    statistics_.reduced_islands += after.reduced_islands - before.reduced_islands;
    statistics_.reduced_fallbacks += after.reduced_fallbacks - before.reduced_fallbacks;
  }
}

StepStatus Simulator::AcceptStep(double step, StepProgress* progress) {
  feedback_.RecordStep(step);
  if (!probing_) {
    last_step_ = step;
    bodies_.MarkKicked();
  }
  AcceptRobotStep(step);
  AcceptInteraction(step);
  time_ += step;
  const SimSettings& s = world_.settings;
  if (s.sleeping) sleep_.Update(&bodies_, contacts_.pairs(), step, s.sleep_speed, s.sleep_time);
  int joints = 0;  // the joints of the accepted step came from the contacts before it
  for (const ContactPair& pair : contacts_.before())
    joints += static_cast<int>(pair.contacts.size());
  const StepEvent event{*this,
                        time_,
                        step,
                        progress->flags,
                        joints,
                        progress->rollbacks,
                        progress->corrections,
                        progress->corrected_bodies,
                        contacts_.pairs(),
                        feedback_,
                        progress->joint_gap};
  AccumulateStep(event, &statistics_);
  if (!observers_.empty() && !probing_) DispatchStep(event);
  *progress = StepProgress{};
  return StatusOfStep(event.flags);
}

// ---- contacts ---------------------------------------------------------------------------

void Simulator::DetectContacts() {
  Stopwatch watch;
  UpdateBounds();
  statistics_.time_split.broad_phase += watch.Lap();
  const auto bounds_of = [this](int id) -> const Eigen::AlignedBox3d& {
    return bodies_[id].bounds;
  };
  const auto may_collide = [this](int a, int b) { return MayCollide(bodies_[a], bodies_[b]); };
  const auto narrow_of = [this](int id) {
    const BodyRecord& body = bodies_[id];
    return NarrowBody{body.geometry.get(), bodies_.GetPose(body), sim_params(id).padding,
                      body.body != nullptr};
  };
  contacts_.Detect(collidable_, bounds_of, may_collide, narrow_of, world_.settings.max_contacts,
                   &statistics_.time_split);
}

// the padded bounds of every moving body, and which bodies take part in contact
void Simulator::UpdateBounds() {
  collidable_.clear();
  for (int id = 0; id < bodies_.size(); ++id) {
    BodyRecord& body = bodies_[id];
    if (!body.geometry || !body.enabled) continue;
    if (body.body) {
      body.bounds = WorldBounds(*body.geometry, bodies_.GetPose(body), sim_params(id).padding);
    }
    if (body.bounds.isEmpty()) continue;
    collidable_.push_back(id);
  }
}

bool Simulator::MayCollide(const BodyRecord& a, const BodyRecord& b) const {
  // static and kinematic bodies do not push each other
  if (!a.moves_freely() && !b.moves_freely()) return false;
  if (a.is_object() && b.is_object()) return world_.settings.rigid_object_collisions;
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

}  // namespace lamina::core
