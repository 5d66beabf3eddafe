// SPDX-License-Identifier: MIT
// The simulator: rigid objects and terrains of a WorldDesc on ODE (double precision) with
// boundary-layer contact. Every setter works on a running simulation. Robots slot in later as
// further bodies and joints.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/contact/collision_geometry.h"
#include "core/model/world_desc.h"
#include "core/sim/sim_state.h"

// ODE's opaque types (ode/common.h), so that this header does not pull in ODE
struct dxWorld;
struct dxBody;
struct dxJointGroup;

namespace lamina::core {

enum class StepStatus {
  kNormal = 0,
  kAdaptiveStep = 1,       ///< a step was rolled back and retaken with a smaller step
  kContactUnreliable = 2,  ///< underlying geometries interpenetrated (beyond the padding)
  kUnstable = 3,           ///< energy blew up and was corrected
  kError = 4,              ///< ODE failed or a state became non-finite; the simulation stopped
};
/// "normal", "adaptive step", ...
const char* StepStatusName(StepStatus status);

enum class SolverType { kStep, kQuickStep };

struct SolverSettings {
  SolverType type = SolverType::kStep;  ///< dWorldStep (exact) or dWorldQuickStep
  int quick_step_iterations = 20;       ///< iterations of dWorldQuickStep
};

/// Counters since construction or the last Reset.
struct SimStatistics {
  long steps = 0;                ///< physics sub-steps taken (accepted)
  long rollbacks = 0;            ///< sub-steps undone and retaken at half the step
  int max_contacts_in_step = 0;  ///< most contact joints in one sub-step
  double max_penetration = 0.0;  ///< deepest boundary-layer overlap in an accepted state, m
  StepStatus worst_status = StepStatus::kNormal;
  std::string error;  ///< what stopped the simulation (kError)
};

/// The contacts between two bodies at the current state, after clustering.
struct ContactPair {
  int a = -1;  ///< object index
  int b = -1;  ///< object index, or -1 - terrain index for a terrain
  ContactList contacts;
  double tolerance = 0.0;  ///< padding sum of the pair (m)
  double max_depth = 0.0;  ///< deepest boundary-layer overlap (m)
  bool penetrating = false;
};

/// Adaptive time stepping gives up halving below this step (s).
inline constexpr double kMinimumAdaptiveStep = 1e-6;

class Simulator {
 public:
  /// Builds the simulation of `world` (copied; later edits go through the setters).
  explicit Simulator(const WorldDesc& world, SolverSettings solver = {});
  ~Simulator();
  Simulator(const Simulator&) = delete;
  Simulator& operator=(const Simulator&) = delete;

  /// Advances by `dt` seconds in sub-steps of at most the simulation step.
  StepStatus Simulate(double dt);
  double time() const { return time_; }
  /// Largest physics sub-step (s).
  void SetSimStep(double step);
  double sim_step() const { return world_.settings.timestep; }
  void SetGravity(const Vec3& gravity);
  void SetSolver(const SolverSettings& solver) { solver_ = solver; }
  /// Back to the initial poses and velocities of the world description, time 0.
  void Reset();
  SimState GetState() const;
  /// GetState into existing storage.
  void CaptureState(SimState* state) const;
  void SetState(const SimState& state);
  const SimStatistics& statistics() const { return statistics_; }
  const WorldDesc& world() const { return world_; }

  // rigid objects, by index in world().objects
  int object_count() const;
  /// Object frame (not the COM) in the world.
  Pose GetObjectPose(int object) const;
  void SetObjectPose(int object, const Pose& pose);
  /// Linear velocity of the object frame's origin and angular velocity, world.
  Twist GetObjectVelocity(int object) const;
  void SetObjectVelocity(int object, const Twist& velocity);

 private:
  struct ObjectBody;
  struct TerrainBody;

  void BuildBodies();
  void ApplyInitialState();
  StepStatus Step(double step);
  bool Integrate(double step);
  bool NeedsRollback(const std::vector<ContactPair>& before, bool* unreliable) const;
  void RecordAcceptedContacts();
  void DetectContacts();
  void AddPairContacts(int a, int b, const CollisionGeometry& geometry_a, const Pose& X_Wa,
                       const CollisionGeometry& geometry_b, const Pose& X_Wb);
  void AddContactJoints(const ContactPair& pair, double step);
  bool StateIsFinite() const;

  WorldDesc world_;
  SolverSettings solver_;
  CollisionGeometryCache geometry_cache_;
  std::unique_ptr<dxWorld, void (*)(dxWorld*)> ode_world_;
  std::unique_ptr<dxJointGroup, void (*)(dxJointGroup*)> contact_group_;
  std::vector<ObjectBody> objects_;
  std::vector<TerrainBody> terrains_;
  std::vector<ContactPair> pairs_;        ///< contacts at the current state
  std::vector<ContactPair> saved_pairs_;  ///< contacts at the start of a tentative step
  SimState rollback_state_;               ///< state at the start of a tentative step
  bool contacts_current_ = false;         ///< pairs_ describes the current state
  ContactList scratch_contacts_;
  double time_ = 0.0;
  SimStatistics statistics_;
};

}  // namespace lamina::core
