// SPDX-License-Identifier: MIT
// Trajectory construction from milestone sequences and files (see trajectory.h).
#include "core/control/trajectory.h"

#include <cmath>
#include <utility>

#include "core/control/motion_queue.h"
#include "core/control/parabolic_ramp.h"
#include "core/diagnostics.h"

namespace lamina::core {
namespace {

// Same nonzero size and finite entries for every vector; nondecreasing finite times when given.
bool CheckMilestones(const std::vector<double>* times, const std::vector<VecX>& configs,
                     const std::vector<VecX>* velocities, std::string* error) {
  if (configs.empty()) return FailWith(error, "no milestones");
  const Eigen::Index dof = configs.front().size();
  if (times && times->size() != configs.size()) {
    return FailWith(error, std::to_string(times->size()) + " times for " +
                               std::to_string(configs.size()) + " milestones");
  }
  if (velocities && velocities->size() != configs.size()) {
    return FailWith(error, std::to_string(velocities->size()) + " velocities for " +
                               std::to_string(configs.size()) + " milestones");
  }
  for (std::size_t k = 0; k < configs.size(); ++k) {
    const std::string which = "milestone " + std::to_string(k);
    if (configs[k].size() != dof || (velocities && (*velocities)[k].size() != dof)) {
      return FailWith(error, which + " has a different size than milestone 0");
    }
    if (!configs[k].allFinite() || (velocities && !(*velocities)[k].allFinite())) {
      return FailWith(error, which + " has a NaN or infinite entry");
    }
    if (times && (!std::isfinite((*times)[k]) || (k > 0 && (*times)[k] < (*times)[k - 1]))) {
      return FailWith(error, which + ": times must be finite and nondecreasing");
    }
  }
  return true;
}

std::vector<PiecewisePolynomial> CurvesStartingAt(double time, const VecX& config) {
  std::vector<PiecewisePolynomial> curves(static_cast<std::size_t>(config.size()));
  for (int i = 0; i < config.size(); ++i) {
    curves[i].Append(PolynomialPiece::Constant(time, time, config[i]));
  }
  return curves;
}

}  // namespace

std::optional<Trajectory> Trajectory::FromTimedLinear(const std::vector<double>& times,
                                                      const std::vector<VecX>& configs,
                                                      std::string* error) {
  if (!CheckMilestones(&times, configs, nullptr, error)) return std::nullopt;
  std::vector<PiecewisePolynomial> curves = CurvesStartingAt(times[0], configs[0]);
  for (std::size_t k = 1; k < configs.size(); ++k) {
    for (int i = 0; i < configs[k].size(); ++i) {
      curves[i].Append(
          PolynomialPiece::Linear(times[k - 1], times[k], configs[k - 1][i], configs[k][i]));
    }
  }
  return Trajectory(std::move(curves));
}

std::optional<Trajectory> Trajectory::FromTimedCubic(const std::vector<double>& times,
                                                     const std::vector<VecX>& configs,
                                                     const std::vector<VecX>& velocities,
                                                     std::string* error) {
  if (!CheckMilestones(&times, configs, &velocities, error)) return std::nullopt;
  std::vector<PiecewisePolynomial> curves = CurvesStartingAt(times[0], configs[0]);
  for (std::size_t k = 1; k < configs.size(); ++k) {
    for (int i = 0; i < configs[k].size(); ++i) {
      curves[i].Append(PolynomialPiece::Hermite(times[k - 1], times[k], configs[k - 1][i],
                                                velocities[k - 1][i], configs[k][i],
                                                velocities[k][i]));
    }
  }
  return Trajectory(std::move(curves));
}

std::optional<Trajectory> Trajectory::FromMilestones(const MilestoneSequence& sequence,
                                                     const JointLimits& limits,
                                                     std::string* error) {
  const bool has_velocities = !sequence.velocities.empty();
  if (!CheckMilestones(nullptr, sequence.configs, has_velocities ? &sequence.velocities : nullptr,
                       error)) {
    return std::nullopt;
  }
  const VecX zero = VecX::Zero(sequence.configs.front().size());
  std::vector<PiecewisePolynomial> curves = CurvesStartingAt(0.0, sequence.configs[0]);
  VecX q = sequence.configs[0];
  VecX v = has_velocities ? sequence.velocities[0] : zero;
  for (std::size_t k = 1; k < sequence.configs.size(); ++k) {
    std::string reason;
    const VecX& target_v = has_velocities ? sequence.velocities[k] : zero;
    const auto ramp = PlanJointRamp(q, v, sequence.configs[k], target_v, limits, &reason);
    if (!ramp) {
      FailWith(error, "milestone " + std::to_string(k) + ": " + reason);
      return std::nullopt;
    }
    ramp->AppendTo(curves.front().EndTime(), &curves);
    for (int i = 0; i < ramp->dof(); ++i) {
      q[i] = ramp->ramps()[i].x1;
      v[i] = ramp->ramps()[i].v1;
    }
  }
  return Trajectory(std::move(curves));
}

std::optional<Trajectory> Trajectory::FromSequence(const MilestoneSequence& sequence,
                                                   const JointLimits& limits, std::string* error) {
  if (sequence.times.empty()) return FromMilestones(sequence, limits, error);
  if (sequence.velocities.empty()) return FromTimedLinear(sequence.times, sequence.configs, error);
  return FromTimedCubic(sequence.times, sequence.configs, sequence.velocities, error);
}

void Trajectory::Eval(double t, VecX* out) const {
  out->resize(dof());
  for (int i = 0; i < dof(); ++i) (*out)[i] = curves_[i].Eval(t);
}

void Trajectory::Deriv(double t, VecX* out) const {
  out->resize(dof());
  for (int i = 0; i < dof(); ++i) (*out)[i] = curves_[i].Deriv(t);
}

VecX Trajectory::Eval(double t) const {
  VecX out;
  Eval(t, &out);
  return out;
}

VecX Trajectory::Deriv(double t) const {
  VecX out;
  Deriv(t, &out);
  return out;
}

bool Trajectory::AppendTo(MotionQueue& queue, double transition_time) const {
  if (queue.dof() != dof()) {
    return queue.AppendCurves(curves_);  // fails with the size message, appends nothing
  }
  if (!queue.AppendLinear(Eval(StartTime()), transition_time)) return false;
  return queue.AppendCurves(curves_);
}

}  // namespace lamina::core
