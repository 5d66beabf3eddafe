// SPDX-License-Identifier: MIT
// Trajectory: a timed robot motion loaded from a Klamp't motion file (.path, .milestones,
// MultiPath .xml, .config), one piecewise polynomial per DOF. Timed milestones become linear
// segments (or cubic Hermite ones when velocities are given); untimed milestones are timed by
// bounded time-optimal ramps between consecutive milestones.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/control/joint_limits.h"
#include "core/control/milestone_sequence.h"
#include "core/control/piecewise_polynomial.h"
#include "core/math_types.h"

namespace lamina::core {

class MotionQueue;

/// Evaluation clamps t into [StartTime(), EndTime()]: before the start the first configuration
/// is held, after the end the last, both with zero velocity. Where two milestones share a time
/// (a jump) the later one is the value at that time.
class Trajectory {
 public:
  /// Timed milestones: linear between them, or cubic Hermite when `sequence.velocities` is set.
  /// Untimed: FromMilestones.
  static std::optional<Trajectory> FromSequence(const MilestoneSequence& sequence,
                                                const JointLimits& limits, std::string* error);
  /// Piecewise linear through (times[k], configs[k]); times nondecreasing.
  static std::optional<Trajectory> FromTimedLinear(const std::vector<double>& times,
                                                   const std::vector<VecX>& configs,
                                                   std::string* error);
  /// Piecewise cubic Hermite through (times[k], configs[k], velocities[k]).
  static std::optional<Trajectory> FromTimedCubic(const std::vector<double>& times,
                                                  const std::vector<VecX>& configs,
                                                  const std::vector<VecX>& velocities,
                                                  std::string* error);
  /// Untimed milestones (velocities zero when `sequence.velocities` is empty), starting at t = 0
  /// and joined by PlanJointRamp ramps within `limits`.
  static std::optional<Trajectory> FromMilestones(const MilestoneSequence& sequence,
                                                  const JointLimits& limits, std::string* error);

  int dof() const { return static_cast<int>(curves_.size()); }
  double StartTime() const { return curves_.empty() ? 0.0 : curves_.front().StartTime(); }
  double EndTime() const { return curves_.empty() ? 0.0 : curves_.front().EndTime(); }
  double Duration() const { return EndTime() - StartTime(); }

  /// Configuration / velocity at time t (s). The pointer forms do not allocate when `out`
  /// already has dof() entries.
  VecX Eval(double t) const;
  VecX Deriv(double t) const;
  void Eval(double t, VecX* out) const;
  void Deriv(double t, VecX* out) const;

  const std::vector<PiecewisePolynomial>& curves() const { return curves_; }

  /// Queues this trajectory: a straight line from the queue's end configuration to the start
  /// over `transition_time` s (Klamp't's 0.1 s path delay), then the trajectory itself.
  /// False with the reason in queue.last_error() (nothing appended when sizes differ).
  bool AppendTo(MotionQueue& queue, double transition_time = 0.1) const;

 private:
  explicit Trajectory(std::vector<PiecewisePolynomial> curves) : curves_(std::move(curves)) {}

  std::vector<PiecewisePolynomial> curves_;
};

}  // namespace lamina::core
