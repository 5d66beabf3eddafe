// SPDX-License-Identifier: MIT
// The simulator: rigid objects and terrains of a WorldDesc on ODE (double precision) with
// boundary-layer contact. Every setter works on a running simulation. Bodies are named by their
// Klamp't world id (terrains, then rigid objects, then robots and their links); robots slot in
// later as further bodies and joints.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/contact/collision_geometry.h"
#include "core/control/robot_controller.h"
#include "core/diagnostics.h"
#include "core/model/params.h"
#include "core/model/world_desc.h"
#include "core/sim/contact_feedback.h"
#include "core/sim/energy_guard.h"
#include "core/sim/sim_state.h"
#include "core/sim/sim_timing.h"

// ODE's opaque types (ode/common.h), so that this header does not pull in ODE
struct dxWorld;
struct dxBody;
struct dxJointGroup;
struct dxJoint;
struct dContact;

namespace lamina::core {

class OdeRobot;

enum class StepStatus {
  kNormal = 0,
  kAdaptiveStep = 1,       ///< a step was rolled back and retaken with a smaller step
  kContactUnreliable = 2,  ///< underlying geometries interpenetrated (beyond the padding)
  kUnstable = 3,           ///< energy blew up (or a state became non-finite) and was corrected
  kError = 4,              ///< ODE failed or a state stayed non-finite; the simulation stopped
};
/// "normal", "adaptive step", ...
const char* StepStatusName(StepStatus status);

/// Counters since construction or the last Reset.
struct SimStatistics {
  long steps = 0;                    ///< physics sub-steps taken (accepted)
  long rollbacks = 0;                ///< sub-steps undone and retaken at half the step
  long instability_corrections = 0;  ///< bodies whose energy blow-up was corrected
  int max_contacts_in_step = 0;      ///< most contact joints in one sub-step
  long contact_joints = 0;           ///< contact joints over all accepted sub-steps
  double max_penetration = 0.0;      ///< deepest boundary-layer overlap in an accepted state, m
  StepStatus worst_status = StepStatus::kNormal;
  std::string error;  ///< what stopped the simulation (kError)
  SimTimeSplit time_split;
};

/// The contacts between two bodies at the current state, after clustering.
struct ContactPair {
  int a = -1;  ///< world id of a body with an ODE body (dynamic or kinematic)
  int b = -1;  ///< world id of the other body (may be static); normals point from b into a
  ContactList contacts;
  double tolerance = 0.0;  ///< padding sum of the pair (m)
  double max_depth = 0.0;  ///< deepest boundary-layer overlap (m)
  bool penetrating = false;
  /// fastest tangential correction of the pair's friction anchor in a step from here (m/s)
  double anchor_speed = 0.0;
};

class Simulator;

/// A handle on one body of a simulation (a terrain, a rigid object, later a robot link): cheap to
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
  /// All four rows (kRestitution in [0, 1], kFriction >= 0, kStiffness > 0, kDamping >= 0; inf
  /// allowed but for restitution) are checked before any is written.
  void SetSurface(const SurfaceDesc& surface);
  double GetPadding() const;
  /// Boundary-layer thickness (m, >= 0); a preshrunk geometry is shrunk again to match.
  void SetPadding(double padding);

  /// Forces that act during every sub-step of the next Simulate call, then end.
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

  /// Advances by `dt` seconds in sub-steps of at most the simulation step.
  StepStatus Simulate(double dt);
  double time() const { return time_; }
  /// Largest physics sub-step (s); throws std::invalid_argument for what the table refuses
  /// (the `timestep` row: > 0, finite).
  void SetSimStep(double step);
  double sim_step() const { return world_.settings.timestep; }
  /// Throws std::invalid_argument for a non-finite gravity (m/s²).
  void SetGravity(const Vec3& gravity);
  /// Sleeping (off by default, as in ODE, Klamp't and MuJoCo): a rigid object that has moved
  /// slower than settings.sleep_speed (linear, m/s, and angular, rad/s) for sleep_time s, together
  /// with every free body it touches, is taken out of the steps until an awake or kinematic
  /// body touches it, a setter or an applied force reaches it, or gravity changes. Robots never
  /// sleep. Contact feedback does not see a sleeper's contacts with inert bodies. Turning it off
  /// wakes everything.
  void SetSleeping(bool on);
  bool sleeping() const { return world_.settings.sleeping; }
  bool ObjectAsleep(int object) const;
  int SleepingObjectCount() const;
  void SetSolver(const SolverSettings& solver);
  SolverSettings solver() const { return world_.settings.solver_settings(); }
  /// Back to the initial poses and velocities of the world description, time 0.
  void Reset();
  SimState GetState() const;
  /// GetState into existing storage.
  void CaptureState(SimState* state) const;
  void SetState(const SimState& state);
  const SimStatistics& statistics() const { return statistics_; }
  /// Warnings from building the simulation (e.g. a preshrink that flipped triangles).
  const Diagnostics& diagnostics() const { return diagnostics_; }
  /// The simulated world: the description it was built from with every setter's edits (surfaces,
  /// paddings, gravity, step); poses are the initial ones (see UpdateWorld).
  const WorldDesc& world() const { return world_; }
  /// Writes the current state and every live edit into `world`, which must have the same
  /// elements as the simulated one: object poses, velocities (as initial velocities), surfaces,
  /// paddings and the global settings.
  void UpdateWorld(WorldDesc* world) const;

  // ---- live edits: the rows of the parameter table (core/model/params.h) ------------------
  /// The value of a row on an element of the simulated world (its description with every edit
  /// so far); nullopt with `error` naming the path when the element or the row does not exist.
  std::optional<ParamValue> GetParam(const ElementIndex& element, const ParamSpec& spec,
                                     std::string* error = nullptr) const;
  /// The one path by which an edit reaches the simulation. Checks the element, the row and the
  /// value exactly as the file readers do (a refused edit changes nothing and `error` names the
  /// path and the rule), writes the simulated description, then by the row's apply kind: kLive
  /// from the next step; kRebuildGeometry rebuilds the body's collision geometry; kRebuildSimulator
  /// builds the whole simulation anew from the description and restores its state (MuJoCo's
  /// mj_recompile); kOnReset changes only what Reset starts from. What the change invalidates
  /// (contacts, energies, friction anchors) and wakes is decided in one place (BodyChanged).
  bool SetParam(const ElementIndex& element, const ParamSpec& spec, const ParamValue& value,
                std::string* error);
  /// Builds the simulation anew from its description in the state it is in (or, stopped by an
  /// error, in `state`); SetState of a stopped simulation does the same.
  void Rebuild();
  /// True after an error stopped the simulation (Simulate returns kError until SetState, Reset
  /// or Rebuild).
  bool halted() const { return halted_; }

  /// Body by Klamp't world id (terrains, then objects, then robots and their links).
  SimBody body(int id) { return SimBody(this, id); }
  int body_count() const;

  // rigid objects, by index in world().objects
  int object_count() const;
  /// Object frame (not the COM) in the world.
  Pose GetObjectPose(int object) const;
  void SetObjectPose(int object, const Pose& pose);
  /// Linear velocity of the object frame's origin and angular velocity, world.
  Twist GetObjectVelocity(int object) const;
  void SetObjectVelocity(int object, const Twist& velocity);

  // robots, by index in world().robots
  int robot_count() const { return static_cast<int>(robots_.size()); }
  /// Joint values (rad or m; one per link; revolute joints keep whole turns) and rates.
  VecX GetRobotConfig(int robot) const;
  VecX GetRobotVelocity(int robot) const;
  /// Teleports a robot (bodies placed by forward kinematics); the controller is not told.
  void SetRobotConfig(int robot, const VecX& q);
  void SetRobotVelocity(int robot, const VecX& dq);
  /// Changes the joint range of a robot link on the running simulation: its joint stops from the
  /// next step, and the position limits of the controller's ramps. Throws std::out_of_range for
  /// a bad robot or link index and std::invalid_argument for a NaN bound or q_min > q_max
  /// (infinite bounds remove the stop).
  void SetJointLimits(int robot, int link, double q_min, double q_max);
  /// The controller of a robot: commands, gains, limits and friction, all live.
  RobotController& controller(int robot) { return controllers_[robot]; }
  const RobotController& controller(int robot) const { return controllers_[robot]; }
  /// Clamped driver efforts at the current state (driver-sized; Klamp't getActualTorque).
  VecX GetActuatorTorques(int robot) const;
  /// No physics: runs the controllers for dt, advances the time and moves every robot to its
  /// commanded configuration with the commanded velocities. Objects stay where they are.
  void FakeSimulate(double dt);

  // contacts at the current state (after clustering), one entry per touching pair
  const std::vector<ContactPair>& contact_pairs() const { return pairs_; }

  // contact feedback, recorded only for pairs that asked for it (see contact_feedback.h for the
  // sign convention). b = -1 means "any body" in the queries.
  /// Records every pair that can touch now: object–terrain, object–object (when rigid objects
  /// collide), robot links with terrains, objects and other robots, and allowed self-collision
  /// pairs (when robot self-collisions are on). Pairs that become collidable later (a body
  /// enabled or made dynamic) need another call.
  void EnableContactFeedbackAll();
  void EnableContactFeedback(int a, int b);
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

 private:
  friend class SimBody;
  struct BodyRecord;

  void Build();
  void TearDown();
  void RebuildWith(const SimState& state);
  void ApplySettingsEdit(const ParamSpec& spec);
  void ApplyBodyEdit(const ElementIndex& element, const ParamSpec& spec);
  void ApplyRobotEdit(const ElementIndex& element, const ParamSpec& spec);
  void BuildBodies();
  void BuildRobot(int robot, int first_link_id);
  void RunControllers(double step);
  void PrepareRobotsForStep(double step);
  void AcceptRobotStep(double step);
  void CaptureBodyState(SimState* state, bool with_controllers) const;
  void CaptureRobotState(SimState* state, bool with_controllers) const;
  void RestoreRobotState(const SimState& state);
  void RestoreControllers(const SimState& state);
  void UpdateWorldRobots(WorldDesc* world) const;
  std::shared_ptr<const CollisionGeometry> LinkCollisionGeometry(int robot, int link);
  /// SetState without forgetting the energies of the instability check (rollbacks).
  void RestoreState(const SimState& state);
  void ApplyInitialState();
  StepStatus Step(double step);
  enum class IntegrateResult { kOk, kOdeError, kNonFinite };
  IntegrateResult Integrate(double step);
  bool NeedsRollback(const std::vector<ContactPair>& before, bool* unreliable) const;
  void AcceptStep(double step);
  void ApplyAccumulatedForces();
  bool CorrectInstabilities(double step);
  void MeasureUnknownEnergies();
  bool StopOverflowingBodies();
  double BodyKineticEnergy(const BodyRecord& body) const;
  double ContactEnergyAllowance(int id, double step) const;
  bool RecoverFromFailedStep();
  void RecordAcceptedContacts();
  void RecordFeedback(double step);
  void DetectContacts();
  bool MayCollide(const BodyRecord& a, const BodyRecord& b) const;
  void FindCandidatePairs();
  void AddPairContacts(int a, int b);
  void UpdateFrictionAnchors(double step);
  bool KeepsTouchedAwake(const BodyRecord& body) const;
  void WakeTouchedSleepers();
  void WakeTouching(int id);
  bool SleepsAgainstInert(const ContactPair& pair) const;
  void UpdateSleep(double step);
  void WakeBody(int id);
  void SetObjectAsleep(int object, bool asleep);
  BodyFrame BodyFrameOf(int id) const;
  void AddContactJoints(const ContactPair& pair, const Vec3* anchor_velocities, double step);
  double HardContactErp(double depth, double step) const;
  static double ContactWeightDepth(const Contact& contact, const ContactPair& pair);
  struct JointFeedbackSlot;
  JointFeedbackSlot* AttachFeedback(dxJoint* joint, const ContactFeedbackRecord& record,
                                    const ContactPair& pair, const Contact& contact,
                                    double friction);
  void AddCoreContactJoint(const dContact& soft_joint, double tolerance, double step,
                           dxBody* body_a, dxBody* body_b, JointFeedbackSlot* slot);
  bool StateIsFinite() const;
  void RebuildCollisionGeometry(int id);
  void ForgetEnergies();

  // body access by world id
  const BodySimParams& sim_params(int id) const;
  BodySimParams* mutable_sim_params(int id);
  BodyRecord* record(int id);
  const BodyRecord* record(int id) const;
  Pose GetBodyPose(const BodyRecord& body) const;
  void SetBodyPose(const BodyRecord& body, const Pose& pose);
  Twist GetBodyVelocity(const BodyRecord& body) const;
  void SetBodyVelocity(const BodyRecord& body, const Twist& velocity);

  // the body operations behind SimBody, by world id; ignored for ids without a body
  bool BodyEnabled(int id) const;
  void SetBodyEnabled(int id, bool enabled);
  bool BodyDynamic(int id) const;
  void SetBodyDynamic(int id, bool dynamic);
  Pose BodyPose(int id) const;
  void SetBodyPose(int id, const Pose& pose);
  Twist BodyVelocity(int id) const;
  void SetBodyVelocity(int id, const Twist& velocity);
  void SetBodyPadding(int id, double padding);
  void SetBodySurface(int id, const SurfaceDesc& surface);
  void AddBodyForce(int id, const Vec3& force, const Vec3& point);
  void AddBodyWrench(int id, const Vec3& force, const Vec3& torque);

  // feedback records touching (a, b); b = -1: every record touching a
  std::vector<const ContactFeedbackRecord*> FeedbackRecords(int a, int b) const;
  ContactFeedbackRecord* FindFeedback(int a, int b);

  WorldDesc world_;
  Diagnostics diagnostics_;
  CollisionGeometryCache geometry_cache_;
  std::unique_ptr<dxWorld, void (*)(dxWorld*)> ode_world_;
  std::unique_ptr<dxJointGroup, void (*)(dxJointGroup*)> contact_group_;
  std::vector<BodyRecord> bodies_;  ///< by world id
  std::vector<int> object_ids_;     ///< world id of each rigid object
  std::vector<std::unique_ptr<OdeRobot>> robots_;
  std::vector<RobotController> controllers_;
  std::vector<std::vector<std::pair<int, int>>> self_collision_pairs_;  ///< per robot, sorted
  struct RobotScratch {
    VecX q, dq, forces;
    std::vector<ServoMotorCommand> motors;
  };
  std::vector<RobotScratch> robot_scratch_;  ///< per robot, reused every sub-step
  std::vector<int> collidable_;              ///< ids of bodies with geometry, for the broad phase
  std::vector<std::pair<int, int>> candidates_;  ///< candidate pairs of the broad phase
  std::vector<ContactPair> pairs_;               ///< contacts at the current state
  std::vector<ContactPair> saved_pairs_;         ///< contacts at the start of a tentative step
  std::vector<std::pair<int, int>> saved_candidates_;  ///< broad phase of saved_pairs_
  SimState rollback_state_;                            ///< state at the start of a tentative step
  std::vector<FrictionAnchor> anchors_;                ///< pairs that stick, sorted by (a, b)
  std::vector<ObjectSleep> sleep_;                     ///< per rigid object
  std::vector<int> sleep_islands_;                ///< scratch of UpdateSleep: union-find parents
  std::vector<char> sleep_ready_, island_ready_;  ///< scratch of UpdateSleep
  std::vector<FrictionAnchor> next_anchors_;      ///< scratch of UpdateFrictionAnchors
  std::vector<Vec3> anchor_velocities_;  ///< per contact of pairs_, in order: anchor correction
  bool contacts_current_ = false;        ///< pairs_ describes the current state
  ContactList scratch_contacts_;
  std::vector<ContactFeedbackRecord> feedback_;              ///< sorted by (first, second)
  std::vector<std::vector<FeedbackContact>> step_feedback_;  ///< per feedback record, one step
  std::vector<JointFeedbackSlot> joint_feedback_;            ///< ODE feedback of this step's joints
  size_t next_feedback_slot_ = 0;
  struct EnergyScratch {
    std::vector<bool> pushed;  ///< per body: touched a kinematic body this step
    std::vector<BodyEnergySample> samples;
    std::vector<int> checked;  ///< body id of each sample
  } energy_scratch_;
  double time_ = 0.0;
  bool halted_ = false;  ///< an error stopped the simulation
  SimStatistics statistics_;
};

}  // namespace lamina::core
