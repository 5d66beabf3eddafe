// SPDX-License-Identifier: MIT
// The contact law of a pair of bodies: blending the two bodies' surfaces (restitution, friction,
// rolling and spinning friction, boundary-layer stiffness and damping) into one, and turning a
// stiffness and damping into the ERP/CFM of an ODE soft contact for a given step.
// docs/contact-model.md ("Blending two surfaces") states the rules and where they differ from
// Klamp't.
#pragma once

#include "core/model/world_desc.h"

namespace lamina::core {

/// The contact law of one pair of surfaces.
struct BlendedSurface {
  double restitution;     ///< coefficient of restitution
  double friction;        ///< Coulomb coefficient of the friction cone
  double stiffness;       ///< N/m; inf = rigid contact
  double damping;         ///< N·s/m; inf = rigid contact
  double rolling = 0.0;   ///< rolling friction, m (torque ≤ rolling · N in the contact plane)
  double spinning = 0.0;  ///< spinning friction, m (torque ≤ spinning · N about the normal)
};

/// Blends two surfaces whose values are >= 0 (inf allowed except for restitution):
/// - restitution: the arithmetic mean (ea + eb) / 2;
/// - friction: the harmonic mean 2 μa μb / (μa + μb); 0 if either side is 0; 2 μb when μa is inf
///   (the limit); inf when both are. No 0.707 factor: the friction cone keeps its μ;
/// - stiffness and damping: the two boundary layers act in series, k = 1 / (1/ka + 1/kb): an
///   infinite side drops out (exactly), two equal layers give k / 2, either side 0 gives 0, both
///   inf give inf. The same rule for the damping c;
/// - rolling and spinning friction (Lamina's; finite): the harmonic mean like friction, 0 if
///   either side is 0, so one body without rolling resistance (every body by default) turns it
///   off for the pair.
/// Symmetric: BlendSurfaces(a, b) and BlendSurfaces(b, a) are bitwise equal.
BlendedSurface BlendSurfaces(const SurfaceDesc& a, const SurfaceDesc& b);

/// How ODE should treat a contact: a soft constraint with its own ERP and CFM, or a hard one.
struct SoftContactParams {
  double erp;  ///< error reduction parameter in [0, 1]; 0 when not soft
  double cfm;  ///< constraint force mixing, m/N·s (ODE's units for a contact row); 0 when not soft
  bool soft;   ///< false: a hard contact using the world's global ERP and CFM
};

/// ODE soft-contact ERP/CFM for step h (s, > 0) from stiffness k (N/m) and damping c (N·s/m):
/// erp = h k / (h k + c), cfm = 1 / (h k + c), which makes the contact row the spring-damper
/// force k x - c v integrated implicitly (ODE manual, "How To Use ERP and CFM").
/// soft = false (a hard contact) when k is inf, and also when c is inf: a damper that cannot move
/// at any speed is rigid (Klamp't computes erp = 0, cfm = 0 there instead: a hard contact that
/// never corrects penetration). k = 0 with c = 0 exerts no force: erp = 0, cfm = inf, and the
/// caller should create no contact joint for it (ODE cannot take an infinite CFM).
SoftContactParams SoftContact(double stiffness, double damping, double step);

}  // namespace lamina::core
