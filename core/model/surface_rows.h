// SPDX-License-Identifier: MIT
// The parameter table's rows of a body's contact surface (kRestitution, kFriction,
// kRollingFriction, kSpinningFriction, kStiffness, kDamping), each with the SurfaceDesc member it
// reads and writes: for code that holds a SurfaceDesc itself (the Python module's
// SurfaceParameters, Simulator::SetBodySurface) and must still take names, help and rules from
// the table rather than spell them; found by the rows' getters, so no key is spelled.
#pragma once

#include <span>

#include "core/model/params.h"

namespace lamina::core {

struct SurfaceRow {
  const ParamSpec* spec;
  double SurfaceDesc::*member;
};

/// The surface rows in table order (core/io's SurfaceRows lists their specs).
std::span<const SurfaceRow> SurfaceMembers();

}  // namespace lamina::core
