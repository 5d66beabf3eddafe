// SPDX-License-Identifier: MIT
// WorldDesc: the editable, serializable description of a world — terrains, rigid objects,
// robots and simulation settings — in SI units. Loaders fill it, the editor edits it, the
// simulator is built from it and the XML writer saves it. Values that Klamp't allows to be
// infinite (stiffness, damping, joint limits) may be +/-inf here too.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "core/geometry/geometry_desc.h"
#include "core/math_types.h"

namespace lamina::core {

/// Contact surface of one body; two bodies' surfaces are blended per contact pair.
///
/// Rolling and spinning friction are Lamina's (Klamp't has no such setting; ODE's
/// dContactRolling implements them) and off by default, which adds no solver rows, so a world
/// without them simulates exactly as before. Both are lengths (m): the lever arm of the contact
/// patch. Each contact resists the relative rotation of the two bodies about the two axes in its
/// contact plane with a torque of at most rolling_friction · N, and about its normal with at most
/// spinning_friction · N (N its normal force, N); the torque always opposes the relative angular
/// velocity, like Coulomb friction opposes sliding. A sphere of radius r rolling on a plane then
/// decelerates at ρ g / (1.4 r) (docs/contact-model.md, "Rolling and spinning friction").
struct SurfaceDesc {
  double restitution = 0.5;        ///< kRestitution, coefficient of restitution in [0, 1]
  double friction = 0.5;           ///< kFriction, Coulomb coefficient >= 0
  double stiffness = kInf;         ///< kStiffness, N/m; inf = rigid contact
  double damping = kInf;           ///< kDamping, N·s/m; inf = rigid contact
  double rolling_friction = 0.0;   ///< kRollingFriction, m, finite >= 0; 0 = off
  double spinning_friction = 0.0;  ///< kSpinningFriction, m, finite >= 0; 0 = off

  bool operator==(const SurfaceDesc&) const = default;
};

/// How the boundary layer is laid: without shrinking, or by shrinking the geometry by the
/// padding so that the padded surface matches the original one.
enum class Preshrink {
  kNone = 0,     ///< geometry as is, layer outside it
  kCopy = 1,     ///< simulate a shrunk copy; the displayed geometry is unchanged
  kInPlace = 2,  ///< replace the geometry itself with the shrunk one
};

/// A body's rigid-body velocity at the start of a simulation, in world coordinates.
struct Twist {
  Vec3 linear = Vec3::Zero();   ///< m/s, of the body origin
  Vec3 angular = Vec3::Zero();  ///< rad/s

  bool operator==(const Twist&) const = default;
};

/// Per-body simulation parameters (the `<simulation>` block of a world file).
struct BodySimParams {
  double padding = 0.0025;  ///< boundary-layer thickness, m
  Preshrink preshrink = Preshrink::kNone;
  SurfaceDesc surface;

  bool operator==(const BodySimParams&) const = default;
};

/// `<display>` attributes exactly as written (color, faceColor, texture, ...), kept so that
/// saving loses nothing; the renderer interprets them.
using DisplayAttributes = std::map<std::string, std::string>;

/// Identity of a terrain, object or robot that survives renaming and reordering (0: none yet;
/// core/edit's WorldDocument gives every element one). Not saved, not compared.
using ElementUid = std::uint64_t;

struct TerrainDesc {
  ElementUid uid = 0;
  std::string name;
  DisplayAttributes display;
  GeometryDesc geometry;  ///< in world coordinates (terrains do not move)
  BodySimParams sim;      ///< defaults: padding 0, restitution 0.1, friction 0.5, rigid
};

struct RigidObjectDesc {
  ElementUid uid = 0;
  std::string name;
  DisplayAttributes display;
  Pose pose = Pose::Identity();  ///< object frame in the world
  GeometryDesc geometry;         ///< in the object frame
  double mass = 1.0;             ///< kg
  Vec3 com = Vec3::Zero();       ///< centre of mass in the object frame, m
  Mat3 inertia = Mat3::Zero();   ///< about the COM, object axes, kg·m²
  BodySimParams sim;             ///< surface, padding, preshrink
  Twist initial_velocity;        ///< velocity at simulation start
};

/// The motion a link's joint axis allows relative to its parent (`.rob` `jointtype`).
enum class LinkJointAxis { kRevolute, kPrismatic };

struct LinkDesc {
  std::string name;
  int parent = -1;  ///< index of the parent link, -1 for a root
  LinkJointAxis axis_type = LinkJointAxis::kRevolute;
  Vec3 axis = Vec3::UnitZ();                         ///< joint axis in the link frame
  Pose parent_transform = Pose::Identity();          ///< link frame in the parent frame at q = 0
  double q_min = -kInf, q_max = kInf;                ///< position limits, rad or m
  double q_initial = 0.0;                            ///< configuration in the robot file
  double velocity_min = -kInf, velocity_max = kInf;  ///< rad/s or m/s
  double acceleration_max = kInf;                    ///< rad/s² or m/s²
  double torque_max = kInf;                          ///< N·m or N
  double power_max = kInf;                           ///< W
  double mass = 1.0;                                 ///< kg
  Vec3 com = Vec3::Zero();                           ///< in the link frame, m
  Mat3 inertia = Mat3::Identity();                   ///< about the COM, link axes, kg·m²
  /// Geometry in the link frame: [0] is the link's own file, later entries are mounted
  /// meshes (`.rob` `mount`). Empty entries are allowed.
  std::vector<GeometryDesc> geometry;
  BodySimParams sim;  ///< defaults: padding 0.0025, restitution 0.1, friction 1, rigid

  bool has_geometry() const;
};

enum class JointType { kNormal, kSpin, kWeld, kFloating, kFloatingPlanar, kBallAndSocket };

/// Groups links into a joint (`.rob` `joint`). Floating joints span the virtual links from
/// `base` (exclusive) up to `link`.
struct JointDesc {
  JointType type = JointType::kNormal;
  int link = 0;
  int base = -1;  ///< floating, floating-planar and ball-and-socket joints only; -1 = world
};

enum class DriverType { kNormal, kAffine, kTranslation, kRotation };

/// An actuator (`.rob` `driver`) with its limits, servo gains and friction.
struct DriverDesc {
  std::string name;
  DriverType type = DriverType::kNormal;
  /// normal: {link}; affine: the driven links; translation/rotation: {axis link, body link}.
  std::vector<int> links;
  std::vector<double> affine_scale;   ///< affine: q_link = offset + scale * value
  std::vector<double> affine_offset;  ///< affine
  double q_min = -kInf, q_max = kInf;
  double velocity_min = -kInf, velocity_max = kInf;
  double torque_min = -kInf, torque_max = kInf;
  double acceleration_min = -kInf, acceleration_max = kInf;
  double servo_p = 0.0;           ///< proportional gain, N·m/rad
  double servo_i = 0.0;           ///< integral gain, N·m/(rad·s)
  double servo_d = 0.0;           ///< derivative gain, N·m·s/rad
  double dry_friction = 0.0;      ///< Coulomb joint friction, N·m
  double viscous_friction = 0.0;  ///< N·m·s/rad
};

struct RobotDesc {
  ElementUid uid = 0;
  std::string name;
  /// Absolute path of the robot file it was loaded from (.rob or .urdf); "" if built in code.
  std::string source_path;
  std::vector<LinkDesc> links;
  std::vector<JointDesc> joints;
  std::vector<DriverDesc> drivers;
  /// `selfcollision` pairs (link indices). When non-empty only these pairs may collide.
  std::vector<std::pair<int, int>> self_collision;
  /// `noselfcollision` pairs (link indices), removed from the default set.
  std::vector<std::pair<int, int>> no_self_collision;
  /// `property` lines: name -> value text (controller, sensors, ...).
  std::map<std::string, std::string> properties;
  VecX config;    ///< initial configuration, one entry per link
  VecX velocity;  ///< initial joint velocities, one entry per link
  /// `<display>` children of the world's `<robot>` element: (link name or "" for all, attributes).
  std::vector<std::pair<std::string, DisplayAttributes>> link_display;

  int dof() const { return static_cast<int>(links.size()); }
  /// `config` / `velocity` when they have one finite entry per link, else zeros.
  VecX InitialConfig() const;
  VecX InitialVelocity() const;
  /// Sum of link masses, kg.
  double TotalMass() const;
  /// Link pairs (i < j) that may collide with each other: all pairs of links with geometry
  /// except parent-child, or the `selfcollision` list, minus `noselfcollision`.
  std::vector<std::pair<int, int>> SelfCollisionPairs() const;
};

/// The physics solver: the exact one, ODE's dWorldStep (a Dantzig LCP, stiff stacks and mass
/// ratios hold) with the islands where its dense LCP is costly (many contacts, large robots)
/// solved to the same law by Lamina's own solvers; ODE's iterative dWorldQuickStep (projected
/// Gauss-Seidel, faster on large robots, softer); or Lamina's Newton solver for every island of
/// free objects and robots, with dWorldStep for the rest (core/sim/object_islands.h: ODE's rows,
/// the same answer, a factorization of the bodies' size instead of the rows'). The values are
/// the table's choices, in order.
enum class SolverType { kStep, kQuickStep, kNewton };

/// The solver of a simulation (SimSettings::solver and quick_step_iterations).
struct SolverSettings {
  SolverType type = SolverType::kStep;  ///< dWorldStep (exact), dWorldQuickStep or Newton
  int quick_step_iterations = 20;       ///< iterations of dWorldQuickStep
  bool operator==(const SolverSettings&) const = default;
};

/// Global simulation settings (`<simulation><globals>`). The first block is Klamp't's; the rest
/// are Lamina's own `<globals>` attributes (written only when they differ from these defaults;
/// Klamp't ignores them): the solver, sleeping, and the contact and stepping internals a user
/// may need to tune. Every field is a row of the parameter table (core/model/params.h), which
/// holds its range, unit and help text.
struct SimSettings {
  double timestep = 0.001;              ///< s, largest physics sub-step
  Vec3 gravity = Vec3(0.0, 0.0, -9.8);  ///< m/s²
  double erp = 0.95;                    ///< global error reduction parameter
  double cfm = 1e-6;                    ///< global constraint force mixing
  int max_contacts = 20;                ///< contacts kept per body pair after clustering
  bool adaptive_time_stepping = true;   ///< roll back and halve the step when needed
  bool rigid_object_collisions = true;  ///< object-object contacts
  bool robot_self_collisions = false;   ///< robot self-contacts (allowed pairs only)
  bool robot_robot_collisions = true;   ///< contacts between different robots

  SolverType solver = SolverType::kStep;  ///< `solver`: "step" (exact), "quick" or "newton"
  int quick_step_iterations = 20;         ///< `quickStepIterations`
  /// `jointCoordinates`: the Newton solver takes robots in their joint coordinates
  bool joint_coordinates = false;
  /// `jointStabilization`: the drift a step leaves in the world's joints taken back in the step
  bool joint_stabilization = true;
  bool sleeping = false;  ///< `sleeping`: idle objects leave the steps
  /// `sleepSpeed`: linear (m/s) and angular (rad/s) speed below which an object is idle
  double sleep_speed = 0.01;
  double sleep_time = 0.5;  ///< `sleepTime`: s an object must stay idle to sleep
  /// `bounceVelocityThreshold`: contacts closing slower than this do not bounce (m/s)
  double bounce_velocity_threshold = 0.01;
  /// `maxCorrectionSpeed`: fastest push-out of a hard contact's layer overlap (m/s)
  double max_correction_speed = 0.01;
  /// `frictionAnchorGain`: fraction of a sticking contact's tangential drift taken back per step
  double friction_anchor_gain = 0.2;
  /// `frictionAnchorSlip`: drift beyond which a contact counts as sliding and is re-anchored (m)
  double friction_anchor_slip = 5e-4;
  /// `minimumAdaptiveTimeStep`: adaptive stepping halves a step no further than this (s)
  double minimum_adaptive_step = 1e-6;

  SolverSettings solver_settings() const { return {solver, quick_step_iterations}; }
  bool operator==(const SimSettings&) const = default;
};

/// Numbering of world elements as Klamp't numbers them: terrains, then rigid objects, then
/// for each robot its own id followed by one id per link.
struct WorldId {
  enum class Kind { kTerrain, kRigidObject, kRobot, kRobotLink, kInvalid };
  Kind kind = Kind::kInvalid;
  int index = -1;  ///< terrain / object / robot index
  int link = -1;   ///< link index for kRobotLink
};

/// The kind of a world-level joint (`<simulation><joint type="...">`).
enum class WorldJointType { kFixed, kHinge, kSlider };

/// A body a world-level joint holds: a rigid object, a robot link, or a terrain (which stands for
/// the world: terrains do not move).
struct WorldJointBody {
  WorldId::Kind kind = WorldId::Kind::kInvalid;  ///< kTerrain, kRigidObject or kRobotLink
  int index = -1;                                ///< terrain, object or robot index
  int link = -1;                                 ///< kRobotLink only

  bool operator==(const WorldJointBody&) const = default;
};

/// A joint between two bodies, or between a body and the world (Klamp't's `<simulation><joint>`,
/// its ODESimulator ODEJoint): fixed, hinge (about `axis` through `point`) or slider (along
/// `axis`). The hinge angle (rad) and the slider travel (m) are those of the first body relative
/// to the second (or to the world), right-handed about / along `axis` (ODE's convention, hence
/// Klamp't's), and 0 at the bodies' initial poses; the limits count from there. Differences from
/// Klamp't: `max` is read as Klamp't documents it (its reader looks for "minimax"), and a hinge
/// limit beyond ±pi is refused rather than silently ignored by ODE.
struct WorldJointDesc {
  WorldJointType type = WorldJointType::kFixed;
  std::vector<WorldJointBody> bodies;  ///< 1 or 2; one, or a terrain: held to the world
  Vec3 point = Vec3::Zero();           ///< hinge: a point of the axis, world frame (m)
  Vec3 axis = Vec3::UnitZ();           ///< hinge, slider: world frame, unit
  double min = -kInf;                  ///< lower limit (rad or m); -inf: none
  double max = kInf;                   ///< upper limit (rad or m); inf: none
  double friction = 0.0;  ///< N·m or N: the most a zero-velocity motor resists with (0: free)

  bool operator==(const WorldJointDesc&) const = default;
};

/// "fixed", "hinge" or "slider".
const char* WorldJointTypeName(WorldJointType type);

struct WorldDesc;
/// Index of the first world joint that holds object `object`; -1 when none does.
int JointHoldingObject(const WorldDesc& world, int object);
/// After the objects were added, removed or reordered: object i of before is now object
/// `new_index[i]`; the world joints' references follow (none may hold a removed object).
void RenumberJointObjects(WorldDesc* world, const std::vector<int>& new_index);

struct WorldDesc {
  std::string name;         ///< from the file name when loaded
  std::string source_path;  ///< absolute path of the world file; "" if built in code
  std::vector<TerrainDesc> terrains;
  std::vector<RigidObjectDesc> objects;
  std::vector<RobotDesc> robots;
  std::vector<WorldJointDesc> joints;  ///< world-level joints, in file order
  SimSettings settings;
  /// `<simulation>` children Lamina does not model (`<state>`: Klamp't's base64 simulator
  /// state), kept verbatim as XML so that saving writes them back.
  std::vector<std::string> preserved_simulation_xml;

  /// Klamp't world id of a terrain, object, robot or robot link.
  int TerrainId(int terrain) const;
  int ObjectId(int object) const;
  int RobotId(int robot) const;
  int RobotLinkId(int robot, int link) const;
  /// Total number of ids (terrains + objects + sum over robots of links + 1).
  int IdCount() const;
  /// What a world id refers to; kind kInvalid when out of range.
  WorldId Resolve(int id) const;
};

/// Lower-case names as the `.rob` format spells them ("normal", "floatingplanar", ...).
const char* JointTypeName(JointType type);
/// "none", "copy" or "in-place".
const char* PreshrinkName(Preshrink preshrink);

/// Default simulation parameters of each kind of body (Klamp't's defaults, except that
/// terrains are rigid rather than soft; see docs/file-formats.md).
BodySimParams DefaultTerrainSimParams();
BodySimParams DefaultObjectSimParams();
BodySimParams DefaultLinkSimParams();

}  // namespace lamina::core
