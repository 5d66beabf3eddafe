// SPDX-License-Identifier: MIT
// A body's geometry as the user described it: a reference to a mesh or primitive file (kept as
// written so that saving reproduces it), its scale and placement, and the loaded shape.
#pragma once

#include <memory>
#include <string>

#include "core/geometry/primitive.h"
#include "core/geometry/triangle_mesh.h"
#include "core/math_types.h"

namespace lamina::core {

enum class GeometryKind { kNone, kMesh, kPrimitive };

struct GeometryDesc {
  GeometryKind kind = GeometryKind::kNone;
  /// Absolute, normalized path of the file the shape was loaded from ("" for inline shapes).
  std::string path;
  /// The mesh in file coordinates, unscaled. Shared by every body that uses the same file.
  std::shared_ptr<const TriangleMesh> mesh;
  /// The primitive in file coordinates, unscaled (kind == kPrimitive).
  Primitive primitive;
  /// Scale applied first, in the file's axes.
  Vec3 scale = Vec3::Ones();
  /// Then this map into the body frame; rigid except for `.rob` `geomtransform` matrices.
  Affine transform = Affine::Identity();
  /// Collision margin of the geometry itself (m), added to the simulation padding.
  double margin = 0.0;

  bool empty() const { return kind == GeometryKind::kNone; }
  /// File coordinates -> body frame: transform * diag(scale).
  Affine Matrix() const { return GeometryMatrix(transform, scale); }
  /// Triangles of the mesh (0 for primitives and empty geometry).
  int triangle_count() const;
};

/// The shape as a mesh in body coordinates (scale and transform applied). Primitives are
/// tessellated; a plane gives an empty mesh.
TriangleMesh BakedMesh(const GeometryDesc& geometry);

}  // namespace lamina::core
