// SPDX-License-Identifier: MIT
#include "tests/common/scene_builders.h"

namespace lamina::test {

core::TerrainDesc PlaneTerrain(double friction, double restitution) {
  core::TerrainDesc ground;
  ground.name = "ground";
  ground.geometry.kind = core::GeometryKind::kPrimitive;
  ground.geometry.primitive = core::Primitive::Plane();
  ground.sim = core::DefaultTerrainSimParams();
  ground.sim.surface.friction = friction;
  ground.sim.surface.restitution = restitution;
  return ground;
}

core::RigidObjectDesc BoxObject(double side, double mass, const core::Vec3& position) {
  core::RigidObjectDesc box;
  box.name = "box";
  box.geometry.kind = core::GeometryKind::kPrimitive;
  box.geometry.primitive = core::Primitive::Box(core::Vec3::Constant(side));
  box.mass = mass;
  box.inertia = core::Mat3::Identity() * (mass * side * side / 6.0);
  box.pose.translation() = position;
  box.sim = core::DefaultObjectSimParams();
  return box;
}

core::RigidObjectDesc SphereObject(double radius, double mass, const core::Vec3& position) {
  core::RigidObjectDesc sphere;
  sphere.name = "sphere";
  sphere.geometry.kind = core::GeometryKind::kPrimitive;
  sphere.geometry.primitive = core::Primitive::Sphere(radius);
  sphere.mass = mass;
  sphere.inertia = core::Mat3::Identity() * (0.4 * mass * radius * radius);
  sphere.pose.translation() = position;
  sphere.sim = core::DefaultObjectSimParams();
  return sphere;
}

}  // namespace lamina::test
