// SPDX-License-Identifier: MIT
// Writing primitives as Klamp't `.geom` text (KrisLibrary's GeometricPrimitive3D layouts).
#include "core/io/geometry_file.h"
#include "core/io/text_statements.h"

namespace lamina::core {

namespace {

std::string VecNumbers(const Vec3& v) {
  return FormatDoubles(v.data(), 3);
}

}  // namespace

std::optional<std::string> WriteGeomText(const Primitive& primitive) {
  const Mat3& rotation = primitive.pose.linear();
  const Vec3& center = primitive.pose.translation();
  switch (primitive.type) {
    case PrimitiveType::kSphere:
      return "Primitive\nSphere\n" + VecNumbers(center) + "  " + FormatDouble(primitive.radius) +
             "\n";
    case PrimitiveType::kBox: {
      // corner origin, unit axes, extents from that corner
      const Vec3 origin = center - rotation * (primitive.size / 2.0);
      return "Primitive\nBox\n" + VecNumbers(origin) + "  " + VecNumbers(rotation.col(0)) + "  " +
             VecNumbers(rotation.col(1)) + "  " + VecNumbers(rotation.col(2)) + "  " +
             VecNumbers(primitive.size) + "\n";
    }
    case PrimitiveType::kCylinder:
    case PrimitiveType::kCapsule: {
      // base centre, axis, radius, height
      const Vec3 axis = rotation.col(2);
      const Vec3 base = center - axis * (primitive.length / 2.0);
      return std::string("Primitive\n") +
             (primitive.type == PrimitiveType::kCylinder ? "Cylinder\n" : "Capsule\n") +
             VecNumbers(base) + "  " + VecNumbers(axis) + "  " + FormatDouble(primitive.radius) +
             " " + FormatDouble(primitive.length) + "\n";
    }
    case PrimitiveType::kPlane:
      return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace lamina::core
