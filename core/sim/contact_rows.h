// SPDX-License-Identifier: MIT
// The contact law as rows: what one contact of a pair asks of ODE's solver, computed without ODE
// (MakeContactRow, pure), and its translation into an ODE contact joint (ToOdeContact). The
// formulas and every difference from Klamp't are in docs/contact-model.md ("Contact response").
//
// - Stiffness shares: the pair pushes with k times its deepest overlap and damps with c, however
//   many points the clustering kept (Klamp't gives every point the full k and c): each contact
//   takes the share w_i/Σw of both by its pressure weight (depth², members summed for a cluster),
//   so the pair's centre of pressure does not depend on the clustering and a point entering or
//   leaving the layer at depth 0 changes nothing. A layer with neither stiffness nor damping
//   pushes with no force at all (no rows).
// - Soft layers rebound as their spring and damper make them: no restitution on top (that would
//   count the rebound twice and pump energy into a body rolling on a tessellated surface).
// - Hard contacts correct a layer overlap no faster than maxCorrectionSpeed, with CFM at most
//   1e-9; at a bouncing impact not at all (the restitution row sets the rebound), and with CFM
//   also at most kBounceRegularization·h/m, so that the rebound loses at most that fraction of
//   its speed whatever the mass and the step (Klamp't's CFM is the world's).
// - Friction: the first direction opposes what friction has to take away (the sliding velocity
//   less the friction anchor's correction), so ODE's per-axis friction becomes isotropic; the
//   anchor's correction is asked on ODE's own axes through motion1/motion2.
// - A soft layer pressed through rests on the rigid geometry under it: a hard "core" row at the
//   core's own depth (depth minus the padding sum) keeps the cores from passing through.
// - Rolling and spinning friction (Lamina's, off by default; Klamp't has none): when the pair's
//   blend is > 0, ODE's dContactRolling rows, angular rows about the two friction axes (bound
//   rolling · N) and the normal (bound spinning · N), N the row's own normal force
//   (dContactApprox1_N). dContactAxisDep keeps the two values apart (with mu2 = mu); an axis
//   that is off gets -1, which ODE 0.16's getInfo1 clamps to 0 without counting a row (0 itself
//   would count a row that getInfo2 never fills). ODE bounds each rolling axis separately, so
//   while the contact rolls rather than slides the friction axes follow the rolling (n × t1 the
//   rolling axis), as they follow the sliding otherwise: the resistance is then ρ N in every
//   direction. Without rolling and spinning the joint is exactly what it was before they
//   existed.
// Units: m, m/s, N/m, N·s/m; normals point from body b into body a; velocities are a minus b.
#pragma once

#include <ode/ode.h>

#include "core/contact/contact.h"
#include "core/contact/surface_blend.h"
#include "core/sim/contact_set.h"

namespace lamina::core {

/// The hard-contact CFM ceiling (the world's CFM when smaller).
inline constexpr double kHardContactCfm = 1e-9;
/// A bouncing row's CFM is at most this times the step times the pair's inverse mass: with CFM
/// the rebound falls short of e·v by CFM·λ, at most this fraction of (1 + e)·v. The fixed ceiling
/// alone took CFM·m·(1 + e)/h: 1.6e-4 of the speed of a 10 kg ball at a 0.125 ms sub-step
/// (2e-6 for 1 kg at 1 ms, where the two agree).
inline constexpr double kBounceRegularization = 1e-6;
/// Sliding slower than this keeps ODE's default friction directions (m/s).
inline constexpr double kSlidingSpeedThreshold = 1e-6;
/// Rolling slower than this does not choose the friction directions (rad/s).
inline constexpr double kRollingRateThreshold = 1e-6;

/// The settings the rows read (SimSettings fields).
struct RowSettings {
  double erp = 0.95;                        ///< the world's ERP
  double cfm = 1e-6;                        ///< the world's CFM
  double max_correction_speed = 0.01;       ///< m/s
  double bounce_velocity_threshold = 0.01;  ///< m/s
};

/// What every contact of one pair shares.
struct PairLaw {
  BlendedSurface surface{};
  SoftContactParams soft{};  ///< the pair's whole stiffness and damping at its deepest overlap
  double floor = 0.0;        ///< smallest weight depth (m)
  double weight_sum = 0.0;   ///< Σ pressure weights of the pair's contacts
  double max_depth = 0.0;    ///< deepest weight depth (m)
  double tolerance = 0.0;    ///< padding sum (m)
  bool pushes = true;        ///< false: a layer with no stiffness and no damping (no rows)
  /// 1/m of the pair's bodies that move, summed (1/kg; 0: not known): bounds the bouncing rows'
  /// CFM (kBounceRegularization)
  double inverse_mass = 0.0;
};

/// One contact joint (and its core row) in ODE's terms, without ODE.
struct ContactRow {
  double mu = 0.0;   ///< Coulomb coefficient (inf allowed)
  double erp = 0.0;  ///< of the normal row
  double cfm = 0.0;
  bool bounce = false;
  double restitution = 0.0;
  double bounce_velocity = 0.0;  ///< closing speed below which it does not bounce (m/s)
  bool has_direction = false;    ///< fdir1 is the first friction direction
  Vec3 fdir1 = Vec3::Zero();
  bool has_motion = false;  ///< the friction rows ask for motion1/motion2 (anchor correction)
  double motion1 = 0.0, motion2 = 0.0;
  bool core = false;  ///< a hard core row at core_depth under this soft contact
  double core_depth = 0.0, core_erp = 0.0, core_cfm = 0.0;
  double rolling = 0.0;   ///< rolling friction, m (0: no rolling rows)
  double spinning = 0.0;  ///< spinning friction, m (0: no spinning row)
};

/// The depth that weighs a contact's share: never quite zero, so every contact keeps a finite law.
double ContactWeightDepth(double depth, double tolerance);
/// The world's ERP, limited so that an overlap of `depth` is pushed out at most at
/// `max_correction_speed`.
double HardContactErp(double depth, double step, const RowSettings& settings);
PairLaw MakePairLaw(const ContactPair& pair, const BlendedSurface& surface, double step);
/// The row of `contact` of a pair with law `law`; `relative_velocity` is a's velocity less b's at
/// the contact point, `anchor_velocity` the friction anchor's correction (friction_anchors.h),
/// `relative_angular_velocity` a's angular velocity less b's (rad/s; read only with rolling
/// friction).
ContactRow MakeContactRow(const Contact& contact, const PairLaw& law, const Vec3& relative_velocity,
                          const Vec3& anchor_velocity, double step, const RowSettings& settings,
                          const Vec3& relative_angular_velocity = Vec3::Zero());
/// The ODE contact joint of a row (and, with `core`, of its core row).
dContact ToOdeContact(const ContactRow& row, const Contact& contact, bool core = false);

}  // namespace lamina::core
