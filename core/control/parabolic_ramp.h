// SPDX-License-Identifier: MIT
// Time-optimal, acceleration- and velocity-bounded parabolic ramps: the 1-D solvers (minimum
// time, minimum acceleration for a fixed duration, minimum time with a lower bound on the
// duration, each optionally within position bounds) and the N-D synchronized and straight-line
// ramps built from them. Pure math; docs/motion.md explains the families and the edge cases.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/control/joint_limits.h"
#include "core/control/piecewise_polynomial.h"
#include "core/math_types.h"

namespace lamina::core {

/// Boundary conditions of a 1-D ramp: from position x0 (m or rad) with velocity v0 to x1 with v1.
struct RampEnds {
  double x0 = 0;
  double v0 = 0;
  double x1 = 0;
  double v1 = 0;
};

/// Bounds of a 1-D ramp: |a| <= acceleration_max, |v| <= velocity_max and, when finite,
/// position_min <= x(t) <= position_max. Infinite entries mean "unbounded".
struct RampBounds {
  double acceleration_max = kInf;
  double velocity_max = kInf;
  double position_min = -kInf;
  double position_max = kInf;
};

/// A 1-D motion of up to three phases on [0, duration]: constant acceleration a1 on [0, t1],
/// cruise at `cruise_velocity` on [t1, t2], constant acceleration a2 on [t2, duration]. Phase 1
/// is evaluated forward from (x0, v0), phase 3 backward from (x1, v1), so the end points are
/// exact. Outside [0, duration] the ramp holds its end values.
///
/// With an infinite acceleration bound and finite speed bound the minimum-time ramp is a
/// straight line at +-velocity_max: then v0 = v1 = cruise_velocity (the requested boundary
/// velocities are dropped; the velocity jumps at both ends). A zero-duration ramp is a jump to
/// (x1, v1).
struct Ramp1D {
  double x0 = 0, v0 = 0, x1 = 0, v1 = 0;
  double a1 = 0;               ///< phase 1 acceleration, per s^2
  double cruise_velocity = 0;  ///< phase 2 velocity, per s
  double a2 = 0;               ///< phase 3 acceleration, per s^2
  double t1 = 0;               ///< s, end of phase 1
  double t2 = 0;               ///< s, end of phase 2, >= t1
  double duration = 0;         ///< s, >= t2

  double Position(double t) const;
  double Velocity(double t) const;
  double Acceleration(double t) const;
  /// The extreme positions reached on [0, duration].
  double MinPosition() const;
  double MaxPosition() const;
  /// Appends the ramp's nonempty phases to `curve` as quadratic pieces starting at time
  /// `start` (a zero-duration ramp appends one jump piece). False when `curve` ends elsewhere.
  bool AppendTo(double start, PiecewisePolynomial* curve) const;
};

/// The minimum-time ramp (families P, PP, PLP; see docs/motion.md) within `bounds`, or nullopt
/// when |v0| or |v1| exceeds velocity_max or no ramp stays within the position bounds.
/// A = inf: with V = inf a jump (duration 0), else a straight line at +-V (see Ramp1D).
std::optional<Ramp1D> MinTimeRamp(const RampEnds& ends, const RampBounds& bounds);

/// The ramp of exactly `duration` seconds with the smallest peak |acceleration| (bang-bang, or
/// bang-cruise-bang when the speed bound is active; when that leaves the position bounds, a
/// full-acceleration profile with a free cruise speed), or nullopt when every such ramp needs
/// |a| > acceleration_max or leaves the bounds.
std::optional<Ramp1D> MinAccelerationRamp(const RampEnds& ends, const RampBounds& bounds,
                                          double duration);

/// The shortest feasible ramp whose duration is >= `min_duration` s. The feasible durations
/// may have gaps (nonzero boundary velocities), so this can be longer than min_duration even
/// when min_duration exceeds the minimum time. With finite position bounds, durations beyond
/// the analytic candidates are searched numerically. nullopt when none is found.
std::optional<Ramp1D> MinTimeRampAtLeast(const RampEnds& ends, const RampBounds& bounds,
                                         double min_duration);

/// Ramps for several DOFs sharing one duration.
class ParabolicRampND {
 public:
  ParabolicRampND() = default;
  /// All ramps must have the same duration.
  explicit ParabolicRampND(std::vector<Ramp1D> ramps) : ramps_(std::move(ramps)) {}

  int dof() const { return static_cast<int>(ramps_.size()); }
  double Duration() const { return ramps_.empty() ? 0.0 : ramps_.front().duration; }
  const std::vector<Ramp1D>& ramps() const { return ramps_; }

  /// Position, velocity and acceleration at time t in [0, Duration()] (held outside). The
  /// pointer forms resize `out` to dof() and do not allocate when it already has that size.
  void Evaluate(double t, VecX* out) const;
  void Derivative(double t, VecX* out) const;
  void Accel(double t, VecX* out) const;
  VecX Evaluate(double t) const;
  VecX Derivative(double t) const;
  VecX Accel(double t) const;

  /// Appends every DOF's pieces, starting at `start`, to (*curves)[i]. False when sizes differ
  /// or a curve does not end at `start`.
  bool AppendTo(double start, std::vector<PiecewisePolynomial>* curves) const;

 private:
  std::vector<Ramp1D> ramps_;
};

/// The synchronized minimum-time ramp from (x0, v0) to (x1, v1) within `limits` (per-DOF
/// position, speed and acceleration bounds): T* = the largest per-DOF minimum time; every
/// other DOF is re-solved for T* with minimum acceleration, and T* is raised when a DOF has
/// no solution of that duration. nullopt with the reason in `*error` when sizes differ, an
/// input is not finite, a boundary speed exceeds its limit or some DOF has no feasible ramp.
std::optional<ParabolicRampND> MinTimeRampND(const VecX& x0, const VecX& v0, const VecX& x1,
                                             const VecX& v1, const JointLimits& limits,
                                             std::string* error);

/// The straight line in joint space from x0 to x1, at rest at both ends, time-optimal along the
/// line: a 1-D ramp on s in [0, 1] with V_s = min V_i/|dx_i|, A_s = min A_i/|dx_i|. Position
/// limits are not checked (a segment between two points in the limit box stays in it).
std::optional<ParabolicRampND> LinearRampND(const VecX& x0, const VecX& x1,
                                            const JointLimits& limits, std::string* error);

/// MinTimeRampND after the pre-clamps of a motion queue: the start speed is clamped into
/// +-velocity_max, a target outside [q_min, q_max] into [q_min + eps*range, q_max - eps*range]
/// (eps = 1e-7), the target speed into +-(1 - 2e-7) velocity_max. A start outside the position
/// limits, or one that cannot brake within them at full acceleration, widens that DOF's bounds
/// just enough to hold the start and its braking stop (no jump back into the limits, no
/// failure from an unavoidable overrun).
std::optional<ParabolicRampND> PlanJointRamp(const VecX& start_q, const VecX& start_v,
                                             const VecX& target_q, const VecX& target_v,
                                             const JointLimits& limits, std::string* error);

/// `target` clamped into the limits like PlanJointRamp clamps a target configuration.
VecX ClampTargetIntoLimits(const VecX& target, const JointLimits& limits);

}  // namespace lamina::core
