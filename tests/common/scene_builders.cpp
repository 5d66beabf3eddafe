// SPDX-License-Identifier: MIT
#include "tests/common/scene_builders.h"

#include <utility>

#include <gtest/gtest.h>

#include "core/io/load_context.h"
#include "core/io/robot_file.h"

namespace lamina::test {

core::GeometryDesc PrimitiveGeometry(const core::Primitive& primitive) {
  core::GeometryDesc geometry;
  geometry.kind = core::GeometryKind::kPrimitive;
  geometry.primitive = primitive;
  return geometry;
}

core::GeometryDesc MeshGeometry(std::shared_ptr<const core::TriangleMesh> mesh,
                                const core::Vec3& scale) {
  core::GeometryDesc geometry;
  geometry.kind = core::GeometryKind::kMesh;
  geometry.mesh = std::move(mesh);
  geometry.scale = scale;
  return geometry;
}

core::TerrainDesc PlaneTerrain(double friction, double restitution) {
  core::TerrainDesc ground;
  ground.name = "ground";
  ground.geometry = PrimitiveGeometry(core::Primitive::Plane());
  ground.sim = core::DefaultTerrainSimParams();
  ground.sim.surface.friction = friction;
  ground.sim.surface.restitution = restitution;
  return ground;
}

core::RigidObjectDesc BoxObject(double side, double mass, const core::Vec3& position) {
  core::RigidObjectDesc box;
  box.name = "box";
  box.geometry = PrimitiveGeometry(core::Primitive::Box(core::Vec3::Constant(side)));
  box.mass = mass;
  box.inertia = core::Mat3::Identity() * (mass * side * side / 6.0);
  box.pose.translation() = position;
  box.sim = core::DefaultObjectSimParams();
  return box;
}

core::RigidObjectDesc SphereObject(double radius, double mass, const core::Vec3& position) {
  core::RigidObjectDesc sphere;
  sphere.name = "sphere";
  sphere.geometry = PrimitiveGeometry(core::Primitive::Sphere(radius));
  sphere.mass = mass;
  sphere.inertia = core::Mat3::Identity() * (0.4 * mass * radius * radius);
  sphere.pose.translation() = position;
  sphere.sim = core::DefaultObjectSimParams();
  return sphere;
}

core::WorldDesc WorldWithRobot(const std::string& rob_text) {
  core::Diagnostics diagnostics;
  core::MeshCache meshes;
  core::LoadContext context{diagnostics, meshes};
  core::WorldDesc world;
  world.robots.emplace_back();
  EXPECT_TRUE(core::ParseRob(rob_text, "/virtual/robot.rob", context, &world.robots[0]))
      << diagnostics.FormatAll();
  return world;
}

core::WorldDesc PendulumWorld(const std::string& extra, double q0) {
  return WorldWithRobot(
      "links \"pendulum\"\nparents -1\nTParent 1 0 0  0 1 0  0 0 1  0 0 1\naxis 0 1 0\n"
      "jointtype r\nmass 2\ncom 0 0 -0.5\ninertia 0.01 0 0  0 0.01 0  0 0 0.01\nq " +
      std::to_string(q0) + "\njoint normal 0\ndriver normal 0\n" + extra);
}

}  // namespace lamina::test
