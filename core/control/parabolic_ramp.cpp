// SPDX-License-Identifier: MIT
// Parabolic ramp solvers (see parabolic_ramp.h and docs/motion.md for the derivations).
#include "core/control/parabolic_ramp.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/diagnostics.h"
namespace lamina::core {
namespace {

// Relative slack on the acceleration and speed bounds (rounding of the closed forms).
constexpr double kRampBoundSlack = 1e-10;
// Phase durations this negative (relative to the ramp's time scale) are rounding, set to 0.
constexpr double kTimeSlack = 1e-12;
// Position bounds are respected to this absolute tolerance (m or rad).
constexpr double kPositionSlack = 1e-9;
// Pre-clamp margins of a queued ramp's target (fractions of the range / speed limit).
constexpr double kTargetRangeMargin = 1e-7;
constexpr double kTargetSpeedMargin = 2e-7;

double RampSign(double x) {
  return x < 0 ? -1.0 : 1.0;
}

bool WithinSpeed(double v, double velocity_max) {
  return std::abs(v) <= velocity_max * (1 + kRampBoundSlack);
}

bool WithinAcceleration(double a, double acceleration_max) {
  return std::abs(a) <= acceleration_max * (1 + kRampBoundSlack);
}

bool WithinPositions(const Ramp1D& ramp, const RampBounds& bounds) {
  return ramp.MinPosition() >= bounds.position_min - kPositionSlack &&
         ramp.MaxPosition() <= bounds.position_max + kPositionSlack;
}

double PeakAbsAcceleration(const Ramp1D& ramp) {
  return std::max(std::abs(ramp.a1), std::abs(ramp.a2));
}

// A ramp that stays at one phase-space point (or jumps to (x1, v1)): duration 0.
Ramp1D Jump(const RampEnds& ends) {
  Ramp1D ramp;
  ramp.x0 = ends.x0;
  ramp.v0 = ends.v0;
  ramp.x1 = ends.x1;
  ramp.v1 = ends.v1;
  ramp.cruise_velocity = ends.v1;
  return ramp;
}

// Accelerate a1 for t1, cruise for `cruise_time`, accelerate a2 for t3 (negative phase times
// from rounding become 0).
Ramp1D ThreePhase(const RampEnds& ends, double a1, double t1, double cruise_velocity,
                  double cruise_time, double a2, double t3) {
  Ramp1D ramp = Jump(ends);
  ramp.a1 = a1;
  ramp.a2 = a2;
  ramp.cruise_velocity = cruise_velocity;
  ramp.t1 = std::max(t1, 0.0);
  ramp.t2 = ramp.t1 + std::max(cruise_time, 0.0);
  ramp.duration = ramp.t2 + std::max(t3, 0.0);
  return ramp;
}

bool NonNegativeTime(double t, double scale) {
  return t >= -kTimeSlack * std::max(1.0, scale);
}

// The real roots of alpha x^2 + beta x + gamma = 0 (rounding-stable form).
std::vector<double> QuadraticRoots(double alpha, double beta, double gamma) {
  if (alpha == 0) {
    if (beta == 0) return {};
    return {-gamma / beta};
  }
  const double discriminant = beta * beta - 4 * alpha * gamma;
  if (discriminant < 0) return {};
  const double q = -0.5 * (beta + RampSign(beta) * std::sqrt(discriminant));
  if (q == 0) return {0.0};
  return {q / alpha, gamma / q};
}

// --- minimum time, finite acceleration bound ----------------------------------------------

// P: one parabola through both ends, T = 2D/(v0 + v1), a = (v1 - v0)/T.
void AddParabola(const RampEnds& e, double A, std::vector<Ramp1D>* out) {
  const double D = e.x1 - e.x0;
  const double speed_sum = e.v0 + e.v1;
  if (speed_sum == 0) return;
  const double T = 2 * D / speed_sum;
  if (!(T > 0) || !std::isfinite(T)) return;
  const double a = (e.v1 - e.v0) / T;
  if (!WithinAcceleration(a, A)) return;
  out->push_back(ThreePhase(e, a, T, e.v1, 0, 0, 0));
}

// PP: a1 = sA until the peak velocity vp, then -sA. The distance gives
// vp^2 = s A D + (v0^2 + v1^2)/2; both roots are tried, with t1 = (vp - v0)/(sA) >= 0 and
// t3 = (vp - v1)/(sA) >= 0.
void AddBangBang(const RampEnds& e, double A, double V, std::vector<Ramp1D>* out) {
  const double D = e.x1 - e.x0;
  const double mean_square = (e.v0 * e.v0 + e.v1 * e.v1) / 2;
  for (double s : {1.0, -1.0}) {
    double peak_square = s * A * D + mean_square;
    if (peak_square < 0) {
      if (peak_square < -1e-12 * (mean_square + std::abs(A * D))) continue;
      peak_square = 0;
    }
    const double root = std::sqrt(peak_square);
    for (double w : {root, -root}) {
      const double vp = s * w;
      const double t1 = (vp - e.v0) / (s * A);
      const double t3 = (vp - e.v1) / (s * A);
      const double scale = std::abs(t1) + std::abs(t3);
      if (!NonNegativeTime(t1, scale) || !NonNegativeTime(t3, scale)) continue;
      if (!WithinSpeed(vp, V)) continue;
      out->push_back(ThreePhase(e, s * A, t1, vp, 0, -s * A, t3));
      if (root == 0) break;
    }
  }
}

// PLP: accelerate to the cruise speed vc = sV, cruise, decelerate to v1. Cruise time =
// (D - d1 - d3)/vc with d1 = (vc^2 - v0^2)/(2sA), d3 = (vc^2 - v1^2)/(2sA).
void AddBangCruiseBang(const RampEnds& e, double A, double V, std::vector<Ramp1D>* out) {
  if (!std::isfinite(V) || V <= 0) return;
  const double D = e.x1 - e.x0;
  for (double s : {1.0, -1.0}) {
    const double vc = s * V;
    const double t1 = (vc - e.v0) / (s * A);
    const double t3 = (vc - e.v1) / (s * A);
    const double d1 = (vc * vc - e.v0 * e.v0) / (2 * s * A);
    const double d3 = (vc * vc - e.v1 * e.v1) / (2 * s * A);
    const double cruise_time = (D - d1 - d3) / vc;
    const double scale = std::abs(t1) + std::abs(t3) + std::abs(cruise_time);
    if (!NonNegativeTime(t1, scale) || !NonNegativeTime(t3, scale) ||
        !NonNegativeTime(cruise_time, scale)) {
      continue;
    }
    out->push_back(ThreePhase(e, s * A, t1, vc, cruise_time, -s * A, t3));
  }
}

// Every locally time-optimal ramp ignoring position bounds, sorted by duration.
std::vector<Ramp1D> MinTimeCandidates(const RampEnds& e, const RampBounds& bounds) {
  const double A = bounds.acceleration_max;
  const double V = bounds.velocity_max;
  const double D = e.x1 - e.x0;
  std::vector<Ramp1D> candidates;
  if (!WithinSpeed(e.v0, V) || !WithinSpeed(e.v1, V)) return candidates;
  if (D == 0 && (e.v0 == e.v1 || std::isinf(A))) {
    candidates.push_back(Jump(e));
    return candidates;
  }
  if (A <= 0 || V <= 0) return candidates;
  if (std::isinf(A)) {
    if (std::isinf(V)) {
      candidates.push_back(Jump(e));
    } else {
      const double vc = RampSign(D) * V;
      const RampEnds line{e.x0, vc, e.x1, vc};
      candidates.push_back(ThreePhase(line, 0, 0, vc, std::abs(D) / V, 0, 0));
    }
    return candidates;
  }
  AddParabola(e, A, &candidates);
  AddBangBang(e, A, V, &candidates);
  AddBangCruiseBang(e, A, V, &candidates);
  std::sort(candidates.begin(), candidates.end(),
            [](const Ramp1D& a, const Ramp1D& b) { return a.duration < b.duration; });
  return candidates;
}

// --- fixed duration -----------------------------------------------------------------------

// Bang-bang with accelerations a, -a and duration T. With dv = v1 - v0 and t1 = (T + dv/a)/2
// the distance condition is T^2 a^2 + (2T(v0 + v1) - 4D) a - dv^2 = 0; the root of larger
// magnitude is the one with t1 in [0, T].
Ramp1D BangBangForDuration(const RampEnds& e, double T) {
  const double D = e.x1 - e.x0;
  const double dv = e.v1 - e.v0;
  const double b = 2 * T * (e.v0 + e.v1) - 4 * D;
  const double root = std::sqrt(b * b + 4 * T * T * dv * dv);
  const double a = -(b + RampSign(b) * root) / (2 * T * T);
  if (a == 0) return ThreePhase(e, 0, T, e.v0, 0, 0, 0);
  const double t1 = std::clamp((T + dv / a) / 2, 0.0, T);
  return ThreePhase(e, a, t1, e.v0 + a * t1, 0, -a, T - t1);
}

// Accelerate a to the cruise velocity vc, cruise, accelerate -a to v1, all in T:
// a = ((vc - v0)^2 + (vc - v1)^2) / (2 (vc T - D)).
std::optional<Ramp1D> CruiseForDuration(const RampEnds& e, double T, double vc) {
  const double D = e.x1 - e.x0;
  const double denominator = vc * T - D;
  if (!(vc * denominator > 0)) return std::nullopt;
  const double a = ((vc - e.v0) * (vc - e.v0) + (vc - e.v1) * (vc - e.v1)) / (2 * denominator);
  if (a == 0 || !std::isfinite(a)) return std::nullopt;
  const double t1 = (vc - e.v0) / a;
  const double t3 = (vc - e.v1) / a;
  const double cruise_time = T - t1 - t3;
  if (!NonNegativeTime(cruise_time, T)) return std::nullopt;
  Ramp1D ramp = ThreePhase(e, a, t1, vc, cruise_time, -a, t3);
  ramp.duration = T;
  ramp.t2 = std::max(ramp.t1, T - std::max(t3, 0.0));
  return ramp;
}

// Full-acceleration phases (|a1| = |a2| = A) around a cruise at a free speed vc, duration T:
// the profile that brakes hardest, so it strays least. With s0 = sign(vc - v0),
// s1 = sign(v1 - vc) the distance is quadratic in vc:
// (s1 - s0)/(2A) vc^2 + (T + (s0 v0 - s1 v1)/A) vc + (s1 v1^2 - s0 v0^2)/(2A) - D = 0.
void AddFullAccelerationForDuration(const RampEnds& e, double T, double A, double V,
                                    std::vector<Ramp1D>* out) {
  const double D = e.x1 - e.x0;
  for (double s0 : {1.0, -1.0}) {
    for (double s1 : {1.0, -1.0}) {
      const double alpha = (s1 - s0) / (2 * A);
      const double beta = T + (s0 * e.v0 - s1 * e.v1) / A;
      const double gamma = (s1 * e.v1 * e.v1 - s0 * e.v0 * e.v0) / (2 * A) - D;
      for (double vc : QuadraticRoots(alpha, beta, gamma)) {
        const double t1 = s0 * (vc - e.v0) / A;
        const double t3 = s1 * (e.v1 - vc) / A;
        const double cruise_time = T - t1 - t3;
        if (!NonNegativeTime(t1, T) || !NonNegativeTime(t3, T) ||
            !NonNegativeTime(cruise_time, T) || !WithinSpeed(vc, V)) {
          continue;
        }
        Ramp1D ramp = ThreePhase(e, s0 * A, t1, vc, cruise_time, s1 * A, t3);
        ramp.duration = T;
        ramp.t2 = std::max(ramp.t1, T - std::max(t3, 0.0));
        out->push_back(ramp);
      }
    }
  }
}

bool IsFeasible(const Ramp1D& ramp, const RampBounds& bounds) {
  return WithinAcceleration(ramp.a1, bounds.acceleration_max) &&
         WithinAcceleration(ramp.a2, bounds.acceleration_max) &&
         WithinSpeed(ramp.cruise_velocity, bounds.velocity_max) && WithinPositions(ramp, bounds);
}

bool HasPositionBounds(const RampBounds& bounds) {
  return std::isfinite(bounds.position_min) || std::isfinite(bounds.position_max);
}

// The smallest feasible duration in (infeasible, feasible], by bisection.
Ramp1D BisectFeasibleDuration(const RampEnds& e, const RampBounds& bounds, double infeasible,
                              Ramp1D feasible) {
  for (int i = 0; i < 60 && feasible.duration - infeasible > 1e-12 * feasible.duration; ++i) {
    const double middle = 0.5 * (infeasible + feasible.duration);
    if (auto ramp = MinAccelerationRamp(e, bounds, middle)) {
      feasible = *ramp;
    } else {
      infeasible = middle;
    }
  }
  return feasible;
}

// Geometrically longer durations after `start` (s), for bounds the closed forms miss.
std::optional<Ramp1D> SearchLongerDuration(const RampEnds& e, const RampBounds& bounds,
                                           double start) {
  double previous = std::max(start, 1e-6);
  for (int i = 0; i < 150; ++i) {
    const double T = previous * 1.1;
    if (auto ramp = MinAccelerationRamp(e, bounds, T)) {
      return BisectFeasibleDuration(e, bounds, previous, *ramp);
    }
    previous = T;
  }
  return std::nullopt;
}

}  // namespace

// --- Ramp1D ----------------------------------------------------------------------------

double Ramp1D::Position(double t) const {
  if (t >= duration) return x1;
  if (t <= 0) return x0;
  if (t <= t1) return x0 + t * (v0 + 0.5 * a1 * t);
  if (t <= t2) return x0 + t1 * (v0 + 0.5 * a1 * t1) + cruise_velocity * (t - t1);
  const double u = t - duration;
  return x1 + u * (v1 + 0.5 * a2 * u);
}

double Ramp1D::Velocity(double t) const {
  if (duration == 0) return v1;
  t = std::clamp(t, 0.0, duration);
  if (t <= t1) return v0 + a1 * t;
  if (t <= t2) return cruise_velocity;
  return v1 + a2 * (t - duration);
}

double Ramp1D::Acceleration(double t) const {
  if (t < 0 || t > duration) return 0.0;
  if (t < t1) return a1;
  if (t < t2) return 0.0;
  if (t2 < duration) return a2;
  return t1 > 0 ? a1 : 0.0;
}

double Ramp1D::MinPosition() const {
  double low = std::min({x0, x1, Position(t1), Position(t2)});
  if (a1 != 0) {
    const double stop = -v0 / a1;
    if (stop > 0 && stop < t1) low = std::min(low, Position(stop));
  }
  if (a2 != 0) {
    const double stop = duration - v1 / a2;
    if (stop > t2 && stop < duration) low = std::min(low, Position(stop));
  }
  return low;
}

double Ramp1D::MaxPosition() const {
  double high = std::max({x0, x1, Position(t1), Position(t2)});
  if (a1 != 0) {
    const double stop = -v0 / a1;
    if (stop > 0 && stop < t1) high = std::max(high, Position(stop));
  }
  if (a2 != 0) {
    const double stop = duration - v1 / a2;
    if (stop > t2 && stop < duration) high = std::max(high, Position(stop));
  }
  return high;
}

bool Ramp1D::AppendTo(double start, PiecewisePolynomial* curve) const {
  if (duration == 0) return curve->Append({start, start, {x1, v1, 0, 0}});
  bool ok = true;
  if (t1 > 0) ok = ok && curve->Append({start, start + t1, {x0, v0, 0.5 * a1, 0}});
  if (t2 > t1) {
    ok = ok && curve->Append({start + t1, start + t2, {Position(t1), cruise_velocity, 0, 0}});
  }
  if (duration > t2) {
    const double d = duration - t2;
    const double x_start = x1 - v1 * d + 0.5 * a2 * d * d;
    ok = ok && curve->Append({start + t2, start + duration, {x_start, v1 - a2 * d, 0.5 * a2, 0}});
  }
  return ok;
}

// --- 1-D solvers --------------------------------------------------------------------------

std::optional<Ramp1D> MinTimeRamp(const RampEnds& ends, const RampBounds& bounds) {
  return MinTimeRampAtLeast(ends, bounds, 0.0);
}

std::optional<Ramp1D> MinAccelerationRamp(const RampEnds& e, const RampBounds& bounds,
                                          double duration) {
  const double A = bounds.acceleration_max;
  const double V = bounds.velocity_max;
  if (!(duration >= 0) || !std::isfinite(duration)) return std::nullopt;
  if (!WithinSpeed(e.v0, V) || !WithinSpeed(e.v1, V)) return std::nullopt;
  const double D = e.x1 - e.x0;
  if (duration == 0) {
    if (D == 0 && (e.v0 == e.v1 || std::isinf(A))) return Jump(e);
    return std::nullopt;
  }
  std::vector<Ramp1D> candidates;
  const Ramp1D bang_bang = BangBangForDuration(e, duration);
  candidates.push_back(bang_bang);
  if (!WithinSpeed(bang_bang.cruise_velocity, V) || HasPositionBounds(bounds)) {
    for (double s : {1.0, -1.0}) {
      if (auto cruise = CruiseForDuration(e, duration, s * V)) candidates.push_back(*cruise);
    }
  }
  if (std::isinf(A) && std::isfinite(V) && std::abs(D) <= V * duration * (1 + kRampBoundSlack)) {
    const double vc = D / duration;  // velocity jumps at both ends
    candidates.push_back(ThreePhase({e.x0, vc, e.x1, vc}, 0, 0, vc, duration, 0, 0));
  }
  if (std::isfinite(A) && A > 0 && HasPositionBounds(bounds)) {
    AddFullAccelerationForDuration(e, duration, A, V, &candidates);
  }
  std::optional<Ramp1D> best;
  for (Ramp1D& ramp : candidates) {
    ramp.duration = duration;
    if (!IsFeasible(ramp, bounds)) continue;
    if (!best || PeakAbsAcceleration(ramp) < PeakAbsAcceleration(*best)) best = ramp;
  }
  return best;
}

std::optional<Ramp1D> MinTimeRampAtLeast(const RampEnds& e, const RampBounds& bounds,
                                         double min_duration) {
  if (!(min_duration >= 0) || !std::isfinite(min_duration)) return std::nullopt;
  const std::vector<Ramp1D> candidates = MinTimeCandidates(e, bounds);
  if (candidates.empty()) return std::nullopt;  // no ramp at all, bounded or not
  std::optional<Ramp1D> direct;  // the shortest closed-form candidate that is feasible
  std::vector<double> durations{min_duration};
  for (const Ramp1D& candidate : candidates) {
    if (candidate.duration < min_duration) continue;
    durations.push_back(candidate.duration);
    if (!direct && WithinPositions(candidate, bounds)) direct = candidate;
  }
  std::sort(durations.begin(), durations.end());
  for (double T : durations) {
    if (direct && direct->duration <= T) return direct;
    if (auto ramp = MinAccelerationRamp(e, bounds, T)) return ramp;
  }
  return SearchLongerDuration(e, bounds, durations.back());
}

// --- N-D ----------------------------------------------------------------------------------

void ParabolicRampND::Evaluate(double t, VecX* out) const {
  out->resize(dof());
  for (int i = 0; i < dof(); ++i) (*out)[i] = ramps_[i].Position(t);
}

void ParabolicRampND::Derivative(double t, VecX* out) const {
  out->resize(dof());
  for (int i = 0; i < dof(); ++i) (*out)[i] = ramps_[i].Velocity(t);
}

void ParabolicRampND::Accel(double t, VecX* out) const {
  out->resize(dof());
  for (int i = 0; i < dof(); ++i) (*out)[i] = ramps_[i].Acceleration(t);
}

VecX ParabolicRampND::Evaluate(double t) const {
  VecX out;
  Evaluate(t, &out);
  return out;
}

VecX ParabolicRampND::Derivative(double t) const {
  VecX out;
  Derivative(t, &out);
  return out;
}

VecX ParabolicRampND::Accel(double t) const {
  VecX out;
  Accel(t, &out);
  return out;
}

bool ParabolicRampND::AppendTo(double start, std::vector<PiecewisePolynomial>* curves) const {
  if (static_cast<int>(curves->size()) != dof()) return false;
  bool ok = true;
  for (int i = 0; i < dof(); ++i) ok = ramps_[i].AppendTo(start, &(*curves)[i]) && ok;
  return ok;
}

namespace {

bool CheckVector(const VecX& v, int dof, const char* name, std::string* error) {
  if (v.size() != dof) {
    return FailWith(error, std::string(name) + " has " + std::to_string(v.size()) +
                               " entries, expected " + std::to_string(dof));
  }
  if (!v.allFinite()) return FailWith(error, std::string(name) + " has a NaN or infinite entry");
  return true;
}

RampBounds BoundsOf(const JointLimits& limits, int i) {
  return {limits.acceleration_max[i], limits.velocity_max[i], limits.q_min[i], limits.q_max[i]};
}

std::string NoRampMessage(int joint, const RampEnds& e, const RampBounds& b) {
  std::string reason = "no feasible ramp";
  if (!WithinSpeed(e.v0, b.velocity_max) || !WithinSpeed(e.v1, b.velocity_max)) {
    reason = "a boundary speed exceeds velocity_max " + std::to_string(b.velocity_max);
  } else if (b.velocity_max == 0 || b.acceleration_max == 0) {
    reason = "the joint must move but its velocity or acceleration limit is 0";
  } else if (HasPositionBounds(b)) {
    reason = "no ramp within the position limits [" + std::to_string(b.position_min) + ", " +
             std::to_string(b.position_max) + "]";
  }
  return "joint " + std::to_string(joint) + ": " + reason + " (from x " + std::to_string(e.x0) +
         ", v " + std::to_string(e.v0) + " to x " + std::to_string(e.x1) + ", v " +
         std::to_string(e.v1) + ")";
}

std::optional<ParabolicRampND> SynchronizedRamp(const std::vector<RampEnds>& ends,
                                                const std::vector<RampBounds>& bounds,
                                                std::string* error) {
  const int dof = static_cast<int>(ends.size());
  std::vector<Ramp1D> ramps(dof);
  double T = 0;
  for (int i = 0; i < dof; ++i) {
    auto ramp = MinTimeRamp(ends[i], bounds[i]);
    if (!ramp) {
      FailWith(error, NoRampMessage(i, ends[i], bounds[i]));
      return std::nullopt;
    }
    ramps[i] = *ramp;
    T = std::max(T, ramp->duration);
  }
  for (int round = 0; round < 1000; ++round) {
    bool raised = false;
    for (int i = 0; i < dof && !raised; ++i) {
      if (ramps[i].duration == T) continue;
      if (auto ramp = MinAccelerationRamp(ends[i], bounds[i], T)) {
        ramps[i] = *ramp;
        continue;
      }
      auto longer = MinTimeRampAtLeast(ends[i], bounds[i], T);
      if (!longer) {
        FailWith(error, NoRampMessage(i, ends[i], bounds[i]) + " lasting at least " +
                            std::to_string(T) + " s");
        return std::nullopt;
      }
      ramps[i] = *longer;
      raised = longer->duration > T;
      T = std::max(T, longer->duration);
    }
    if (!raised) return ParabolicRampND(std::move(ramps));
  }
  FailWith(error, "the joints' ramps could not be synchronized (no common duration found)");
  return std::nullopt;
}

}  // namespace

std::optional<ParabolicRampND> MinTimeRampND(const VecX& x0, const VecX& v0, const VecX& x1,
                                             const VecX& v1, const JointLimits& limits,
                                             std::string* error) {
  const int dof = static_cast<int>(x0.size());
  if (!limits.IsValid(dof, error) || !CheckVector(x0, dof, "start position", error) ||
      !CheckVector(v0, dof, "start velocity", error) ||
      !CheckVector(x1, dof, "target position", error) ||
      !CheckVector(v1, dof, "target velocity", error)) {
    return std::nullopt;
  }
  std::vector<RampEnds> ends(dof);
  std::vector<RampBounds> bounds(dof);
  for (int i = 0; i < dof; ++i) {
    ends[i] = {x0[i], v0[i], x1[i], v1[i]};
    bounds[i] = BoundsOf(limits, i);
  }
  return SynchronizedRamp(ends, bounds, error);
}

std::optional<ParabolicRampND> LinearRampND(const VecX& x0, const VecX& x1,
                                            const JointLimits& limits, std::string* error) {
  const int dof = static_cast<int>(x0.size());
  if (!limits.IsValid(dof, error) || !CheckVector(x0, dof, "start position", error) ||
      !CheckVector(x1, dof, "target position", error)) {
    return std::nullopt;
  }
  RampBounds line_bounds;  // on s in [0, 1]
  for (int i = 0; i < dof; ++i) {
    const double dx = std::abs(x1[i] - x0[i]);
    if (dx == 0) continue;
    line_bounds.velocity_max = std::min(line_bounds.velocity_max, limits.velocity_max[i] / dx);
    line_bounds.acceleration_max =
        std::min(line_bounds.acceleration_max, limits.acceleration_max[i] / dx);
  }
  const bool moves = x0 != x1;
  const auto s = moves ? MinTimeRamp({0, 0, 1, 0}, line_bounds) : Ramp1D{};
  if (!s) {
    FailWith(error,
             "no straight-line ramp: a moving joint has a zero velocity or acceleration limit");
    return std::nullopt;
  }
  std::vector<Ramp1D> ramps(dof, *s);
  for (int i = 0; i < dof; ++i) {
    const double dx = moves ? x1[i] - x0[i] : 0.0;
    Ramp1D& r = ramps[i];
    r.x0 = x0[i];
    r.x1 = x1[i];
    r.v0 = dx * s->v0;
    r.v1 = dx * s->v1;
    r.a1 = dx * s->a1;
    r.a2 = dx * s->a2;
    r.cruise_velocity = dx * s->cruise_velocity;
  }
  return ParabolicRampND(std::move(ramps));
}

VecX ClampTargetIntoLimits(const VecX& target, const JointLimits& limits) {
  VecX clamped = target;
  for (int i = 0; i < target.size(); ++i) {
    const double low = limits.q_min[i];
    const double high = limits.q_max[i];
    if (target[i] >= low && target[i] <= high) continue;
    const double range = high - low;
    const double margin = std::isfinite(range) ? kTargetRangeMargin * range : 0.0;
    clamped[i] = std::clamp(target[i], low + margin, high - margin);
  }
  return clamped;
}

std::optional<ParabolicRampND> PlanJointRamp(const VecX& start_q, const VecX& start_v,
                                             const VecX& target_q, const VecX& target_v,
                                             const JointLimits& limits, std::string* error) {
  const int dof = static_cast<int>(start_q.size());
  if (!limits.IsValid(dof, error) || !CheckVector(start_q, dof, "start position", error) ||
      !CheckVector(start_v, dof, "start velocity", error) ||
      !CheckVector(target_q, dof, "target position", error) ||
      !CheckVector(target_v, dof, "target velocity", error)) {
    return std::nullopt;
  }
  const VecX target = ClampTargetIntoLimits(target_q, limits);
  std::vector<RampEnds> ends(dof);
  std::vector<RampBounds> bounds(dof);
  for (int i = 0; i < dof; ++i) {
    const double V = limits.velocity_max[i];
    const double target_speed = V * (1 - kTargetSpeedMargin);
    ends[i] = {start_q[i], std::clamp(start_v[i], -V, V), target[i],
               std::clamp(target_v[i], -target_speed, target_speed)};
    bounds[i] = BoundsOf(limits, i);
    // room for the start and for braking from the start velocity at full acceleration
    const double stop =
        ends[i].x0 + ends[i].v0 * std::abs(ends[i].v0) / (2 * limits.acceleration_max[i]);
    const double reach_low = std::min(ends[i].x0, std::isfinite(stop) ? stop : ends[i].x0);
    const double reach_high = std::max(ends[i].x0, std::isfinite(stop) ? stop : ends[i].x0);
    bounds[i].position_min = std::min(bounds[i].position_min, reach_low);
    bounds[i].position_max = std::max(bounds[i].position_max, reach_high);
  }
  return SynchronizedRamp(ends, bounds, error);
}

}  // namespace lamina::core
