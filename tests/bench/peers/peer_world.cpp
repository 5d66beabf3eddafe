// SPDX-License-Identifier: MIT
#include "tests/bench/peers/peer_world.h"

#include <cmath>

#include "core/contact/surface_blend.h"

namespace lamina::peers {
namespace {

using core::GeometryDesc;
using core::GeometryKind;
using core::PrimitiveType;

bool Refuse(const std::string& text, std::string* why) {
  *why = text;
  return false;
}

// The primitive of `geometry` in the body frame, grown by `padding`; false for anything else.
bool ShapeOf(const GeometryDesc& geometry, double padding, PeerShape* shape, std::string* why) {
  if (geometry.kind != GeometryKind::kPrimitive)
    return Refuse(
        "a mesh or point cloud (the peers are given primitives only: MuJoCo would take a mesh's "
        "convex hull)",
        why);
  const core::Primitive& p = geometry.primitive;
  const core::Affine placed = geometry.Matrix() * p.pose;
  const double scale = geometry.scale.x();
  const bool uniform = (geometry.scale.array() == scale).all();
  if (!uniform && !(p.type == PrimitiveType::kBox && p.pose.linear().isIdentity(1e-12)))
    return Refuse("a primitive scaled unevenly", why);
  const Mat3 linear = geometry.transform.linear();
  shape->pose = Pose::Identity();
  shape->pose.translation() = placed.translation();
  shape->pose.linear() = linear * p.pose.linear();
  const double grow = padding + geometry.margin;  // 0 padding for a preshrunk body
  if (p.type == PrimitiveType::kBox) {
    shape->kind = PeerShape::Kind::kBox;
    shape->half_size = geometry.scale.cwiseProduct(p.size) / 2 + Vec3::Constant(grow);
    return true;
  }
  if (p.type == PrimitiveType::kSphere) {
    shape->kind = PeerShape::Kind::kSphere;
    shape->radius = scale * p.radius + grow;
    return true;
  }
  return Refuse(std::string("a ") + p.TypeName(), why);
}

bool AddBody(const std::string& name, const GeometryDesc& geometry, const core::BodySimParams& sim,
             PeerBody* body, std::string* why) {
  body->name = name;
  body->surface = sim.surface;
  if (std::isfinite(sim.surface.stiffness) || std::isfinite(sim.surface.damping))
    return Refuse(name + ": a soft surface", why);
  if (sim.surface.rolling_friction > 0 || sim.surface.spinning_friction > 0)
    return Refuse(name + ": rolling or spinning friction", why);
  if (geometry.empty()) return true;
  // a preshrunk body's padded surface is its geometry as described
  const double padding = sim.preshrink == core::Preshrink::kNone ? sim.padding : 0.0;
  PeerShape shape;
  if (!ShapeOf(geometry, padding, &shape, why)) return Refuse(name + ": " + *why, why);
  body->shapes.push_back(shape);
  return true;
}

bool AddTerrains(const core::WorldDesc& world, PeerWorld* peer, std::string* why) {
  for (const core::TerrainDesc& terrain : world.terrains) {
    PeerBody body;
    if (!AddBody(terrain.name, terrain.geometry, terrain.sim, &body, why)) return false;
    peer->bodies.push_back(body);
  }
  return true;
}

bool AddObjects(const core::WorldDesc& world, PeerWorld* peer, std::string* why) {
  for (std::size_t i = 0; i < world.objects.size(); ++i) {
    const core::RigidObjectDesc& object = world.objects[i];
    PeerBody body;
    if (!AddBody(object.name, object.geometry, object.sim, &body, why)) return false;
    body.dynamic = true;
    body.object = static_cast<int>(i);
    body.pose = object.pose;
    body.mass = object.mass;
    body.com = object.com;
    body.inertia = object.inertia;
    body.velocity = object.initial_velocity;
    peer->bodies.push_back(body);
  }
  return true;
}

bool AddHinge(const core::WorldJointDesc& joint, PeerWorld* peer, std::string* why) {
  if (joint.type != core::WorldJointType::kHinge) return Refuse("a fixed or slider joint", why);
  if (std::isfinite(joint.min) || std::isfinite(joint.max) || joint.friction != 0.0)
    return Refuse("a hinge with limits or friction", why);
  PeerHinge hinge;
  hinge.point = joint.point;
  hinge.axis = joint.axis.normalized();
  const core::WorldJointBody& first = joint.bodies.at(0);
  if (first.kind != core::WorldId::Kind::kRigidObject) return Refuse("a robot's joint", why);
  hinge.body = PeerBodyOfObject(*peer, first.index);
  if (joint.bodies.size() > 1 && joint.bodies[1].kind == core::WorldId::Kind::kRigidObject)
    hinge.parent = PeerBodyOfObject(*peer, joint.bodies[1].index);
  for (const PeerHinge& other : peer->hinges) {
    if (other.body == hinge.body) return Refuse("an object held by two joints", why);
  }
  peer->hinges.push_back(hinge);
  return true;
}

bool Joined(const PeerWorld& peer, int a, int b) {
  for (const PeerHinge& hinge : peer.hinges) {
    if ((hinge.body == a && hinge.parent == b) || (hinge.body == b && hinge.parent == a))
      return true;
  }
  return false;
}

void AddPair(int a, int b, PeerWorld* peer) {
  const core::BlendedSurface blend =
      core::BlendSurfaces(peer->bodies[a].surface, peer->bodies[b].surface);
  peer->pairs.push_back({a, b, blend.friction, blend.restitution});
}

// Terrain–object pairs always; object–object pairs when the world lets objects collide and no
// joint joins them.
void AddPairs(const core::WorldDesc& world, PeerWorld* peer) {
  const int count = static_cast<int>(peer->bodies.size());
  for (int a = 0; a < count; ++a) {
    for (int b = a + 1; b < count; ++b) {
      const PeerBody &first = peer->bodies[a], &second = peer->bodies[b];
      if (first.shapes.empty() || second.shapes.empty()) continue;
      if (!first.dynamic && !second.dynamic) continue;
      if (first.dynamic && second.dynamic &&
          (!world.settings.rigid_object_collisions || Joined(*peer, a, b)))
        continue;
      AddPair(a, b, peer);
    }
  }
}

}  // namespace

int PeerBodyOfObject(const PeerWorld& peer, int object) {
  for (std::size_t i = 0; i < peer.bodies.size(); ++i) {
    if (peer.bodies[i].object == object) return static_cast<int>(i);
  }
  return -1;
}

bool BuildPeerWorld(const core::WorldDesc& world, PeerWorld* peer, std::string* why) {
  *peer = PeerWorld{};
  if (!world.robots.empty()) return Refuse("a robot", why);
  if (!AddTerrains(world, peer, why) || !AddObjects(world, peer, why)) return false;
  for (const core::WorldJointDesc& joint : world.joints) {
    if (!AddHinge(joint, peer, why)) return false;
  }
  AddPairs(world, peer);
  peer->gravity = world.settings.gravity;
  peer->bounce_velocity_threshold = world.settings.bounce_velocity_threshold;
  return true;
}

}  // namespace lamina::peers
