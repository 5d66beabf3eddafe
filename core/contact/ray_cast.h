// SPDX-License-Identifier: MIT
// Ray casting against one collision geometry, for laser range sensors: the distance along a
// ray to where it first meets the geometry's surface. Pure and exact: analytic intersections
// for primitives (slabs and quadratics in the primitive's own frame), Möller–Trumbore on every
// triangle of a mesh whose bounds the ray crosses. Allocates nothing; safe to call from any
// thread.
//
// Conventions:
//  - Units are metres; the ray is given in the world frame and the geometry is placed by the
//    pose of its body frame in the world (the frame of CollisionGeometry::mesh() and
//    primitive(); a primitive's own pose, which includes the geometry placement, is applied on
//    top).
//  - The geometry itself is hit: no padding, and not the geometry's margin().
//  - Primitives are closed solids (a plane is the half-space below it): touching the surface
//    counts as a hit (a tangent ray reads the distance of the touching point), and a ray that
//    starts inside or on the surface reads 0 (a laser inside a solid sees nothing), never the
//    distance to where it leaves.
//  - Meshes need not be closed, so they have no inside: they are two-sided surfaces, hit from
//    either side of each triangle. A ray that starts inside a closed mesh reads the distance to
//    the wall it leaves through; a ray in the plane of a triangle does not hit that triangle.
//  - Point clouds have no surface (their points have no size), so every ray misses them: a
//    laser sees through a point cloud.
#pragma once

#include "core/contact/collision_geometry.h"
#include "core/math_types.h"

namespace lamina::core {

/// The smallest distance t in [0, max_distance] (m, both ends included) at which the ray
/// origin + t * direction meets `geometry` placed at X_W (body frame -> world), or +infinity
/// when it does not (misses, the surface lies behind the origin or beyond max_distance).
/// `origin` and `direction` are in the world frame; `direction` should be a unit vector and is
/// normalized here, so its length does not matter. A zero or non-finite direction, or a
/// negative max_distance, gives +infinity. 0 when the origin is inside a primitive or on its
/// surface (see the conventions above).
double RayCast(const CollisionGeometry& geometry, const Pose& X_W, const Vec3& origin,
               const Vec3& direction, double max_distance);

}  // namespace lamina::core
