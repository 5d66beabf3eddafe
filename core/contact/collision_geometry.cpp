// SPDX-License-Identifier: MIT
// Collision geometry construction and the FCL adapter: the one translation unit that includes
// FCL. Holds the bounding-volume hierarchy of each mesh and the traversals the contact
// routines need (FCL has no "all pairs within a tolerance" query).
#include "core/contact/collision_geometry.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <tuple>

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/narrowphase/detail/primitive_shape_algorithm/triangle_distance.h>

#include "core/contact/mesh_query.h"

namespace lamina::core {

struct MeshBvh {
  fcl::BVHModel<fcl::OBBRSSd> model;
  mesh_detail::MeshTopology topology;
};

namespace {

using mesh_detail::MeshTopology;
using mesh_detail::TrianglePairHit;

using FclModel = fcl::BVHModel<fcl::OBBRSSd>;

std::vector<Vec3> TriangleNormals(const TriangleMesh& mesh) {
  std::vector<Vec3> normals;
  normals.reserve(mesh.triangles.size());
  for (const Eigen::Vector3i& t : mesh.triangles) {
    const Vec3& a = mesh.vertices[t[0]];
    const Vec3 n = (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a);
    const double length = n.norm();
    normals.push_back(length > 0.0 ? Vec3(n / length) : Vec3::Zero());
  }
  return normals;
}

// lowest-numbered vertex at each vertex's exact position
std::vector<int> WeldVertices(const TriangleMesh& mesh) {
  std::vector<int> order(mesh.vertices.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  const auto position = [&mesh](int i) {
    const Vec3& v = mesh.vertices[i];
    return std::make_tuple(v.x(), v.y(), v.z());
  };
  std::sort(order.begin(), order.end(), [&position](int i, int j) {
    return std::make_pair(position(i), i) < std::make_pair(position(j), j);
  });
  std::vector<int> welded(order.size());
  for (size_t k = 0; k < order.size(); ++k) {
    const bool same = k > 0 && position(order[k]) == position(order[k - 1]);
    welded[order[k]] = same ? welded[order[k - 1]] : order[k];
  }
  return welded;
}

std::vector<Vec3> VertexNormals(const TriangleMesh& mesh, const std::vector<Vec3>& face_normals,
                                const std::vector<int>& welded) {
  std::vector<Vec3> sums(mesh.vertices.size(), Vec3::Zero());
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) sums[welded[mesh.triangles[t][k]]] += face_normals[t];
  }
  std::vector<Vec3> normals(mesh.vertices.size());
  for (size_t v = 0; v < normals.size(); ++v) {
    const Vec3& sum = sums[welded[v]];
    const double length = sum.norm();
    normals[v] = length > 0.0 ? Vec3(sum / length) : Vec3::Zero();
  }
  return normals;
}

// Triangles sharing an edge (welded vertices). On a non-manifold edge every triangle takes the
// lowest-numbered other triangle of the edge as its neighbour.
std::vector<Eigen::Vector3i> TriangleNeighbors(const TriangleMesh& mesh,
                                               const std::vector<int>& welded) {
  struct EdgeUse {
    std::pair<int, int> edge;
    int triangle;
    int corner;
    bool operator<(const EdgeUse& o) const {
      return std::tie(edge, triangle, corner) < std::tie(o.edge, o.triangle, o.corner);
    }
  };
  std::vector<EdgeUse> uses;
  uses.reserve(3 * mesh.triangles.size());
  for (int t = 0; t < mesh.triangle_count(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const int u = welded[mesh.triangles[t][(k + 1) % 3]];
      const int v = welded[mesh.triangles[t][(k + 2) % 3]];
      uses.push_back({{std::min(u, v), std::max(u, v)}, t, k});
    }
  }
  std::sort(uses.begin(), uses.end());
  std::vector<Eigen::Vector3i> neighbors(mesh.triangles.size(), Eigen::Vector3i::Constant(-1));
  for (size_t first = 0; first < uses.size();) {
    size_t last = first;
    while (last < uses.size() && uses[last].edge == uses[first].edge) ++last;
    for (size_t i = first; i < last; ++i) {
      const size_t other = (i == first && last - first > 1) ? first + 1 : first;
      if (other != i) neighbors[uses[i].triangle][uses[i].corner] = uses[other].triangle;
    }
    first = last;
  }
  return neighbors;
}

std::shared_ptr<const MeshBvh> BuildBvh(const TriangleMesh& mesh,
                                        const std::vector<Vec3>& face_normals) {
  auto bvh = std::make_shared<MeshBvh>();
  std::vector<fcl::Vector3d> points(mesh.vertices.begin(), mesh.vertices.end());
  std::vector<fcl::Triangle> triangles;
  triangles.reserve(mesh.triangles.size());
  for (const Eigen::Vector3i& t : mesh.triangles) triangles.emplace_back(t[0], t[1], t[2]);
  bvh->model.beginModel(static_cast<int>(triangles.size()), static_cast<int>(points.size()));
  bvh->model.addSubModel(points, triangles);
  bvh->model.endModel();
  bvh->topology.welded = WeldVertices(mesh);
  bvh->topology.vertex_normals = VertexNormals(mesh, face_normals, bvh->topology.welded);
  bvh->topology.neighbors = TriangleNeighbors(mesh, bvh->topology.welded);
  return bvh;
}

bool NearlyEqual(double a, double b) {
  return std::abs(a - b) <= 1e-9 * std::max(std::abs(a), std::abs(b));
}

// The plane through F's origin whose normal is F's image of +z as a normal (inverse transpose).
Primitive PlacedPlane(const Affine& F) {
  const Vec3 normal = F.linear().inverse().transpose().col(2).normalized();
  const Vec3 helper = std::abs(normal.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 x = helper.cross(normal).normalized();
  Pose pose = Pose::Identity();
  pose.linear() << x, normal.cross(x), normal;
  pose.translation() = F.translation();
  return Primitive::Plane(pose);
}

// The primitive mapped by F (primitive frame -> body frame) if it stays the same kind of shape:
// F's columns must be orthogonal, with equal lengths where the shape needs it.
std::optional<Primitive> PlacedPrimitive(const Primitive& primitive, const Affine& F) {
  if (primitive.type == PrimitiveType::kPlane) return PlacedPlane(F);
  const Mat3 L = F.linear();
  const Vec3 s = L.colwise().norm();
  if (s.minCoeff() <= 0.0) return std::nullopt;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if (std::abs(L.col(i).dot(L.col(j))) > 1e-9 * s[i] * s[j]) return std::nullopt;
  }
  const bool uniform_xy = NearlyEqual(s.x(), s.y());
  const bool uniform = uniform_xy && NearlyEqual(s.x(), s.z());
  Primitive placed = primitive;
  switch (primitive.type) {
    case PrimitiveType::kSphere:
    case PrimitiveType::kCapsule:
      if (!uniform) return std::nullopt;
      placed.radius *= s.x();
      placed.length *= s.x();
      break;
    case PrimitiveType::kCylinder:
      if (!uniform_xy) return std::nullopt;
      placed.radius *= s.x();
      placed.length *= s.z();
      break;
    case PrimitiveType::kBox:
      placed.size = primitive.size.cwiseProduct(s);
      break;
    case PrimitiveType::kPlane:
      break;
  }
  Mat3 rotation = L * s.cwiseInverse().asDiagonal();
  // every shape here is symmetric under z -> -z, so a mirroring map only flips that axis
  if (rotation.determinant() < 0.0) rotation.col(2) = -rotation.col(2);
  placed.pose = Pose::Identity();
  placed.pose.linear() = rotation;
  placed.pose.translation() = F.translation();
  return placed;
}

Eigen::AlignedBox3d PrimitiveBounds(const Primitive& p) {
  if (p.type == PrimitiveType::kPlane) {
    return Eigen::AlignedBox3d(Vec3::Constant(-kInf), Vec3::Constant(kInf));
  }
  const Mat3 R = p.pose.linear();
  Vec3 half = Vec3::Zero();
  switch (p.type) {
    case PrimitiveType::kSphere:
      half = Vec3::Constant(p.radius);
      break;
    case PrimitiveType::kBox:
      half = R.cwiseAbs() * (0.5 * p.size);
      break;
    case PrimitiveType::kCapsule:
      half = 0.5 * p.length * R.col(2).cwiseAbs() + Vec3::Constant(p.radius);
      break;
    case PrimitiveType::kCylinder:
      for (int i = 0; i < 3; ++i) {
        const double a = std::abs(R(i, 2));
        half[i] = 0.5 * p.length * a + p.radius * std::sqrt(std::max(0.0, 1.0 - a * a));
      }
      break;
    case PrimitiveType::kPlane:
      break;
  }
  const Vec3 c = p.pose.translation();
  return Eigen::AlignedBox3d(c - half, c + half);
}

// Pairs of nodes are pruned by the distance between their bounding volumes (b's volumes are
// mapped into a's frame by R, T, as FCL's own distance traversal does).
class PairTraversal {
 public:
  PairTraversal(const FclModel& a, const FclModel& b, const Pose& X_ab, double tolerance,
                std::vector<TrianglePairHit>* hits)
      : a_(a),
        b_(b),
        R_(X_ab.linear()),
        T_(X_ab.translation()),
        tolerance_(tolerance),
        hits_(hits) {}

  void Visit(int node_a, int node_b) const {
    const fcl::BVNode<fcl::OBBRSSd>& na = a_.getBV(node_a);
    const fcl::BVNode<fcl::OBBRSSd>& nb = b_.getBV(node_b);
    if (Far(na.bv, nb.bv)) return;
    if (na.isLeaf() && nb.isLeaf()) {
      Leaf(na.primitiveId(), nb.primitiveId());
    } else if (nb.isLeaf() || (!na.isLeaf() && na.bv.size() >= nb.bv.size())) {
      Visit(na.leftChild(), node_b);
      Visit(na.rightChild(), node_b);
    } else {
      Visit(node_a, nb.leftChild());
      Visit(node_a, nb.rightChild());
    }
  }

 private:
  // FCL's RSS distance (the rectangles' distance minus the radii), after a cheaper test of the
  // boxes grown by half the tolerance each; both volumes share their axes
  bool Far(const fcl::OBBRSSd& va, const fcl::OBBRSSd& vb) const {
    const Mat3 at = va.obb.axis.transpose();
    const Mat3 B = at * R_ * vb.obb.axis;
    const Vec3 grow = Vec3::Constant(0.5 * tolerance_);
    const Vec3 T_obb = at * (R_ * vb.obb.To + T_ - va.obb.To);
    if (fcl::obbDisjoint(B, T_obb, Vec3(va.obb.extent + grow), Vec3(vb.obb.extent + grow))) {
      return true;
    }
    const Vec3 T_rss = at * (R_ * vb.rss.To + T_ - va.rss.To);
    return fcl::rectDistance(B, T_rss, va.rss.l, vb.rss.l) - va.rss.r - vb.rss.r > tolerance_;
  }

  void Leaf(int triangle_a, int triangle_b) const {
    const fcl::Triangle& ta = a_.tri_indices[triangle_a];
    const fcl::Triangle& tb = b_.tri_indices[triangle_b];
    fcl::Vector3d p, q;
    const double distance = fcl::detail::TriangleDistance<double>::triDistance(
        a_.vertices[ta[0]], a_.vertices[ta[1]], a_.vertices[ta[2]], b_.vertices[tb[0]],
        b_.vertices[tb[1]], b_.vertices[tb[2]], R_, T_, p, q);
    if (distance <= tolerance_) hits_->push_back({triangle_a, triangle_b, distance, p, q});
  }

  const FclModel& a_;
  const FclModel& b_;
  const Mat3 R_;
  const Vec3 T_;
  const double tolerance_;
  std::vector<TrianglePairHit>* hits_;
};

// Depth-first over one hierarchy, descending where `keep(bounding volume)` holds.
template <typename Keep>
void CollectTriangles(const FclModel& model, int node, const Keep& keep,
                      std::vector<int>* triangles) {
  const fcl::BVNode<fcl::OBBRSSd>& n = model.getBV(node);
  if (!keep(n.bv.obb)) return;
  if (n.isLeaf()) {
    triangles->push_back(n.primitiveId());
    return;
  }
  CollectTriangles(model, n.leftChild(), keep, triangles);
  CollectTriangles(model, n.rightChild(), keep, triangles);
}

}  // namespace

namespace mesh_detail {

const MeshTopology& Topology(const MeshBvh& bvh) {
  return bvh.topology;
}

void NearTrianglePairs(const MeshBvh& a, const MeshBvh& b, const Pose& X_ab, double tolerance,
                       std::vector<TrianglePairHit>* hits) {
  if (a.model.getNumBVs() == 0 || b.model.getNumBVs() == 0) return;
  PairTraversal(a.model, b.model, X_ab, tolerance, hits).Visit(0, 0);
}

void TrianglesNearBox(const MeshBvh& bvh, const Pose& X_mesh_box, const Vec3& half_extents,
                      std::vector<int>* triangles) {
  if (bvh.model.getNumBVs() == 0) return;
  fcl::OBBd box;
  box.axis = X_mesh_box.linear();
  box.To = X_mesh_box.translation();
  box.extent = half_extents;
  CollectTriangles(
      bvh.model, 0, [&box](const fcl::OBBd& volume) { return volume.overlap(box); }, triangles);
}

void TrianglesBelowPlane(const MeshBvh& bvh, const Vec3& normal, double height,
                         std::vector<int>* triangles) {
  if (bvh.model.getNumBVs() == 0) return;
  const auto below = [&normal, height](const fcl::OBBd& volume) {
    const double reach = (volume.axis.transpose() * normal).cwiseAbs().dot(volume.extent);
    return normal.dot(volume.To) - reach < height;
  };
  CollectTriangles(bvh.model, 0, below, triangles);
}

}  // namespace mesh_detail

std::shared_ptr<const CollisionGeometry> CollisionGeometry::Build(const GeometryDesc& desc) {
  if (desc.kind == GeometryKind::kNone) return nullptr;
  auto geometry = std::make_shared<CollisionGeometry>();
  geometry->margin_ = desc.margin;
  if (desc.kind == GeometryKind::kPrimitive) {
    const std::optional<Primitive> placed =
        PlacedPrimitive(desc.primitive, desc.Matrix() * desc.primitive.pose);
    if (placed) {
      geometry->kind_ = Kind::kPrimitive;
      geometry->primitive_ = *placed;
      geometry->local_bounds_ = PrimitiveBounds(*placed);
      return geometry;
    }
  }
  geometry->kind_ = Kind::kMesh;
  geometry->mesh_ = BakedMesh(desc);
  if (geometry->mesh_.triangles.empty()) return nullptr;
  geometry->triangle_normals_ = TriangleNormals(geometry->mesh_);
  geometry->bvh_ = BuildBvh(geometry->mesh_, geometry->triangle_normals_);
  geometry->local_bounds_ = geometry->mesh_.Bounds();
  return geometry;
}

std::shared_ptr<const CollisionGeometry> CollisionGeometryCache::Get(const GeometryDesc& desc) {
  if (desc.kind == GeometryKind::kNone) return nullptr;
  // the key: the shared mesh (null for primitives), then every number that shapes the result
  std::vector<double> numbers;
  const Affine matrix = desc.Matrix();
  numbers.assign(matrix.matrix().data(), matrix.matrix().data() + 16);
  numbers.push_back(desc.margin);
  if (desc.kind == GeometryKind::kPrimitive) {
    const Primitive& p = desc.primitive;
    numbers.push_back(static_cast<double>(p.type));
    numbers.insert(numbers.end(), {p.radius, p.length, p.size.x(), p.size.y(), p.size.z()});
    numbers.insert(numbers.end(), p.pose.matrix().data(), p.pose.matrix().data() + 16);
  }
  const TriangleMesh* mesh = desc.kind == GeometryKind::kMesh ? desc.mesh.get() : nullptr;
  auto key = std::make_pair(mesh, std::move(numbers));
  const auto found = cache_.find(key);
  if (found != cache_.end()) return found->second;
  std::shared_ptr<const CollisionGeometry> built = CollisionGeometry::Build(desc);
  cache_.emplace(std::move(key), built);
  return built;
}

}  // namespace lamina::core
