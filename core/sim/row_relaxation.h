// SPDX-License-Identifier: MIT
// Projected Gauss–Seidel over an island's rows (the law of newton_solver.h, the method of ODE's
// QuickStep): the fallback of an island the Newton solver did not settle and that is too large for
// dWorldStep's dense LCP (object_islands.h kMostHandBackRows).
//
// Each sweep visits the rows in order and moves one row's force λ_i to where its law holds with
// the others fixed:
//   λ_i ← clamp(λ_i + (c_i − J_i v − cfm_i λ_i) / (h J_i M⁻¹ J_iᵀ + cfm_i), lo_i, hi_i),
//   v ← v + h M⁻¹ J_iᵀ (change of λ_i),
// a friction row's bounds its coefficients times |λ| of its normal row as it is then. Whatever the
// number of sweeps, every force lies inside its bounds and v = v_free + h M⁻¹ Σ J_iᵀ λ_i: the
// answer is one the contacts can give (no pull, friction within its cone), only not the exact
// one where the sweeps have not converged (heavy on light, long stacks: QuickStep's weakness).
// An unconverged Newton iterate is no such answer: its wrench M (v − v_free)/h need not be any
// Jᵀ λ with λ in its bounds (one Newton step a time step on a settling 210-box pyramid: boxes sank
// 5.8 mm and the top one moved 2.5 cm in 40 steps; with 50 sweeps from no force instead, 2e-5 m
// and 6e-5 m). Sweeps converge slowly on redundant rows (a face's four contacts: 1.4e-4 m/s
// from the exact answer after 10 sweeps, 7.9e-6 after 100).
//
// Units: those of newton_solver.h (m, kg, s, N).
#pragma once

#include <vector>

#include "core/sim/newton_solver.h"

namespace lamina::core {

/// Sweeps `sweeps` times over `rows` (newton_solver.h's NewtonRow: bounds, friction rows after
/// their normal's index or before it) from no force: not from an unconverged Newton iterate's,
/// clamp(x/cfm) on rows of cfm 1e-9, which can be far off (from those, a 210-box pyramid given
/// one Newton step a time step flew apart). Writes result->force (N per row) and
/// result->velocity (v_free + h M⁻¹ Jᵀ λ per body); result->converged is false and
/// result->iterations the sweeps taken (the answer is approximate). A row whose Jacobian is zero
/// on both bodies and whose cfm is 0 keeps no force.
void RelaxRows(const std::vector<NewtonBody>& bodies, const std::vector<NewtonRow>& rows,
               double step, int sweeps, NewtonResult* result);

}  // namespace lamina::core
