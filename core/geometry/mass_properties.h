// SPDX-License-Identifier: MIT
// Mass properties from geometry ("automass"): centre of mass and inertia of a solid, of a
// thin shell, or of a blend of the two, for a given total mass; and of a body made of rigid parts
// (welded links, mounted meshes): the parallel-axis theorem, once.
#pragma once

#include <vector>

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
/// Same for a body's geometry (scale and transform applied; primitives analytically). A point
/// cloud has neither volume nor area: as in Klamp't, every point carries an equal share of the
/// mass (`surface_fraction` is ignored); invalid when its points are collinear (or absent),
/// since then the inertia about their line is zero.
MassProperties ComputeMassProperties(const GeometryDesc& geometry, double mass,
                                     double surface_fraction);

/// Inertia about a point `d` away from the centre of mass (kg·m²): I + m (|d|² 1 − d dᵀ).
Mat3 ShiftInertia(const Mat3& inertia_at_com, double mass, const Vec3& d);

/// One rigid part of a composite body.
struct MassPart {
  double mass = 0.0;             ///< kg
  Vec3 com = Vec3::Zero();       ///< in the part's frame, m
  Mat3 inertia = Mat3::Zero();   ///< about its COM, the part's axes, kg·m²
  Pose pose = Pose::Identity();  ///< the part's frame in the composite's frame
};

/// The composite of `parts`: total mass, its centre of mass and inertia about it in the
/// composite's frame (exact: rotated inertias plus the parallel-axis terms). `valid` is false
/// (and com the origin) when the parts have no mass.
struct CompositeMass {
  double mass = 0.0;
  MassProperties properties;
};
CompositeMass CombineMass(const std::vector<MassPart>& parts);

}  // namespace lamina::core
