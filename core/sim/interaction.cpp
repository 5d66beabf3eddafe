// SPDX-License-Identifier: MIT
#include "core/sim/interaction.h"

#include <algorithm>
#include <cmath>

namespace lamina::core {

namespace {

constexpr double kStandardGravity = 9.81;  // m/s², for the cap in a world without gravity

Mat3 Cross(const Vec3& r) {
  Mat3 m;
  m << 0, -r.z(), r.y(), r.z(), 0, -r.x(), -r.y(), r.x(), 0;
  return m;
}

}  // namespace

std::optional<std::string> CheckDragSpringSettings(const DragSpringSettings& settings) {
  const auto positive = [](double x) { return std::isfinite(x) && x > 0.0; };
  if (!positive(settings.frequency) || !positive(settings.max_force_per_weight) ||
      !positive(settings.max_stretch) || !std::isfinite(settings.damping_ratio) ||
      settings.damping_ratio < 0.0) {
    return "a drag spring needs a frequency, force cap and stretch > 0 and a damping ratio >= 0";
  }
  return std::nullopt;
}

DragSpring MakeDragSpring(double mass, double gravity, const DragSpringSettings& settings) {
  const double omega = 2.0 * kPi * settings.frequency;
  const double g = gravity > 0.0 ? gravity : kStandardGravity;
  return {mass * omega * omega, 2.0 * settings.damping_ratio * mass * omega,
          settings.max_force_per_weight * mass * g};
}

double DragScale(const DragSpring& spring, const Vec3& stretch, const Vec3& velocity,
                 const Vec3& gravity, double h) {
  const double bound = spring.stiffness * stretch.norm() +
                       (spring.stiffness * h + spring.damping) * (velocity + h * gravity).norm();
  return bound > spring.max_force ? spring.max_force / bound : 1.0;
}

Vec3 CapStretch(const Vec3& point, const Vec3& target, double max_stretch) {
  const Vec3 stretch = target - point;
  const double length = stretch.norm();
  if (length <= max_stretch) return target;
  return point + stretch * (max_stretch / length);
}

double RigidEffectiveMass(double mass, const Mat3& inertia, const Vec3& r) {
  const Mat3 cross = Cross(r);
  const double trace = 3.0 / mass + (cross * inertia.inverse() * cross.transpose()).trace();
  return 3.0 / trace;
}

TurnSpring MakeTurnSpring(double inertia, double mass, double gravity,
                          const DragSpringSettings& settings) {
  const double omega = 2.0 * kPi * settings.frequency;
  const double g = gravity > 0.0 ? gravity : kStandardGravity;
  return {inertia * omega * omega, 2.0 * settings.damping_ratio * inertia * omega,
          settings.max_force_per_weight * g * std::sqrt(mass * inertia)};
}

double TurnScale(const TurnSpring& spring, const Vec3& turn, const Vec3& angular_velocity,
                 double h) {
  const double bound = spring.stiffness * turn.norm() +
                       (spring.stiffness * h + spring.damping) * angular_velocity.norm();
  return bound > spring.max_torque ? spring.max_torque / bound : 1.0;
}

Vec3 CappedTurn(const Mat3& from, const Mat3& to, double max_turn) {
  const Vec3 turn = MomentFromRotation(to * from.transpose());
  const double angle = turn.norm();
  return angle <= max_turn ? turn : Vec3(turn * (max_turn / angle));
}

double RigidEffectiveInertia(const Mat3& inertia) {
  return 3.0 / inertia.inverse().trace();
}

}  // namespace lamina::core
