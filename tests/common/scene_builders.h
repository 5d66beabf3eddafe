// SPDX-License-Identifier: MIT
// Small worlds built in code for physics tests: a ground plane, boxes and spheres with the
// default object surface.
#pragma once

#include "core/model/world_desc.h"

namespace lamina::test {

/// The z <= 0 half-space as a rigid terrain with the given friction and restitution.
core::TerrainDesc PlaneTerrain(double friction, double restitution);
/// A cube primitive of full side `side`, mass `mass` and the matching inertia, at `position`.
core::RigidObjectDesc BoxObject(double side, double mass, const core::Vec3& position);
/// A sphere primitive of radius `radius`, solid inertia, at `position`.
core::RigidObjectDesc SphereObject(double radius, double mass, const core::Vec3& position);

}  // namespace lamina::test
