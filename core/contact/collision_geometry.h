// SPDX-License-Identifier: MIT
// Collision geometry of a body in its own frame, with scale and placement baked in: a
// triangle mesh with its bounding-volume hierarchy (built once and shared by every body that
// uses the same file at the same scale), an analytic primitive, or a point cloud grouped into
// small boxes of nearby points.
#pragma once

#include <map>
#include <memory>
#include <utility>
#include <vector>

#include "core/contact/contact.h"
#include "core/geometry/geometry_desc.h"

namespace lamina::core {

/// Opaque bounding-volume hierarchy of a mesh (FCL). Defined in collision_geometry.cpp.
struct MeshBvh;
struct NearPairCache;  // near_pair_cache.h

class CollisionGeometry {
 public:
  enum class Kind { kMesh, kPrimitive, kPointCloud };

  /// Points [begin, end) of points() and their bounds (body frame, m).
  struct PointLeaf {
    int begin = 0;
    int end = 0;
    Eigen::AlignedBox3d bounds;
  };

  /// Geometry for `desc`: a mesh (with its BVH) for meshes, and for primitives whose scale keeps
  /// them the same kind of shape (uniform scale, or any axis scale of an unrotated box); other
  /// scaled primitives become tessellated meshes; point clouds keep their points. nullptr for
  /// empty geometry (a mesh without triangles, a cloud without points).
  static std::shared_ptr<const CollisionGeometry> Build(const GeometryDesc& desc);

  Kind kind() const { return kind_; }
  /// Mesh in the body frame (kind kMesh).
  const TriangleMesh& mesh() const { return mesh_; }
  const MeshBvh& bvh() const { return *bvh_; }
  /// Unit outward normal of each triangle, body frame (kind kMesh); zero for a triangle without
  /// area (flat to rounding).
  const std::vector<Vec3>& triangle_normals() const { return triangle_normals_; }
  /// Primitive in the body frame (its pose includes the geometry placement; kind kPrimitive).
  const Primitive& primitive() const { return primitive_; }
  /// Points in the body frame (kind kPointCloud), ordered leaf by leaf.
  const std::vector<Vec3>& points() const { return points_; }
  /// Groups of at most kPointsPerLeaf nearby points covering points() in order (kPointCloud):
  /// what the contact routines test against the other body's bounds before any single point.
  const std::vector<PointLeaf>& point_leaves() const { return point_leaves_; }
  static constexpr int kPointsPerLeaf = 16;
  /// Collision margin of the geometry itself (m), added to the body's padding.
  double margin() const { return margin_; }
  /// Bounds in the body frame (infinite for a plane).
  const Eigen::AlignedBox3d& local_bounds() const { return local_bounds_; }

 private:
  Kind kind_ = Kind::kPrimitive;
  TriangleMesh mesh_;
  std::shared_ptr<const MeshBvh> bvh_;
  std::vector<Vec3> triangle_normals_;
  Primitive primitive_;
  std::vector<Vec3> points_;
  std::vector<PointLeaf> point_leaves_;
  double margin_ = 0.0;
  Eigen::AlignedBox3d local_bounds_;
};

/// Builds each distinct (mesh or point cloud, placement) once. Not thread-safe.
class CollisionGeometryCache {
 public:
  std::shared_ptr<const CollisionGeometry> Get(const GeometryDesc& desc);
  int size() const { return static_cast<int>(cache_.size()); }

 private:
  std::map<std::pair<const void*, std::vector<double>>, std::shared_ptr<const CollisionGeometry>>
      cache_;
};

/// Every contact between a (at pose X_Wa, padding pad_a) and b (X_Wb, pad_b), appended to
/// `out`. Paddings include nothing else: the geometries' own margins are added inside, and
/// half of kLayerEdgeSlack to each (contact.h).
/// Deterministic: the same inputs give the same contacts in the same order. A point cloud's
/// points are balls of its padding (point_cloud_contacts.h). `cache`: the triangle pairs of a
/// mesh–mesh pair kept from the last call for the same two bodies (near_pair_cache.h; the
/// contacts are bitwise the same with or without it).
void Collide(const CollisionGeometry& a, const Pose& X_Wa, double pad_a, const CollisionGeometry& b,
             const Pose& X_Wb, double pad_b, ContactList* out, NearPairCache* cache = nullptr);

}  // namespace lamina::core
