// SPDX-License-Identifier: MIT
// MotionQueue: the timed motion a robot controller follows, one piecewise polynomial per DOF,
// with a running clock. Commands append linear, cubic and time-optimal ramp segments at the
// end or cut the queue at the current time (Klamp't PolynomialMotionQueue semantics; the
// differences are listed in docs/motion.md).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/control/joint_limits.h"
#include "core/control/piecewise_polynomial.h"
#include "core/math_types.h"

namespace lamina::core {

/// Times are in the queue's own clock (s): it starts at 0, advances with Advance() and is not
/// reset by SetConstant(). Every append starts at end_time(), or at time() when the queue has
/// already run out (the end state is held until then, at rest). Failing commands return false,
/// leave the queue unchanged and say why in last_error(); they never assert.
class MotionQueue {
 public:
  /// The queue's DOF count is limits.dof(). Ramp commands fail while the limits are invalid.
  explicit MotionQueue(JointLimits limits);

  /// Replaces the ramp limits; the next ramp command uses them. False (limits unchanged) when
  /// they are invalid or have a different DOF count.
  bool SetLimits(JointLimits limits);
  const JointLimits& limits() const { return limits_; }
  int dof() const { return limits_.dof(); }

  /// Holds `q` from time() on (everything queued is dropped).
  bool SetConstant(const VecX& q);
  /// Drops everything after time(); the queue then ends at the current state.
  void Cut();
  /// A straight line from the end configuration to q over `duration` s (0: a jump).
  bool AppendLinear(const VecX& q, double duration);
  /// Per DOF the cubic Hermite from (end config, end velocity) to (q, v) over `duration` s.
  bool AppendCubic(const VecX& q, const VecX& v, double duration);
  /// The time-optimal bounded ramp from (end config, end velocity) to (q, v) (v = 0 by
  /// default) within the limits, with the pre-clamps of PlanJointRamp.
  bool AppendRamp(const VecX& q);
  bool AppendRamp(const VecX& q, const VecX& v);
  /// The time-optimal straight line to q, from rest to rest (a nonzero end velocity is dropped).
  bool AppendLinearRamp(const VecX& q);
  /// A line reaching q at absolute queue time `t_abs` >= end_time() (append_tq).
  bool AppendTimedLinear(double t_abs, const VecX& q);
  /// A cubic reaching (q, v) at absolute queue time `t_abs` >= end_time() (append_tqv).
  bool AppendTimedCubic(double t_abs, const VecX& q, const VecX& v);
  /// Cut(), then move at constant velocity `v` until absolute time `t_abs` >= time(), then hold
  /// (set_tv).
  bool SetConstantVelocity(const VecX& v, double t_abs);
  /// Appends one curve per DOF, all on the same time range, shifted to start at the append time.
  /// Their start values must match the end configuration (1e-6).
  bool AppendCurves(const std::vector<PiecewisePolynomial>& curves);

  /// Moves the clock forward by dt >= 0 s and trims pieces that ended long ago.
  void Advance(double dt);

  double time() const { return time_; }
  double start_time() const;
  double end_time() const;
  /// end_time() - time(), at least 0.
  double RemainingTime() const;
  bool empty() const { return curves_.empty() || curves_.front().empty(); }

  /// State at time(). The pointer forms do not allocate when `out` has dof() entries.
  VecX Config() const;
  VecX Velocity() const;
  void Config(VecX* out) const { Eval(time_, out); }
  void Velocity(VecX* out) const { Deriv(time_, out); }
  /// State at any queue time t (held before the start and after the end, with zero velocity).
  VecX Eval(double t) const;
  VecX Deriv(double t) const;
  void Eval(double t, VecX* out) const;
  void Deriv(double t, VecX* out) const;
  /// The state the next append starts from.
  VecX EndConfig() const;
  VecX EndVelocity() const;

  const std::string& last_error() const { return last_error_; }
  /// Total number of polynomial pieces held (all DOFs).
  std::size_t piece_count() const;
  const std::vector<PiecewisePolynomial>& curves() const { return curves_; }

 private:
  // The time, configuration and velocity the next append starts from.
  struct AppendStart {
    double time = 0;
    VecX q;
    VecX v;
  };
  bool CanAppend(const char* command);
  AppendStart StartOfAppend() const;
  // Extends a queue that ran out with a hold up to `time`.
  void HoldUntil(double time);
  bool CheckVector(const VecX& v, const char* command, const char* name);
  bool CheckDuration(double duration, const char* command);
  bool Fail(std::string message);
  void Succeed() { last_error_.clear(); }

  JointLimits limits_;
  std::vector<PiecewisePolynomial> curves_;
  double time_ = 0;
  std::string last_error_;
};

}  // namespace lamina::core
