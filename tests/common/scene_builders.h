// SPDX-License-Identifier: MIT
// Small worlds built in code for physics tests: a ground plane, boxes and spheres with the
// default object surface.
#pragma once

#include <memory>
#include <string>

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
/// A world holding one robot parsed from `.rob` text (the test fails if it does not parse).
core::WorldDesc WorldWithRobot(const std::string& rob_text);
/// A pendulum robot alone: one link hinged to the world at (0, 0, 1) about y, 2 kg with its
/// centre of mass 0.5 m below the pivot at q = 0 (0.01 kg·m² about it), one normal driver;
/// `extra` adds .rob statements (gains, limits, friction).
core::WorldDesc PendulumWorld(const std::string& extra, double q0 = 0.0);
/// A sphere primitive of radius `radius`, solid inertia, at `position`.
core::RigidObjectDesc SphereObject(double radius, double mass, const core::Vec3& position);

}  // namespace lamina::test
