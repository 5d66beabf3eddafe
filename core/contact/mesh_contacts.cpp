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

// barycentric slack for a vertex lying exactly over a face's edge
constexpr double kOverFaceTolerance = 1e-9;

// A mesh vertex over a face of the other mesh.
struct VertexHit {
  int vertex = 0;
  double distance = 0.0;       ///< signed along the face normal, negative behind the face
  Vec3 normal = Vec3::Zero();  ///< from b into a, in a's frame
  Vec3 on_a = Vec3::Zero();
  Vec3 on_b = Vec3::Zero();
};

struct MeshMeshScratch {
  std::vector<TrianglePairHit> hits;
  std::vector<PairCandidate> candidates;
  std::vector<int> order;
  std::vector<int> selected;
  std::vector<VertexHit> vertex_hits;
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

// The normal from b into a of a selected pair, in a's frame. When a closest point lies inside
// a face, that face's outward normal is used and the distance is signed along it, so a point
// that has sunk behind the face is pushed back out instead of further in (a closest-point
// direction flips when surfaces cross). Otherwise the feature normal or the closest-point
// direction, as Klamp't does.
Vec3 PairNormal(const CollisionGeometry& a, const CollisionGeometry& b, const Pose& X_ab,
                const PairCandidate& c, double* signed_distance, bool* from_face) {
  *from_face = false;
  const Vec3& p = c.hit.point_a;
  const Vec3& q = c.hit.point_b;
  const double d = c.hit.distance;
  if (!c.crossing) {
    using Type = TriangleFeature::Type;
    const Triangle3 tri_a = MeshTriangle(a, c.hit.triangle_a);
    const Triangle3 tri_b = MeshTriangle(b, c.hit.triangle_b, X_ab);
    const bool q_on_face = ClassifyFeature(BarycentricCoordinates(q, tri_b)).type == Type::kFace;
    const bool p_on_face = ClassifyFeature(BarycentricCoordinates(p, tri_a)).type == Type::kFace;
    // parallel faces: their closest points are an arbitrary spot of the overlap; the vertex
    // contacts (CollectVertexHits) hold such faces at their corners instead
    if (q_on_face && p_on_face) return Vec3::Zero();
    Vec3 face_normal = Vec3::Zero();
    if (q_on_face) {
      face_normal = X_ab.linear() * b.triangle_normals()[c.hit.triangle_b];
    } else if (p_on_face) {
      face_normal = -a.triangle_normals()[c.hit.triangle_a];
    }
    if (!face_normal.isZero()) {
      *signed_distance = face_normal.dot(p - q);
      *from_face = true;
      return face_normal;
    }
  }
  *signed_distance = d;
  return d < kFeatureNormalDistance
             ? MeshMeshFeatureNormal(a, c.hit.triangle_a, b, c.hit.triangle_b, X_ab, p, q)
             : Vec3((p - q) / d);
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

// Crossing triangles (the meshes interpenetrate beyond the boundary layer) give no usable
// normal: a side face crossing a bottom face would push sideways. They only take part when no
// triangle pair of the two meshes is separated, so deep overlaps still produce contacts.
void SelectPairs(MeshMeshScratch* s) {
  s->order.clear();
  for (size_t i = 0; i < s->candidates.size(); ++i) {
    if (!s->candidates[i].crossing) s->order.push_back(static_cast<int>(i));
  }
  if (s->order.empty()) {
    for (size_t i = 0; i < s->candidates.size(); ++i) s->order.push_back(static_cast<int>(i));
  }
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

// The vertices of one mesh that lie over a face of the other within `tolerance` (or behind it by
// less than `tolerance`), each with its nearest face: a face resting on a face touches at its
// corners, which the closest points of triangle pairs alone do not find. `from_a` picks whose
// vertices; everything is in a's frame.
void CollectVertexHits(const CollisionGeometry& a, const CollisionGeometry& b, const Pose& X_ab,
                       const std::vector<PairCandidate>& candidates, double tolerance, bool from_a,
                       std::vector<VertexHit>* hits) {
  hits->clear();
  const CollisionGeometry& own = from_a ? a : b;
  for (const PairCandidate& c : candidates) {
    const int own_triangle = from_a ? c.hit.triangle_a : c.hit.triangle_b;
    const int face = from_a ? c.hit.triangle_b : c.hit.triangle_a;
    const Triangle3 face_triangle = from_a ? MeshTriangle(b, face, X_ab) : MeshTriangle(a, face);
    const Vec3 outward =
        from_a ? Vec3(X_ab.linear() * b.triangle_normals()[face]) : a.triangle_normals()[face];
    for (int k = 0; k < 3; ++k) {
      const int vertex = own.mesh().triangles[own_triangle][k];
      const Vec3 v =
          from_a ? own.mesh().vertices[vertex] : Vec3(X_ab * own.mesh().vertices[vertex]);
      // the vertex must project onto the face or its boundary (aligned boxes put corners on
      // the partner's edges)
      const Vec3 barycentric = BarycentricCoordinates(v, face_triangle);
      if ((barycentric.array() < -kOverFaceTolerance).any()) continue;
      const Vec3 projected = barycentric[0] * face_triangle[0] + barycentric[1] * face_triangle[1] +
                             barycentric[2] * face_triangle[2];
      const double distance = outward.dot(v - projected);
      if (distance > tolerance || distance < -tolerance) continue;
      // touching the face's boundary: the face normal is one of several; the triangle pairs'
      // feature normals decide there
      const bool on_boundary = (barycentric.array() <= kOverFaceTolerance).any();
      if (on_boundary && std::abs(distance) < kFeatureNormalDistance) continue;
      VertexHit hit{vertex, distance, from_a ? outward : Vec3(-outward), v, projected};
      if (!from_a) std::swap(hit.on_a, hit.on_b);
      hits->push_back(hit);
    }
  }
  // keep each vertex's nearest face, in vertex order
  std::sort(hits->begin(), hits->end(), [](const VertexHit& x, const VertexHit& y) {
    return std::make_tuple(x.vertex, std::abs(x.distance)) <
           std::make_tuple(y.vertex, std::abs(y.distance));
  });
  hits->erase(
      std::unique(hits->begin(), hits->end(),
                  [](const VertexHit& x, const VertexHit& y) { return x.vertex == y.vertex; }),
      hits->end());
}

// a contact between point p on a and q on b (a's frame) with normal n (a's frame): positioned
// midway between the padded surfaces, p - pad_a n and q + pad_b n
void AppendContact(const Pose& X_Wa, double pad_a, double pad_b, const Vec3& p, const Vec3& q,
                   const Vec3& n, double depth, bool penetrating, ContactList* out) {
  Contact contact;
  contact.normal = X_Wa.linear() * n;
  contact.position = X_Wa * (0.5 * (p + q)) + 0.5 * (pad_b - pad_a) * contact.normal;
  contact.depth = std::max(0.0, depth);
  contact.penetrating = penetrating;
  out->push_back(contact);
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
  const bool crossing = std::any_of(s.candidates.begin(), s.candidates.end(),
                                    [](const PairCandidate& c) { return c.crossing; });
  SelectPairs(&s);
  // vertices over faces first: their face normals tell which way the pair separates
  Vec3 reference = Vec3::Zero();
  for (const bool from_a : {true, false}) {
    CollectVertexHits(a, b, X_ab, s.candidates, tolerance, from_a, &s.vertex_hits);
    for (const VertexHit& hit : s.vertex_hits) {
      reference += hit.normal;
      AppendContact(X_Wa, pad_a, pad_b, hit.on_a, hit.on_b, hit.normal, tolerance - hit.distance,
                    crossing || hit.distance < 0.0, out);
    }
  }
  for (const int i : s.selected) {
    const PairCandidate& c = s.candidates[i];
    double signed_distance = c.hit.distance;
    bool from_face = false;
    Vec3 n_a = PairNormal(a, b, X_ab, c, &signed_distance, &from_face);
    if (!(n_a.norm() >= kMinNormalLength)) continue;  // also rejects NaN
    if (!from_face && n_a.dot(reference) < 0.0) {
      // an edge or vertex closest-point direction flips once the surfaces have crossed
      n_a = -n_a;
      signed_distance = -signed_distance;
    }
    AppendContact(X_Wa, pad_a, pad_b, c.hit.point_a, c.hit.point_b, n_a,
                  tolerance - signed_distance, crossing || signed_distance < 0.0, out);
  }
}

}  // namespace lamina::core
