// SPDX-License-Identifier: MIT
// MotionQueue commands, clock and front trimming (see motion_queue.h).
#include "core/control/motion_queue.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/control/parabolic_ramp.h"

namespace lamina::core {
namespace {

// Trim the front once the clock is this far past the start: max(kTrimMinAge, kTrimFraction *
// queued duration) (s), so trimming is rare and the memory stays bounded.
constexpr double kTrimMinAge = 0.1;
constexpr double kTrimFraction = 0.1;
// Appended curves must start within this distance of the end configuration.
constexpr double kCurveJoinTolerance = 1e-6;
// A timed command may name an end time this much before the queue's end (rounding), s.
constexpr double kQueueTimeTolerance = 1e-12;

}  // namespace

MotionQueue::MotionQueue(JointLimits limits) : limits_(std::move(limits)) {
  curves_.resize(static_cast<std::size_t>(std::max(0, limits_.dof())));
}

bool MotionQueue::SetLimits(JointLimits limits) {
  std::string reason;
  if (!limits.IsValid(dof(), &reason)) return Fail("SetLimits: " + reason);
  limits_ = std::move(limits);
  Succeed();
  return true;
}

bool MotionQueue::Fail(std::string message) {
  last_error_ = std::move(message);
  return false;
}

bool MotionQueue::CheckVector(const VecX& v, const char* command, const char* name) {
  if (v.size() != dof()) {
    return Fail(std::string(command) + ": " + name + " has " + std::to_string(v.size()) +
                " entries, expected " + std::to_string(dof()));
  }
  if (!v.allFinite()) return Fail(std::string(command) + ": " + name + " has a NaN or inf entry");
  return true;
}

bool MotionQueue::CheckDuration(double duration, const char* command) {
  if (!std::isfinite(duration) || duration < 0) {
    return Fail(std::string(command) + ": duration " + std::to_string(duration) +
                " must be finite and >= 0");
  }
  return true;
}

bool MotionQueue::CanAppend(const char* command) {
  if (empty()) return Fail(std::string(command) + ": the queue is empty (call SetConstant first)");
  return true;
}

double MotionQueue::start_time() const {
  return empty() ? time_ : curves_.front().StartTime();
}

double MotionQueue::end_time() const {
  return empty() ? time_ : curves_.front().EndTime();
}

double MotionQueue::RemainingTime() const {
  return std::max(0.0, end_time() - time_);
}

MotionQueue::AppendStart MotionQueue::StartOfAppend() const {
  AppendStart start{end_time(), EndConfig(), EndVelocity()};
  if (time_ > start.time) {  // ran out: the end configuration is held, at rest
    start.time = time_;
    start.v.setZero();
  }
  return start;
}

void MotionQueue::HoldUntil(double time) {
  for (PiecewisePolynomial& curve : curves_) {
    if (curve.EndTime() < time) {
      curve.Append(PolynomialPiece::Constant(curve.EndTime(), time, curve.EndValue()));
    }
  }
}

bool MotionQueue::SetConstant(const VecX& q) {
  if (!CheckVector(q, "SetConstant", "configuration")) return false;
  for (int i = 0; i < dof(); ++i) {
    curves_[i].Clear();
    curves_[i].Append(PolynomialPiece::Constant(time_, time_, q[i]));
  }
  Succeed();
  return true;
}

void MotionQueue::Cut() {
  for (PiecewisePolynomial& curve : curves_) curve.CutAfter(time_);
  if (!empty()) HoldUntil(time_);
}

bool MotionQueue::AppendLinear(const VecX& q, double duration) {
  if (!CanAppend("AppendLinear") || !CheckVector(q, "AppendLinear", "configuration") ||
      !CheckDuration(duration, "AppendLinear")) {
    return false;
  }
  const AppendStart start = StartOfAppend();
  HoldUntil(start.time);
  for (int i = 0; i < dof(); ++i) {
    curves_[i].Append(PolynomialPiece::Linear(start.time, start.time + duration, start.q[i], q[i]));
  }
  Succeed();
  return true;
}

bool MotionQueue::AppendCubic(const VecX& q, const VecX& v, double duration) {
  if (!CanAppend("AppendCubic") || !CheckVector(q, "AppendCubic", "configuration") ||
      !CheckVector(v, "AppendCubic", "velocity") || !CheckDuration(duration, "AppendCubic")) {
    return false;
  }
  const AppendStart start = StartOfAppend();
  HoldUntil(start.time);
  for (int i = 0; i < dof(); ++i) {
    curves_[i].Append(PolynomialPiece::Hermite(start.time, start.time + duration, start.q[i],
                                               start.v[i], q[i], v[i]));
  }
  Succeed();
  return true;
}

bool MotionQueue::AppendRamp(const VecX& q) {
  if (!CheckVector(q, "AppendRamp", "configuration")) return false;
  return AppendRamp(q, VecX::Zero(dof()));
}

bool MotionQueue::AppendRamp(const VecX& q, const VecX& v) {
  if (!CanAppend("AppendRamp") || !CheckVector(q, "AppendRamp", "configuration") ||
      !CheckVector(v, "AppendRamp", "velocity")) {
    return false;
  }
  const AppendStart start = StartOfAppend();
  std::string reason;
  const auto ramp = PlanJointRamp(start.q, start.v, q, v, limits_, &reason);
  if (!ramp) return Fail("AppendRamp: " + reason);
  HoldUntil(start.time);
  ramp->AppendTo(start.time, &curves_);
  Succeed();
  return true;
}

bool MotionQueue::AppendLinearRamp(const VecX& q) {
  if (!CanAppend("AppendLinearRamp") || !CheckVector(q, "AppendLinearRamp", "configuration")) {
    return false;
  }
  std::string reason;
  if (!limits_.IsValid(dof(), &reason)) return Fail("AppendLinearRamp: " + reason);
  const AppendStart start = StartOfAppend();
  const auto ramp = LinearRampND(start.q, ClampTargetIntoLimits(q, limits_), limits_, &reason);
  if (!ramp) return Fail("AppendLinearRamp: " + reason);
  HoldUntil(start.time);
  ramp->AppendTo(start.time, &curves_);
  Succeed();
  return true;
}

bool MotionQueue::AppendTimedLinear(double t_abs, const VecX& q) {
  if (!CanAppend("AppendTimedLinear") || !CheckVector(q, "AppendTimedLinear", "configuration")) {
    return false;
  }
  const double begin = StartOfAppend().time;
  if (!(t_abs >= begin - kQueueTimeTolerance) || !std::isfinite(t_abs)) {
    return Fail("AppendTimedLinear: time " + std::to_string(t_abs) +
                " s is before the queue's end time " + std::to_string(begin) + " s");
  }
  return AppendLinear(q, std::max(0.0, t_abs - begin));
}

bool MotionQueue::AppendTimedCubic(double t_abs, const VecX& q, const VecX& v) {
  if (!CanAppend("AppendTimedCubic") || !CheckVector(q, "AppendTimedCubic", "configuration") ||
      !CheckVector(v, "AppendTimedCubic", "velocity")) {
    return false;
  }
  const double begin = StartOfAppend().time;
  if (!(t_abs >= begin - kQueueTimeTolerance) || !std::isfinite(t_abs)) {
    return Fail("AppendTimedCubic: time " + std::to_string(t_abs) +
                " s is before the queue's end time " + std::to_string(begin) + " s");
  }
  return AppendCubic(q, v, std::max(0.0, t_abs - begin));
}

bool MotionQueue::SetConstantVelocity(const VecX& v, double t_abs) {
  if (!CanAppend("SetConstantVelocity") || !CheckVector(v, "SetConstantVelocity", "velocity")) {
    return false;
  }
  if (!(t_abs >= time_) || !std::isfinite(t_abs)) {
    return Fail("SetConstantVelocity: time " + std::to_string(t_abs) +
                " s is before the current time " + std::to_string(time_) + " s");
  }
  Cut();
  const VecX q = EndConfig();
  for (int i = 0; i < dof(); ++i) curves_[i].Append({time_, t_abs, {q[i], v[i], 0, 0}});
  Succeed();
  return true;
}

bool MotionQueue::AppendCurves(const std::vector<PiecewisePolynomial>& curves) {
  if (!CanAppend("AppendCurves")) return false;
  if (static_cast<int>(curves.size()) != dof()) {
    return Fail("AppendCurves: " + std::to_string(curves.size()) + " curves, expected " +
                std::to_string(dof()));
  }
  const AppendStart start = StartOfAppend();
  for (int i = 0; i < dof(); ++i) {
    const PiecewisePolynomial& curve = curves[i];
    if (curve.empty() || curve.StartTime() != curves[0].StartTime() ||
        curve.EndTime() != curves[0].EndTime()) {
      return Fail("AppendCurves: the curves are empty or cover different time ranges");
    }
    if (std::abs(curve.Eval(curve.StartTime()) - start.q[i]) > kCurveJoinTolerance) {
      return Fail("AppendCurves: joint " + std::to_string(i) + " starts at " +
                  std::to_string(curve.Eval(curve.StartTime())) + ", the queue ends at " +
                  std::to_string(start.q[i]));
    }
  }
  HoldUntil(start.time);
  for (int i = 0; i < dof(); ++i) {
    PiecewisePolynomial shifted = curves[i];
    shifted.Shift(start.time - curves[i].StartTime());
    for (const PolynomialPiece& piece : shifted.pieces()) curves_[i].Append(piece);
  }
  Succeed();
  return true;
}

void MotionQueue::Advance(double dt) {
  if (!std::isfinite(dt) || dt < 0) {
    Fail("Advance: dt " + std::to_string(dt) + " must be finite and >= 0 (ignored)");
    return;
  }
  time_ += dt;
  if (empty()) return;
  const double age = time_ - start_time();
  if (age > std::max(kTrimMinAge, kTrimFraction * (end_time() - start_time()))) {
    for (PiecewisePolynomial& curve : curves_) curve.TrimFront(time_);
  }
}

void MotionQueue::Eval(double t, VecX* out) const {
  out->resize(dof());
  for (int i = 0; i < dof(); ++i) (*out)[i] = curves_[i].Eval(t);
}

void MotionQueue::Deriv(double t, VecX* out) const {
  out->resize(dof());
  for (int i = 0; i < dof(); ++i) (*out)[i] = curves_[i].Deriv(t);
}

VecX MotionQueue::Eval(double t) const {
  VecX out;
  Eval(t, &out);
  return out;
}

VecX MotionQueue::Deriv(double t) const {
  VecX out;
  Deriv(t, &out);
  return out;
}

VecX MotionQueue::Config() const {
  return Eval(time_);
}
VecX MotionQueue::Velocity() const {
  return Deriv(time_);
}

VecX MotionQueue::EndConfig() const {
  VecX out(dof());
  for (int i = 0; i < dof(); ++i) out[i] = curves_[i].EndValue();
  return out;
}

VecX MotionQueue::EndVelocity() const {
  VecX out(dof());
  for (int i = 0; i < dof(); ++i) out[i] = curves_[i].EndDerivative();
  return out;
}

std::size_t MotionQueue::piece_count() const {
  std::size_t count = 0;
  for (const PiecewisePolynomial& curve : curves_) count += curve.piece_count();
  return count;
}

}  // namespace lamina::core
