// SPDX-License-Identifier: MIT
// Small worlds built in code for physics tests: a ground plane, boxes and spheres with the
// default object surface.
#pragma once

#include <memory>

#include "core/model/world_desc.h"

namespace lamina::test {

/// A geometry made of `primitive`, unscaled and in place.
core::GeometryDesc PrimitiveGeometry(const core::Primitive& primitive);
/// A geometry made of `mesh` (shared, not copied) scaled by `scale`.
core::GeometryDesc MeshGeometry(std::shared_ptr<const core::TriangleMesh> mesh,
                                const core::Vec3& scale = core::Vec3::Ones());

/// The z <= 0 half-space as a rigid terrain with the given friction and restitution.
core::TerrainDesc PlaneTerrain(double friction, double restitution);
/// A cube primitive of full side `side`, mass `mass` and the matching inertia, at `position`.
core::RigidObjectDesc BoxObject(double side, double mass, const core::Vec3& position);
/// A sphere primitive of radius `radius`, solid inertia, at `position`.
core::RigidObjectDesc SphereObject(double radius, double mass, const core::Vec3& position);

}  // namespace lamina::test
