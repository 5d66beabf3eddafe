// SPDX-License-Identifier: MIT
#include "core/sim/energy_guard.h"

#include <cmath>

namespace lamina::core {

namespace {

double Allowance(const BodyEnergySample& body, const InstabilitySettings& settings) {
  return settings.growth_factor * body.energy_before + settings.energy_per_kg * body.mass +
         body.external_work;
}

}  // namespace

double KineticEnergy(double mass, const Mat3& inertia, const Vec3& velocity,
                     const Vec3& angular_velocity) {
  return 0.5 * mass * velocity.squaredNorm() +
         0.5 * angular_velocity.dot(inertia * angular_velocity);
}

double ExternalWorkBound(const Vec3& force, const Vec3& torque, double speed_before,
                         double speed_after, double angular_speed_before,
                         double angular_speed_after, double step) {
  return step * (force.norm() * std::max(speed_before, speed_after) +
                 torque.norm() * std::max(angular_speed_before, angular_speed_after));
}

std::vector<double> InstabilityScales(const std::vector<BodyEnergySample>& bodies,
                                      const InstabilitySettings& settings) {
  double total_after = 0.0;
  double total_allowance = 0.0;
  for (const BodyEnergySample& body : bodies) {
    total_after += body.energy_after;
    total_allowance += Allowance(body, settings);
  }
  if (!(total_after > total_allowance)) return {};
  // the total is over the sum of the allowances, so at least one body is over its own
  std::vector<double> scales(bodies.size(), 1.0);
  for (size_t i = 0; i < bodies.size(); ++i) {
    const double allowance = Allowance(bodies[i], settings);
    if (bodies[i].energy_after > allowance) {
      scales[i] = std::sqrt(settings.post_correction * allowance / bodies[i].energy_after);
    }
  }
  return scales;
}

}  // namespace lamina::core
