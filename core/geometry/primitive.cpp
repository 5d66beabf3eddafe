// SPDX-License-Identifier: MIT
#include "core/geometry/primitive.h"

namespace lamina::core {

Primitive Primitive::Sphere(double radius, const Vec3& center) {
  Primitive p;
  p.type = PrimitiveType::kSphere;
  p.radius = radius;
  p.pose.translation() = center;
  return p;
}

Primitive Primitive::Box(const Vec3& size, const Pose& pose) {
  Primitive p;
  p.type = PrimitiveType::kBox;
  p.size = size;
  p.pose = pose;
  return p;
}

Primitive Primitive::Cylinder(double radius, double length, const Pose& pose) {
  Primitive p;
  p.type = PrimitiveType::kCylinder;
  p.radius = radius;
  p.length = length;
  p.pose = pose;
  return p;
}

Primitive Primitive::Capsule(double radius, double length, const Pose& pose) {
  Primitive p;
  p.type = PrimitiveType::kCapsule;
  p.radius = radius;
  p.length = length;
  p.pose = pose;
  return p;
}

Primitive Primitive::Plane(const Pose& pose) {
  Primitive p;
  p.type = PrimitiveType::kPlane;
  p.pose = pose;
  return p;
}

double Primitive::Volume() const {
  switch (type) {
    case PrimitiveType::kSphere:
      return 4.0 / 3.0 * kPi * radius * radius * radius;
    case PrimitiveType::kBox:
      return size.x() * size.y() * size.z();
    case PrimitiveType::kCylinder:
      return kPi * radius * radius * length;
    case PrimitiveType::kCapsule:
      return kPi * radius * radius * length + 4.0 / 3.0 * kPi * radius * radius * radius;
    case PrimitiveType::kPlane:
      return kInf;
  }
  return 0.0;
}

const char* Primitive::TypeName() const {
  switch (type) {
    case PrimitiveType::kSphere:
      return "sphere";
    case PrimitiveType::kBox:
      return "box";
    case PrimitiveType::kCylinder:
      return "cylinder";
    case PrimitiveType::kCapsule:
      return "capsule";
    case PrimitiveType::kPlane:
      return "plane";
  }
  return "unknown";
}

}  // namespace lamina::core
