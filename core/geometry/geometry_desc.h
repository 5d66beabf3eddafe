// SPDX-License-Identifier: MIT
// A body's geometry as the user described it: a reference to a mesh, primitive or point-cloud
// file (kept as written so that saving reproduces it), its scale and placement, and the loaded
// shape.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/geometry/point_cloud.h"
#include "core/geometry/primitive.h"
#include "core/geometry/triangle_mesh.h"
#include "core/math_types.h"

namespace lamina::core {

/// kPointCloud: points without size or surface (a `.pcd` file); in contact each point is a ball of
/// the body's padding, and automass puts an equal mass at every point (Klamp't's rule).
enum class GeometryKind { kNone, kMesh, kPrimitive, kPointCloud };

struct GeometryDesc {
  GeometryKind kind = GeometryKind::kNone;
  /// Absolute, normalized path of the file the shape was loaded from ("" for inline shapes).
  std::string path;
  /// The mesh in file coordinates, unscaled. Shared by every body that uses the same file.
  std::shared_ptr<const TriangleMesh> mesh;
  /// The primitive in file coordinates, unscaled (kind == kPrimitive).
  Primitive primitive;
  /// The points in file coordinates, unscaled (kind == kPointCloud). Shared like meshes.
  std::shared_ptr<const PointCloud> point_cloud;
  /// Scale applied first, in the file's axes.
  Vec3 scale = Vec3::Ones();
  /// Then this map into the body frame; rigid except for `.rob` `geomtransform` matrices.
  Affine transform = Affine::Identity();
  /// Collision margin of the geometry itself (m), added to the simulation padding.
  double margin = 0.0;

  bool empty() const { return kind == GeometryKind::kNone; }
  /// File coordinates -> body frame: transform * diag(scale).
  Affine Matrix() const { return GeometryMatrix(transform, scale); }
  /// Triangles of the mesh (0 for primitives, point clouds and empty geometry).
  int triangle_count() const;
  /// Points of the point cloud (0 for every other kind).
  int point_count() const;
};

/// The shape as a mesh in body coordinates (scale and transform applied). Primitives are
/// tessellated; a plane and a point cloud give an empty mesh.
TriangleMesh BakedMesh(const GeometryDesc& geometry);
/// The points of a point cloud in body coordinates (scale and transform applied); empty for
/// every other kind.
std::vector<Vec3> BakedPoints(const GeometryDesc& geometry);

}  // namespace lamina::core
