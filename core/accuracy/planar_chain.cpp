// SPDX-License-Identifier: MIT
#include "core/accuracy/planar_chain.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace lamina::core {
namespace {

constexpr double kLineTolerance = 1e-9;  // m, rad: how far off the plane and lines a chain may be

// ℓ_ki: how far link k's centre moves per radian of link i.
double Lever(const PlanarChain& chain, int k, int i) {
  if (i < k) return chain.links[i].length;
  return i == k ? chain.links[k].com : 0.0;
}

// B_ij = Σ_{k ≥ max(i,j)} m_k·ℓ_ki·ℓ_kj.
Eigen::MatrixXd Coupling(const PlanarChain& chain) {
  const int n = static_cast<int>(chain.links.size());
  Eigen::MatrixXd b = Eigen::MatrixXd::Zero(n, n);
  for (int k = 0; k < n; ++k) {
    for (int i = 0; i <= k; ++i) {
      for (int j = 0; j <= k; ++j)
        b(i, j) += chain.links[k].mass * Lever(chain, k, i) * Lever(chain, k, j);
    }
  }
  return b;
}

Eigen::MatrixXd MassMatrix(const PlanarChain& chain, const Eigen::MatrixXd& b,
                           const Eigen::VectorXd& angle) {
  const int n = static_cast<int>(angle.size());
  Eigen::MatrixXd m(n, n);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) m(i, j) = b(i, j) * std::cos(angle[i] - angle[j]);
    m(i, i) += chain.links[i].inertia;
  }
  return m;
}

// Σ_k m_k·ℓ_ki: the gravity lever of angle i (kg·m).
double GravityLever(const PlanarChain& chain, int i) {
  double sum = 0.0;
  for (int k = i; k < static_cast<int>(chain.links.size()); ++k)
    sum += chain.links[k].mass * Lever(chain, k, i);
  return sum;
}

PlanarChainState Derivative(const PlanarChain& chain, const PlanarChainConstants& constants,
                            const PlanarChainState& state) {
  return {state.rate, chain.Accelerations(state, constants)};
}

PlanarChainState Advance(const PlanarChainState& state, const PlanarChainState& slope, double h) {
  return {state.angle + h * slope.angle, state.rate + h * slope.rate};
}

Eigen::Vector2d Direction(double angle) {
  return {std::cos(angle), std::sin(angle)};
}

}  // namespace

PlanarChainConstants PlanarChain::Constants() const {
  PlanarChainConstants constants{Coupling(*this), Eigen::VectorXd(links.size())};
  for (int i = 0; i < constants.lever.size(); ++i) constants.lever[i] = GravityLever(*this, i);
  return constants;
}

Eigen::VectorXd PlanarChain::Accelerations(const PlanarChainState& state) const {
  return Accelerations(state, Constants());
}

Eigen::VectorXd PlanarChain::Accelerations(const PlanarChainState& state,
                                           const PlanarChainConstants& constants) const {
  const Eigen::MatrixXd& b = constants.coupling;
  const int n = static_cast<int>(links.size());
  Eigen::VectorXd force(n);
  for (int i = 0; i < n; ++i) {
    double coriolis = 0.0;
    for (int j = 0; j < n; ++j) {
      coriolis +=
          b(i, j) * std::sin(state.angle[i] - state.angle[j]) * state.rate[j] * state.rate[j];
    }
    force[i] = -coriolis - g * std::sin(state.angle[i]) * constants.lever[i];
  }
  return MassMatrix(*this, b, state.angle).ldlt().solve(force);
}

double PlanarChain::Energy(const PlanarChainState& state) const {
  const Eigen::MatrixXd m = MassMatrix(*this, Coupling(*this), state.angle);
  double potential = 0.0;
  const std::vector<Eigen::Vector2d> centres = Centres(state.angle);
  for (std::size_t k = 0; k < links.size(); ++k) potential -= g * links[k].mass * centres[k].x();
  return 0.5 * state.rate.dot(m * state.rate) + potential;
}

std::vector<Eigen::Vector2d> PlanarChain::Centres(const Eigen::VectorXd& angle) const {
  std::vector<Eigen::Vector2d> centres;
  Eigen::Vector2d hinge = Eigen::Vector2d::Zero();
  for (std::size_t k = 0; k < links.size(); ++k) {
    const Eigen::Vector2d u = Direction(angle[static_cast<int>(k)]);
    centres.push_back(hinge + links[k].com * u);
    hinge += links[k].length * u;
  }
  return centres;
}

PlanarChainState Rk4Step(const PlanarChain& chain, const PlanarChainConstants& constants,
                         const PlanarChainState& state, double step) {
  const PlanarChainState k1 = Derivative(chain, constants, state);
  const PlanarChainState k2 = Derivative(chain, constants, Advance(state, k1, 0.5 * step));
  const PlanarChainState k3 = Derivative(chain, constants, Advance(state, k2, 0.5 * step));
  const PlanarChainState k4 = Derivative(chain, constants, Advance(state, k3, step));
  return {state.angle + step / 6.0 * (k1.angle + 2.0 * k2.angle + 2.0 * k3.angle + k4.angle),
          state.rate + step / 6.0 * (k1.rate + 2.0 * k2.rate + 2.0 * k3.rate + k4.rate)};
}

PlanarChainTrajectory::PlanarChainTrajectory(PlanarChain chain, const PlanarChainState& start,
                                             double duration, double step)
    : chain_(std::move(chain)), constants_(chain_.Constants()), step_(step) {
  const int count = std::max(1, static_cast<int>(std::ceil(duration / step - 1e-9)));
  samples_.reserve(count + 1);
  samples_.push_back(start);
  for (int i = 0; i < count; ++i)
    samples_.push_back(Rk4Step(chain_, constants_, samples_.back(), step_));
  for (const PlanarChainState& s : samples_)
    accelerations_.push_back(chain_.Accelerations(s, constants_));
}

PlanarChainState PlanarChainTrajectory::State(double t) const {
  const double last = static_cast<double>(samples_.size() - 1);
  const double at = std::clamp(t / step_, 0.0, last);
  const std::size_t i = std::min(static_cast<std::size_t>(at), samples_.size() - 2);
  const double s = at - static_cast<double>(i), h = step_;
  const PlanarChainState& a = samples_[i];
  const PlanarChainState& b = samples_[i + 1];
  // cubic Hermite on the angle (values and rates), and on the rate (rates and accelerations)
  const double h00 = (1 + 2 * s) * (1 - s) * (1 - s), h10 = s * (1 - s) * (1 - s);
  const double h01 = s * s * (3 - 2 * s), h11 = s * s * (s - 1);
  return {
      h00 * a.angle + h10 * h * a.rate + h01 * b.angle + h11 * h * b.rate,
      h00 * a.rate + h10 * h * accelerations_[i] + h01 * b.rate + h11 * h * accelerations_[i + 1]};
}

std::vector<Vec3> WorldPlanarChain::Centres(const Eigen::VectorXd& angle) const {
  std::vector<Vec3> centres;
  const std::vector<Eigen::Vector2d> planar = chain.Centres(angle);
  for (std::size_t k = 0; k < planar.size(); ++k) {
    centres.push_back(pivot + planar[k].x() * down + planar[k].y() * side + offsets[k] * axis);
  }
  return centres;
}

namespace {

// Joint k must be a hinge holding object k, and object k − 1 (k > 0) or the world (k = 0).
std::string CheckJoint(const WorldDesc& world, int k, const Vec3& axis) {
  const WorldJointDesc& joint = world.joints[k];
  const std::string name = "joint " + std::to_string(k);
  if (joint.type != WorldJointType::kHinge) return name + " is not a hinge";
  const auto holds = [&](std::size_t slot, int object) {
    return joint.bodies.size() > slot && joint.bodies[slot].kind == WorldId::Kind::kRigidObject &&
           joint.bodies[slot].index == object;
  };
  if (!holds(0, k)) return name + " does not hold object " + std::to_string(k) + " first";
  if (k > 0 && !holds(1, k - 1)) return name + " does not join object " + std::to_string(k - 1);
  if (k == 0 && joint.bodies.size() > 1 && joint.bodies[1].kind == WorldId::Kind::kRigidObject) {
    return name + " is not held to the world";
  }
  if (joint.axis.normalized().cross(axis).norm() > kLineTolerance) {
    return name + "'s axis is not parallel to joint 0's";
  }
  return "";
}

// Link k read off the world, with its angle, rate and centre's offset along the axis.
std::string ReadLink(const WorldDesc& world, int k, WorldPlanarChain* out) {
  const RigidObjectDesc& object = world.objects[k];
  const auto planar = [&](const Vec3& v) {
    return Eigen::Vector2d((v - out->pivot).dot(out->down), (v - out->pivot).dot(out->side));
  };
  const Vec3 com = object.pose * object.com;
  const Eigen::Vector2d hinge = planar(world.joints[k].point), centre = planar(com);
  const bool last = k + 1 == static_cast<int>(world.objects.size());
  const Eigen::Vector2d span = last ? Eigen::Vector2d(centre - hinge)
                                    : Eigen::Vector2d(planar(world.joints[k + 1].point) - hinge);
  if (span.norm() < kLineTolerance) return "object " + std::to_string(k) + " has no length";
  const Eigen::Vector2d u = span.normalized();
  const Eigen::Vector2d arm = centre - hinge;
  if (std::abs(arm.x() * u.y() - arm.y() * u.x()) > kLineTolerance) {
    return "object " + std::to_string(k) + "'s centre of mass is off the line of its hinges";
  }
  const Mat3 rotation = object.pose.linear();
  PlanarLink link{object.mass,
                  out->axis.dot(rotation * object.inertia * rotation.transpose() * out->axis),
                  arm.dot(u), last ? 0.0 : span.norm()};
  out->chain.links.push_back(link);
  out->start.angle[k] = std::atan2(u.y(), u.x());
  out->start.rate[k] = object.initial_velocity.angular.dot(out->axis);
  out->offsets.push_back((com - out->pivot).dot(out->axis));
  return "";
}

}  // namespace

std::string ReadPlanarChain(const WorldDesc& world, WorldPlanarChain* out) {
  const int n = static_cast<int>(world.objects.size());
  if (n == 0 || world.joints.size() != world.objects.size()) return "not one hinge per object";
  *out = WorldPlanarChain{};
  out->axis = world.joints[0].axis.normalized();
  out->pivot = world.joints[0].point;
  out->chain.g = world.settings.gravity.norm();
  if (out->chain.g <= 0.0) return "no gravity";
  out->down = world.settings.gravity / out->chain.g;
  if (std::abs(out->down.dot(out->axis)) > kLineTolerance) return "gravity is not in the plane";
  out->side = out->axis.cross(out->down);
  out->start.angle.resize(n);
  out->start.rate.resize(n);
  for (int k = 0; k < n; ++k) {
    std::string problem = CheckJoint(world, k, out->axis);
    if (problem.empty()) problem = ReadLink(world, k, out);
    if (!problem.empty()) return problem;
  }
  return "";
}

}  // namespace lamina::core
