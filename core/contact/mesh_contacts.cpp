// SPDX-License-Identifier: MIT
// Mesh-mesh contacts (Klamp't's MeshMeshContacts on FCL hierarchies) and the feature normals
// of collision meshes. Mesh-primitive contacts are in mesh_primitive_contacts.cpp.
#include "core/contact/mesh_contacts.h"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "core/contact/mesh_query.h"
#include "core/contact/triangle_queries.h"

namespace lamina::core {

using mesh_detail::ClassifyFeature;
using mesh_detail::FeatureNormal;
using mesh_detail::Triangle3;
using mesh_detail::TriangleFeature;
using mesh_detail::TrianglePairHit;

namespace {

using mesh_detail::BarycentricCoordinates;
using mesh_detail::ClosestPointsOfTriangles;
using mesh_detail::kFeatureNormalDistance;
using mesh_detail::kMinNormalLength;
using mesh_detail::TrianglePairPoints;
using mesh_detail::TrianglesCross;

// Klamp't's rule: a barycentric coordinate this close to zero counts as zero
constexpr double kBarycentricZero = 1e-3;

Triangle3 MeshTriangle(const CollisionGeometry& mesh, int triangle,
                       const Pose& X = Pose::Identity()) {
  const Eigen::Vector3i& t = mesh.mesh().triangles[triangle];
  const std::vector<Vec3>& v = mesh.mesh().vertices;
  return {X * v[t[0]], X * v[t[1]], X * v[t[2]]};
}

Vec3 UnitOrZero(const Vec3& v) {
  const double length = v.norm();
  return length > 1e-12 ? Vec3(v / length) : Vec3::Zero();
}

// Direction of the edge opposite `corner` (frame of `triangle`).
Vec3 EdgeVector(const Triangle3& triangle, int corner) {
  return triangle[(corner + 2) % 3] - triangle[(corner + 1) % 3];
}

// `v` without its component along `edge`
Vec3 AcrossEdge(const Vec3& v, const Vec3& edge) {
  const double length2 = edge.squaredNorm();
  return length2 > 0.0 ? Vec3(v - edge * (edge.dot(v) / length2)) : v;
}

// Normal from b into a between two edges, both in a's frame (Klamp't: the cross product of
// the edge directions, oriented so that it separates the edges). Edges that touch exactly
// cannot be told apart by position: then the edge normals na, nb orient it.
Vec3 EdgeEdgeNormal(const Triangle3& ta, int ea, const Triangle3& tb, int eb, const Vec3& na,
                    const Vec3& nb) {
  const Vec3 n = EdgeVector(ta, ea).normalized().cross(EdgeVector(tb, eb).normalized());
  if (n.norm() < kMinNormalLength) return UnitOrZero(nb - na);  // parallel edges
  const Vec3 unit = n.normalized();
  const double separation = unit.dot(ta[(ea + 1) % 3] - tb[(eb + 1) % 3]);
  const bool flip = std::abs(separation) > 1e-12 ? separation < 0.0 : unit.dot(nb - na) < 0.0;
  return flip ? Vec3(-unit) : unit;
}

// Klamp't's ContactNormal: the normal from b into a at nearly coincident closest points p (on
// a's triangle) and q (on b's), all in a's frame.
Vec3 MeshMeshFeatureNormal(const CollisionGeometry& a, int ta, const CollisionGeometry& b, int tb,
                           const Pose& X_ab, const Vec3& p, const Vec3& q) {
  const Triangle3 tri_a = MeshTriangle(a, ta);
  const Triangle3 tri_b = MeshTriangle(b, tb, X_ab);
  const TriangleFeature fa = ClassifyFeature(BarycentricCoordinates(p, tri_a));
  const TriangleFeature fb = ClassifyFeature(BarycentricCoordinates(q, tri_b));
  using Type = TriangleFeature::Type;
  if (fa.type == Type::kFace) return -a.triangle_normals()[ta];
  const Mat3 R = X_ab.linear();
  if (fb.type == Type::kFace) return R * b.triangle_normals()[tb];
  const Vec3 na = FeatureNormal(a, ta, fa);
  const Vec3 nb = R * FeatureNormal(b, tb, fb);
  if (fa.type == Type::kVertex && fb.type == Type::kVertex) return UnitOrZero(nb - na);
  if (fa.type == Type::kVertex) return UnitOrZero(nb - AcrossEdge(na, EdgeVector(tri_b, fb.index)));
  if (fb.type == Type::kVertex) return UnitOrZero(AcrossEdge(nb, EdgeVector(tri_a, fa.index)) - na);
  return EdgeEdgeNormal(tri_a, fa.index, tri_b, fb.index, na, nb);
}

// A triangle pair within the tolerance; `crossing` when the triangles intersect.
struct PairCandidate {
  TrianglePairHit hit;
  bool crossing = false;
};

struct MeshMeshScratch {
  std::vector<TrianglePairHit> hits;
  std::vector<PairCandidate> candidates;
  std::vector<int> order;
  std::vector<int> selected;
};

MeshMeshScratch& Scratch() {
  thread_local MeshMeshScratch scratch;
  return scratch;
}

// Crossing pairs have distance 0 and their closest points at the middle of the crossing. FCL
// reports other pairs at distance exactly 0 (touching) with arbitrary points: those are
// recomputed from the triangles' features.
void FindCrossings(const CollisionGeometry& a, const CollisionGeometry& b, const Pose& X_ab,
                   MeshMeshScratch* s) {
  s->candidates.clear();
  for (const TrianglePairHit& hit : s->hits) {
    PairCandidate candidate{hit, false};
    if (hit.distance < kFeatureNormalDistance) {
      const Triangle3 ta = MeshTriangle(a, hit.triangle_a);
      const Triangle3 tb = MeshTriangle(b, hit.triangle_b, X_ab);
      Vec3 middle;
      if (TrianglesCross(ta, tb, &middle)) {
        candidate = {{hit.triangle_a, hit.triangle_b, 0.0, middle, middle}, true};
      } else if (hit.distance == 0.0) {
        const TrianglePairPoints points = ClosestPointsOfTriangles(ta, tb);
        candidate.hit.distance = points.distance;
        candidate.hit.point_a = points.on_a;
        candidate.hit.point_b = points.on_b;
      }
    }
    s->candidates.push_back(candidate);
  }
}

// Appends to `selected` the closest partner of every triangle of one side: `side` 0 groups by
// a's triangles, 1 by b's. Ties go to crossing pairs, then to the lower partner index.
void SelectClosestPartners(int side, MeshMeshScratch* s) {
  const auto key = [s, side](int i) {
    const PairCandidate& c = s->candidates[i];
    const int own = side == 0 ? c.hit.triangle_a : c.hit.triangle_b;
    const int partner = side == 0 ? c.hit.triangle_b : c.hit.triangle_a;
    return std::make_tuple(own, c.hit.distance, !c.crossing, partner);
  };
  std::sort(s->order.begin(), s->order.end(), [&key](int i, int j) { return key(i) < key(j); });
  for (size_t k = 0; k < s->order.size(); ++k) {
    if (k == 0 || std::get<0>(key(s->order[k])) != std::get<0>(key(s->order[k - 1]))) {
      s->selected.push_back(s->order[k]);
    }
  }
}

void SelectPairs(MeshMeshScratch* s) {
  s->order.resize(s->candidates.size());
  for (size_t i = 0; i < s->order.size(); ++i) s->order[i] = static_cast<int>(i);
  s->selected.clear();
  SelectClosestPartners(0, s);
  SelectClosestPartners(1, s);
  const auto pair = [s](int i) {
    return std::make_pair(s->candidates[i].hit.triangle_a, s->candidates[i].hit.triangle_b);
  };
  std::sort(s->selected.begin(), s->selected.end(),
            [&pair](int i, int j) { return pair(i) < pair(j); });
  s->selected.erase(std::unique(s->selected.begin(), s->selected.end()), s->selected.end());
}

}  // namespace

namespace mesh_detail {

TriangleFeature ClassifyFeature(const Vec3& barycentric) {
  int zeros = 0, zero_index = -1, largest = 0;
  for (int k = 0; k < 3; ++k) {
    if (std::abs(barycentric[k]) <= kBarycentricZero) {
      ++zeros;
      if (zero_index < 0) zero_index = k;
    }
    if (barycentric[k] > barycentric[largest]) largest = k;
  }
  if (zeros >= 2) return {TriangleFeature::Type::kVertex, largest};
  if (zeros == 1) return {TriangleFeature::Type::kEdge, zero_index};
  return {TriangleFeature::Type::kFace, 0};
}

Vec3 VertexNormal(const CollisionGeometry& mesh, int triangle, int corner) {
  return Topology(mesh.bvh()).vertex_normals[mesh.mesh().triangles[triangle][corner]];
}

Vec3 EdgeNormal(const CollisionGeometry& mesh, int triangle, int corner) {
  const Vec3& n = mesh.triangle_normals()[triangle];
  const int neighbor = Topology(mesh.bvh()).neighbors[triangle][corner];
  if (neighbor < 0) return n;
  const Vec3 sum = n + mesh.triangle_normals()[neighbor];
  return sum.norm() > 1e-12 ? Vec3(sum.normalized()) : n;
}

Vec3 FeatureNormal(const CollisionGeometry& mesh, int triangle, const TriangleFeature& feature) {
  switch (feature.type) {
    case TriangleFeature::Type::kVertex:
      return VertexNormal(mesh, triangle, feature.index);
    case TriangleFeature::Type::kEdge:
      return EdgeNormal(mesh, triangle, feature.index);
    case TriangleFeature::Type::kFace:
      break;
  }
  return mesh.triangle_normals()[triangle];
}

}  // namespace mesh_detail

void MeshMeshContacts(const CollisionGeometry& a, const Pose& X_Wa, double pad_a,
                      const CollisionGeometry& b, const Pose& X_Wb, double pad_b,
                      ContactList* out) {
  const double tolerance = pad_a + pad_b;
  const Pose X_ab = X_Wa.inverse() * X_Wb;
  MeshMeshScratch& s = Scratch();
  s.hits.clear();
  mesh_detail::NearTrianglePairs(a.bvh(), b.bvh(), X_ab, tolerance, &s.hits);
  if (s.hits.empty()) return;
  FindCrossings(a, b, X_ab, &s);
  SelectPairs(&s);
  for (const int i : s.selected) {
    const PairCandidate& c = s.candidates[i];
    const Vec3& p = c.hit.point_a;
    const Vec3& q = c.hit.point_b;
    const double d = c.hit.distance;
    const Vec3 n_a =
        d < kFeatureNormalDistance
            ? MeshMeshFeatureNormal(a, c.hit.triangle_a, b, c.hit.triangle_b, X_ab, p, q)
            : Vec3((p - q) / d);
    if (!(n_a.norm() >= kMinNormalLength)) continue;  // also rejects NaN
    Contact contact;
    contact.normal = X_Wa.linear() * n_a;
    // midway between the padded surfaces: p - pad_a n and q + pad_b n
    contact.position = X_Wa * (0.5 * (p + q)) + 0.5 * (pad_b - pad_a) * contact.normal;
    contact.depth = std::max(0.0, tolerance - d);
    contact.penetrating = c.crossing;
    out->push_back(contact);
  }
}

}  // namespace lamina::core
