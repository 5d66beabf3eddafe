// SPDX-License-Identifier: MIT
// RobotController: the controller and actuator emulation of one simulated robot, pure math.
// It maps between link space (one value per link) and driver space (one value per actuator),
// runs the per-driver actuator law at the physics rate, runs the motion-queue controller at its
// own period, and implements the Klamp't SimRobotController command set (docs/motion.md,
// "Controller").
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/control/actuator.h"
#include "core/control/joint_limits.h"
#include "core/control/motion_queue.h"
#include "core/math_types.h"
#include "core/model/world_desc.h"

namespace lamina::core {

/// Everything that evolves while simulating, for exact save/restore.
struct RobotControllerState {
  std::vector<ActuatorState> actuators;  ///< one per driver
  MotionQueue queue{JointLimits{}};      ///< link space
  double next_control_time = 0;          ///< s, simulation time
  VecX sensed_q;                         ///< link space, last Update()
  VecX sensed_dq;                        ///< link space, last Update()
  bool manual = false;                   ///< manual override: the queue does not drive the PIDs
};

/// A joint motor that applies a PID law implicitly: over the step the motor's force is
/// f = (velocity - dq_end) / cfm, bounded by ±fmax, which is kP·(e - h·dq_end) +
/// kD·(dq_des - dq_end) + kI·I + τ_ff (the position error taken at the end of the step) when
/// cfm = 1 / (kP·h + kD) and velocity = (kP·e + kD·dq_des + kI·I + τ_ff) / (kP·h + kD).
struct ServoMotorCommand {
  int link = -1;          ///< the driven link (its hinge or slider)
  double velocity = 0.0;  ///< target rate (rad/s or m/s)
  double cfm = 0.0;       ///< 1 / (kP·h + kD)
  double fmax = 0.0;      ///< largest |force| the PD part may add (N·m or N); may be inf
  /// The driver's viscous friction is part of this motor's damping (added to kD in cfm): it
  /// is then not applied again as joint friction.
  bool includes_viscous = false;
  /// The simulator solves the row without its bound this step (core/sim/servo_bounds.h).
  bool unbounded = false;
};

/// Default control period (s) when the robot has no `controller` property with a rate.
inline constexpr double kDefaultControlPeriod = 0.01;
/// Acceleration bound (rad/s² or m/s²) for ramps when a link has neither accMax nor torqueMax.
inline constexpr double kDefaultAccelerationMax = 10.0;

/// The controller of one robot. Vectors named q/dq/τ are link-sized unless said otherwise.
/// Commands return false with a message in last_error() on bad input (wrong size, NaN, negative
/// durations, failed ramps) and then leave the controller unchanged; nothing asserts.
///
/// Driver ↔ link mapping (driver value v):
/// - normal: v = q[link];
/// - affine: q[links[j]] = offset_j + scale_j·v, read back as the least-squares v of all its
///   links, Σ scale_j (q_j − offset_j) / Σ scale_j² (Klamp't averages (q_j − offset_j)/scale_j);
/// - translation / rotation ({axis link, body link}): v = q[axis link], the virtual floating-base
///   DOF whose axis the force/torque acts along; its effort goes on that link index (the
///   simulator turns a virtual link's generalized force into a body force/torque along the
///   link's axis).
class RobotController {
 public:
  /// A controller with its own copy of the robot (shared by copies of this controller). Sensed
  /// and commanded state start at robot.config (zero if it has the wrong size) and
  /// robot.velocity; every driver starts in PID mode holding its current value. The control
  /// period is 1/rate (or timeStep) of the `controller` property when given, else
  /// kDefaultControlPeriod.
  explicit RobotController(const RobotDesc& robot);
  /// A controller of `robot` itself, which must outlive it: the simulator's, so that its robot
  /// description is the only copy of the driver data (gains, friction and torque limits edited
  /// on either are the same values, survive Reset and are saved).
  static RobotController ViewOf(RobotDesc* robot);

  int dof() const { return robot_->dof(); }
  int driver_count() const { return static_cast<int>(robot_->drivers.size()); }
  const RobotDesc& robot() const { return *robot_; }

  /// The robot's drivers: gains, torque limits and friction are read at every use.
  std::vector<DriverDesc>& drivers() { return robot_->drivers; }
  const std::vector<DriverDesc>& drivers() const { return robot_->drivers; }
  std::vector<ActuatorState>& actuators() { return actuators_; }
  const std::vector<ActuatorState>& actuators() const { return actuators_; }

  // ---- link ↔ driver mapping -------------------------------------------------------------

  /// Driver value of driver d at link configuration q.
  double DriverValue(int d, const VecX& q) const;
  /// Driver velocity of driver d at link velocities dq.
  double DriverVelocity(int d, const VecX& dq) const;
  /// All driver values / velocities (driver-sized).
  VecX DriverValues(const VecX& q) const;
  VecX DriverVelocities(const VecX& dq) const;
  /// `base` (link-sized) with every driven link set from driver values (offset included) or,
  /// with `velocity`, from driver velocities (scale only).
  VecX LinkValuesFromDrivers(const VecX& driver_values, const VecX& base, bool velocity) const;
  /// Driver-space generalized forces of link-space ones (the transpose of the mapping):
  /// normal τ[link], affine Σ scale_j·τ[links[j]], translation/rotation τ[axis link].
  VecX DriverForcesFromLinks(const VecX& link_forces) const;

  // ---- physics rate --------------------------------------------------------------------

  /// Link-sized generalized forces of all drivers at state (q, dq) (N·m or N); no state change,
  /// so the simulator may call it again when it retakes a step. Affine drivers in PID mode add
  /// Klamp't's corrective transmission term.
  void ComputeLinkForces(const VecX& q, const VecX& dq, VecX* link_forces) const;
  /// ComputeLinkForces with normal PID drivers taken out and returned as joint-motor commands,
  /// for the simulator to solve implicitly over a step of h s (stable for any gains and link
  /// inertia; the explicit law is not once kD·h exceeds about twice the joint's inertia). A motor
  /// is bounded by ±fmax: the smaller of the driver's two torque limits (limits that do not
  /// straddle zero keep the explicit law).
  /// With `only` (per driver), only the drivers it marks go to motors; the others keep the
  /// explicit law.
  void ComputeImplicitServo(const VecX& q, const VecX& dq, double h, VecX* link_forces,
                            std::vector<ServoMotorCommand>* motors,
                            const std::vector<char>* only = nullptr) const;
  /// Whether some normal PID driver has no torque limit (what DivergingServos looks at).
  bool HasUnlimitedServo() const;
  /// Marks (per driver) each normal PID driver without a torque limit whose explicit law
  /// diverges at step `h` on its joint's inertia (`link_inertias`, per link: dynamics.h's
  /// JointInertias): explicit_pd.h. Such a law would take the joint to infinity; a limited one
  /// chatters at its limit instead, as in Klamp't.
  void DivergingServos(const VecX& link_inertias, double h, std::vector<char>* diverging) const;
  /// The clamped driver efforts at (q, dq) (driver-sized; Klamp't getActualTorque).
  VecX DriverEfforts(const VecX& q, const VecX& dq) const;
  /// After an accepted physics step of h s ending at q: PID integrals, locked-velocity targets.
  void AcceptStep(const VecX& q, double h);

  // ---- control rate --------------------------------------------------------------------

  double control_period() const { return control_period_; }
  /// Period > 0 (s); false otherwise. Klamp't setRate.
  bool SetControlPeriod(double period);
  /// True when the controller should run for a step ending at simulation time `time` (s):
  /// next control time <= time + 1 ns (the simulator passes curTime + h, Klamp't's rule; the
  /// tolerance absorbs rounding in the accumulated periods).
  bool ControlDue(double time) const;
  double next_control_time() const { return next_control_time_; }
  /// Stores the sensed state (exact simulated q, dq), starts the queue at the sensed config
  /// clamped into the limits if it is empty, advances it by one control period and, unless in
  /// manual mode, puts every driver in PID mode tracking it: q_des/dq_des from the queue, the
  /// integral kept, feed-forward = gravity torques when enabled, else 0 (so a torque command
  /// ends at the first update after a motion command, as in Klamp't). Schedules the next run
  /// one period later. False on bad sizes/NaN.
  bool Update(double time, const VecX& sensed_q, const VecX& sensed_dq);
  /// Gravity compensation feed-forward (off by default; ignored for floating-base robots) for
  /// the gravity of SetGravity.
  void SetGravityCompensation(bool on);
  /// The gravity the compensation balances: (0, 0, -9.8) m/s² until set; the simulator keeps it
  /// equal to the world's.
  void SetGravity(const Vec3& gravity) { gravity_ = gravity; }
  bool gravity_compensation() const { return gravity_compensation_; }

  // ---- Klamp't commands ----------------------------------------------------------------

  /// PID mode on every driver with targets q, dq (link- or driver-sized; link-sized wins when
  /// both sizes are equal) and feed-forward τ_ff (0 if omitted); keeps the integrals; manual on.
  bool SetPIDCommand(const VecX& q, const VecX& dq);
  bool SetPIDCommand(const VecX& q, const VecX& dq, const VecX& torque_ff);
  /// Driver-sized gains, written into the drivers (as Klamp't's setPIDGains writes the robot's).
  bool SetPIDGains(const VecX& kp, const VecX& ki, const VecX& kd);
  void GetPIDGains(VecX* kp, VecX* ki, VecX* kd) const;
  /// Torque mode on every driver (link- or driver-sized); manual on.
  bool SetTorque(const VecX& torque);
  /// Raw `torque` fields (driver-sized; Klamp't getCommandedTorque).
  VecX CommandedTorques() const;
  /// Move at velocity dq for T s of queue time, then hold.
  bool SetVelocity(const VecX& dq, double duration);
  bool SetMilestone(const VecX& q);
  bool SetMilestone(const VecX& q, const VecX& dq);
  bool AddMilestone(const VecX& q);
  bool AddMilestone(const VecX& q, const VecX& dq);
  /// Ramp commands plan only driven links: undriven ones (a floating base) are held.
  bool AddMilestoneLinear(const VecX& q);
  bool SetLinear(const VecX& q, double duration);
  bool AddLinear(const VecX& q, double duration);
  bool SetCubic(const VecX& q, const VecX& dq, double duration);
  bool AddCubic(const VecX& q, const VecX& dq, double duration);
  /// Queue time left (s).
  double RemainingTime() const { return queue_.RemainingTime(); }
  void SetManualMode(bool manual) { manual_ = manual; }
  bool manual_mode() const { return manual_; }

  /// Commanded config / velocity from the PID targets, in link space (undriven links: sensed).
  /// False if some driver is not in PID mode (Klamp't raises).
  bool GetCommandedConfig(VecX* q) const;
  bool GetCommandedVelocity(VecX* dq) const;
  /// Link config from the drivers' q_des whatever their mode (for teleporting, fakeSimulate).
  VecX CommandedLinkConfig() const;
  const VecX& sensed_config() const { return sensed_q_; }
  const VecX& sensed_velocity() const { return sensed_dq_; }

  // ---- limits, queue, state --------------------------------------------------------------

  /// Ramp limits (link space); derived from the links at construction, see LinkRampLimits.
  const JointLimits& limits() const { return limits_; }
  bool SetLimits(const JointLimits& limits);
  const MotionQueue& queue() const { return queue_; }

  RobotControllerState GetState() const;
  /// False (nothing changed) when the sizes do not match this robot.
  bool SetState(const RobotControllerState& state);

  const std::string& last_error() const { return last_error_; }

 private:
  explicit RobotController(std::shared_ptr<RobotDesc> robot);
  explicit RobotController(RobotDesc* robot);
  void Initialize();
  bool UsableDriver(int d) const;
  bool AllPid() const;
  // Checks a link-sized vector (finite entries).
  bool CheckLinkVector(const VecX& v, const char* command, const char* name);
  // Converts a link- or driver-sized value vector to driver space; velocity = scale only.
  bool ToDriverSpace(const VecX& v, bool velocity, const char* command, const char* name,
                     VecX* out);
  bool ToDriverForces(const VecX& torque, const char* command, VecX* out);
  void EnablePathControl();
  // Runs a queue command on path control; restores queue and manual flag when it fails.
  template <typename Command>
  bool QueueCommand(const char* command, Command&& run);
  void AddAffineCorrection(int d, const VecX& q, const VecX& dq, VecX* link_forces) const;
  // link forces of the drivers' explicit law, without the drivers `skip` marks (when given)
  void AddDriverForces(const VecX& q, const VecX& dq, const std::vector<char>* skip,
                       VecX* link_forces) const;
  // a normal PID driver whose law ComputeImplicitServo turns into a joint motor
  bool ServoDriver(int d) const;
  bool UnlimitedServo(int d) const;
  void SetTargetsFromQueue();
  // `q` with the links no driver moves (a floating base) held at the queue's end value, or with
  // `velocity`, at rest: ramps cannot plan motion the robot cannot make
  VecX HoldUndriven(const VecX& q, bool velocity) const;
  bool Fail(std::string message);
  bool Succeed();

  std::shared_ptr<RobotDesc> owned_;  ///< the robot when this controller keeps its own copy
  RobotDesc* robot_ = nullptr;        ///< the robot: owned_, or the simulator's description
  std::vector<ActuatorState> actuators_;
  JointLimits limits_;
  MotionQueue queue_{JointLimits{}};
  VecX sensed_q_;
  VecX sensed_dq_;
  double control_period_ = kDefaultControlPeriod;
  double next_control_time_ = 0;
  bool manual_ = false;
  bool gravity_compensation_ = false;
  bool floating_base_ = false;
  std::vector<bool> driven_;  ///< per link: some driver moves it
  /// ComputeImplicitServo's scratch: per driver, its law goes to a motor this step
  mutable std::vector<char> implicit_;
  Vec3 gravity_ = Vec3(0, 0, -9.8);
  std::string last_error_;
};

/// Ramp limits from the links: q_min/q_max, velocity_max (min of velocity_max and −velocity_min),
/// acceleration_max. An infinite acceleration_max with a finite torque_max uses
/// torque_max / I_eff, I_eff the subtree's effective inertia (revolute) or mass (prismatic) about
/// the joint at robot.config; when that is unavailable, kDefaultAccelerationMax.
JointLimits LinkRampLimits(const RobotDesc& robot);

/// The control period of a `controller` property's XML: 1/rate or timeStep (s); 0 if absent.
double ControlPeriodFromProperty(const std::string& xml);

}  // namespace lamina::core
