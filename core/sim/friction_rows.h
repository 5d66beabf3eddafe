// SPDX-License-Identifier: MIT
// Joint dry-friction rows kept out of dWorldStep's pivoting when their answer is known. A joint
// with dry friction has a motor row of velocity 0 bounded by its friction torque F (ode_robot.h:
// J v' = 0 − cfm·λ, |λ| ≤ F, cfm 1e-9). ODE's Dantzig LCP factorizes every unbounded row in one
// block and takes each bounded row in one pivot at a time (servo_bounds.h), so on a humanoid the
// 30 friction rows cost as much as its contacts: HRP-2 standing on a plane steps 1.6× faster with
// no joint friction at all. A friction row has one of two known answers for most steps:
// - sticking: the joint holds, |λ| < F. The same step without the bound gives exactly the same
//   answer, so the row goes unbounded when the force it would apply at the joint's current rate
//   is well inside F (kUnboundedFrictionFraction, as for servos);
// - sliding: the joint keeps turning the same way, λ = −F·sign(rate). The row then applies
//   exactly its bound, the same as a torque of −F·sign(rate) applied to the joint, so the row is
//   left out and that torque applied instead, when the force at the current rate is far beyond
//   F (kExplicitFrictionFactor).
// Either guess is checked after the step from the joint's rate (the row's law gives the force it
// would have applied, −rate/cfm); a guess that failed (the joint slipped, or stopped or turned
// back) makes the row bounded, for the retaken sub-step and kFrictionGuessHoldoff accepted steps
// after it, and the sub-step is retaken from its start (Simulator::TrySubStep), so an accepted
// step is always a solution of the bounded LCP.
//
// Units: rates in rad/s (m/s for sliders), forces in N·m (N). Sign: the joint's own (the rate and
// force that increase q). Only robots dWorldStep itself solves use these rows (one touching a free
// object, held by a world joint, dragged): the exact solver's direct solve (direct_solver.h) and
// the Newton solver take a bounded row at no extra cost (with guesses the Newton solver ran HRP-2
// on rough ground 1.19× slower, from retakes), and QuickStep keeps its rows bounded. Not in
// Klamp't, whose friction rows are always bounded.
#pragma once

namespace lamina::core {

enum class FrictionRowMode {
  kBounded,    ///< the row as it is: |λ| ≤ F, pivoted by the LCP
  kUnbounded,  ///< the row without its bound (the joint is expected to hold)
  kExplicit,   ///< no row: a torque of −F·sign(rate) (the joint is expected to keep sliding)
};

/// What one joint's friction row was given for a step, to check it afterwards.
struct FrictionCommand {
  int link = -1;
  double fmax = 0.0;  ///< F, N·m or N
  double cfm = 0.0;   ///< the row's CFM
  double rate = 0.0;  ///< the joint's rate at the step's start
  FrictionRowMode mode = FrictionRowMode::kBounded;
};

/// A row goes unbounded when the force at the current rate is below this fraction of F.
inline constexpr double kUnboundedFrictionFraction = 0.5;
/// A row becomes a torque when the force at the current rate is beyond this multiple of F.
inline constexpr double kExplicitFrictionFactor = 2.0;

/// After a guess failed, the row stays bounded for the retaken sub-step and this many accepted
/// steps: a joint whose load jumps from step to step (a humanoid on rough ground: 9000 failed
/// guesses in 2000 steps without it) would otherwise pay a retake on most steps.
inline constexpr int kFrictionGuessHoldoff = 50;

/// The force the row of bound `fmax` and CFM `cfm` applies at the joint rate `rate`, unbounded:
/// −rate / cfm.
double FrictionRowForce(double cfm, double rate);

/// How to give the row of bound `fmax` (> 0, finite) and CFM `cfm` (> 0) at the joint rate
/// `rate_now` to the coming step. Anything else (an infinite or zero bound) stays bounded.
FrictionRowMode ChooseFrictionRow(double fmax, double cfm, double rate_now);

/// The torque a row given as `mode` is replaced by (−F·sign(rate_now) for kExplicit, else 0).
double ExplicitFrictionTorque(FrictionRowMode mode, double fmax, double rate_now);

/// One row standing for two unbounded rows on the same joint axis: the servo's (target rate
/// `velocity`, CFM `servo_cfm`) and a holding friction row's (target 0, CFM `friction_cfm`). Each
/// row's force is (c − J v)/cfm, so their sum is (c_s/cfm_s) − J v (1/cfm_s + 1/cfm_f): the force
/// of one row of CFM cfm_s·cfm_f/(cfm_s + cfm_f) and target rate velocity·cfm_f/(cfm_s + cfm_f),
/// at every v. Under dWorldStep a humanoid's unbounded friction rows are a seventh of its rows and,
/// the LCP being cubic in the rows, about 40 % of its solve (HRP-2 standing); merged, the step
/// has one row per joint axis for both. Both CFMs >= 0 and not both 0.
struct MergedRow {
  double velocity = 0.0;  ///< rad/s (m/s)
  double cfm = 0.0;
};
MergedRow MergeServoAndFrictionRows(double velocity, double servo_cfm, double friction_cfm);

/// Whether the step that took the joint from `rate_now` to `rate_after` is the bounded row's
/// answer: for kUnbounded the force stayed within F, for kExplicit the row would have applied
/// exactly −F·sign(rate_now); 1e-9 relative slack for the rounding of the solve. False for a
/// non-finite rate; true for kBounded.
bool FrictionGuessHeld(FrictionRowMode mode, double fmax, double cfm, double rate_now,
                       double rate_after);

}  // namespace lamina::core
