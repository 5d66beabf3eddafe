// SPDX-License-Identifier: MIT
// Analytic shapes: sphere, box, cylinder, capsule and plane, each centred in its own frame.
#pragma once

#include <string>

#include "core/math_types.h"

namespace lamina::core {

enum class PrimitiveType { kSphere, kBox, kCylinder, kCapsule, kPlane };

/// A primitive shape. `pose` places the shape's own frame in the geometry frame.
///  - sphere: centre at the origin, `radius`
///  - box: centred, full edge lengths `size` (m)
///  - cylinder, capsule: axis along local z, centred, `radius` and `length` (m; a capsule's
///    length is that of its cylindrical part, the caps add `radius` at each end)
///  - plane: the half-space z <= 0 of its frame (infinite), normal +z
struct Primitive {
  PrimitiveType type = PrimitiveType::kSphere;
  Pose pose = Pose::Identity();
  double radius = 0.0;       ///< m (sphere, cylinder, capsule)
  double length = 0.0;       ///< m (cylinder, capsule)
  Vec3 size = Vec3::Zero();  ///< m (box)

  static Primitive Sphere(double radius, const Vec3& center = Vec3::Zero());
  static Primitive Box(const Vec3& size, const Pose& pose = Pose::Identity());
  static Primitive Cylinder(double radius, double length, const Pose& pose = Pose::Identity());
  static Primitive Capsule(double radius, double length, const Pose& pose = Pose::Identity());
  static Primitive Plane(const Pose& pose = Pose::Identity());

  /// Volume in m^3 (infinite for a plane).
  double Volume() const;
  /// Lower-case name used in files and messages: "sphere", "box", ...
  const char* TypeName() const;
};

}  // namespace lamina::core
