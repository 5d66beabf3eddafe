// SPDX-License-Identifier: MIT
#include "core/geometry/tessellate.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace lamina::core {

namespace {

// A point of a profile curve in the (radius, z) half-plane.
struct ProfilePoint {
  double radius;
  double z;
};

// Revolves a profile running from the top pole to the bottom pole (both on the z axis) about
// z. Every inner profile point becomes a ring of `segments` vertices; the result is closed
// and counter-clockwise seen from outside.
TriangleMesh Revolve(const std::vector<ProfilePoint>& profile, int segments) {
  TriangleMesh mesh;
  const int rings = static_cast<int>(profile.size()) - 2;
  mesh.vertices.emplace_back(0.0, 0.0, profile.front().z);
  for (int i = 1; i <= rings; ++i) {
    for (int j = 0; j < segments; ++j) {
      const double phi = 2.0 * kPi * j / segments;
      mesh.vertices.emplace_back(profile[i].radius * std::cos(phi),
                                 profile[i].radius * std::sin(phi), profile[i].z);
    }
  }
  mesh.vertices.emplace_back(0.0, 0.0, profile.back().z);
  const int bottom = mesh.vertex_count() - 1;
  const auto ring = [segments](int i, int j) { return 1 + (i - 1) * segments + j % segments; };
  for (int j = 0; j < segments; ++j) {
    mesh.triangles.emplace_back(0, ring(1, j), ring(1, j + 1));
    for (int i = 1; i < rings; ++i) {
      mesh.triangles.emplace_back(ring(i, j), ring(i + 1, j), ring(i + 1, j + 1));
      mesh.triangles.emplace_back(ring(i, j), ring(i + 1, j + 1), ring(i, j + 1));
    }
    mesh.triangles.emplace_back(bottom, ring(rings, j + 1), ring(rings, j));
  }
  return mesh;
}

// Quarter circle of `steps` segments from angle `from` (radians from +z), centred at height z0.
void AppendArc(double radius, double z0, double from, int steps, std::vector<ProfilePoint>* out) {
  for (int i = 0; i <= steps; ++i) {
    const double theta = from + 0.5 * kPi * i / steps;
    out->push_back({radius * std::sin(theta), z0 + radius * std::cos(theta)});
  }
}

std::vector<ProfilePoint> SphereProfile(double radius, int segments) {
  std::vector<ProfilePoint> profile;
  const int quarter = std::max(1, segments / 4);
  AppendArc(radius, 0.0, 0.0, quarter, &profile);
  profile.pop_back();  // the equator is shared by both arcs
  AppendArc(radius, 0.0, 0.5 * kPi, quarter, &profile);
  return profile;
}

std::vector<ProfilePoint> CapsuleProfile(double radius, double length, int segments) {
  std::vector<ProfilePoint> profile;
  const int quarter = std::max(1, segments / 4);
  AppendArc(radius, 0.5 * length, 0.0, quarter, &profile);
  AppendArc(radius, -0.5 * length, 0.5 * kPi, quarter, &profile);
  return profile;
}

std::vector<ProfilePoint> CylinderProfile(double radius, double length) {
  return {
      {0.0, 0.5 * length}, {radius, 0.5 * length}, {radius, -0.5 * length}, {0.0, -0.5 * length}};
}

// 8 corners (bit k of the index set = + side along axis k) and 2 triangles per face.
TriangleMesh BoxMesh(const Vec3& size) {
  TriangleMesh mesh;
  for (int i = 0; i < 8; ++i) {
    mesh.vertices.emplace_back((i & 1 ? 0.5 : -0.5) * size.x(), (i & 2 ? 0.5 : -0.5) * size.y(),
                               (i & 4 ? 0.5 : -0.5) * size.z());
  }
  for (int k = 0; k < 3; ++k) {
    const int u = 1 << ((k + 1) % 3);
    const int w = 1 << ((k + 2) % 3);
    for (int side = 0; side < 2; ++side) {
      const int base = side ? (1 << k) : 0;
      // counter-clockwise seen from +axis k because u x w = k; reversed for the - face
      std::array<int, 4> quad = {base, base | u, base | u | w, base | w};
      if (!side) std::reverse(quad.begin(), quad.end());
      mesh.triangles.emplace_back(quad[0], quad[1], quad[2]);
      mesh.triangles.emplace_back(quad[0], quad[2], quad[3]);
    }
  }
  return mesh;
}

TriangleMesh LocalMesh(const Primitive& primitive, int segments) {
  switch (primitive.type) {
    case PrimitiveType::kSphere:
      return Revolve(SphereProfile(primitive.radius, segments), segments);
    case PrimitiveType::kBox:
      return BoxMesh(primitive.size);
    case PrimitiveType::kCylinder:
      return Revolve(CylinderProfile(primitive.radius, primitive.length), segments);
    case PrimitiveType::kCapsule:
      return Revolve(CapsuleProfile(primitive.radius, primitive.length, segments), segments);
    case PrimitiveType::kPlane:
      break;
  }
  return TriangleMesh();
}

}  // namespace

TriangleMesh Tessellate(const Primitive& primitive, int segments) {
  TriangleMesh mesh = LocalMesh(primitive, std::max(segments, 4));
  for (Vec3& v : mesh.vertices) v = primitive.pose * v;
  return mesh;
}

}  // namespace lamina::core
