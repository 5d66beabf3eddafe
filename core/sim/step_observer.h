// SPDX-License-Identifier: MIT
// What a simulation reports about its steps: the status of a Simulate call, the counters since
// construction or Reset, and the per-step event that observers receive (Jolt's
// PhysicsStepListener, Box2D's per-step events). The event is the single source of per-step
// numbers: the statistics are accumulated from it, `run --log` writes its rows from it, and plots
// keep ring buffers of it. It is sent after every ACCEPTED physics sub-step (a rolled-back
// tentative step sends nothing), so nothing an observer sees depends on how Simulate is chunked.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/sim/contact_set.h"
#include "core/sim/sim_timing.h"

namespace lamina::core {

class Simulator;
class FeedbackRecorder;

/// From the best to the worst; a Simulate call reports the worst of its steps. Klamp't has the
/// same statuses but "joint open" (its numbers: KlamptStatusCode).
enum class StepStatus {
  kNormal = 0,
  kAdaptiveStep = 1,  ///< a step was rolled back and retaken with a smaller step
  /// underlying geometries interpenetrated (beyond the padding), or an island of contacts too
  /// large for dWorldStep was not solved to the Newton solver's tolerance (object_islands.h)
  kContactUnreliable = 2,
  /// a robot's or the world's joint is open beyond JointBreakGap (robot_guard.h): the solver did
  /// not hold it at this step (e.g. QuickStep's iterations on a long taut chain, or a slider
  /// pushed slowly past its stops; one that opens that far within a step is "unstable")
  kJointOpen = 3,
  kUnstable = 4,  ///< energy blew up (or a state became non-finite) and was corrected
  kError = 5,     ///< ODE failed or a state stayed non-finite; the simulation stopped
};
/// "normal", "adaptive step", "contact unreliable", "joint open", "unstable", "error".
const char* StepStatusName(StepStatus status);
/// Klamp't's number of a status (SimStatus: 0 normal, 1 adaptive time stepping, 2 contact
/// unreliable, 3 unstable, 4 error): "joint open", which Klamp't does not have, is its 2 (the
/// simulation goes on, its constraints unreliable), the worse ones one lower than here.
int KlamptStatusCode(StepStatus status);
/// The status of Klamp't's number `code` (0…4; 2 is "contact unreliable").
StepStatus StatusOfKlamptCode(int code);

/// What happened in one accepted step (bits; several at once).
enum StepFlag : unsigned {
  kStepRetaken = 1u << 0,       ///< it was rolled back and retaken smaller before
  kStepUnreliable = 1u << 1,    ///< geometries interpenetrate after it, or an island unsolved
  kStepCorrected = 1u << 2,     ///< the instability check slowed bodies down
  kStepRecovered = 1u << 3,     ///< a non-finite state was undone with the culprits stopped
  kStepOverflowStop = 1u << 4,  ///< bodies with overflowing energy were stopped before it
  kStepJointOpen = 1u << 5,     ///< a joint is open beyond its break gap after it
};

/// Counters since construction or the last Reset.
struct SimStatistics {
  long steps = 0;                    ///< physics sub-steps taken (accepted)
  long rollbacks = 0;                ///< sub-steps undone and retaken at half the step
  long instability_corrections = 0;  ///< bodies whose energy blow-up was corrected
  /// accepted steps after which geometries interpenetrated, or in which an island too large for
  /// dWorldStep kept an unconverged answer (newton_unconverged)
  long unreliable_steps = 0;
  int max_contacts_in_step = 0;  ///< most contact joints in one sub-step
  long contact_joints = 0;       ///< contact joints over all accepted sub-steps
  double max_penetration = 0.0;  ///< deepest boundary-layer overlap in an accepted state, m
  /// the widest joint gap (robot_guard.h, joint_projection.h) in an accepted state, m
  double max_joint_gap = 0.0;
  long joint_open_steps = 0;  ///< accepted steps after which a joint was open (kStepJointOpen)
  /// solver "newton" (object_islands.h), over every sub-step tried (retaken ones too)
  long newton_islands = 0;    ///< object islands the Newton solver took
  long newton_fallbacks = 0;  ///< of those, handed back to ODE's solver (no convergence)
  /// of those, not converged and too large to hand back (ObjectIslands::kMostHandBackRows): the
  /// island was relaxed by Gauss–Seidel sweeps (row_relaxation.h) and its step is "contact
  /// unreliable"
  long newton_unconverged = 0;
  long newton_iterations = 0;  ///< Newton steps in all
  /// Hessians factored for them (fewer than Newton steps where a kept one served:
  /// newton_solver.h)
  long newton_factorizations = 0;
  /// robot islands solved directly (direct_solver.h): the exact solver's robots, and under the
  /// Newton solver the islands with a robot of at least Simulator::kDirectRobotBodies bodies
  /// that one Newton step did not settle (object_islands.h)
  long direct_islands = 0;
  /// of those, not settled: handed back to dWorldStep
  long direct_fallbacks = 0;
  /// robot islands the Newton solver took in their joint coordinates (reduced_basis.h), and of
  /// those, not converged (then solved over every body)
  long reduced_islands = 0;
  long reduced_fallbacks = 0;
  StepStatus worst_status = StepStatus::kNormal;
  std::string error;  ///< what stopped the simulation (kError)
  SimTimeSplit time_split;
};

/// One accepted physics sub-step, as observers see it (valid during the call only).
struct StepEvent {
  const Simulator& simulator;  ///< the state after the step (poses, robots, energies)
  double time = 0.0;           ///< simulated time after the step (s)
  double h = 0.0;              ///< its length (s)
  unsigned flags = 0;          ///< StepFlag bits
  int contact_joints = 0;      ///< contacts of the pairs the step was solved with (as before)
  int rollbacks = 0;           ///< tentative steps undone since the previous accepted one
  int corrections = 0;         ///< bodies slowed or stopped by the stability checks
  const std::vector<int>& corrected_bodies;  ///< their world ids (a body may appear twice)
  const std::vector<ContactPair>& contacts;  ///< touching pairs after the step
  const FeedbackRecorder& feedback;          ///< recorded pairs, this step's forces
  double joint_gap = 0.0;  ///< the widest gap of a robot's or the world's joint after it, m
};

using StepObserver = std::function<void(const StepEvent&)>;

/// The status a step with `flags` reports (the worst of its bits).
StepStatus StatusOfStep(unsigned flags);
/// Adds one event to the counters (the simulator's own statistics are kept this way).
void AccumulateStep(const StepEvent& event, SimStatistics* statistics);

}  // namespace lamina::core
