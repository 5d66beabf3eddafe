// SPDX-License-Identifier: MIT
// The Simulator's robots: building their bodies and joints, running their controllers at the
// control rate and their actuators and joint friction at every physics step, their part of the
// simulation state, and fakeSimulate.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/geometry/shrink.h"
#include "core/robot/dynamics.h"
#include "core/sim/body_change.h"
#include "core/sim/ode_conversions.h"
#include "core/sim/ode_robot.h"
#include "core/sim/robot_guard.h"
#include "core/sim/servo_bounds.h"
#include "core/sim/simulator.h"

namespace lamina::core {

namespace {

void RequireFiniteVector(const VecX& v, int size, const char* what) {
  if (v.size() != size || !v.allFinite()) {
    throw std::invalid_argument(std::string(what) + " must have " + std::to_string(size) +
                                " finite entries");
  }
}

// one mesh of every geometry of a link, in the link frame (a link's own file plus its mounts)
GeometryDesc CombinedLinkGeometry(const LinkDesc& link) {
  auto mesh = std::make_shared<TriangleMesh>();
  for (const GeometryDesc& part : link.geometry) {
    if (part.empty()) continue;
    const TriangleMesh baked = BakedMesh(part);
    const int offset = static_cast<int>(mesh->vertices.size());
    mesh->vertices.insert(mesh->vertices.end(), baked.vertices.begin(), baked.vertices.end());
    for (const Eigen::Vector3i& t : baked.triangles) {
      mesh->triangles.push_back(t + Eigen::Vector3i::Constant(offset));
    }
  }
  GeometryDesc combined;
  combined.kind = GeometryKind::kMesh;
  combined.mesh = std::move(mesh);
  return combined;
}

}  // namespace

int Simulator::RequireRobot(int robot) const {
  if (robot < 0 || robot >= robot_count()) {
    throw std::out_of_range("robots[" + std::to_string(robot) + "]: the world has " +
                            std::to_string(robot_count()) + " robots");
  }
  return robot;
}

RobotController& Simulator::controller(int robot) {
  return controllers_[RequireRobot(robot)];
}

const RobotController& Simulator::controller(int robot) const {
  return controllers_[RequireRobot(robot)];
}

// every link of `robot` made `changes` (body_change.h)
void Simulator::RobotLinksChanged(int robot, unsigned changes) {
  const int first = world_.RobotLinkId(robot, 0);
  for (int l = 0; l < robots_[robot]->dof(); ++l) BodyChanged(first + l, changes);
}

void Simulator::BuildRobot(int robot, int first_link_id) {
  const RobotDesc& desc = world_.robots[robot];
  robots_.push_back(std::make_unique<OdeRobot>(ode_world_.get(), desc, diagnostics_));
  robot_scratch_.emplace_back();
  self_collision_pairs_.push_back(desc.SelfCollisionPairs());
  std::sort(self_collision_pairs_.back().begin(), self_collision_pairs_.back().end());
  const OdeRobot& sim_robot = *robots_.back();
  for (int l = 0; l < desc.dof(); ++l) {
    const OdeRobot::Link& link = sim_robot.link(l);
    BodyRecord& record = bodies_[first_link_id + l];
    record.kind = WorldId::Kind::kRobotLink;
    record.index = robot;
    record.link = l;
    record.body = link.kind == OdeRobot::LinkKind::kBody ? link.body : nullptr;
    record.owns_body = link.owns_body;
    record.rotation_in_body = link.rotation_in_body;
    record.fixed_pose = link.fixed_pose;
    record.com = link.com;
    record.mass = link.owns_body ? link.mass : 0.0;
    record.inertia = link.owns_body ? link.inertia : Mat3::Zero();
    if (link.kind != OdeRobot::LinkKind::kVirtual) RebuildCollisionGeometry(first_link_id + l);
  }
}

std::shared_ptr<const CollisionGeometry> Simulator::LinkCollisionGeometry(int robot, int link) {
  const LinkDesc& desc = world_.robots[robot].links[link];
  int parts = 0;
  const GeometryDesc* single = nullptr;
  for (const GeometryDesc& part : desc.geometry) {
    if (part.empty()) continue;
    ++parts;
    single = &part;
  }
  if (parts == 0) return nullptr;
  const GeometryDesc geometry = parts == 1 ? *single : CombinedLinkGeometry(desc);
  if (desc.sim.preshrink != Preshrink::kNone && desc.sim.padding > 0.0) {
    return CollisionGeometry::Build(ShrinkGeometry(geometry, desc.sim.padding, &diagnostics_));
  }
  return parts == 1 ? geometry_cache_.Get(geometry) : CollisionGeometry::Build(geometry);
}

// Klamp't's order within a sub-step: the sensors sample the state at the start of the step,
// then the controller runs when its next time falls within the step. A robot that declares
// sensors is controlled from its joint sensors' readings (the first full-length
// JointPositionSensor and JointVelocitySensor: their noise, resolution and hold between samples,
// as Klamp't's controllers read them); one that declares none, or no such sensor, is sensed
// exactly at the step's start (Klamp't's default q and dq are exact, and reading them here
// would only add the hold: the controller runs in the step before a sensor's next time)
void Simulator::RunControllers(double step) {
  for (int r = 0; r < robot_count(); ++r) {
    SampleSensors(r, step);
    RobotController& controller = controllers_[r];
    if (!controller.ControlDue(time_ + step)) continue;
    RobotScratch& scratch = robot_scratch_[r];
    const RobotSensors& sensors = sensors_[r];
    const bool declared = !sensors.defaults();
    if (!declared || !sensors.SensedJoints(false, &scratch.q)) robots_[r]->GetConfig(&scratch.q);
    if (!declared || !sensors.SensedJoints(true, &scratch.dq)) {
      robots_[r]->GetVelocity(&scratch.dq);
    }
    controller.Update(time_, scratch.q, scratch.dq);
  }
}

// before every ODE step (also a retaken one): stops, joint friction and actuator efforts from
// the state the step starts from; with the exact solver PID actuators are joint motors that ODE
// solves implicitly with the step (stable whatever the gains and link inertias)
void Simulator::PrepareRobotsForStep(double step) {
  for (int r = 0; r < robot_count(); ++r) {
    OdeRobot& robot = *robots_[r];
    RobotScratch& scratch = robot_scratch_[r];
    robot.GetConfig(&scratch.q);
    robot.GetVelocity(&scratch.dq);
    robot.PrepareStep(scratch.q, step, world_.settings.erp);
    if (world_.settings.solver != SolverType::kQuickStep) {  // robots are dWorldStep's
      controllers_[r].ComputeImplicitServo(scratch.q, scratch.dq, step, &scratch.forces,
                                           &scratch.motors);
      MarkUnboundedServos(&scratch);
    } else {
      // QuickStep's iterations converge stiff servo rows on light chains too slowly (ATHLETE
      // creeps 60 mm in 2 s with implicit servos, 16 mm with the explicit law): explicit there,
      // but for an unlimited actuator whose explicit law would diverge (explicit_pd.h)
      QuickStepServos(r, step);
    }
    // (dWorldStep's pivoting is what the guesses save; the Newton solver takes bounds at no
    // extra cost, and QuickStep keeps its rows bounded)
    // (a robot the exact solver solves directly takes its bounded rows at no extra cost either)
    const bool guess = world_.settings.solver == SolverType::kStep && !RobotSolvedDirectly(r);
    scratch.friction_holdoff.resize(scratch.dq.size(), 0);
    robot.SetJointFriction(controllers_[r].drivers(), scratch.q, scratch.dq, scratch.motors, guess,
                           scratch.friction_holdoff, &scratch.friction);
    for (const FrictionCommand& row : scratch.friction) {
      scratch.forces[row.link] += ExplicitFrictionTorque(row.mode, row.fmax, row.rate);
    }
    robot.SetServos(scratch.motors);
    robot.MergeHoldingFriction(scratch.motors, scratch.friction);
    robot.ApplyLinkForces(scratch.forces);
  }
}

// under QuickStep: the explicit law, or a motor for the servos without a torque limit whose
// explicit law diverges at this step on the inertia their joint moves (1 / (M⁻¹)_ii, dynamics.h)
void Simulator::QuickStepServos(int robot, double step) {
  RobotScratch& scratch = robot_scratch_[robot];
  RobotController& controller = controllers_[robot];
  scratch.diverging.clear();
  if (controller.HasUnlimitedServo()) {
    const VecX inertias = JointInertias(world_.robots[robot], scratch.q, FreeJoints(robot));
    controller.DivergingServos(inertias, step, &scratch.diverging);
  }
  if (std::find(scratch.diverging.begin(), scratch.diverging.end(), 1) == scratch.diverging.end()) {
    controller.ComputeLinkForces(scratch.q, scratch.dq, &scratch.forces);
    scratch.motors.clear();
    return;
  }
  controller.ComputeImplicitServo(scratch.q, scratch.dq, step, &scratch.forces, &scratch.motors,
                                  &scratch.diverging);
}

// true when robot r's island goes to the exact solver's direct solve this step (object_islands.h)
bool Simulator::RobotSolvedDirectly(int robot) {
  if (!islands_active_ || world_.settings.solver != SolverType::kStep) return false;
  const int first = world_.RobotLinkId(robot, 0);
  for (int l = 0; l < robots_[robot]->dof(); ++l) {
    const int id = IslandBody(first + l);
    if (id >= 0) return islands_.Takes(id);
  }
  return false;
}

// the servo rows whose force at the current rate is well inside their limit go unbounded, but
// for those an earlier try of this sub-step found over it (servo_bounds.h)
void Simulator::MarkUnboundedServos(RobotScratch* scratch) {
  scratch->keep_bound.resize(scratch->dq.size(), 0);
  for (ServoMotorCommand& motor : scratch->motors) {
    motor.unbounded = motor.link >= 0 && motor.link < scratch->dq.size() &&
                      !scratch->keep_bound[motor.link] &&
                      ServoMayGoUnbounded(motor, scratch->dq[motor.link]);
  }
}

// After an ODE step: whether an unbounded servo row applied more than its limit. Those rows are
// marked to stay bounded when the sub-step is retaken.
bool Simulator::BoundOverrunServos() {
  bool overrun = false;
  for (int r = 0; r < robot_count(); ++r) {
    RobotScratch& scratch = robot_scratch_[r];
    bool read = false;
    for (const ServoMotorCommand& motor : scratch.motors) {
      if (!motor.unbounded) continue;
      if (!read) robots_[r]->GetVelocity(&scratch.rates_after);
      read = true;
      if (ServoForceWithinBound(motor, scratch.rates_after[motor.link])) continue;
      scratch.keep_bound[motor.link] = 1;
      overrun = true;
    }
  }
  return overrun;
}

// After an ODE step: whether a friction row given unbounded or as a torque did not give the
// bounded row's answer (friction_rows.h). Those rows stay bounded for the retaken sub-step and
// the next kFrictionGuessHoldoff accepted steps.
bool Simulator::FrictionGuessesFailed() {
  bool failed = false;
  for (int r = 0; r < robot_count(); ++r) {
    RobotScratch& scratch = robot_scratch_[r];
    if (scratch.friction.empty()) continue;
    robots_[r]->GetVelocity(&scratch.rates_after);
    for (const FrictionCommand& row : scratch.friction) {
      const double after = scratch.rates_after[row.link];
      if (FrictionGuessHeld(row.mode, row.fmax, row.cfm, row.rate, after)) continue;
      scratch.friction_holdoff[row.link] = kFrictionGuessHoldoff;
      failed = true;
    }
  }
  return failed;
}

void Simulator::AcceptRobotStep(double step) {
  for (int r = 0; r < robot_count(); ++r) {
    RobotScratch& scratch = robot_scratch_[r];
    std::fill(scratch.keep_bound.begin(), scratch.keep_bound.end(), 0);  // a new sub-step
    for (int& holdoff : scratch.friction_holdoff) holdoff = std::max(0, holdoff - 1);
    robots_[r]->AcceptStep();
    RecordSensorStep(r);
    robots_[r]->GetConfig(&scratch.q);
    controllers_[r].AcceptStep(scratch.q, step);
  }
}

void Simulator::CaptureRobotState(SimState* state, bool with_controllers) const {
  state->robots.resize(robots_.size());
  for (int r = 0; r < robot_count(); ++r) {
    RobotSimState& robot_state = state->robots[r];
    const OdeRobot& robot = *robots_[r];
    robot_state.bodies.clear();
    for (int l = 0; l < robot.dof(); ++l) {
      if (!robot.link(l).owns_body) continue;
      robot_state.bodies.push_back(ReadBodyState(robot.link(l).body));
    }
    robot.CaptureJointState(&robot_state.joints);
    if (!with_controllers) continue;
    robot_state.controller = controllers_[r].GetState();
    robot_state.sensors = sensors_[r].GetState();
    robot_state.friction_holdoff = robot_scratch_[r].friction_holdoff;
  }
}

void Simulator::RestoreRobotState(const SimState& state) {
  for (int r = 0; r < robot_count() && r < static_cast<int>(state.robots.size()); ++r) {
    RestoreOneRobot(r, state.robots[r]);
  }
}

void Simulator::RestoreOneRobot(int robot, const RobotSimState& state) {
  OdeRobot& sim_robot = *robots_[robot];
  size_t next = 0;
  for (int l = 0; l < sim_robot.dof() && next < state.bodies.size(); ++l) {
    if (!sim_robot.link(l).owns_body) continue;
    WriteBodyState(sim_robot.link(l).body, state.bodies[next++]);
  }
  sim_robot.RestoreJointState(state.joints);
}

// ---- robots in the step guard (robot_guard.h) --------------------------------------------

// the gap of every joint of `robot` at the current state, m
void Simulator::MeasureJointGaps(int robot, std::vector<double>* gaps) {
  RobotScratch& scratch = robot_scratch_[robot];
  const OdeRobot& sim_robot = *robots_[robot];
  const int first = world_.RobotLinkId(robot, 0);
  scratch.frames.resize(sim_robot.dof());
  scratch.known.resize(sim_robot.dof());
  for (int l = 0; l < sim_robot.dof(); ++l) {
    scratch.known[l] = sim_robot.link(l).kind != OdeRobot::LinkKind::kVirtual;
    scratch.frames[l] = bodies_.GetPose(bodies_[first + l]);
  }
  RobotJointGaps(world_.robots[robot], scratch.frames, scratch.known, gaps);
}

void Simulator::MeasureRobotJointGapsBefore() {
  for (int r = 0; r < robot_count(); ++r) MeasureJointGaps(r, &robot_scratch_[r].gaps_before);
}

// after a tentative step: every robot whose joints came apart goes back to where the step
// started, at rest; the number of its bodies stopped (their ids appended to `ids`)
int Simulator::StopBrokenRobots(std::vector<int>* ids) {
  int stopped = 0;
  for (int r = 0; r < robot_count(); ++r) {
    RobotScratch& scratch = robot_scratch_[r];
    MeasureJointGaps(r, &scratch.gaps);
    if (!RobotJointsBroke(world_.robots[r], scratch.gaps_before, scratch.gaps)) continue;
    RestoreOneRobot(r, guard_.rollback_state().robots[r]);
    scratch.gaps = scratch.gaps_before;
    robots_[r]->SetVelocity(VecX::Zero(robots_[r]->dof()));
    RobotLinksChanged(r, kPoseChanged | kVelocityChanged);
    const int first = world_.RobotLinkId(r, 0);
    for (int l = 0; l < robots_[r]->dof(); ++l) {
      if (!robots_[r]->link(l).owns_body) continue;
      ++stopped;
      ids->push_back(first + l);
    }
  }
  return stopped;
}

// after a step (StopBrokenRobots measured the robots' gaps): whether a robot's or the world's
// joint is open beyond its break gap; `largest` is raised to the widest gap
bool Simulator::JointsOpen(double* largest) const {
  bool open = world_joints_.AnyOpen(largest);
  for (int r = 0; r < robot_count(); ++r) {
    open = RobotJointsOpen(world_.robots[r], robot_scratch_[r].gaps, largest) || open;
  }
  return open;
}

void Simulator::RestoreControllers(const SimState& state) {
  for (int r = 0; r < robot_count() && r < static_cast<int>(state.robots.size()); ++r) {
    controllers_[r].SetState(state.robots[r].controller);
    sensors_[r].SetState(state.robots[r].sensors);
    robot_scratch_[r].friction_holdoff = state.robots[r].friction_holdoff;
  }
}

VecX Simulator::GetRobotConfig(int robot) const {
  RequireRobot(robot);
  VecX q;
  robots_[robot]->GetConfig(&q);
  return q;
}

VecX Simulator::GetRobotVelocity(int robot) const {
  RequireRobot(robot);
  VecX dq;
  robots_[robot]->GetVelocity(&dq);
  return dq;
}

void Simulator::SetRobotConfig(int robot, const VecX& q) {
  RequireRobot(robot);
  RequireFiniteVector(q, robots_[robot]->dof(), "a robot configuration");
  robots_[robot]->SetConfig(q);
  RobotLinksChanged(robot, kPoseChanged);
}

void Simulator::SetRobotVelocity(int robot, const VecX& dq) {
  RequireRobot(robot);
  RequireFiniteVector(dq, robots_[robot]->dof(), "a robot velocity");
  robots_[robot]->SetVelocity(dq);
  RobotLinksChanged(robot, kVelocityChanged);
}

VecX Simulator::GetActuatorTorques(int robot) const {
  RequireRobot(robot);
  return controllers_[robot].DriverEfforts(GetRobotConfig(robot), GetRobotVelocity(robot));
}

void Simulator::FakeSimulate(double dt) {
  if (!(dt >= 0.0) || !std::isfinite(dt)) {
    throw std::invalid_argument("FakeSimulate: dt must be finite and >= 0");
  }
  RunControllers(dt);
  time_ += dt;
  for (int r = 0; r < robot_count(); ++r) {
    const RobotController& controller = controllers_[r];
    VecX dq = VecX::Zero(robots_[r]->dof());
    if (!controller.GetCommandedVelocity(&dq)) dq.setZero();
    robots_[r]->SetConfig(controller.CommandedLinkConfig());
    robots_[r]->SetVelocity(dq);
    // a teleport like SetRobotConfig: the same rule decides what it invalidates and wakes
    RobotLinksChanged(r, kPoseChanged | kVelocityChanged);
  }
}

}  // namespace lamina::core
