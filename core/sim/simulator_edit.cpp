// SPDX-License-Identifier: MIT
// Live edits of a running simulation: the parameter table's rows (Simulator::SetParam), the
// typed setters built on it, and rebuilding the simulation from its description.
#include <stdexcept>
#include <string>

#include <ode/ode.h>

#include "core/model/surface_rows.h"
#include "core/sim/body_change.h"
#include "core/sim/ode_robot.h"
#include "core/sim/simulator.h"

namespace lamina::core {

namespace {

// the typed setters throw what SetParam would refuse
void SetOrThrow(Simulator* simulator, const ElementIndex& element, std::string_view key,
                const ParamValue& value) {
  const ParamSpec* spec = FindParam(key, element.kind);
  std::string error;
  if (spec == nullptr || !simulator->SetParam(element, *spec, value, &error)) {
    throw std::invalid_argument(spec == nullptr ? "no parameter " + std::string(key) : error);
  }
}

}  // namespace

std::optional<ParamValue> Simulator::GetParam(const ElementIndex& element, const ParamSpec& spec,
                                              std::string* error) const {
  return core::GetParam(world_, element, spec, error);
}

bool Simulator::SetParam(const ElementIndex& element, const ParamSpec& spec,
                         const ParamValue& value, std::string* error) {
  // a change of an object's centre of mass keeps its frame where it is (the mass moves)
  const bool keeps_frame = element.kind == ElementKind::kObject && spec.key == "com" &&
                           element.index >= 0 && element.index < object_count() && !halted_;
  const Pose frame = keeps_frame ? GetObjectPose(element.index) : Pose::Identity();
  const Twist twist = keeps_frame ? GetObjectVelocity(element.index) : Twist{};
  if (!core::SetParam(&world_, element, spec, value, error)) return false;
  switch (spec.apply) {
    case ParamApply::kOnReset:
      return true;
    case ParamApply::kRebuildSimulator:
      Rebuild();
      if (keeps_frame) {
        SetObjectPose(element.index, frame);
        SetObjectVelocity(element.index, twist);
      }
      return true;
    default:
      break;
  }
  if (element.kind == ElementKind::kSettings) {
    ApplySettingsEdit(spec);
  } else if (IsBodyParam(spec)) {
    ApplyBodyEdit(element, spec);
  } else {
    ApplyRobotEdit(element, spec);
  }
  return true;
}

void Simulator::ApplySettingsEdit(const ParamSpec& spec) {
  const SimSettings& s = world_.settings;
  if (spec.key == "gravity") {
    dWorldSetGravity(ode_world_.get(), s.gravity.x(), s.gravity.y(), s.gravity.z());
    for (RobotController& controller : controllers_) controller.SetGravity(s.gravity);
    for (int id : bodies_.object_ids()) BodyChanged(id, kForceApplied);
  } else if (spec.key == "ERP") {
    dWorldSetERP(ode_world_.get(), s.erp);
  } else if (spec.key == "CFM") {
    dWorldSetCFM(ode_world_.get(), s.cfm);
  } else if (spec.key == "sleeping") {
    if (!s.sleeping) sleep_.WakeAll(&bodies_);
  } else if (spec.key == "maxContacts" || spec.key == "rigidObjectCollisions" ||
             spec.key == "robotSelfCollisions" || spec.key == "robotRobotCollisions") {
    // what touches changed: contacts are found again, and what slept on them wakes
    contacts_.Invalidate();
    sleep_.WakeAll(&bodies_);
  }
}

void Simulator::ApplyBodyEdit(const ElementIndex& element, const ParamSpec& spec) {
  const int id = WorldIdOfElement(world_, element);
  if (spec.apply == ParamApply::kRebuildGeometry) {
    RebuildCollisionGeometry(id);
    BodyChanged(id, kShapeChanged);
  } else {
    BodyChanged(id, kSurfaceChanged);
  }
}

// joint limits move the joint's stops; joint, velocity and torque limits (a non-affine driver's
// are its link's) change the controller's ramp limits of the link (LinkRampLimits)
void Simulator::ApplyRobotEdit(const ElementIndex& element, const ParamSpec& spec) {
  const RobotDesc& robot = world_.robots[element.index];
  int link = -1;
  if (element.kind == ElementKind::kLink && spec.key == "jointLimits") {
    link = element.sub;
    robots_[element.index]->UpdateStops(link);
  } else if (element.kind == ElementKind::kDriver &&
             (spec.key == "velocityLimits" || spec.key == "torqueLimits")) {
    const DriverDesc& driver = robot.drivers[element.sub];
    if (driver.type != DriverType::kAffine && !driver.links.empty()) link = driver.links.front();
  }
  if (link < 0 || link >= robot.dof()) return;
  const JointLimits derived = LinkRampLimits(robot);
  JointLimits limits = controllers_[element.index].limits();
  limits.q_min[link] = derived.q_min[link];
  limits.q_max[link] = derived.q_max[link];
  limits.velocity_max[link] = derived.velocity_max[link];
  limits.acceleration_max[link] = derived.acceleration_max[link];
  controllers_[element.index].SetLimits(limits);
}

// ---- the typed setters ------------------------------------------------------------------

void Simulator::SetSimStep(double step) {
  SetOrThrow(this, ElementIndex::Settings(), "timestep", {step});
}

void Simulator::SetGravity(const Vec3& gravity) {
  SetOrThrow(this, ElementIndex::Settings(), "gravity", {gravity.x(), gravity.y(), gravity.z()});
}

void Simulator::SetSleeping(bool on) {
  SetOrThrow(this, ElementIndex::Settings(), "sleeping", {on ? 1.0 : 0.0});
}

void Simulator::SetSolver(const SolverSettings& solver) {
  const double iterations = solver.quick_step_iterations;
  const ParamSpec& spec = *FindParam("quickStepIterations", ElementKind::kSettings);
  if (auto error = CheckParam(spec, {iterations}, 1)) {
    throw std::invalid_argument("settings." + *error);
  }
  SetOrThrow(this, ElementIndex::Settings(), "solver", {static_cast<double>(solver.type)});
  SetOrThrow(this, ElementIndex::Settings(), "quickStepIterations", {iterations});
}

void Simulator::SetBodyPadding(int id, double padding) {
  RequireBody(id);
  const std::optional<ElementIndex> element = ElementOfWorldId(world_, id);
  SetOrThrow(this, *element, "padding", {padding});
}

void Simulator::SetBodySurface(int id, const SurfaceDesc& surface) {
  RequireBody(id);
  const std::optional<ElementIndex> element = ElementOfWorldId(world_, id);
  // every surface row checked before any is written
  for (const SurfaceRow& row : SurfaceMembers()) {
    if (auto error = CheckParam(*row.spec, {surface.*row.member}, 1)) {
      throw std::invalid_argument(ElementPath(*element) + "." + *error);
    }
  }
  for (const SurfaceRow& row : SurfaceMembers()) {
    SetOrThrow(this, *element, row.spec->key, {surface.*row.member});
  }
}

void Simulator::SetJointLimits(int robot, int link, double q_min, double q_max) {
  const ElementIndex element = ElementIndex::Link(robot, link);
  if (auto error = CheckElement(world_, element)) throw std::out_of_range(*error);
  SetOrThrow(this, element, "jointLimits", {q_min, q_max});
}

}  // namespace lamina::core
