// SPDX-License-Identifier: MIT
// What MuJoCo and Bullet are given of an accuracy scene (lamina-peers, tests/bench/peers): the
// scene's world description reduced to what both engines take the same way, in SI units and world
// coordinates. A scene that needs more (meshes, robots, soft or rolling contact, joint limits or
// friction) is refused with the reason, and the peers leave it out.
//
// Differences from the Lamina world they come from, all stated in docs/accuracy.md "Peers":
// - The boundary layer becomes solid: a shape grows by its body's padding (a box's half sizes, a
//   sphere's radius), so the peers' surfaces are where Lamina's padded surfaces touch; a
//   preshrunk body's shape stays as described, which is where its padded surface lies. A padded
//   box is rounded at its edges in Lamina and sharp here.
// - Each touching pair gets Lamina's blended surface (BlendSurfaces: the harmonic mean of the
//   frictions, the mean of the restitutions) exactly, not the engine's own combination rule.
#pragma once

#include <string>
#include <vector>

#include "core/math_types.h"
#include "core/model/world_desc.h"

namespace lamina::peers {

using core::Mat3;
using core::Pose;
using core::Vec3;

/// A box or a sphere of a body, in the body frame, already grown by the body's padding.
struct PeerShape {
  enum class Kind { kBox, kSphere } kind = Kind::kBox;
  Pose pose = Pose::Identity();   ///< centre and axes in the body frame
  Vec3 half_size = Vec3::Zero();  ///< box, m
  double radius = 0.0;            ///< sphere, m
};

/// A terrain (static) or a rigid object (dynamic), with the object's frame as its frame.
struct PeerBody {
  std::string name;
  bool dynamic = false;
  int object = -1;               ///< index in the world's objects; -1 for a terrain
  Pose pose = Pose::Identity();  ///< body (object) frame in the world
  double mass = 0.0;             ///< kg (dynamic only)
  Vec3 com = Vec3::Zero();       ///< in the body frame, m
  Mat3 inertia = Mat3::Zero();   ///< about the COM, body axes, kg·m²
  core::Twist velocity;          ///< initial: of the frame origin, and angular, world
  core::SurfaceDesc surface;
  std::vector<PeerShape> shapes;
};

/// A hinge between a body and its parent (another dynamic body, or the world: -1).
struct PeerHinge {
  int body = -1;              ///< index in PeerWorld::bodies (dynamic)
  int parent = -1;            ///< index in PeerWorld::bodies, or -1 for the world
  Vec3 point = Vec3::Zero();  ///< on the axis, world, at the initial poses
  Vec3 axis = Vec3::UnitY();  ///< world, unit
};

/// A pair of bodies that may touch, with Lamina's blended surface.
struct PeerPair {
  int a = -1, b = -1;  ///< indices in PeerWorld::bodies
  double friction = 0.5;
  double restitution = 0.0;
};

struct PeerWorld {
  std::vector<PeerBody> bodies;  ///< the terrains, then the objects in the world's order
  std::vector<PeerHinge> hinges;
  std::vector<PeerPair> pairs;  ///< every pair that may collide
  Vec3 gravity = Vec3(0, 0, -9.8);
  double bounce_velocity_threshold = 0.01;  ///< m/s: slower contacts do not bounce
};

/// The peers' version of `world`; false with `why` saying what neither engine is given here.
bool BuildPeerWorld(const core::WorldDesc& world, PeerWorld* peer, std::string* why);

/// Object `object`'s index in `peer.bodies`.
int PeerBodyOfObject(const PeerWorld& peer, int object);

}  // namespace lamina::peers
