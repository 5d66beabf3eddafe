// SPDX-License-Identifier: MIT
// Point-cloud contacts (point_cloud_contacts.h): every point a ball of the cloud's padding,
// culled leaf by leaf, against a primitive, a mesh or another cloud.
#include "core/contact/point_cloud_contacts.h"

#include <algorithm>

#include "core/contact/mesh_query.h"
#include "core/contact/primitive_pairs.h"
#include "core/contact/triangle_queries.h"

namespace lamina::core {

namespace {

using Box = Eigen::AlignedBox3d;
using Leaf = CollisionGeometry::PointLeaf;
using primitive_detail::ContactSink;
using primitive_detail::PlacedPrimitive;

// Points closer than this (m) have no direction between them.
constexpr double kNoDirection = 1e-12;

// False when the boxes are more than `reach` apart along an axis.
bool Near(const Box& x, const Box& y, double reach) {
  return !(((x.min() - y.max()).array() > reach).any() ||
           ((y.min() - x.max()).array() > reach).any());
}

// `box` (frame F) as axis-aligned bounds in frame G, where X_GF maps F to G.
Box MappedBox(const Box& box, const Pose& X_GF) {
  if (box.isEmpty()) return box;
  if (!box.min().allFinite() || !box.max().allFinite()) {
    return Box(Vec3::Constant(-kInf), Vec3::Constant(kInf));
  }
  Box out;
  for (int corner = 0; corner < 8; ++corner) out.extend(X_GF * box.corner(Box::CornerType(corner)));
  return out;
}

// The leaves of a that may come within reach of b's bounds (b's frame -> a's by X_ab); a
// plane's bounds are infinite, so a plane is tested by the height of each leaf's lowest corner.
class LeafFilter {
 public:
  LeafFilter(const CollisionGeometry& b, const Pose& X_ab, double reach)
      : bounds_(MappedBox(b.local_bounds(), X_ab)), reach_(reach) {
    is_plane_ = b.kind() == CollisionGeometry::Kind::kPrimitive &&
                b.primitive().type == PrimitiveType::kPlane;
    if (!is_plane_) return;
    const Pose X_a_plane = X_ab * b.primitive().pose;
    normal_ = X_a_plane.linear().col(2);
    height_ = normal_.dot(X_a_plane.translation());
  }

  bool Passes(const Box& leaf) const {
    if (!is_plane_) return Near(leaf, bounds_, reach_);
    const double lowest = normal_.dot(leaf.center()) - normal_.cwiseAbs().dot(0.5 * leaf.sizes());
    return lowest - height_ <= reach_;
  }

 private:
  Box bounds_;
  double reach_;
  bool is_plane_ = false;
  Vec3 normal_ = Vec3::UnitZ();
  double height_ = 0.0;
};

void PrimitivePointContacts(const CollisionGeometry& a, const Pose& X_Wa,
                            const CollisionGeometry& b, const Pose& X_Wb, ContactSink* sink) {
  const PlacedPrimitive shape{&b.primitive(), X_Wb * b.primitive().pose};
  const LeafFilter filter(b, X_Wa.inverse() * X_Wb, sink->tolerance());
  for (const Leaf& leaf : a.point_leaves()) {
    if (!filter.Passes(leaf.bounds)) continue;
    for (int i = leaf.begin; i < leaf.end; ++i) {
      const Vec3 p = X_Wa * a.points()[i];
      sink->AddBall(true, p, 0.0, primitive_detail::QueryPoint(shape, p));
    }
  }
}

// The points of a cloud against a mesh b, in b's frame.
class MeshPointTester {
 public:
  MeshPointTester(const CollisionGeometry& mesh, const Pose& X_Wb, const Pose& X_ba,
                  ContactSink* sink)
      : mesh_(mesh), X_Wb_(X_Wb), X_ba_(X_ba), sink_(sink) {}

  // every point of `leaf` against the triangles near the leaf's box
  void TestLeaf(const CollisionGeometry& cloud, const Pose& X_Wa, const Leaf& leaf) {
    triangles_.clear();
    mesh_detail::TrianglesNearAlignedBox(mesh_.bvh(), MappedBox(leaf.bounds, X_ba_),
                                         sink_->tolerance(), &triangles_);
    if (triangles_.empty()) return;
    std::erase_if(triangles_, [this](int t) { return mesh_.triangle_normals()[t].isZero(); });
    boxes_.clear();
    for (const int t : triangles_) {
      const mesh_detail::Triangle3 c = Corners(t);
      boxes_.emplace_back(c[0].cwiseMin(c[1]).cwiseMin(c[2]), c[0].cwiseMax(c[1]).cwiseMax(c[2]));
    }
    for (int i = leaf.begin; i < leaf.end; ++i) {
      TestPoint(X_Wa * cloud.points()[i], X_ba_ * cloud.points()[i]);
    }
  }

 private:
  struct Nearest {
    int triangle = -1;
    double distance = kInf;
    mesh_detail::TrianglePoint closest;
  };

  // the nearest triangle to p_b among the leaf's within reach (the lowest index on a tie:
  // sorted, strict <); a triangle whose box is farther than the best so far is skipped
  Nearest NearestTriangle(const Vec3& p_b) const {
    Nearest best;
    for (std::size_t k = 0; k < triangles_.size(); ++k) {
      const double limit = std::min(best.distance, sink_->tolerance());
      if (boxes_[k].squaredExteriorDistance(p_b) > limit * limit) continue;
      const int t = triangles_[k];
      const mesh_detail::TrianglePoint c = mesh_detail::ClosestPointOnTriangle(p_b, Corners(t));
      const double distance = (p_b - c.point).norm();
      if (distance < best.distance) best = {t, distance, c};
    }
    return best;
  }

  mesh_detail::Triangle3 Corners(int t) const {
    const Eigen::Vector3i& index = mesh_.mesh().triangles[t];
    const std::vector<Vec3>& v = mesh_.mesh().vertices;
    return {v[index[0]], v[index[1]], v[index[2]]};
  }

  void TestPoint(const Vec3& p_W, const Vec3& p_b) {
    const Nearest nearest = NearestTriangle(p_b);
    if (nearest.triangle < 0 || !(nearest.distance < sink_->tolerance())) return;  // none in reach
    Vec3 normal;
    const double distance = SignedDistance(p_b, nearest, &normal);
    sink_->Add(p_W, X_Wb_ * nearest.closest.point, X_Wb_.linear() * normal, distance);
  }

  // signed along the face normal inside a face; else along p - c turned to the feature's side
  double SignedDistance(const Vec3& p_b, const Nearest& nearest, Vec3* normal) const {
    const mesh_detail::TriangleFeature feature =
        mesh_detail::ClassifyFeature(nearest.closest.barycentric);
    const Vec3 offset = p_b - nearest.closest.point;
    if (feature.type == mesh_detail::TriangleFeature::Type::kFace) {
      *normal = mesh_.triangle_normals()[nearest.triangle];
      return normal->dot(offset);
    }
    *normal = mesh_detail::FeatureNormal(mesh_, nearest.triangle, feature);
    if (nearest.distance < mesh_detail::kFeatureNormalDistance) return nearest.distance;
    const double side = offset.dot(*normal) < 0.0 ? -1.0 : 1.0;
    *normal = side * offset / nearest.distance;
    return side * nearest.distance;
  }

  const CollisionGeometry& mesh_;
  const Pose X_Wb_;
  const Pose X_ba_;
  ContactSink* sink_;
  std::vector<int> triangles_;  // near the current leaf, with area, sorted
  std::vector<Box> boxes_;      // their bounds
};

void MeshPointContacts(const CollisionGeometry& a, const Pose& X_Wa, const CollisionGeometry& b,
                       const Pose& X_Wb, ContactSink* sink) {
  const Pose X_ba = X_Wb.inverse() * X_Wa;
  const LeafFilter filter(b, X_Wa.inverse() * X_Wb, sink->tolerance());
  MeshPointTester tester(b, X_Wb, X_ba, sink);
  for (const Leaf& leaf : a.point_leaves()) {
    if (filter.Passes(leaf.bounds)) tester.TestLeaf(a, X_Wa, leaf);
  }
}

// Each point of cloud a against the nearest point of cloud b (b's points in a's frame).
class CloudPairTester {
 public:
  CloudPairTester(const CollisionGeometry& b, const Pose& X_ab, ContactSink* sink) : sink_(sink) {
    points_b_.reserve(b.points().size());
    for (const Vec3& q : b.points()) points_b_.push_back(X_ab * q);
    for (const Leaf& leaf : b.point_leaves()) {
      leaves_b_.push_back({leaf.begin, leaf.end, MappedBox(leaf.bounds, X_ab)});
    }
  }

  void TestLeaf(const CollisionGeometry& a, const Pose& X_Wa, const Leaf& leaf) {
    near_.clear();
    for (const Leaf& other : leaves_b_) {
      if (Near(leaf.bounds, other.bounds, sink_->tolerance())) near_.push_back(&other);
    }
    if (near_.empty()) return;
    for (int i = leaf.begin; i < leaf.end; ++i) TestPoint(a.points()[i], X_Wa);
  }

 private:
  void TestPoint(const Vec3& p, const Pose& X_Wa) {
    double best = kInf;
    int nearest = -1;
    for (const Leaf* other : near_) {
      for (int j = other->begin; j < other->end; ++j) {
        const double distance = (p - points_b_[j]).norm();
        if (distance < best) {
          best = distance;
          nearest = j;
        }
      }
    }
    if (nearest < 0 || best < kNoDirection) return;
    const Vec3 normal = X_Wa.linear() * ((p - points_b_[nearest]) / best);
    sink_->Add(X_Wa * p, X_Wa * points_b_[nearest], normal, best);
  }

  ContactSink* sink_;
  std::vector<Vec3> points_b_;
  std::vector<Leaf> leaves_b_;
  std::vector<const Leaf*> near_;
};

void CloudCloudContacts(const CollisionGeometry& a, const Pose& X_Wa, const CollisionGeometry& b,
                        const Pose& X_Wb, ContactSink* sink) {
  CloudPairTester tester(b, X_Wa.inverse() * X_Wb, sink);
  for (const Leaf& leaf : a.point_leaves()) tester.TestLeaf(a, X_Wa, leaf);
}

// Halves [begin, end) at the median of the longest side of its bounds until leaves are small.
void Split(int begin, int end, int per_leaf, std::vector<Vec3>* points, std::vector<Leaf>* leaves) {
  Box bounds;
  for (int i = begin; i < end; ++i) bounds.extend((*points)[i]);
  if (end - begin <= per_leaf) {
    leaves->push_back({begin, end, bounds});
    return;
  }
  int axis = 0;
  bounds.sizes().maxCoeff(&axis);
  const int middle = begin + (end - begin) / 2;
  std::nth_element(points->begin() + begin, points->begin() + middle, points->begin() + end,
                   [axis](const Vec3& x, const Vec3& y) { return x[axis] < y[axis]; });
  Split(begin, middle, per_leaf, points, leaves);
  Split(middle, end, per_leaf, points, leaves);
}

}  // namespace

void PointCloudContacts(const CollisionGeometry& a, const Pose& X_Wa, double pad_a,
                        const CollisionGeometry& b, const Pose& X_Wb, double pad_b,
                        ContactList* out) {
  ContactSink sink(pad_a, pad_b, out);
  switch (b.kind()) {
    case CollisionGeometry::Kind::kPrimitive:
      PrimitivePointContacts(a, X_Wa, b, X_Wb, &sink);
      break;
    case CollisionGeometry::Kind::kMesh:
      MeshPointContacts(a, X_Wa, b, X_Wb, &sink);
      break;
    case CollisionGeometry::Kind::kPointCloud:
      CloudCloudContacts(a, X_Wa, b, X_Wb, &sink);
      break;
  }
}

namespace point_cloud_detail {

std::vector<CollisionGeometry::PointLeaf> PartitionPoints(int per_leaf, std::vector<Vec3>* points) {
  std::vector<Leaf> leaves;
  if (points->empty()) return leaves;
  Split(0, static_cast<int>(points->size()), std::max(per_leaf, 1), points, &leaves);
  return leaves;
}

}  // namespace point_cloud_detail

}  // namespace lamina::core
