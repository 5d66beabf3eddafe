// SPDX-License-Identifier: MIT
// The rows of the parameter table (params.h) and the value checks, parsing and formatting.
#include "core/model/params.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/Eigenvalues>

#include "core/model/surface_rows.h"
#include "core/number_text.h"

namespace lamina::core {

ParamValue VectorValue(const VecX& v) {
  return ParamValue(v.data(), v.data() + v.size());
}

VecX ValueVector(const ParamValue& value) {
  return Eigen::Map<const VecX>(value.data(), static_cast<Eigen::Index>(value.size()));
}

namespace {

constexpr unsigned kSettings = KindBit(ElementKind::kSettings);
constexpr unsigned kBodies =
    KindBit(ElementKind::kTerrain) | KindBit(ElementKind::kObject) | KindBit(ElementKind::kLink);
constexpr unsigned kMassive = KindBit(ElementKind::kObject) | KindBit(ElementKind::kLink);
constexpr unsigned kObject = KindBit(ElementKind::kObject);
constexpr unsigned kRobot = KindBit(ElementKind::kRobot);
constexpr unsigned kLink = KindBit(ElementKind::kLink);
constexpr unsigned kDriver = KindBit(ElementKind::kDriver);

constexpr std::string_view kSolverChoices[] = {"step", "quick", "newton"};
constexpr std::string_view kPreshrinkChoices[] = {"none", "copy", "in-place"};

// ---- accessors ----------------------------------------------------------------------------

ParamValue One(double value) {
  return {value};
}

ParamValue Vec3Value(const Vec3& v) {
  return {v.x(), v.y(), v.z()};
}

Vec3 ValueVec3(const ParamValue& value) {
  return {value[0], value[1], value[2]};
}

ParamValue MatValue(const Mat3& m) {
  ParamValue value;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) value.push_back(m(i, j));
  }
  return value;
}

Mat3 ValueMat(const ParamValue& value) {
  Mat3 m;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) m(i, j) = value[3 * i + j];
  }
  return m;
}

SimSettings& Settings(WorldDesc* world) {
  return world->settings;
}

// a settings field as a row: double, int or bool member of SimSettings
template <auto Member>
ParamValue GetSetting(const WorldDesc& world, const ElementIndex&) {
  return One(static_cast<double>(world.settings.*Member));
}

template <auto Member>
void SetSetting(WorldDesc* world, const ElementIndex&, const ParamValue& value) {
  using Field = std::remove_reference_t<decltype(Settings(world).*Member)>;
  if constexpr (std::is_same_v<Field, bool>) {
    Settings(world).*Member = value[0] != 0.0;
  } else {
    Settings(world).*Member = static_cast<Field>(value[0]);
  }
}

ParamValue GetGravity(const WorldDesc& world, const ElementIndex&) {
  return Vec3Value(world.settings.gravity);
}

void SetGravity(WorldDesc* world, const ElementIndex&, const ParamValue& value) {
  world->settings.gravity = ValueVec3(value);
}

ParamValue GetSolver(const WorldDesc& world, const ElementIndex&) {
  return One(static_cast<double>(world.settings.solver));
}

void SetSolver(WorldDesc* world, const ElementIndex&, const ParamValue& value) {
  world->settings.solver = static_cast<SolverType>(static_cast<int>(value[0]));
}

// a BodySimParams field of a terrain, object or link
template <auto Member>
ParamValue GetBody(const WorldDesc& world, const ElementIndex& element) {
  return One(BodyParamsOf(world, element)->*Member);
}

template <auto Member>
void SetBody(WorldDesc* world, const ElementIndex& element, const ParamValue& value) {
  BodyParamsOf(world, element)->*Member = value[0];
}

template <auto Member>
ParamValue GetSurface(const WorldDesc& world, const ElementIndex& element) {
  return One(BodyParamsOf(world, element)->surface.*Member);
}

template <auto Member>
void SetSurface(WorldDesc* world, const ElementIndex& element, const ParamValue& value) {
  BodyParamsOf(world, element)->surface.*Member = value[0];
}

ParamValue GetPreshrink(const WorldDesc& world, const ElementIndex& element) {
  return One(static_cast<double>(BodyParamsOf(world, element)->preshrink));
}

void SetPreshrink(WorldDesc* world, const ElementIndex& element, const ParamValue& value) {
  BodyParamsOf(world, element)->preshrink = static_cast<Preshrink>(static_cast<int>(value[0]));
}

// mass properties of an object or a link
template <typename Field>
Field& MassField(WorldDesc* world, const ElementIndex& element, Field RigidObjectDesc::*object,
                 Field LinkDesc::*link) {
  if (element.kind == ElementKind::kObject) return world->objects[element.index].*object;
  return world->robots[element.index].links[element.sub].*link;
}

template <typename Field>
const Field& MassField(const WorldDesc& world, const ElementIndex& element,
                       Field RigidObjectDesc::*object, Field LinkDesc::*link) {
  return MassField(const_cast<WorldDesc*>(&world), element, object, link);
}

ParamValue GetMass(const WorldDesc& world, const ElementIndex& element) {
  return One(MassField(world, element, &RigidObjectDesc::mass, &LinkDesc::mass));
}

void SetMass(WorldDesc* world, const ElementIndex& element, const ParamValue& value) {
  MassField(world, element, &RigidObjectDesc::mass, &LinkDesc::mass) = value[0];
}

ParamValue GetCom(const WorldDesc& world, const ElementIndex& element) {
  return Vec3Value(MassField(world, element, &RigidObjectDesc::com, &LinkDesc::com));
}

void SetCom(WorldDesc* world, const ElementIndex& element, const ParamValue& value) {
  MassField(world, element, &RigidObjectDesc::com, &LinkDesc::com) = ValueVec3(value);
}

ParamValue GetInertia(const WorldDesc& world, const ElementIndex& element) {
  return MatValue(MassField(world, element, &RigidObjectDesc::inertia, &LinkDesc::inertia));
}

void SetInertia(WorldDesc* world, const ElementIndex& element, const ParamValue& value) {
  MassField(world, element, &RigidObjectDesc::inertia, &LinkDesc::inertia) = ValueMat(value);
}

ParamValue GetTransform(const WorldDesc& world, const ElementIndex& element) {
  return PoseToValue(world.objects[element.index].pose);
}

void SetTransform(WorldDesc* world, const ElementIndex& element, const ParamValue& value) {
  world->objects[element.index].pose = ValueToPose(value);
}

ParamValue GetObjectVelocity(const WorldDesc& world, const ElementIndex& element) {
  return TwistToValue(world.objects[element.index].initial_velocity);
}

void SetObjectVelocity(WorldDesc* world, const ElementIndex& element, const ParamValue& value) {
  world->objects[element.index].initial_velocity = ValueToTwist(value);
}

ParamValue GetRobotConfig(const WorldDesc& world, const ElementIndex& element) {
  return VectorValue(world.robots[element.index].InitialConfig());
}

void SetRobotConfig(WorldDesc* world, const ElementIndex& element, const ParamValue& value) {
  world->robots[element.index].config = ValueVector(value);
}

ParamValue GetRobotVelocity(const WorldDesc& world, const ElementIndex& element) {
  return VectorValue(world.robots[element.index].InitialVelocity());
}

void SetRobotVelocity(WorldDesc* world, const ElementIndex& element, const ParamValue& value) {
  world->robots[element.index].velocity = ValueVector(value);
}

ParamValue GetJointLimits(const WorldDesc& world, const ElementIndex& element) {
  const LinkDesc& link = world.robots[element.index].links[element.sub];
  return {link.q_min, link.q_max};
}

// A non-affine driver's limits are its link's (a .rob copies qmin/qmax, velmin/velmax and
// ±torquemax of the link into it): the two setters below keep both copies equal.
bool FollowsLink(const DriverDesc& driver) {
  return driver.type != DriverType::kAffine && !driver.links.empty();
}

void SetJointLimits(WorldDesc* world, const ElementIndex& element, const ParamValue& value) {
  RobotDesc& robot = world->robots[element.index];
  LinkDesc& link = robot.links[element.sub];
  link.q_min = value[0];
  link.q_max = value[1];
  for (DriverDesc& driver : robot.drivers) {
    if (!FollowsLink(driver) || driver.links.front() != element.sub) continue;
    driver.q_min = value[0];
    driver.q_max = value[1];
  }
}

DriverDesc& Driver(WorldDesc* world, const ElementIndex& element) {
  return world->robots[element.index].drivers[element.sub];
}

template <auto Member>
ParamValue GetDriver(const WorldDesc& world, const ElementIndex& element) {
  return One(Driver(const_cast<WorldDesc*>(&world), element).*Member);
}

template <auto Member>
void SetDriver(WorldDesc* world, const ElementIndex& element, const ParamValue& value) {
  Driver(world, element).*Member = value[0];
}

template <auto Min, auto Max>
ParamValue GetDriverRange(const WorldDesc& world, const ElementIndex& element) {
  const DriverDesc& driver = Driver(const_cast<WorldDesc*>(&world), element);
  return {driver.*Min, driver.*Max};
}

template <auto Min, auto Max>
void SetDriverRange(WorldDesc* world, const ElementIndex& element, const ParamValue& value) {
  Driver(world, element).*Min = value[0];
  Driver(world, element).*Max = value[1];
}

LinkDesc* FollowedLink(WorldDesc* world, const ElementIndex& element) {
  const DriverDesc& driver = Driver(world, element);
  if (!FollowsLink(driver)) return nullptr;
  const int link = driver.links.front();
  std::vector<LinkDesc>& links = world->robots[element.index].links;
  return link >= 0 && link < static_cast<int>(links.size()) ? &links[link] : nullptr;
}

void SetVelocityLimits(WorldDesc* world, const ElementIndex& element, const ParamValue& value) {
  SetDriverRange<&DriverDesc::velocity_min, &DriverDesc::velocity_max>(world, element, value);
  if (LinkDesc* link = FollowedLink(world, element)) {
    link->velocity_min = value[0];
    link->velocity_max = value[1];
  }
}

void SetTorqueLimits(WorldDesc* world, const ElementIndex& element, const ParamValue& value) {
  SetDriverRange<&DriverDesc::torque_min, &DriverDesc::torque_max>(world, element, value);
  if (LinkDesc* link = FollowedLink(world, element)) {
    link->torque_max = std::max(-value[0], value[1]);
  }
}

// ---- the rows -----------------------------------------------------------------------------

using T = ParamType;
using A = ParamApply;
constexpr double kNoMax = kInf;
constexpr double kNoMin = -kInf;
constexpr std::span<const std::string_view> kNoChoices;

// clang-format off
const ParamSpec kParams[] = {
    // ---- settings: Klamp't's <globals> ----
    {"timestep", "time step", "s", kSettings, T::kReal, 0, kNoMax, true, false, true, A::kLive, true,
     "largest physics sub-step; adaptive stepping may take smaller ones", kNoChoices,
     GetSetting<&SimSettings::timestep>, SetSetting<&SimSettings::timestep>},
    {"gravity", "gravity", "m/s²", kSettings, T::kVec3, kNoMin, kNoMax, false, false, false, A::kLive,
     true, "gravitational acceleration, world frame", kNoChoices, GetGravity, SetGravity},
    {"ERP", "ERP", "", kSettings, T::kReal, 0, 1, false, false, false, A::kLive, true,
     "error reduction of joints and hard contacts (fraction of an error corrected per step)",
     kNoChoices, GetSetting<&SimSettings::erp>, SetSetting<&SimSettings::erp>},
    {"CFM", "CFM", "", kSettings, T::kReal, 0, kNoMax, false, false, true, A::kLive, true,
     "constraint force mixing of joints (softness); hard contacts use at most 1e-9",
     kNoChoices, GetSetting<&SimSettings::cfm>, SetSetting<&SimSettings::cfm>},
    {"maxContacts", "max contacts", "", kSettings, T::kInteger, 1, 1e6, false, false, false,
     A::kLive, true, "contacts kept per body pair after clustering", kNoChoices,
     GetSetting<&SimSettings::max_contacts>, SetSetting<&SimSettings::max_contacts>},
    {"adaptiveTimeStepping", "adaptive stepping", "", kSettings, T::kBool, 0, 1, false, false,
     false, A::kLive, true,
     "retake a step in halves when it uses up more than half of a boundary layer", kNoChoices,
     GetSetting<&SimSettings::adaptive_time_stepping>,
     SetSetting<&SimSettings::adaptive_time_stepping>},
    {"rigidObjectCollisions", "object-object contact", "", kSettings, T::kBool, 0, 1, false, false,
     false, A::kLive, true, "rigid objects collide with each other", kNoChoices,
     GetSetting<&SimSettings::rigid_object_collisions>,
     SetSetting<&SimSettings::rigid_object_collisions>},
    {"robotSelfCollisions", "robot self-contact", "", kSettings, T::kBool, 0, 1, false, false,
     false, A::kLive, true, "a robot's links collide with each other (allowed pairs only)",
     kNoChoices, GetSetting<&SimSettings::robot_self_collisions>,
     SetSetting<&SimSettings::robot_self_collisions>},
    {"robotRobotCollisions", "robot-robot contact", "", kSettings, T::kBool, 0, 1, false, false,
     false, A::kLive, true, "different robots collide with each other", kNoChoices,
     GetSetting<&SimSettings::robot_robot_collisions>,
     SetSetting<&SimSettings::robot_robot_collisions>},
    // ---- settings: Lamina's <globals> ----
    {"solver", "solver", "", kSettings, T::kChoice, 0, 2, false, false, false, A::kLive, false,
     "step: the exact solver, ODE's dWorldStep, with islands of many contacts and large robots "
     "solved to the same law by Lamina's own solvers; quick: the iterative dWorldQuickStep "
     "(faster, softer); newton: islands of free objects and robots by Lamina's Newton solver, "
     "the rest by dWorldStep",
     kSolverChoices, GetSolver, SetSolver},
    {"quickStepIterations", "quick step iterations", "", kSettings, T::kInteger, 1, 1e6, false,
     false, true, A::kLive, false, "iterations of dWorldQuickStep per step", kNoChoices,
     GetSetting<&SimSettings::quick_step_iterations>,
     SetSetting<&SimSettings::quick_step_iterations>},
    {"jointCoordinates", "joint coordinates", "", kSettings, T::kBool, 0, 1, false, false, false,
     A::kLive, false,
     "newton: robots and world hinges and sliders solved in their joint coordinates, one "
     "unknown per joint, and put back on their joints after each step: no joint drift and a "
     "heavy end on light links holds at large steps; slower on long chains",
     kNoChoices, GetSetting<&SimSettings::joint_coordinates>,
     SetSetting<&SimSettings::joint_coordinates>},
    {"jointStabilization", "close joint gaps", "", kSettings, T::kBool, 0, 1, false, false, false,
     A::kLive, false,
     "the drift a step leaves in the world's hinges, sliders and fixed joints taken back in the "
     "step: a body on a hinge to the world follows its arc, the rest moves along the joints' rows "
     "at the step's start (SHAKE: the energy kept); off: as Klamp't, a gap of about (omega h)^2 r "
     "rides along and ERP closes it a step later",
     kNoChoices, GetSetting<&SimSettings::joint_stabilization>,
     SetSetting<&SimSettings::joint_stabilization>},
    {"sleeping", "sleep idle objects", "", kSettings, T::kBool, 0, 1, false, false, false,
     A::kLive, false,
     "islands of touching objects idle for sleepTime leave the steps until something wakes them",
     kNoChoices, GetSetting<&SimSettings::sleeping>, SetSetting<&SimSettings::sleeping>},
    {"sleepSpeed", "sleep speed", "m/s", kSettings, T::kReal, 0, kNoMax, false, false, true,
     A::kLive, false,
     "an object slower than this (linear m/s and angular rad/s) counts as idle", kNoChoices,
     GetSetting<&SimSettings::sleep_speed>, SetSetting<&SimSettings::sleep_speed>},
    {"sleepTime", "sleep time", "s", kSettings, T::kReal, 0, kNoMax, false, false, false,
     A::kLive, false, "how long an object must stay idle before it sleeps", kNoChoices,
     GetSetting<&SimSettings::sleep_time>, SetSetting<&SimSettings::sleep_time>},
    {"bounceVelocityThreshold", "bounce threshold", "m/s", kSettings, T::kReal, 0, kNoMax, false,
     false, true, A::kLive, false,
     "contacts closing slower than this do not bounce, so resting bodies do not chatter",
     kNoChoices, GetSetting<&SimSettings::bounce_velocity_threshold>,
     SetSetting<&SimSettings::bounce_velocity_threshold>},
    {"maxCorrectionSpeed", "overlap push-out speed", "m/s", kSettings, T::kReal, 0, kNoMax, true,
     false, true, A::kLive, false,
     "a hard contact pushes a layer overlap out no faster than this (ERP alone would turn a 0.6 "
     "mm overlap into a 0.57 m/s rebound)",
     kNoChoices, GetSetting<&SimSettings::max_correction_speed>,
     SetSetting<&SimSettings::max_correction_speed>},
    {"frictionAnchorGain", "friction anchor gain", "", kSettings, T::kReal, 0, 1, false, false,
     false, A::kLive, false,
     "fraction of a sticking contact's tangential drift taken back per step (0: no anchors)",
     kNoChoices, GetSetting<&SimSettings::friction_anchor_gain>,
     SetSetting<&SimSettings::friction_anchor_gain>},
    {"frictionAnchorSlip", "friction anchor slip", "m", kSettings, T::kReal, 0, kNoMax, true, false,
     true, A::kLive, false,
     "drift beyond which a contact counts as sliding and is re-anchored where it is",
     kNoChoices, GetSetting<&SimSettings::friction_anchor_slip>,
     SetSetting<&SimSettings::friction_anchor_slip>},
    {"minimumAdaptiveTimeStep", "minimum adaptive step", "s", kSettings, T::kReal, 0, kNoMax, true,
     false, true, A::kLive, false, "adaptive stepping halves a step no further than this",
     kNoChoices, GetSetting<&SimSettings::minimum_adaptive_step>,
     SetSetting<&SimSettings::minimum_adaptive_step>},
    // ---- bodies: padding and surface (terrains, objects, robot links) ----
    {"padding", "padding", "m", kBodies, T::kReal, 0, kNoMax, false, false, false,
     A::kRebuildGeometry, true, "boundary-layer thickness around the geometry", kNoChoices,
     GetBody<&BodySimParams::padding>, SetBody<&BodySimParams::padding>},
    {"preshrink", "preshrink", "", kBodies, T::kChoice, 0, 2, false, false, false,
     A::kRebuildSimulator, true,
     "none: layer outside the geometry; copy/in-place: geometry shrunk by the padding so the "
     "padded surface matches it",
     kPreshrinkChoices, GetPreshrink, SetPreshrink},
    {"kRestitution", "restitution", "", kBodies, T::kReal, 0, 1, false, false, false, A::kLive, true,
     "coefficient of restitution of hard contacts (pairs average it)", kNoChoices,
     GetSurface<&SurfaceDesc::restitution>, SetSurface<&SurfaceDesc::restitution>},
    {"kFriction", "friction", "", kBodies, T::kReal, 0, kNoMax, false, true, false, A::kLive, true,
     "Coulomb friction coefficient (pairs take the harmonic mean; inf: no sliding)", kNoChoices,
     GetSurface<&SurfaceDesc::friction>, SetSurface<&SurfaceDesc::friction>},
    {"kRollingFriction", "rolling friction", "m", kBodies, T::kReal, 0, kNoMax, false, false,
     false, A::kLive, false,
     "rolling resistance: torque about the contact plane's axes up to this times the normal force "
     "(pairs take the harmonic mean; 0: off, a ball rolls forever)",
     kNoChoices, GetSurface<&SurfaceDesc::rolling_friction>,
     SetSurface<&SurfaceDesc::rolling_friction>},
    {"kSpinningFriction", "spinning friction", "m", kBodies, T::kReal, 0, kNoMax, false, false,
     false, A::kLive, false,
     "spinning resistance: torque about the contact normal up to this times the normal force "
     "(pairs take the harmonic mean; 0: off)",
     kNoChoices, GetSurface<&SurfaceDesc::spinning_friction>,
     SetSurface<&SurfaceDesc::spinning_friction>},
    {"kStiffness", "stiffness", "N/m", kBodies, T::kReal, 0, kNoMax, true, true, true, A::kLive,
     true, "boundary-layer spring (pairs in series; inf: hard contact)", kNoChoices,
     GetSurface<&SurfaceDesc::stiffness>, SetSurface<&SurfaceDesc::stiffness>},
    {"kDamping", "damping", "N·s/m", kBodies, T::kReal, 0, kNoMax, false, true, true, A::kLive,
     true, "boundary-layer damper (pairs in series; inf: hard contact)", kNoChoices,
     GetSurface<&SurfaceDesc::damping>, SetSurface<&SurfaceDesc::damping>},
    // ---- objects and links: mass properties ----
    {"mass", "mass", "kg", kMassive, T::kReal, 0, kNoMax, false, false, true,
     A::kRebuildSimulator, true, "mass of the body", kNoChoices, GetMass, SetMass},
    {"com", "centre of mass", "m", kMassive, T::kVec3, kNoMin, kNoMax, false, false, false,
     A::kRebuildSimulator, true, "centre of mass in the body frame", kNoChoices, GetCom, SetCom},
    {"inertia", "inertia", "kg·m²", kMassive, T::kInertia, kNoMin, kNoMax, false, false, false,
     A::kRebuildSimulator, true,
     "inertia about the centre of mass, body axes (symmetric, positive semi-definite)",
     kNoChoices, GetInertia, SetInertia},
    // ---- initial conditions ----
    {"transform", "initial pose", "m", kObject, T::kPose, kNoMin, kNoMax, false, false, false,
     A::kOnReset, true, "the object frame at the start: rotation (column-major), translation",
     kNoChoices, GetTransform, SetTransform},
    {"velocity", "initial velocity", "rad/s, m/s", kObject, T::kTwist, kNoMin, kNoMax, false,
     false, false, A::kOnReset, true,
     "the object's velocity at the start: angular (rad/s), then linear of its origin (m/s)",
     kNoChoices, GetObjectVelocity, SetObjectVelocity},
    {"config", "initial configuration", "rad or m", kRobot, T::kVector, kNoMin, kNoMax, false,
     false, false, A::kOnReset, true, "joint values at the start, one per link", kNoChoices,
     GetRobotConfig, SetRobotConfig},
    {"velocity", "initial joint velocity", "rad/s or m/s", kRobot, T::kVector, kNoMin, kNoMax,
     false, false, false, A::kOnReset, true, "joint rates at the start, one per link", kNoChoices,
     GetRobotVelocity, SetRobotVelocity},
    // ---- links ----
    {"jointLimits", "joint limits", "rad or m", kLink, T::kRange, kNoMin, kNoMax, false, true,
     false, A::kLive, true, "range of the link's joint: stops and the controller's ramps",
     kNoChoices, GetJointLimits, SetJointLimits},
    // ---- drivers ----
    {"servoP", "kP", "N·m/rad", kDriver, T::kReal, 0, kNoMax, false, false, true, A::kLive, true,
     "proportional gain of the PID servo", kNoChoices, GetDriver<&DriverDesc::servo_p>,
     SetDriver<&DriverDesc::servo_p>},
    {"servoI", "kI", "N·m/(rad·s)", kDriver, T::kReal, 0, kNoMax, false, false, true, A::kLive,
     true, "integral gain of the PID servo", kNoChoices, GetDriver<&DriverDesc::servo_i>,
     SetDriver<&DriverDesc::servo_i>},
    {"servoD", "kD", "N·m·s/rad", kDriver, T::kReal, 0, kNoMax, false, false, true, A::kLive, true,
     "derivative gain of the PID servo", kNoChoices, GetDriver<&DriverDesc::servo_d>,
     SetDriver<&DriverDesc::servo_d>},
    {"torqueLimits", "torque limits", "N·m or N", kDriver, T::kRange, kNoMin, kNoMax, false, true,
     false, A::kLive, true, "the driver's effort is clamped into [min, max]", kNoChoices,
     GetDriverRange<&DriverDesc::torque_min, &DriverDesc::torque_max>, SetTorqueLimits},
    {"velocityLimits", "velocity limits", "rad/s or m/s", kDriver, T::kRange, kNoMin, kNoMax, false,
     true, false, A::kLive, true, "the driver's rate range", kNoChoices,
     GetDriverRange<&DriverDesc::velocity_min, &DriverDesc::velocity_max>, SetVelocityLimits},
    {"dryFriction", "dry friction", "N·m or N", kDriver, T::kReal, 0, kNoMax, false, false, true,
     A::kLive, true, "Coulomb friction of the driven joint", kNoChoices,
     GetDriver<&DriverDesc::dry_friction>, SetDriver<&DriverDesc::dry_friction>},
    {"viscousFriction", "viscous friction", "N·m·s/rad", kDriver, T::kReal, 0, kNoMax, false,
     false, true, A::kLive, true, "viscous friction of the driven joint", kNoChoices,
     GetDriver<&DriverDesc::viscous_friction>, SetDriver<&DriverDesc::viscous_friction>},
};
// clang-format on

// ---- checks -------------------------------------------------------------------------------

int FixedSize(ParamType type) {
  switch (type) {
    case T::kVec3:
      return 3;
    case T::kRange:
      return 2;
    case T::kPose:
      return 12;
    case T::kTwist:
      return 6;
    case T::kInertia:
      return 9;
    case T::kVector:
      return -1;
    default:
      return 1;
  }
}

bool ComponentAccepted(const ParamSpec& spec, double x) {
  if (std::isnan(x)) return false;
  if (std::isinf(x)) {
    if (!spec.allow_inf) return false;
    return x > 0 || spec.type == T::kRange;
  }
  if (spec.min_exclusive ? !(x > spec.min) : !(x >= spec.min)) return false;
  return x <= spec.max;
}

bool InertiaAccepted(const ParamValue& value) {
  const Mat3 inertia = ValueMat(value);
  if (!inertia.allFinite()) return false;
  const double scale = std::max(1.0, inertia.cwiseAbs().maxCoeff());
  if ((inertia - inertia.transpose()).cwiseAbs().maxCoeff() > 1e-9 * scale) return false;
  const Eigen::SelfAdjointEigenSolver<Mat3> solver(inertia, Eigen::EigenvaluesOnly);
  return solver.eigenvalues().minCoeff() >= -1e-12 * scale;
}

bool ShapeAccepted(const ParamSpec& spec, const ParamValue& value) {
  switch (spec.type) {
    case T::kInteger:
    case T::kChoice:
      return value[0] == std::floor(value[0]);
    case T::kBool:
      return value[0] == 0.0 || value[0] == 1.0;
    case T::kRange:
      return value[0] <= value[1];
    case T::kPose:
      return IsRotation(ValueToPose(value).linear());
    case T::kInertia:
      return InertiaAccepted(value);
    default:
      return true;
  }
}

std::string Interval(const ParamSpec& spec) {
  const std::string low = FormatDouble(spec.min);
  if (std::isinf(spec.max)) {
    return std::string(spec.min_exclusive ? "> " : ">= ") + low;
  }
  return (spec.min_exclusive ? "in (" : "in [") + low + ", " + FormatDouble(spec.max) + "]";
}

std::string RealRule(const ParamSpec& spec) {
  if (std::isinf(spec.min) && std::isinf(spec.max)) return "finite";
  std::string rule = Interval(spec);
  if (spec.allow_inf) rule += " (inf allowed)";
  return rule;
}

std::string Join(std::span<const std::string_view> words) {
  std::string out;
  for (size_t i = 0; i < words.size(); ++i) {
    out += (i == 0 ? "" : i + 1 == words.size() ? " or " : ", ");
    out += words[i];
  }
  return out;
}

}  // namespace

std::span<const ParamSpec> Params() {
  return kParams;
}

const ParamSpec* FindParam(std::string_view key, ElementKind kind) {
  for (const ParamSpec& spec : kParams) {
    if (spec.key == key && spec.AppliesTo(kind)) return &spec;
  }
  return nullptr;
}

int ParamId(const ParamSpec& spec) {
  return static_cast<int>(&spec - kParams);
}

std::vector<const ParamSpec*> ParamsOf(ElementKind kind) {
  std::vector<const ParamSpec*> rows;
  for (const ParamSpec& spec : kParams) {
    if (spec.AppliesTo(kind)) rows.push_back(&spec);
  }
  return rows;
}

int ParamSize(const ParamSpec& spec, const WorldDesc& world, const ElementIndex& element) {
  const int fixed = FixedSize(spec.type);
  if (fixed >= 0) return fixed;
  const bool robot = element.index >= 0 && element.index < static_cast<int>(world.robots.size());
  return robot ? world.robots[element.index].dof() : 0;
}

std::string ParamRule(const ParamSpec& spec) {
  switch (spec.type) {
    case T::kReal:
      return "must be " + RealRule(spec);
    case T::kInteger:
      return "must be a whole number " + Interval(spec);
    case T::kBool:
      return "must be true or false (1 or 0)";
    case T::kChoice:
      return "must be " + Join(spec.choices);
    case T::kVec3:
      return "must be 3 finite numbers";
    case T::kRange:
      return "must be 2 numbers min <= max (inf and -inf allowed)";
    case T::kPose:
      return "must be 12 finite numbers: a rotation (column-major) and a translation";
    case T::kTwist:
      return "must be 6 finite numbers: angular, then linear velocity";
    case T::kInertia:
      return "must be a symmetric positive semi-definite 3x3 matrix";
    case T::kVector:
      return "must be one finite number per link";
  }
  return "";
}

bool ParamAccepts(const ParamSpec& spec, const ParamValue& value, int size) {
  if (static_cast<int>(value.size()) != size || size < 0) return false;
  for (double x : value) {
    if (!ComponentAccepted(spec, x)) return false;
  }
  return value.empty() || ShapeAccepted(spec, value);
}

std::optional<std::string> CheckParam(const ParamSpec& spec, const ParamValue& value, int size) {
  if (ParamAccepts(spec, value, size)) return std::nullopt;
  std::string got;
  for (size_t i = 0; i < value.size(); ++i) got += (i ? "," : "") + FormatDouble(value[i]);
  if (static_cast<int>(value.size()) != size) {
    got += " (" + std::to_string(value.size()) + " numbers, needs " + std::to_string(size) + ")";
  }
  return std::string(spec.key) + " " + ParamRule(spec) + ", got " + got;
}

std::optional<ParamValue> GetParam(const WorldDesc& world, const ElementIndex& element,
                                   const ParamSpec& spec, std::string* error) {
  std::optional<std::string> problem = CheckElement(world, element);
  if (!problem && !spec.AppliesTo(element.kind)) {
    problem = ElementPath(element) + ": has no '" + std::string(spec.key) + "'";
  }
  if (problem) {
    if (error) *error = *problem;
    return std::nullopt;
  }
  return spec.get(world, element);
}

std::optional<std::string> CheckParamOn(const WorldDesc& world, const ElementIndex& element,
                                        const ParamSpec& spec, const ParamValue& value) {
  if (auto problem = CheckParam(spec, value, ParamSize(spec, world, element))) {
    return ElementPath(element) + "." + *problem;
  }
  // a non-affine driver's torque limits are ±torqueMax of its link: a .rob holds nothing else
  if (spec.key == "torqueLimits" && element.kind == ElementKind::kDriver &&
      world.robots[element.index].drivers[element.sub].type != DriverType::kAffine &&
      value[0] != -value[1]) {
    return ElementPath(element) +
           ".torqueLimits must be -max,max for a driver that is not affine (its link's "
           "torqueMax), got " +
           FormatParamValue(spec, value);
  }
  return std::nullopt;
}

bool SetParam(WorldDesc* world, const ElementIndex& element, const ParamSpec& spec,
              const ParamValue& value, std::string* error) {
  if (!GetParam(*world, element, spec, error)) return false;
  if (auto problem = CheckParamOn(*world, element, spec, value)) {
    if (error) *error = *problem;
    return false;
  }
  spec.set(world, element, value);
  return true;
}

std::optional<ParamValue> ParseParamValue(const ParamSpec& spec, std::string_view text,
                                          std::string* error) {
  const std::string whole(text);
  const std::string lower = ToLower(whole);
  if (spec.type == T::kBool) {
    if (lower == "true" || lower == "1" || lower == "on") return One(1.0);
    if (lower == "false" || lower == "0" || lower == "off") return One(0.0);
  }
  if (spec.type == T::kChoice) {
    for (size_t i = 0; i < spec.choices.size(); ++i) {
      if (lower == spec.choices[i]) return One(static_cast<double>(i));
    }
  }
  ParamValue value;
  size_t start = 0;
  while (start <= whole.size()) {
    const size_t comma = std::min(whole.find(',', start), whole.size());
    std::string token = whole.substr(start, comma - start);
    token.erase(0, token.find_first_not_of(" \t"));
    token.erase(token.find_last_not_of(" \t") + 1);
    double number = 0.0;
    if (ToLower(token) == "nan") {
      number = std::nan("");
    } else if (!ParseDouble(token, &number)) {
      if (error) {
        *error = "'" + whole + "' is not a value of " + std::string(spec.key) + ", which " +
                 ParamRule(spec);
      }
      return std::nullopt;
    }
    value.push_back(number);
    start = comma + 1;
  }
  if (spec.type == T::kInertia && value.size() == 3) {
    value = {value[0], 0, 0, 0, value[1], 0, 0, 0, value[2]};
  }
  return value;
}

std::string FormatParamValue(const ParamSpec& spec, const ParamValue& value) {
  if (value.size() == 1 && spec.type == T::kBool) return value[0] != 0.0 ? "true" : "false";
  if (value.size() == 1 && spec.type == T::kChoice && value[0] >= 0 &&
      value[0] < static_cast<double>(spec.choices.size())) {
    return std::string(spec.choices[static_cast<size_t>(value[0])]);
  }
  std::string out;
  for (size_t i = 0; i < value.size(); ++i) {
    if (i > 0) out += ',';
    out += FormatDouble(value[i]);
  }
  return out;
}

// Klamp't Python's se3: (R as 9 numbers column by column, t)
ParamValue PoseToValue(const Pose& pose) {
  ParamValue value;
  for (int column = 0; column < 3; ++column) {
    for (int row = 0; row < 3; ++row) value.push_back(pose.linear()(row, column));
  }
  for (int k = 0; k < 3; ++k) value.push_back(pose.translation()[k]);
  return value;
}

Pose ValueToPose(const ParamValue& value) {
  Pose pose = Pose::Identity();
  Mat3 rotation;
  for (int column = 0; column < 3; ++column) {
    for (int row = 0; row < 3; ++row) rotation(row, column) = value[3 * column + row];
  }
  pose.linear() = rotation;
  pose.translation() = Vec3(value[9], value[10], value[11]);
  return pose;
}

ParamValue TwistToValue(const Twist& twist) {
  return {twist.angular.x(), twist.angular.y(), twist.angular.z(),
          twist.linear.x(),  twist.linear.y(),  twist.linear.z()};
}

Twist ValueToTwist(const ParamValue& value) {
  return {Vec3(value[3], value[4], value[5]), Vec3(value[0], value[1], value[2])};
}

namespace {

// the row whose getter is GetSurface<Member>
template <double SurfaceDesc::*Member>
SurfaceRow SurfaceRowOf() {
  for (const ParamSpec& spec : Params()) {
    if (spec.get == &GetSurface<Member>) return {&spec, Member};
  }
  throw std::logic_error("params.cpp: no row reads this SurfaceDesc member");
}

}  // namespace

std::span<const SurfaceRow> SurfaceMembers() {
  static const SurfaceRow kRows[] = {SurfaceRowOf<&SurfaceDesc::restitution>(),
                                     SurfaceRowOf<&SurfaceDesc::friction>(),
                                     SurfaceRowOf<&SurfaceDesc::rolling_friction>(),
                                     SurfaceRowOf<&SurfaceDesc::spinning_friction>(),
                                     SurfaceRowOf<&SurfaceDesc::stiffness>(),
                                     SurfaceRowOf<&SurfaceDesc::damping>()};
  return kRows;
}

}  // namespace lamina::core
