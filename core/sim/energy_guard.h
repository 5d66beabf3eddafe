// SPDX-License-Identifier: MIT
// Instability detection: kinetic energy that appears from nowhere within one step. Energy moves
// between bodies through contact and comes in through gravity and applied forces; a step whose
// total kinetic energy grows beyond what those can supply (plus a margin) has blown up, and the
// bodies that gained the energy are slowed down.
//
// Differences from Klamp't (klampt-internals §2.5): the kinetic energy is ½ m v² + ½ ωᵀ I ω
// (Klamp't drops the ½); the test is on the total energy of the free bodies with the work of
// gravity and applied forces allowed for, so a heavy body handing its momentum to a light one in an
// impact is not an instability (Klamp't tests every body alone and fires on heavyblocktest); only
// the bodies that gained too much are slowed (Klamp't scales every body in the world).
#pragma once

#include <vector>

#include "core/math_types.h"

namespace lamina::core {

struct InstabilitySettings {
  double growth_factor = 1.5;    ///< energy may grow by this factor in one step...
  double energy_per_kg = 1.0;    ///< ...plus this much per kilogram of mass (J/kg)
  double post_correction = 0.8;  ///< a corrected body keeps this fraction of its allowance
};

/// One free body over one step.
struct BodyEnergySample {
  double mass = 0.0;           ///< kg
  double energy_before = 0.0;  ///< kinetic energy at the start of the step (J)
  double energy_after = 0.0;   ///< kinetic energy at the end of the step (J)
  /// energy the body may gain from outside (J): an upper bound of the work of gravity and
  /// applied forces, plus what its contacts may legitimately release (layer correction, springs)
  double external_work = 0.0;
};

/// ½ m |v|² + ½ ωᵀ I ω, with `inertia` about the COM in world axes.
double KineticEnergy(double mass, const Mat3& inertia, const Vec3& velocity,
                     const Vec3& angular_velocity);

/// Upper bound of the work that a constant force and torque can do in `step` seconds on a body
/// whose speeds at the two ends of the step are given: h (|F| max|v| + |τ| max|ω|).
double ExternalWorkBound(const Vec3& force, const Vec3& torque, double speed_before,
                         double speed_after, double angular_speed_before,
                         double angular_speed_after, double step);

/// Velocity scale per body (1 = untouched): empty when the step is stable. When the total energy
/// exceeds the sum of the allowances growth·before + energy_per_kg·mass + external work, every
/// body over its own allowance (there is at least one) is scaled down to post_correction of it.
std::vector<double> InstabilityScales(const std::vector<BodyEnergySample>& bodies,
                                      const InstabilitySettings& settings = {});

}  // namespace lamina::core
