// SPDX-License-Identifier: MIT
// ODE's contact joint as Newton solver rows (newton_solver.h): what getInfo2 of
// ode/src/joints/contact.cpp (ODE 0.16) writes for a dContact, so that the Newton solver and
// dWorldStep solve the same rows. Used by object_islands.cpp.
#pragma once

#include <vector>

#include "core/sim/newton_solver.h"
#include "core/sim/ode_fwd.h"

namespace lamina::core {

/// The rows of ODE's contact joint `contact` between bodies `a` and `b` (null: the fixed world)
/// appended to `rows`, with the bodies' island indices `ia`, `ib` (-1 outside the island: a
/// kinematic body's velocity goes into the right-hand side). World ERP/CFM and the contact
/// parameters are read from `world`; `step` in s. Returns whether ODE swapped the bodies (a
/// null `a`): the rows' first body is then `b`, and its feedback is reported on `b`.
bool ContactJointRows(const dContact& contact, dxBody* a, dxBody* b, int ia, int ib, dxWorld* world,
                      double step, std::vector<NewtonRow>* rows);

}  // namespace lamina::core
