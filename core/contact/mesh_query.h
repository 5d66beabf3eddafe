// SPDX-License-Identifier: MIT
// Internal services of collision meshes shared by the mesh contact routines (not part of the
// public contact API): the mesh topology built once with the hierarchy, feature normals, and
// queries on the FCL bounding-volume hierarchy. The queries are implemented in
// collision_geometry.cpp, the only file that includes FCL (its headers are slow to compile);
// the feature normals in mesh_contacts.cpp.
#pragma once

#include <algorithm>
#include <vector>

#include "core/contact/collision_geometry.h"
#include "core/contact/near_pair_cache.h"

namespace lamina::core::mesh_detail {

/// Closest points nearer than this take their contact normal from the mesh features (Klamp't's
/// gNormalFromGeometryTolerance); normals shorter than kMinNormalLength are dropped.
inline constexpr double kFeatureNormalDistance = 1e-5;
inline constexpr double kMinNormalLength = 1e-4;

/// Values over the vertices, triangles or hierarchy nodes of a mesh, all emptied at once in
/// constant time: a query on a large terrain touches few of them. Keep one per thread and
/// reuse it, so that queries do not allocate.
template <typename T>
class SparseArray {
 public:
  /// Empties the array and makes room for indices below `size`.
  void Clear(size_t size) {
    if (stamps_.size() < size) {
      values_.resize(size);
      stamps_.resize(size, 0);
    }
    if (++generation_ == 0) {  // wrapped around: forget every stamp
      std::fill(stamps_.begin(), stamps_.end(), 0u);
      generation_ = 1;
    }
  }
  /// True when i was set since the last Clear.
  bool Has(int i) const { return stamps_[i] == generation_; }
  /// The value at i (meaningful when Has(i)).
  const T& operator[](int i) const { return values_[i]; }
  /// Marks i as set; returns its value to assign.
  T& Set(int i) {
    stamps_[i] = generation_;
    return values_[i];
  }

 private:
  std::vector<T> values_;
  std::vector<unsigned> stamps_;  // values_[i] is set when stamps_[i] == generation_
  unsigned generation_ = 0;
};

/// Adjacency of a collision mesh. Vertices at identical positions count as one vertex.
struct MeshTopology {
  /// Per triangle, the triangle across edge k (the edge opposite corner k); -1 on a border.
  std::vector<Eigen::Vector3i> neighbors;
  /// Per vertex, the lowest-numbered vertex at the same position.
  std::vector<int> welded;
  /// Per vertex, the unit sum of the normals of the triangles around it (zero if none).
  std::vector<Vec3> vertex_normals;
};

/// The topology built with `bvh`.
const MeshTopology& Topology(const MeshBvh& bvh);

/// Where on a triangle a point lies, from its barycentric coordinates: a coordinate within
/// 1e-3 of zero counts as zero (Klamp't's rule). `index` is the corner of a vertex and the
/// corner opposite an edge.
struct TriangleFeature {
  enum class Type { kVertex, kEdge, kFace };
  Type type = Type::kFace;
  int index = 0;
};
TriangleFeature ClassifyFeature(const Vec3& barycentric);

/// Unit outward normals in the mesh frame: of the vertex at `corner` of `triangle`, of the edge
/// opposite `corner` (mean of the two faces), and of the feature a point lies on.
Vec3 VertexNormal(const CollisionGeometry& mesh, int triangle, int corner);
Vec3 EdgeNormal(const CollisionGeometry& mesh, int triangle, int corner);
Vec3 FeatureNormal(const CollisionGeometry& mesh, int triangle, const TriangleFeature& feature);

/// A pair of triangles closer than the tolerance, with their closest points in a's frame.
struct TrianglePairHit {
  /// Which closest points the distance came from: a corner of one triangle and its foot inside
  /// the other (all of the corner's triangle on one side of the other's plane, so no point of it
  /// is nearer), or FCL's general triangle distance (kGeneral).
  enum class Foot : signed char { kGeneral, kCornerOfBOverA, kCornerOfAOverB };

  int triangle_a = 0;
  int triangle_b = 0;
  double distance = 0.0;
  Vec3 point_a = Vec3::Zero();
  Vec3 point_b = Vec3::Zero();
  Foot foot = Foot::kGeneral;
  int corner = 0;  ///< the corner (0..2) of its triangle, when `foot` names one
};

/// How NearTrianglePairs narrows down the triangle pairs it measures. Every way reports
/// bitwise the same pairs; they differ only in speed.
enum class PairSearch {
  kAuto,             ///< the fastest for the two meshes' sizes
  kReference,        ///< the exact distance of every pair, nothing pruned (for tests)
  kEveryPair,        ///< every triangle of a against every triangle of b
  kSmallerInLarger,  ///< the smaller mesh's bounds through the larger mesh's hierarchy
  kBothHierarchies,  ///< a traversal of both hierarchies
};

/// Every triangle pair of a and b (b placed in a's frame by X_ab) whose distance is at most
/// `tolerance`, appended to `hits` in (triangle_a, triangle_b) order. With a `cache` (and the
/// automatic search) the pairs come from its candidates while they hold, and the cache is
/// filled anew when they do not (near_pair_cache.h): bitwise the same pairs.
void NearTrianglePairs(const MeshBvh& a, const MeshBvh& b, const Pose& X_ab, double tolerance,
                       std::vector<TrianglePairHit>* hits, PairSearch search = PairSearch::kAuto,
                       NearPairCache* cache = nullptr);

/// Triangles whose bounding volumes overlap the box with centre frame X_mesh_box and
/// `half_extents`, appended to `triangles` (a superset of the triangles touching the box).
void TrianglesNearBox(const MeshBvh& bvh, const Pose& X_mesh_box, const Vec3& half_extents,
                      std::vector<int>* triangles);

/// Triangles whose bounding volumes may come within `reach` of the axis-aligned `bounds` (mesh
/// frame), appended to `triangles` in increasing order (a superset of the triangles within
/// `reach` of the box). Cheaper per node than TrianglesNearBox (six separating axes, not 15).
void TrianglesNearAlignedBox(const MeshBvh& bvh, const Eigen::AlignedBox3d& bounds, double reach,
                             std::vector<int>* triangles);

/// Triangles whose bounding volumes reach below `height` along the unit `normal` (points x
/// with normal.dot(x) < height exist in the volume), appended to `triangles`.
void TrianglesBelowPlane(const MeshBvh& bvh, const Vec3& normal, double height,
                         std::vector<int>* triangles);

}  // namespace lamina::core::mesh_detail
