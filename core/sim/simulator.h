// SPDX-License-Identifier: MIT
// The simulator: the terrains, rigid objects and robots of a WorldDesc on ODE (double precision)
// with boundary-layer contact. Bodies are named by their Klamp't world id (terrains, then rigid
// objects, then robots and their links).
//
// The class orchestrates units that each own their data: the body table (body_table.h), the
// contact set with its broad phase (contact_set.h, broad_phase.h), the contact rows
// (contact_rows.h), the friction anchors (friction_anchors.h), the step guard (rollback and
// stability, step_guard.h), the feedback recorder (contact_feedback.h) and sleep (sleep.h).
// Every edit of a running simulation reaches it through one path (SetParam and the typed setters
// built on it), and what a change of a body invalidates is decided by one rule (body_change.h).
// Results do not depend on how Simulate is chunked into whole multiples of the step:
// Simulate(0.01) once and Simulate(0.001) ten times give bit-identical states.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/contact/collision_geometry.h"
#include "core/contact/surface_blend.h"
#include "core/control/robot_controller.h"
#include "core/diagnostics.h"
#include "core/model/params.h"
#include "core/model/world_desc.h"
#include "core/sim/body_table.h"
#include "core/sim/contact_feedback.h"
#include "core/sim/contact_set.h"
#include "core/sim/error_meter.h"
#include "core/sim/friction_anchors.h"
#include "core/sim/friction_rows.h"
#include "core/sim/interaction.h"
#include "core/sim/joint_stabilization.h"
#include "core/sim/object_islands.h"
#include "core/sim/sim_state.h"
#include "core/sim/sleep.h"
#include "core/sim/step_guard.h"
#include "core/sim/step_observer.h"
#include "core/sim/world_joints.h"

namespace lamina::core {

class OdeRobot;
class Simulator;
struct PairLaw;

/// A handle on one body of a simulation (a terrain, a rigid object or a robot link): cheap to
/// copy, valid as long as its Simulator. Every setter takes effect on the running simulation and
/// throws std::invalid_argument for a value the parameter table refuses (the message names the
/// path and the rule, as the file readers do) or a non-finite pose, velocity or force. Terrains
/// are static: their pose and velocity setters and forces do nothing.
class SimBody {
 public:
  SimBody(Simulator* simulator, int id) : simulator_(simulator), id_(id) {}
  /// Klamp't world id.
  int id() const { return id_; }
  /// False for an id that is not a terrain, object or link of the world.
  bool valid() const;

  /// A disabled body is frozen where it is and takes no part in contact.
  void Enable(bool enabled = true);
  bool enabled() const;
  /// With dynamics off a body is kinematic: it moves with the velocity it is given, ignores
  /// forces and contacts, and pushes dynamic bodies as if it had infinite mass.
  void EnableDynamics(bool dynamic = true);
  bool dynamics_enabled() const;

  /// Body frame (the object or link frame, not the COM) in the world.
  Pose GetTransform() const;
  void SetTransform(const Pose& pose);
  /// Linear velocity of the body frame's origin and angular velocity, world.
  Twist GetVelocity() const;
  void SetVelocity(const Twist& velocity);

  SurfaceDesc GetSurface() const;
  /// Every surface row (kRestitution in [0, 1], kFriction >= 0, kRollingFriction and
  /// kSpinningFriction finite >= 0, kStiffness > 0, kDamping >= 0; inf allowed for friction,
  /// stiffness and damping) is checked before any is written.
  void SetSurface(const SurfaceDesc& surface);
  double GetPadding() const;
  /// Boundary-layer thickness (m, >= 0); a preshrunk geometry is shrunk again to match.
  void SetPadding(double padding);

  /// Forces that act during every sub-step of the next Simulate call, then end (Klamp't's
  /// autokill hooks). For forces that last, see Simulator::SetAppliedWrench.
  /// `force` (N, world) at `point` (world).
  void ApplyForceAtPoint(const Vec3& force, const Vec3& point);
  /// `force` (N, world) at `point` given in the body frame.
  void ApplyForceAtLocalPoint(const Vec3& force, const Vec3& point);
  /// `force` (N, world) at the centre of mass and `torque` (N·m, world).
  void ApplyWrench(const Vec3& force, const Vec3& torque);

 private:
  Simulator* simulator_;
  int id_;
};

class Simulator {
 public:
  /// Builds the simulation of `world` (copied; later edits go through the setters), with the
  /// world's solver settings or `solver`.
  explicit Simulator(const WorldDesc& world);
  Simulator(const WorldDesc& world, const SolverSettings& solver);
  ~Simulator();
  Simulator(const Simulator&) = delete;
  Simulator& operator=(const Simulator&) = delete;

  /// Advances by `dt` seconds (finite, >= 0; std::invalid_argument otherwise) in sub-steps of at
  /// most the simulation step. The steps lie on the grid of whole steps: a remainder within a
  /// part per million of a step is taken as a whole step, and one shorter than a part per million
  /// of a step is dropped, so calls of whole multiples of the step take the same steps however
  /// they are chunked (a call of 1.5 steps ends with a half step, and the next call's steps start
  /// from there).
  StepStatus Simulate(double dt);
  double time() const { return time_; }
  /// Largest physics sub-step (s); throws std::invalid_argument for what the table refuses
  /// (the `timestep` row: > 0, finite).
  void SetSimStep(double step);
  double sim_step() const { return world_.settings.timestep; }
  /// Throws std::invalid_argument for a non-finite gravity (m/s²).
  void SetGravity(const Vec3& gravity);
  /// Sleeping (off by default, as in ODE, Klamp't and MuJoCo; sleep.h has the rules). Robots
  /// never sleep. Contact feedback does not see a sleeper's contacts with inert bodies. Turning
  /// it off wakes everything.
  void SetSleeping(bool on);
  bool sleeping() const { return world_.settings.sleeping; }
  bool ObjectAsleep(int object) const { return sleep_.asleep(object); }
  int SleepingObjectCount() const { return sleep_.asleep_count(); }
  void SetSolver(const SolverSettings& solver);
  SolverSettings solver() const { return world_.settings.solver_settings(); }
  /// Back to the initial poses and velocities of the world description, time 0; held wrenches,
  /// drags and kinematic targets end.
  void Reset();
  SimState GetState() const;
  /// GetState into existing storage.
  void CaptureState(SimState* state) const;
  /// Restores a state of this simulation exactly; a simulation stopped by an error is built anew
  /// first (ODE cannot be trusted after one of its errors). std::invalid_argument for a state
  /// that is not finite.
  void SetState(const SimState& state);
  const SimStatistics& statistics() const { return statistics_; }
  /// The live accuracy meter (error_meter.h): off by default. On, some steps are first taken
  /// once whole and once in halves from the same state, both thrown away, and the state restored
  /// exactly, so results are bit-identical with the meter on or off; it costs at most the
  /// meter's budget (5 %) of the stepping time. Turning it on or off restarts its reading.
  void SetErrorMeter(bool on);
  bool error_meter() const { return meter_on_; }
  ErrorMeterReading error_meter_reading() const { return meter_.Reading(); }
  /// Warnings from building the simulation (e.g. a preshrink that flipped triangles).
  const Diagnostics& diagnostics() const { return diagnostics_; }
  /// The simulated world: the description it was built from with every edit since (surfaces,
  /// paddings, settings, drivers, joint limits); poses are the initial ones (see UpdateWorld).
  const WorldDesc& world() const { return world_; }
  /// Klamp't's UpdateModel: writes every row of the parameter table as the simulation has it
  /// (every live edit) into `world`, which must have the same elements (std::invalid_argument
  /// otherwise), and the current state as its initial conditions: object poses and velocities,
  /// robot configurations and velocities. An editor never calls it on its document (runtime state
  /// enters a document only through an explicit edit, core/edit).
  void UpdateWorld(WorldDesc* world) const;

  // ---- live edits: the rows of the parameter table (core/model/params.h) ------------------
  /// The value of a row on an element of the simulated world (its description with every edit
  /// so far); nullopt with `error` naming the path when the element or the row does not exist.
  std::optional<ParamValue> GetParam(const ElementIndex& element, const ParamSpec& spec,
                                     std::string* error = nullptr) const;
  /// The one path by which an edit reaches the simulation. Checks the element, the row and the
  /// value exactly as the file readers do (a refused edit changes nothing and `error` names the
  /// path and the rule), writes the simulated description, then by the row's apply kind: kLive
  /// from the next step; kRebuildGeometry rebuilds the body's collision geometry;
  /// kRebuildSimulator builds the whole simulation anew from the description and restores its
  /// state (MuJoCo's mj_recompile); kOnReset changes only what Reset starts from.
  bool SetParam(const ElementIndex& element, const ParamSpec& spec, const ParamValue& value,
                std::string* error);
  /// Builds the simulation anew from its description in the state it is in; a simulation stopped
  /// by an error, in the state at the start of the step that failed.
  void Rebuild();
  /// True after an error stopped the simulation (Simulate returns kError until SetState, Reset
  /// or Rebuild).
  bool halted() const { return halted_; }

  // ---- step observers ---------------------------------------------------------------------
  /// `observer` is called after every accepted physics sub-step (step_observer.h); the id
  /// removes it. An observer may add or remove observers (an added one is called from the next
  /// step); it must not step or edit the simulation, and an exception from it ends the Simulate
  /// call.
  int AddStepObserver(StepObserver observer);
  void RemoveStepObserver(int id);
  /// A step another engine took (tests/bench/peers: MuJoCo and Bullet run the accuracy scenes,
  /// and a Simulator of the same world mirrors their states so that the same probes judge
  /// them). Call it after setting the poses and velocities the other engine reached: nothing is
  /// integrated or collided; the time advances by `h` (> 0, finite; std::invalid_argument
  /// otherwise), the statistics count an accepted step with `contact_joints` and `contacts`
  /// (their max_depth: the other engine's deepest penetration, m) and the observers see it.
  void MirrorStep(double h, int contact_joints, const std::vector<ContactPair>& contacts);

  /// Body by Klamp't world id (terrains, then objects, then robots and their links).
  SimBody body(int id) { return SimBody(this, id); }
  /// Body `id` has an ODE body (it is dynamic or kinematic, not static); false for other ids.
  bool BodyMoves(int id) const {
    const BodyRecord* body = bodies_.Find(id);
    return body != nullptr && body->body != nullptr;
  }
  int body_count() const { return bodies_.size(); }
  /// Kinetic energy of every freely moving body (J) and potential energy of every body with mass
  /// in gravity (−Σ m g·p_com, J), at the current state.
  double KineticEnergy() const;
  double PotentialEnergy() const;

  // rigid objects, by index in world().objects; std::out_of_range for a bad index
  int object_count() const { return static_cast<int>(bodies_.object_ids().size()); }
  /// Object frame (not the COM) in the world.
  Pose GetObjectPose(int object) const;
  void SetObjectPose(int object, const Pose& pose);
  /// Linear velocity of the object frame's origin and angular velocity, world.
  Twist GetObjectVelocity(int object) const;
  void SetObjectVelocity(int object, const Twist& velocity);

  // ---- forces that last (MuJoCo's xfrc_applied) -----------------------------------------
  /// A force (N, world) at the centre of mass and a torque (N·m, world) on body `id`, acting at
  /// every step until changed or cleared, however Simulate is chunked. Replaces the body's
  /// previous held wrench. std::invalid_argument for non-finite values; nothing for static ids.
  void SetAppliedWrench(int id, const Vec3& force, const Vec3& torque);
  /// A force (N, world direction) that lasts, acting at `local_point` (body frame, moves with
  /// the body).
  void SetAppliedForceAtLocalPoint(int id, const Vec3& force, const Vec3& local_point);
  void ClearAppliedWrench(int id);
  void ClearAppliedWrenches();

  // ---- interaction: the mouse spring and kinematic drags (interaction.h) -----------------
  /// Grabs body `id` (an object or robot link with an ODE body) at world point `point` with an
  /// implicit spring towards a target (initially the point itself). False for a static,
  /// disabled, kinematic or unknown body; std::invalid_argument for bad settings. One grab at a
  /// time; a new one replaces the old. The grabbed body stays awake and out of the energy check.
  bool StartDrag(int id, const Vec3& point, const DragSpringSettings& settings = {});
  /// Moves the spring's target (world). Held until the next call or EndDrag, whatever the
  /// chunking; the stretch is capped at settings.max_stretch.
  void SetDragTarget(const Vec3& target);
  void EndDrag();
  bool dragging() const { return drag_.active; }
  /// The turn drag (interaction.h): grabs body `id` with an implicit rotational spring that turns
  /// it towards a target orientation (initially its own), scaled by its rotational effective
  /// inertia (a robot link's articulated one). False for what StartDrag refuses and for a link no
  /// free hinge turns; std::invalid_argument for bad settings (max_stretch is not used). Ends
  /// like a grab (EndDrag) and replaces it: one grab at a time.
  bool StartRotateDrag(int id, const DragSpringSettings& settings = {});
  /// The orientation (world) the turn drag turns the body's frame towards, held like
  /// SetDragTarget; nothing without a turn drag. std::invalid_argument for a matrix that is not a
  /// rotation.
  void SetDragTargetOrientation(const Mat3& rotation);
  /// The grab: body, point, target, spring parameters and the force on the body in the last
  /// step (N, world); for a turn drag its target orientation, spring and torque (N·m, world).
  const DragState& drag() const { return drag_; }
  /// Body `id` becomes kinematic and moves, at constant velocity, to reach the frame `target`
  /// after `duration` s of simulated time (a step if 0), then stops there; it pushes what it
  /// meets and carries what rests on it by friction (Box2D's b2Body_SetTargetTransform).
  /// Calling it again (every frame of a mouse drag) retargets it. False (nothing done) for a
  /// static or disabled body; std::invalid_argument for a pose that is not rigid.
  bool SetKinematicTarget(int id, const Pose& target, double duration);
  /// The body becomes dynamic again (unless it was kinematic before the first target) with the
  /// velocity it last moved at, so a throw works; held still on its target for longer than its
  /// last move took, it is released at rest.
  void ReleaseKinematicTarget(int id);
  bool HasKinematicTarget(int id) const { return targets_.count(id) != 0; }

  // robots, by index in world().robots
  int robot_count() const { return static_cast<int>(robots_.size()); }
  /// Joint values (rad or m; one per link; revolute joints keep whole turns) and rates.
  VecX GetRobotConfig(int robot) const;
  VecX GetRobotVelocity(int robot) const;
  /// Teleports a robot (bodies placed by forward kinematics); the controller is not told.
  void SetRobotConfig(int robot, const VecX& q);
  void SetRobotVelocity(int robot, const VecX& dq);
  /// Changes the joint range of a robot link on the running simulation (the jointLimits row):
  /// its joint stops from the next step, and the position limits of the controller's ramps.
  /// Throws std::out_of_range for a bad robot or link index and std::invalid_argument for what
  /// the table refuses (a NaN bound or q_min > q_max; infinite bounds remove the stop).
  void SetJointLimits(int robot, int link, double q_min, double q_max);
  /// The controller of a robot: commands, gains, limits and friction, all live (its drivers are
  /// this simulation's description: RobotController::ViewOf). std::out_of_range for a bad index.
  RobotController& controller(int robot);
  const RobotController& controller(int robot) const;
  /// Clamped driver efforts at the current state (driver-sized; Klamp't getActualTorque).
  VecX GetActuatorTorques(int robot) const;

  /// The robot's sensors (core/sensors/robot_sensors.h): sampled at the start of every physics
  /// step before its controller, each at its own rate (simulator_sensors.cpp).
  RobotSensors& sensors(int robot);
  const RobotSensors& sensors(int robot) const;
  /// What camera sensors render through (null: cameras measure nothing); not owned, and must
  /// outlive its use. A simulation without cameras never calls it.
  void SetCameraRenderer(CameraRenderer* renderer) { camera_renderer_ = renderer; }
  /// Distance (m) from `origin` along unit `direction` to the first body surface (padding not
  /// counted), skipping body `ignore_id` (-1: none); +inf beyond `max_distance`.
  double CastRay(const Vec3& origin, const Vec3& direction, double max_distance,
                 int ignore_id = -1) const;
  /// No physics: runs the controllers for dt, advances the time and moves every robot to its
  /// commanded configuration with the commanded velocities. Objects stay where they are.
  void FakeSimulate(double dt);

  // contacts at the current state (after clustering), one entry per touching pair
  const std::vector<ContactPair>& contact_pairs() const { return contacts_.pairs(); }
  /// Whether mesh–mesh pairs keep their candidate triangle pairs between steps (on by default;
  /// bitwise the same contacts either way: core/contact/near_pair_cache.h). For tests and
  /// benchmarks.
  void SetReuseContactPairs(bool reuse) { contacts_.SetReusePairs(reuse); }
  /// Whether the islands of robots with at least kDirectRobotBodies bodies go to the direct
  /// solve (direct_solver.h) when one Newton step does not settle them (on by default), under
  /// both solvers; off, the exact solver leaves them to dWorldStep's own LCP, as other islands,
  /// and the Newton solver takes them alone. For tests and comparisons;
  /// SetDirectRobotMinimumBodies changes the size.
  void SetDirectRobotSolve(bool direct) { direct_robots_ = direct; }
  void SetDirectRobotMinimumBodies(int bodies) { direct_min_bodies_ = bodies; }
  /// Whether such a robot's island first gets one Newton step, under both solvers (on by
  /// default: object_islands.h; the direct solve takes what it does not settle). For tests.
  void SetRobotNewtonStep(bool newton) { islands_.SetRobotNewtonStep(newton); }
  /// dWorldStep's dense LCP grows as the cube of a robot's rows, the direct solve about as its
  /// bodies: HRP-2 (36 bodies) steps 3× faster directly, the TX90L arm (6) 1.8× slower.
  static constexpr int kDirectRobotBodies = 12;
  /// Whether the exact solver gives an island of free objects with at least
  /// kNewtonObjectContacts contacts (and no robot) to the Newton solver (on by default:
  /// object_islands.h; the same row law, its answer where ODE's Dantzig solver is exact, the
  /// consistent one where friction saturates) or leaves it to dWorldStep's own LCP. For tests
  /// and comparisons.
  void SetNewtonObjectIslands(bool newton) { newton_objects_ = newton; }
  /// dWorldStep's dense LCP grows as the cube of the rows (three per contact), a Newton step
  /// with the bodies: the 10-box stack's island (40 contacts) takes about a ninth of
  /// dWorldStep's solver time, stiffness_test.xml's balls on a mesh (up to 20) a quarter; a block
  /// sliding on 4 contacts twice as long (docs/simulator.md).
  static constexpr int kNewtonObjectContacts = 8;
  /// The most Newton steps an island (but a large robot's) gets (0: the solver's own choice,
  /// ObjectIslands::NewtonBudget). For tests: an island that does not converge goes to
  /// dWorldStep, or, beyond ObjectIslands::kMostHandBackRows rows, is relaxed by
  /// Gauss–Seidel sweeps (row_relaxation.h) and flags its step "contact unreliable".
  void SetNewtonBudget(int steps) { islands_.SetNewtonBudget(steps); }
  /// Hierarchy searches of mesh–mesh pairs, and queries answered from kept candidates.
  long long ContactPairSearches() const { return contacts_.PairCollections(); }
  long long ContactPairReuses() const { return contacts_.PairReuses(); }
  /// The blend of the current surfaces of bodies a and b (BlendSurfaces, surface_blend.h): the
  /// one function the contact joints, the step guard and readouts (contact_readout.h) take it
  /// from. std::out_of_range for an id that is not a terrain, object or link.
  BlendedSurface PairSurface(int a, int b) const;
  /// What every contact joint of `pair` shares in a step of `step` s (MakePairLaw with
  /// PairSurface, contact_rows.h): the joints are built from it.
  PairLaw PairContactLaw(const ContactPair& pair, double step) const;

  // contact feedback, recorded only for pairs that asked for it (see contact_feedback.h for the
  // sign convention). b = -1 means "any body" in the queries.
  /// Records every pair that can touch now: object–terrain, object–object (when rigid objects
  /// collide), robot links with terrains, objects and other robots, and allowed self-collision
  /// pairs (when robot self-collisions are on). Pairs that become collidable later (a body
  /// enabled or made dynamic) need another call.
  void EnableContactFeedbackAll();
  void EnableContactFeedback(int a, int b);
  const FeedbackRecorder& feedback() const { return feedback_; }
  /// The pairs (first < second) whose feedback is recorded, sorted.
  std::vector<std::pair<int, int>> ContactFeedbackPairs() const;
  /// Contacts acted between a and b in the last sub-step.
  bool InContact(int a, int b = -1) const;
  /// During the last Simulate call: some sub-step had contact / had none / interpenetrated.
  bool HadContact(int a, int b = -1) const;
  bool HadSeparation(int a, int b = -1) const;
  bool HadPenetration(int a, int b = -1) const;
  /// Contacts of the last sub-step, normals into a.
  std::vector<FeedbackContact> GetContacts(int a, int b) const;
  /// Force on a of each contact of GetContacts(a, b) (N, world).
  std::vector<Vec3> GetContactForces(int a, int b) const;
  /// Total contact force on a from b in the last sub-step (N, world).
  Vec3 ContactForce(int a, int b = -1) const;
  /// Total contact torque on a from b about the world origin in the last sub-step (N·m).
  Vec3 ContactTorque(int a, int b = -1) const;
  /// Time average over the last Simulate call of the contact force / torque on a from b.
  Vec3 MeanContactForce(int a, int b = -1) const;
  Vec3 MeanContactTorque(int a, int b = -1) const;

  // ---- world-level joints (world().joints; world_joints.h) -------------------------------
  int world_joint_count() const { return world_joints_.size(); }
  /// Joint `joint`'s hinge angle (rad) or slider travel (m) from the initial pose, and its rate
  /// (rad/s, m/s); 0 for a fixed joint. std::out_of_range for a joint that does not exist.
  double WorldJointPosition(int joint) const { return world_joints_.Position(joint); }
  double WorldJointRate(int joint) const { return world_joints_.Rate(joint); }

 private:
  friend class SimBody;
  struct RobotScratch {
    VecX q, dq, forces;
    std::vector<ServoMotorCommand> motors;
    VecX rates_after;                       ///< joint rates after a tentative step (servo check)
    std::vector<char> keep_bound;           ///< per link: its servo row stays bounded this sub-step
    std::vector<FrictionCommand> friction;  ///< friction rows given unbounded or as torques
    std::vector<int> friction_holdoff;  ///< per link: accepted steps its friction row stays bounded
    std::vector<double> gaps, gaps_before;  ///< joint gaps now and at the sub-step's start
    std::vector<Pose> frames;               ///< link frames, for the gaps
    std::vector<char> known;                ///< links with a frame (not virtual)
    std::vector<int> joint_count;           ///< per owning link: the robot's joints on its body
    std::vector<char> diverging;  ///< per driver: QuickStep solves its servo implicitly this step
  };
  struct RobotPlacement {  ///< where a robot is, to place it again after a rebuild
    VecX q, dq;
    std::vector<Pose> frames;  ///< of its links
  };
  struct StepProgress {  ///< what the sub-steps of one Step reported so far
    unsigned flags = 0;
    int rollbacks = 0;
    int corrections = 0;
    std::vector<int> corrected_bodies;  ///< world ids of the bodies slowed or stopped
    double joint_gap = 0.0;             ///< m, the widest joint gap after the accepted sub-step
  };
  enum class IntegrateResult { kOk, kOdeError, kNonFinite };
  enum class SubStep { kAccepted, kRetake, kError };

  // building (simulator.cpp, simulator_bodies.cpp, simulator_robots.cpp)
  void Build();
  void TearDown();
  void RebuildWith(const SimState& state);
  void BuildKeepingFlags();
  std::vector<RobotPlacement> RobotPlacements() const;
  void KeepRobotPlacements(const std::vector<RobotPlacement>& placements);
  void BuildBodies();
  void BuildObject(int id, int object);
  void BuildRobot(int robot, int first_link_id);
  void RebuildCollisionGeometry(int id);
  std::shared_ptr<const CollisionGeometry> LinkCollisionGeometry(int robot, int link);
  void ApplyInitialState();
  void BuildWorldJoints();

  // the step (simulator.cpp)
  StepStatus Step(double step);
  SubStep TrySubStep(double* h, StepProgress* progress, bool* recovered);
  IntegrateResult Integrate(double step);
  /// The gravity of a step of `step` (gravity_kick.h; the world's while the meter probes).
  Vec3 KickGravity(double step) const;
  void BuildConstraints(double step);
  StepStatus AcceptStep(double step, StepProgress* progress);
  SubStep Halt(const std::string& error);
  void DispatchStep(const StepEvent& event);
  void DetectContacts();
  void UpdateBounds();
  bool MayCollide(const BodyRecord& a, const BodyRecord& b) const;
  // the tunnelling check (simulator_sweep.cpp)
  bool ObjectTunnelled() const;
  bool SegmentCrossesBody(int id, const Vec3& from, const Vec3& to) const;
  void CaptureBodyState(SimState* state, bool with_controllers) const;
  void RestoreState(const SimState& state);

  // contact joints and feedback (simulator_contacts.cpp)
  void AddContactJoints(const ContactPair& pair, const Vec3* anchor_velocities, double step);
  /// The islands of free objects and robots Lamina's solvers take, before the contact joints
  /// (object_islands.h); `exact`: the exact solver's
  void PrepareObjectIslands(bool exact);
  /// The world id that stands for `id`'s ODE body in the islands (a merged link: the link that
  /// owns the body), or -1 when it does not move freely or sleeps
  int IslandBody(int id) const;
  bool IsRobotLink(int id) const;
  /// Robot `robot` can go to the Newton solver this step: every body moving freely and awake,
  /// none dragged, no joint on its bodies but its own
  bool RobotForIslands(int robot);
  bool RobotSolvedDirectly(int robot);
  int OwnBodies(int robot) const;
  void KeepRobotJoints(int robot);
  /// Under the Newton solver in joint coordinates: the world's hinges and sliders between free
  /// rigid objects (or one and the world) kept in the islands; `kept[id]`: how many on body id
  void KeepWorldJoints(std::vector<int>* kept);
  bool WorldJointIslandBodies(int joint, int* a, int* b) const;
  /// After a step: the bodies of those the reduced step took back on their joints
  void ProjectReducedWorldJoints();
  /// Before and after a step: the other world joints' drift in it taken back
  /// (simulator_joints.cpp)
  void PrepareJointStabilization();
  void StabilizeWorldJoints(double step);

  // the accuracy meter (simulator_meter.cpp)
  void SampleStepError(double step);
  bool ProbeSteps(const SimState& start, const std::vector<double>& steps,
                  std::vector<Vec3>* positions);
  std::vector<Vec3> MovingBodyPositions() const;

  // robots (simulator_robots.cpp)
  void RunControllers(double step);
  void PrepareRobotsForStep(double step);
  void MarkUnboundedServos(RobotScratch* scratch);
  void QuickStepServos(int robot, double step);
  bool BoundOverrunServos();
  bool FrictionGuessesFailed();
  void AcceptRobotStep(double step);
  void CaptureRobotState(SimState* state, bool with_controllers) const;
  void RestoreRobotState(const SimState& state);
  void RestoreOneRobot(int robot, const RobotSimState& state);
  // robots in the step guard (robot_guard.h)
  void MeasureJointGaps(int robot, std::vector<double>* gaps);
  void MeasureRobotJointGapsBefore();
  int StopBrokenRobots(std::vector<int>* ids);
  bool JointsOpen(double* largest) const;
  void ProjectReducedRobots();
  void RestoreControllers(const SimState& state);
  void RobotLinksChanged(int robot, unsigned changes);
  int RequireRobot(int robot) const;

  // sensors (simulator_sensors.cpp)
  void BuildSensors();
  void SampleSensors(int robot, double step);
  void RecordSensorStep(int robot);
  std::vector<LinkContact> RobotContacts(int robot) const;

  // edits (simulator_edit.cpp)
  void ApplySettingsEdit(const ParamSpec& spec);
  void ApplyBodyEdit(const ElementIndex& element, const ParamSpec& spec);
  void ApplyRobotEdit(const ElementIndex& element, const ParamSpec& spec);
  void SetBodySurface(int id, const SurfaceDesc& surface);
  void SetBodyPadding(int id, double padding);

  // interaction (simulator_interaction.cpp)
  void MoveKinematicTargets(double step);
  void AddDragJoint(double step);
  void AddTurnJoint(double step);
  void AcceptInteraction(double step);
  void ClearInteraction();
  std::vector<bool> FreeJoints(int robot) const;
  double EffectiveMassAt(int id, const Vec3& point) const;
  double EffectiveInertiaOf(int id) const;
  bool TurnSpringOf(int id, const DragSpringSettings& settings, DragState* drag) const;
  bool CanGrab(int id) const;
  void RescaleDrag();
  std::vector<int> SharingBody(int id) const;

  // bodies (simulator_bodies.cpp)
  /// The one invalidation rule (body_change.h): what `changes` to body `id` make stale and wake.
  void BodyChanged(int id, unsigned changes);
  const BodySimParams& sim_params(int id) const;
  BodyRecord& RequireObject(int object);
  const BodyRecord& RequireObject(int object) const;
  BodyRecord& RequireBody(int id);
  const BodyRecord& RequireBody(int id) const;
  bool BodyEnabled(int id) const;
  void SetBodyEnabled(int id, bool enabled);
  bool BodyDynamic(int id) const;
  void SetBodyDynamic(int id, bool dynamic);
  Pose BodyPose(int id) const;
  void SetBodyPose(int id, const Pose& pose);
  Twist BodyVelocity(int id) const;
  void SetBodyVelocity(int id, const Twist& velocity);
  void AddBodyForce(int id, const Vec3& force, const Vec3& point);
  void AddBodyWrench(int id, const Vec3& force, const Vec3& torque);

  WorldDesc world_;
  Diagnostics diagnostics_;
  CollisionGeometryCache geometry_cache_;
  OdeWorldPtr ode_world_;
  OdeJointGroupPtr contact_group_;
  std::unique_ptr<OdeDragJoint, void (*)(OdeDragJoint*)> drag_joint_;  ///< the spring's readout
  BodyTable bodies_;
  std::vector<std::unique_ptr<OdeRobot>> robots_;
  OdeWorldJoints world_joints_;
  JointStabilizer stabilizer_;  ///< and its inputs, reused every step (StabilizeWorldJoints)
  std::vector<dxBody*> stabilized_ids_;
  std::vector<StabilizedBody> stabilized_bodies_;
  std::vector<StabilizedJoint> stabilized_joints_;
  std::vector<RobotController> controllers_;
  std::vector<RobotSensors> sensors_;  ///< per robot; made once, as the controllers
  CameraRenderer* camera_renderer_ = nullptr;
  std::vector<std::vector<std::pair<int, int>>> self_collision_pairs_;  ///< per robot, sorted
  std::vector<RobotScratch> robot_scratch_;  ///< per robot, reused every sub-step
  std::vector<int> island_joint_count_;      ///< PrepareObjectIslands: kept world joints per body
  std::vector<int> collidable_;              ///< ids of bodies with geometry, for the broad phase
  ContactSet contacts_;
  FrictionAnchors anchors_;
  StepGuard guard_;
  FeedbackRecorder feedback_;
  ObjectIslands islands_;  ///< this step's islands for Lamina's own solvers (object_islands.h)
  bool islands_active_ = false;  ///< islands_ takes part in this step
  /// an island too large to hand back kept an unconverged answer in this sub-step
  bool islands_unconverged_ = false;
  bool direct_robots_ = true;   ///< SetDirectRobotSolve
  bool newton_objects_ = true;  ///< SetNewtonObjectIslands
  int direct_min_bodies_ = kDirectRobotBodies;
  SleepTracker sleep_;
  DragState drag_;
  std::map<int, KinematicTarget> targets_;  ///< by body id
  std::vector<std::pair<int, StepObserver>> observers_;
  bool dispatching_ = false;  ///< observers are being called
  int next_observer_ = 0;
  double time_ = 0.0;
  double last_step_ = 0.0;  ///< the last accepted step (s; 0: none yet; gravity_kick.h)
  bool halted_ = false;     ///< an error stopped the simulation
  SimState last_good_;      ///< when halted: the state at the start of the step that failed
  SimStatistics statistics_;
  ErrorMeter meter_;
  bool meter_on_ = false;
  bool probing_ = false;  ///< the meter's probe steps: no observers, nothing kept
};

}  // namespace lamina::core
