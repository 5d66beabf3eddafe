// SPDX-License-Identifier: MIT
// Collision geometry construction and the FCL adapter: the one translation unit that includes
// FCL. Holds the bounding-volume hierarchy of each mesh and the traversals the contact
// routines need (FCL has no "all pairs within a tolerance" query).
#include "core/contact/collision_geometry.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <optional>
#include <tuple>

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/narrowphase/detail/primitive_shape_algorithm/triangle_distance.h>

#include "core/contact/mesh_query.h"
#include "core/contact/near_pair_cache.h"
#include "core/contact/point_cloud_contacts.h"

namespace lamina::core {

struct MeshBvh {
  fcl::BVHModel<fcl::OBBRSSd> model;
  mesh_detail::MeshTopology topology;
  /// The plane of a triangle: normal.dot(x) == offset on it; a zero normal if degenerate.
  struct Plane {
    Vec3 normal = Vec3::Zero();
    double offset = 0.0;
  };
  /// Per triangle, its corners, and its axis-aligned bounds and plane (the cheap tests that
  /// spare most far triangle pairs the exact distance), in the mesh frame.
  std::vector<std::array<Vec3, 3>> triangle_corners;
  std::vector<Eigen::AlignedBox3d> triangle_bounds;
  std::vector<Plane> triangle_planes;
  /// Per triangle, the planes through its edges, perpendicular to it and facing away from it:
  /// the triangle lies on their inner side (normal.dot(x) <= offset). A zero normal and an
  /// infinite offset where the triangle is degenerate.
  std::vector<std::array<Plane, 3>> edge_planes;
  /// Per hierarchy node, the radius of the sphere about its box's centre that holds the box.
  std::vector<double> node_radii;
  /// The largest distance of a vertex from the mesh's origin (m; near_pair_cache.h).
  double vertex_radius = 0.0;
  /// Unique to this hierarchy in the process (a cache of triangle pairs names meshes by it).
  std::uint64_t serial = 0;
};

namespace {

using mesh_detail::MeshTopology;
using mesh_detail::PairSearch;
using mesh_detail::TrianglePairHit;

using FclModel = fcl::BVHModel<fcl::OBBRSSd>;

// a triangle whose corner angle's sine is below this is flat: its cross product is rounding
// (HRP-2's arm has a triangle through an edge's midpoint, sine 9.5e-16, whose "normal" pointed
// anywhere), so it gets no normal, as one of exactly collinear corners does
constexpr double kFlatSine = 1e-12;

// unit outward normals; zero for a triangle without area (every contact routine skips those)
std::vector<Vec3> TriangleNormals(const TriangleMesh& mesh) {
  std::vector<Vec3> normals;
  normals.reserve(mesh.triangles.size());
  for (const Eigen::Vector3i& t : mesh.triangles) {
    const Vec3& a = mesh.vertices[t[0]];
    const Vec3 e0 = mesh.vertices[t[1]] - a, e1 = mesh.vertices[t[2]] - a;
    const Vec3 n = e0.cross(e1);
    const double length = n.norm();
    const bool flat = !(length > kFlatSine * e0.norm() * e1.norm());
    normals.push_back(flat ? Vec3::Zero() : Vec3(n / length));
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

Eigen::AlignedBox3d TriangleBounds(const Vec3& p, const Vec3& q, const Vec3& r) {
  return Eigen::AlignedBox3d(p.cwiseMin(q).cwiseMin(r), p.cwiseMax(q).cwiseMax(r));
}

std::vector<std::array<Vec3, 3>> AllTriangleCorners(const TriangleMesh& mesh) {
  std::vector<std::array<Vec3, 3>> corners;
  corners.reserve(mesh.triangles.size());
  for (const Eigen::Vector3i& t : mesh.triangles) {
    corners.push_back({mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]});
  }
  return corners;
}

std::vector<Eigen::AlignedBox3d> AllTriangleBounds(
    const std::vector<std::array<Vec3, 3>>& triangle_corners) {
  std::vector<Eigen::AlignedBox3d> bounds;
  bounds.reserve(triangle_corners.size());
  for (const std::array<Vec3, 3>& c : triangle_corners) {
    bounds.push_back(TriangleBounds(c[0], c[1], c[2]));
  }
  return bounds;
}

std::vector<MeshBvh::Plane> AllTrianglePlanes(const TriangleMesh& mesh,
                                              const std::vector<Vec3>& face_normals) {
  std::vector<MeshBvh::Plane> planes;
  planes.reserve(mesh.triangles.size());
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Vec3& n = face_normals[t];
    planes.push_back({n, n.dot(mesh.vertices[mesh.triangles[t][0]])});
  }
  return planes;
}

// The plane through the edge of c opposite corner k, perpendicular to c, with c behind it.
MeshBvh::Plane EdgePlane(const std::array<Vec3, 3>& c, int k) {
  const Vec3 face = (c[1] - c[0]).cross(c[2] - c[0]);
  const Vec3& start = c[(k + 1) % 3];
  const Vec3 normal = (c[(k + 2) % 3] - start).cross(face);
  const double length = normal.norm();
  if (!(length > 0.0)) return {Vec3::Zero(), kInf};
  const Vec3 unit = normal.dot(c[k] - start) > 0.0 ? Vec3(-normal / length) : Vec3(normal / length);
  return {unit, unit.dot(start)};
}

std::vector<std::array<MeshBvh::Plane, 3>> AllEdgePlanes(
    const std::vector<std::array<Vec3, 3>>& triangle_corners) {
  std::vector<std::array<MeshBvh::Plane, 3>> planes;
  planes.reserve(triangle_corners.size());
  for (const std::array<Vec3, 3>& c : triangle_corners) {
    planes.push_back({EdgePlane(c, 0), EdgePlane(c, 1), EdgePlane(c, 2)});
  }
  return planes;
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
  bvh->triangle_corners = AllTriangleCorners(mesh);
  bvh->triangle_bounds = AllTriangleBounds(bvh->triangle_corners);
  bvh->triangle_planes = AllTrianglePlanes(mesh, face_normals);
  bvh->edge_planes = AllEdgePlanes(bvh->triangle_corners);
  for (int node = 0; node < bvh->model.getNumBVs(); ++node) {
    bvh->node_radii.push_back(bvh->model.getBV(node).bv.obb.extent.norm());
  }
  for (const Vec3& v : mesh.vertices) bvh->vertex_radius = std::max(bvh->vertex_radius, v.norm());
  static std::atomic<std::uint64_t> next_serial{1};
  bvh->serial = next_serial++;
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
std::optional<Primitive> PrimitiveUnder(const Primitive& primitive, const Affine& F) {
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

// Box tests prune only pairs farther apart than the tolerance by this much more (m): far beyond
// the rounding of any distance here, so that every search path keeps the same triangle pairs.
constexpr double kBoundsSlack = 1e-9;
// Meshes this small against each other test every triangle pair (bounds first): cheaper than
// traversing two hierarchies whose volumes nearly all overlap when small meshes touch.
constexpr long kEveryPairLimit = 4096;
// Up to this many pairs every pair is tested whatever the meshes' sizes (two 12-triangle cubes).
constexpr long kEveryPairAlways = 256;
// A mesh this small is bounded as a whole and run through the other mesh's hierarchy, before
// every pair is tried: a two-triangle floor under a 724-triangle wheel (ATHLETE) keeps only the
// wheel's triangles near the floor's slab instead of testing all 1448 pairs.
constexpr int kSmallMeshTriangles = 64;
// ... as long as this many pairs at most are near the bounds: testing a pair's boxes costs far
// less than comparing two volumes of the hierarchies (a 960-triangle ball sunk into its padding
// on a 12-triangle slab has half its triangles, 5800 pairs, near the slab).
constexpr long kSmallerInLargerPairLimit = 16384;

// A triangle of b in a's frame with its bounds, plane and edge planes there.
struct PlacedTriangle {
  std::array<Vec3, 3> corners;
  Eigen::AlignedBox3d bounds;
  MeshBvh::Plane plane;
  std::array<MeshBvh::Plane, 3> edges;
};

// True when the boxes are more than `reach` apart along an axis: so is every pair of points.
bool Apart(const Eigen::AlignedBox3d& x, const Eigen::AlignedBox3d& y, double reach) {
  return ((x.min() - y.max()).array() > reach).any() || ((y.min() - x.max()).array() > reach).any();
}

// True when all three corners lie more than `reach` to one side of the plane.
bool Beyond(const MeshBvh::Plane& plane, const std::array<Vec3, 3>& corners, double reach) {
  const Vec3 heights(plane.normal.dot(corners[0]), plane.normal.dot(corners[1]),
                     plane.normal.dot(corners[2]));
  return heights.minCoeff() - plane.offset > reach || heights.maxCoeff() - plane.offset < -reach;
}

// True when all three corners lie more than `reach` outside one of the edge planes of a
// triangle: every point of the corners' triangle is then farther than `reach` from it (it lies
// behind each of its edge planes).
bool BeyondAnEdge(const std::array<MeshBvh::Plane, 3>& edges, const std::array<Vec3, 3>& corners,
                  double reach) {
  for (const MeshBvh::Plane& edge : edges) {
    const double lowest = std::min(
        {edge.normal.dot(corners[0]), edge.normal.dot(corners[1]), edge.normal.dot(corners[2])});
    if (lowest - edge.offset > reach) return true;
  }
  return false;
}

// The corner of `corners` nearest to the triangle of `plane` and `edges` when that settles the
// pair's distance, or -1: all three corners lie strictly on one side of the plane (so every
// point of their triangle is at least as far from the plane as the nearest corner) and the
// nearest corner (lowest index on ties) lies within the edge planes (its foot on the plane is a
// point of the triangle). `height` is then its signed height over the plane. Degenerate
// triangles (zero normal) and non-finite corners give -1.
int CornerOverFace(const MeshBvh::Plane& plane, const std::array<MeshBvh::Plane, 3>& edges,
                   const std::array<Vec3, 3>& corners, double* height) {
  const Vec3 h(plane.normal.dot(corners[0]) - plane.offset,
               plane.normal.dot(corners[1]) - plane.offset,
               plane.normal.dot(corners[2]) - plane.offset);
  if (!((h.array() > 0.0).all() || (h.array() < 0.0).all())) return -1;
  int nearest = 0;
  for (int k = 1; k < 3; ++k) {
    if (std::abs(h[k]) < std::abs(h[nearest])) nearest = k;
  }
  for (const MeshBvh::Plane& edge : edges) {
    if (!(edge.normal.dot(corners[nearest]) <= edge.offset)) return -1;
  }
  *height = h[nearest];
  return nearest;
}

// False when the oriented box and the aligned box (centre, half extents) are separated along
// one of their six face axes (a conservative overlap test).
bool MayOverlap(const fcl::OBBd& volume, const Vec3& centre, const Vec3& half) {
  const Vec3 offset = volume.To - centre;
  const Mat3& axes = volume.axis;
  const Vec3 volume_reach = axes.cwiseAbs() * volume.extent;
  if (((offset.cwiseAbs() - volume_reach - half).array() > 0.0).any()) return false;
  const Vec3 box_reach = axes.transpose().cwiseAbs() * half;
  return !(((axes.transpose() * offset).cwiseAbs() - box_reach - volume.extent).array() > 0.0)
              .any();
}

// A bounding volume of b in a's frame: the centre of its box, and its rectangle's axes and
// centre.
struct PlacedVolume {
  Vec3 obb_centre;
  Mat3 rss_axis;
  Vec3 rss_centre;
};

// Working memory of NearPairSearch, kept between queries so that a query does not allocate.
struct PairSearchScratch {
  mesh_detail::SparseArray<PlacedTriangle> placed_triangles;  // b's, in a's frame
  mesh_detail::SparseArray<PlacedVolume> placed_volumes;      // b's, in a's frame
  std::vector<int> triangles;                                 // SmallerInLarger's near ones
  std::vector<int> partners;  // the smaller mesh's triangles near those
};

PairSearchScratch& SearchScratch() {
  thread_local PairSearchScratch scratch;
  return scratch;
}

// Depth-first over one hierarchy, descending where `keep(bounding volume)` holds. Gives up
// (returns false) once `triangles` holds more than `limit`.
template <typename Keep>
bool CollectTriangles(const FclModel& model, int node, const Keep& keep, size_t limit,
                      std::vector<int>* triangles) {
  const fcl::BVNode<fcl::OBBRSSd>& n = model.getBV(node);
  if (!keep(n.bv.obb)) return true;
  if (n.isLeaf()) {
    triangles->push_back(n.primitiveId());
    return triangles->size() <= limit;
  }
  return CollectTriangles(model, n.leftChild(), keep, limit, triangles) &&
         CollectTriangles(model, n.rightChild(), keep, limit, triangles);
}

// Triangles of `model` whose volumes may come within reach of `bounds` (model frame), sorted;
// false if there are more than `limit`.
bool TrianglesNearBounds(const FclModel& model, const Eigen::AlignedBox3d& bounds, double reach,
                         size_t limit, std::vector<int>* triangles) {
  const Vec3 centre = bounds.center();
  const Vec3 half = 0.5 * bounds.sizes() + Vec3::Constant(reach);
  const auto near = [&centre, &half](const fcl::OBBd& volume) {
    return MayOverlap(volume, centre, half);
  };
  if (!CollectTriangles(model, 0, near, limit, triangles)) return false;
  std::sort(triangles->begin(), triangles->end());
  return true;
}

// Every pair of a triangle of a and a triangle of b (placed in a's frame by R, T) within the
// tolerance. Each path only narrows down the candidates; the test of a pair is always the
// same: the triangles' bounds and planes, then the exact triangle distance (Measure) with b's
// corners computed as R v + T (as FCL itself maps them), so all paths report bitwise the same
// pairs.
class NearPairSearch {
 public:
  // Reports into `hits` the pairs within `tolerance`, or, with `candidates`, collects the pairs
  // its cheap tests keep (no distance measured) there instead.
  NearPairSearch(const MeshBvh& a, const MeshBvh& b, const Pose& X_ab, double tolerance,
                 std::vector<TrianglePairHit>* hits,
                 std::vector<std::pair<int, int>>* candidates = nullptr)
      : a_(a),
        b_(b),
        X_ab_(X_ab),
        R_(X_ab.linear()),
        T_(X_ab.translation()),
        tolerance_(tolerance),
        reach_(tolerance + kBoundsSlack),
        hits_(hits),
        candidates_(candidates),
        scratch_(SearchScratch()) {
    scratch_.placed_triangles.Clear(b.model.num_tris);
    scratch_.placed_volumes.Clear(b.model.getNumBVs());
  }

  // The exact distance (Measure) of every pair, without the cheap tests that spare most pairs:
  // what the searches below must reproduce bitwise.
  void Reference() const {
    for (int ta = 0; ta < a_.model.num_tris; ++ta) {
      for (int tb = 0; tb < b_.model.num_tris; ++tb) Measure(ta, tb, PlacedOfB(tb));
    }
  }

  // Every triangle of a against every triangle of b.
  void EveryPair() const {
    for (int ta = 0; ta < a_.model.num_tris; ++ta) {
      for (int tb = 0; tb < b_.model.num_tris; ++tb) Test(ta, tb);
    }
  }

  // The bounds of the mesh with fewer triangles through the other's hierarchy, then the
  // triangles found there against every triangle of the smaller mesh whose box is within reach
  // of theirs (a ball's triangles near a slab against the slab's top face only). Finds nothing and
  // returns false when more than `limit` triangles are near the bounds: a small mesh may
  // still span a large one.
  bool SmallerInLarger(size_t limit) const {
    std::vector<int>& near = scratch_.triangles;
    near.clear();
    if (b_.model.num_tris <= a_.model.num_tris) {
      Eigen::AlignedBox3d bounds;
      for (int tb = 0; tb < b_.model.num_tris; ++tb) bounds.extend(PlacedOfB(tb).bounds);
      if (!TrianglesNearBounds(a_.model, bounds, reach_, limit, &near)) return false;
      Eigen::AlignedBox3d near_bounds;
      for (const int ta : near) near_bounds.extend(a_.triangle_bounds[ta]);
      std::vector<int>& partners = scratch_.partners;
      partners.clear();
      for (int tb = 0; tb < b_.model.num_tris; ++tb) {
        if (!Apart(near_bounds, PlacedOfB(tb).bounds, reach_)) partners.push_back(tb);
      }
      for (const int ta : near) {
        for (const int tb : partners) Test(ta, tb);
      }
    } else {
      const Pose X_ba = X_ab_.inverse();
      Eigen::AlignedBox3d bounds;
      for (int v = 0; v < a_.model.num_vertices; ++v) bounds.extend(X_ba * a_.model.vertices[v]);
      if (!TrianglesNearBounds(b_.model, bounds, reach_, limit, &near)) return false;
      Eigen::AlignedBox3d near_bounds;
      for (const int tb : near) near_bounds.extend(PlacedOfB(tb).bounds);
      for (int ta = 0; ta < a_.model.num_tris; ++ta) {
        if (Apart(a_.triangle_bounds[ta], near_bounds, reach_)) continue;
        for (const int tb : near) Test(ta, tb);
      }
    }
    return true;
  }

  // The given pairs only (sorted: the hits come in their order). With `directly`, a pair whose
  // boxes meet is measured without Test's plane tests: they only spare Measure pairs beyond reach,
  // which it would not report either (Reference measures every pair), so the hits are the same
  // to the last bit. Returns how many pairs were measured or tested past their boxes.
  size_t Pairs(const std::vector<std::pair<int, int>>& pairs, bool directly) const {
    size_t near = 0;
    for (const auto& [ta, tb] : pairs) {
      const PlacedTriangle& placed = PlacedOfB(tb);
      if (Apart(a_.triangle_bounds[ta], placed.bounds, reach_)) continue;
      ++near;
      if (directly) {
        Measure(ta, tb, placed);
      } else {
        TestPlanes(ta, tb, placed);
      }
    }
    return near;
  }

  // A traversal of both hierarchies, pairs of nodes pruned by the distance between their
  // bounding volumes; the pairs then sorted.
  void BothHierarchies() const {
    if (candidates_ != nullptr) {
      const size_t first = candidates_->size();
      Visit(0, 0);
      std::sort(candidates_->begin() + static_cast<std::ptrdiff_t>(first), candidates_->end());
      return;
    }
    const size_t first = hits_->size();
    Visit(0, 0);
    std::sort(hits_->begin() + static_cast<std::ptrdiff_t>(first), hits_->end(),
              [](const TrianglePairHit& x, const TrianglePairHit& y) {
                return std::tie(x.triangle_a, x.triangle_b) < std::tie(y.triangle_a, y.triangle_b);
              });
  }

 private:
  // Triangle tb of b in a's frame, mapped on first use in the query.
  const PlacedTriangle& PlacedOfB(int tb) const {
    if (scratch_.placed_triangles.Has(tb)) return scratch_.placed_triangles[tb];
    const std::array<Vec3, 3>& corners = b_.triangle_corners[tb];
    PlacedTriangle& placed = scratch_.placed_triangles.Set(tb);
    for (int k = 0; k < 3; ++k) placed.corners[k] = R_ * corners[k] + T_;
    placed.bounds = TriangleBounds(placed.corners[0], placed.corners[1], placed.corners[2]);
    placed.plane.normal = R_ * b_.triangle_planes[tb].normal;
    placed.plane.offset = placed.plane.normal.dot(placed.corners[0]);
    for (int k = 0; k < 3; ++k) {  // the edge opposite corner k starts at corner k + 1
      const MeshBvh::Plane& edge = b_.edge_planes[tb][k];
      placed.edges[k].normal = R_ * edge.normal;
      placed.edges[k].offset = std::isfinite(edge.offset)
                                   ? placed.edges[k].normal.dot(placed.corners[(k + 1) % 3])
                                   : kInf;
    }
    return placed;
  }

  void Test(int ta, int tb) const {
    const PlacedTriangle& placed = PlacedOfB(tb);
    if (!Apart(a_.triangle_bounds[ta], placed.bounds, reach_)) TestPlanes(ta, tb, placed);
  }

  // Test past the boxes: the planes and edge planes, then the distance or the candidate list.
  void TestPlanes(int ta, int tb, const PlacedTriangle& placed) const {
    const std::array<Vec3, 3>& corners = a_.triangle_corners[ta];
    if (Beyond(a_.triangle_planes[ta], placed.corners, reach_) ||
        Beyond(placed.plane, corners, reach_) || BeyondAnEdge(placed.edges, corners, reach_) ||
        BeyondAnEdge(a_.edge_planes[ta], placed.corners, reach_)) {
      return;
    }
    if (candidates_ != nullptr) {
      candidates_->emplace_back(ta, tb);
    } else {
      Measure(ta, tb, placed);
    }
  }

  // The pair's exact distance, kept within the tolerance: a corner over the other face when
  // that settles it (CornerOverFace), else FCL's general routine.
  void Measure(int ta, int tb, const PlacedTriangle& placed) const {
    using Foot = TrianglePairHit::Foot;
    const std::array<Vec3, 3>& corners_a = a_.triangle_corners[ta];
    const MeshBvh::Plane& plane_a = a_.triangle_planes[ta];
    TrianglePairHit hit{ta, tb};
    double height = 0.0;
    if (const int k = CornerOverFace(plane_a, a_.edge_planes[ta], placed.corners, &height);
        k >= 0) {
      hit.foot = Foot::kCornerOfBOverA;
      hit.corner = k;
      hit.distance = std::abs(height);
      hit.point_b = placed.corners[k];
      hit.point_a = hit.point_b - height * plane_a.normal;
    } else if (const int j = CornerOverFace(placed.plane, placed.edges, corners_a, &height);
               j >= 0) {
      hit.foot = Foot::kCornerOfAOverB;
      hit.corner = j;
      hit.distance = std::abs(height);
      hit.point_a = corners_a[j];
      hit.point_b = hit.point_a - height * placed.plane.normal;
    } else {
      fcl::Vector3d p, q;
      hit.distance = fcl::detail::TriangleDistance<double>::triDistance(
          corners_a.data(), placed.corners.data(), p, q);
      hit.point_a = p;
      hit.point_b = q;
    }
    if (hit.distance <= tolerance_) hits_->push_back(hit);
  }

  void Visit(int node_a, int node_b) const {
    const fcl::BVNode<fcl::OBBRSSd>& na = a_.model.getBV(node_a);
    const fcl::BVNode<fcl::OBBRSSd>& nb = b_.model.getBV(node_b);
    if (Far(node_a, node_b)) return;
    if (na.isLeaf() && nb.isLeaf()) {
      Test(na.primitiveId(), nb.primitiveId());
    } else if (nb.isLeaf() || (!na.isLeaf() && na.bv.size() >= nb.bv.size())) {
      Visit(na.leftChild(), node_b);
      Visit(na.rightChild(), node_b);
    } else {
      Visit(node_a, nb.leftChild());
      Visit(node_a, nb.rightChild());
    }
  }

  // Node b's volume in a's frame, mapped on the first visit of the query.
  const PlacedVolume& PlacedVolumeOfB(int node_b) const {
    mesh_detail::SparseArray<PlacedVolume>& placed = scratch_.placed_volumes;
    if (!placed.Has(node_b)) {
      const fcl::OBBRSSd& v = b_.model.getBV(node_b).bv;
      placed.Set(node_b) = {R_ * v.obb.To + T_, R_ * v.rss.axis, R_ * v.rss.To + T_};
    }
    return placed[node_b];
  }

  // The volumes' spheres beyond reach, or else FCL's RSS distance (the rectangles' distance
  // minus the radii) beyond reach. (FCL's box test on top prunes hardly more and costs as much.)
  bool Far(int node_a, int node_b) const {
    const fcl::OBBRSSd& va = a_.model.getBV(node_a).bv;
    const fcl::OBBRSSd& vb = b_.model.getBV(node_b).bv;
    const PlacedVolume& pb = PlacedVolumeOfB(node_b);
    const double spheres = a_.node_radii[node_a] + b_.node_radii[node_b] + reach_;
    if ((pb.obb_centre - va.obb.To).squaredNorm() > spheres * spheres) return true;
    const Mat3 at = va.rss.axis.transpose();
    const Mat3 B = at * pb.rss_axis;
    const Vec3 T = at * (pb.rss_centre - va.rss.To);
    return fcl::rectDistance(B, T, va.rss.l, vb.rss.l) - va.rss.r - vb.rss.r > reach_;
  }

  const MeshBvh& a_;
  const MeshBvh& b_;
  const Pose X_ab_;
  const Mat3 R_;
  const Vec3 T_;
  const double tolerance_;
  const double reach_;
  std::vector<TrianglePairHit>* hits_;
  std::vector<std::pair<int, int>>* candidates_;
  PairSearchScratch& scratch_;
};

}  // namespace

namespace mesh_detail {

const MeshTopology& Topology(const MeshBvh& bvh) {
  return bvh.topology;
}

namespace {

void Search(const NearPairSearch& finder, const MeshBvh& a, const MeshBvh& b, PairSearch search) {
  const long pairs = static_cast<long>(a.model.num_tris) * b.model.num_tris;
  const int fewer = std::min(a.model.num_tris, b.model.num_tris);
  switch (search) {
    case PairSearch::kAuto:
      if (pairs > kEveryPairAlways && fewer <= kSmallMeshTriangles &&
          finder.SmallerInLarger(kSmallerInLargerPairLimit / fewer)) {
        break;
      }
      if (pairs <= kEveryPairLimit) {
        finder.EveryPair();
      } else {
        finder.BothHierarchies();
      }
      break;
    case PairSearch::kReference:
      finder.Reference();
      break;
    case PairSearch::kEveryPair:
      finder.EveryPair();
      break;
    case PairSearch::kSmallerInLarger:
      finder.SmallerInLarger(std::numeric_limits<size_t>::max());
      break;
    case PairSearch::kBothHierarchies:
      finder.BothHierarchies();
      break;
  }
}

// The candidates of the tolerance widened by the cache's slack, from a search of the hierarchies
// at the current pose (near_pair_cache.h).
void CollectCandidates(const MeshBvh& a, const MeshBvh& b, const Pose& X_ab, double tolerance,
                       NearPairCache* cache) {
  cache->mesh_a = a.serial;
  cache->mesh_b = b.serial;
  cache->tolerance = tolerance;
  cache->slack = NearPairSlack(tolerance);
  cache->X_ab = X_ab;
  cache->candidates.clear();
  const NearPairSearch collector(a, b, X_ab, tolerance + cache->slack, nullptr, &cache->candidates);
  Search(collector, a, b, PairSearch::kAuto);
  if (!std::is_sorted(cache->candidates.begin(), cache->candidates.end())) {
    std::sort(cache->candidates.begin(), cache->candidates.end());
  }
  ++cache->collections;
}

}  // namespace

void NearTrianglePairs(const MeshBvh& a, const MeshBvh& b, const Pose& X_ab, double tolerance,
                       std::vector<TrianglePairHit>* hits, PairSearch search,
                       NearPairCache* cache) {
  if (a.model.getNumBVs() == 0 || b.model.getNumBVs() == 0) return;
  if (cache == nullptr || search != PairSearch::kAuto) {
    Search(NearPairSearch(a, b, X_ab, tolerance, hits), a, b, search);
    return;
  }
  if (NearPairCacheHolds(*cache, a.serial, b.serial, tolerance, X_ab, a.vertex_radius,
                         b.vertex_radius)) {
    ++cache->reuses;
  } else {
    CollectCandidates(a, b, X_ab, tolerance, cache);
  }
  const size_t first = hits->size();
  const size_t near =
      NearPairSearch(a, b, X_ab, tolerance, hits).Pairs(cache->candidates, cache->measure_directly);
  cache->measure_directly =
      static_cast<double>(hits->size() - first) >= kDirectMeasureHits * static_cast<double>(near);
}

void TrianglesNearBox(const MeshBvh& bvh, const Pose& X_mesh_box, const Vec3& half_extents,
                      std::vector<int>* triangles) {
  if (bvh.model.getNumBVs() == 0) return;
  fcl::OBBd box;
  box.axis = X_mesh_box.linear();
  box.To = X_mesh_box.translation();
  box.extent = half_extents;
  const auto overlaps = [&box](const fcl::OBBd& volume) { return volume.overlap(box); };
  CollectTriangles(bvh.model, 0, overlaps, std::numeric_limits<size_t>::max(), triangles);
}

void TrianglesNearAlignedBox(const MeshBvh& bvh, const Eigen::AlignedBox3d& bounds, double reach,
                             std::vector<int>* triangles) {
  if (bvh.model.getNumBVs() == 0 || bounds.isEmpty()) return;
  TrianglesNearBounds(bvh.model, bounds, reach, std::numeric_limits<size_t>::max(), triangles);
}

void TrianglesBelowPlane(const MeshBvh& bvh, const Vec3& normal, double height,
                         std::vector<int>* triangles) {
  if (bvh.model.getNumBVs() == 0) return;
  const auto below = [&normal, height](const fcl::OBBd& volume) {
    const double reach = (volume.axis.transpose() * normal).cwiseAbs().dot(volume.extent);
    return normal.dot(volume.To) - reach < height;
  };
  CollectTriangles(bvh.model, 0, below, std::numeric_limits<size_t>::max(), triangles);
}

}  // namespace mesh_detail

std::shared_ptr<const CollisionGeometry> CollisionGeometry::Build(const GeometryDesc& desc) {
  if (desc.kind == GeometryKind::kNone) return nullptr;
  auto geometry = std::make_shared<CollisionGeometry>();
  geometry->margin_ = desc.margin;
  if (desc.kind == GeometryKind::kPointCloud) {
    geometry->kind_ = Kind::kPointCloud;
    geometry->points_ = BakedPoints(desc);
    if (geometry->points_.empty()) return nullptr;
    geometry->point_leaves_ =
        point_cloud_detail::PartitionPoints(kPointsPerLeaf, &geometry->points_);
    for (const PointLeaf& leaf : geometry->point_leaves_)
      geometry->local_bounds_.extend(leaf.bounds);
    return geometry;
  }
  if (desc.kind == GeometryKind::kPrimitive) {
    const std::optional<Primitive> placed =
        PrimitiveUnder(desc.primitive, desc.Matrix() * desc.primitive.pose);
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

namespace {

// the shared mesh or point cloud a geometry refers to; null for primitives
const void* SharedShape(const GeometryDesc& desc) {
  if (desc.kind == GeometryKind::kMesh) return desc.mesh.get();
  if (desc.kind == GeometryKind::kPointCloud) return desc.point_cloud.get();
  return nullptr;
}

}  // namespace

std::shared_ptr<const CollisionGeometry> CollisionGeometryCache::Get(const GeometryDesc& desc) {
  if (desc.kind == GeometryKind::kNone) return nullptr;
  // the key: the shared mesh or cloud (null for primitives), then every number that shapes it
  std::vector<double> numbers;
  const Affine matrix = desc.Matrix();
  numbers.assign(matrix.matrix().data(), matrix.matrix().data() + 16);
  numbers.push_back(desc.margin);
  numbers.push_back(static_cast<double>(desc.kind));
  if (desc.kind == GeometryKind::kPrimitive) {
    const Primitive& p = desc.primitive;
    numbers.push_back(static_cast<double>(p.type));
    numbers.insert(numbers.end(), {p.radius, p.length, p.size.x(), p.size.y(), p.size.z()});
    numbers.insert(numbers.end(), p.pose.matrix().data(), p.pose.matrix().data() + 16);
  }
  auto key = std::make_pair(SharedShape(desc), std::move(numbers));
  const auto found = cache_.find(key);
  if (found != cache_.end()) return found->second;
  std::shared_ptr<const CollisionGeometry> built = CollisionGeometry::Build(desc);
  cache_.emplace(std::move(key), built);
  return built;
}

}  // namespace lamina::core
