// SPDX-License-Identifier: MIT
// Mass properties from geometry ("automass"): centre of mass and inertia of a solid, of a
// thin shell, or of a blend of the two, for a given total mass.
#pragma once

#include "core/geometry/geometry_desc.h"
#include "core/math_types.h"

namespace lamina::core {

struct MassProperties {
  Vec3 com = Vec3::Zero();      ///< m, in the frame of the input
  Mat3 inertia = Mat3::Zero();  ///< about the COM, kg·m²
  bool valid = false;           ///< false for empty or degenerate geometry
};

/// `surface_fraction` 0 = uniform solid, 1 = uniform thin shell (Klamp't's default for .rob
/// `automass`), in between a blend: COM and covariance are f·shell + (1-f)·solid.
/// The mesh must be closed and outward-oriented for the solid part to be right.
MassProperties ComputeMassProperties(const TriangleMesh& mesh, double mass,
                                     double surface_fraction);
/// Same for a body's geometry (scale and transform applied; primitives analytically).
MassProperties ComputeMassProperties(const GeometryDesc& geometry, double mass,
                                     double surface_fraction);

}  // namespace lamina::core
