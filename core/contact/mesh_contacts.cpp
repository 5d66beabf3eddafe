// SPDX-License-Identifier: MIT
// Mesh-mesh contacts (Klamp't's MeshMeshContacts on FCL hierarchies) and the feature normals
// of collision meshes. Mesh-primitive contacts are in mesh_primitive_contacts.cpp.
#include "core/contact/mesh_contacts.h"

#include <algorithm>
#include <cmath>
#include <optional>
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
using mesh_detail::BarycentricMap;
using mesh_detail::ClosestPointsOfTriangles;
using mesh_detail::kFeatureNormalDistance;
using mesh_detail::kMinNormalLength;
using mesh_detail::SparseArray;
using mesh_detail::Topology;
using mesh_detail::TrianglePairPoints;
using mesh_detail::TrianglesCross;

// Klamp't's rule: a barycentric coordinate this close to zero counts as zero
constexpr double kBarycentricZero = 1e-3;
// two triangles whose normals are within 1° of each other make a flat edge
constexpr double kFlatEdgeCosine = 0.99984769515639127;  // cos(1°)

Triangle3 MeshTriangle(const CollisionGeometry& mesh, int triangle) {
  const Eigen::Vector3i& t = mesh.mesh().triangles[triangle];
  const std::vector<Vec3>& v = mesh.mesh().vertices;
  return {v[t[0]], v[t[1]], v[t[2]]};
}

// b's vertices in a's frame, each mapped once per query and only when asked for.
class PlacedVertices {
 public:
  void Reset(const TriangleMesh& mesh, const Pose& X) {
    mesh_ = &mesh;
    X_ = X;
    positions_.Clear(mesh.vertices.size());
  }

  const Vec3& operator[](int vertex) {
    if (!positions_.Has(vertex)) positions_.Set(vertex) = X_ * mesh_->vertices[vertex];
    return positions_[vertex];
  }

 private:
  const TriangleMesh* mesh_ = nullptr;
  Pose X_ = Pose::Identity();
  SparseArray<Vec3> positions_;
};

// The meshes of one query: a in its own frame, b placed in it by X_ab.
struct MeshPair {
  const CollisionGeometry& a;
  const CollisionGeometry& b;
  const Pose& X_ab;
  PlacedVertices* b_vertices;

  Triangle3 TriangleA(int t) const { return MeshTriangle(a, t); }
  Triangle3 TriangleB(int t) const {
    const Eigen::Vector3i& corners = b.mesh().triangles[t];
    return {(*b_vertices)[corners[0]], (*b_vertices)[corners[1]], (*b_vertices)[corners[2]]};
  }
  const Vec3& VertexB(int vertex) const { return (*b_vertices)[vertex]; }
};

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

// True when the two triangles that share the edge opposite `corner` are coplanar within
// kFlatEdgeCosine: such an edge (a square face's diagonal, say) has no direction of its own,
// and the cross product with another edge would point anywhere along the face.
bool IsFlatEdge(const CollisionGeometry& mesh, int triangle, int corner) {
  const int neighbor = Topology(mesh.bvh()).neighbors[triangle][corner];
  if (neighbor < 0) return false;
  return mesh.triangle_normals()[triangle].dot(mesh.triangle_normals()[neighbor]) >=
         kFlatEdgeCosine;
}

// Where a closest point lies on its triangle, as far as the face normal is concerned.
enum class FacePlace { kInterior, kFlatEdge, kElsewhere };

// kFlatEdge: on an edge between coplanar triangles, where the face's normal is the surface's
// only normal.
FacePlace PlaceOnFace(const CollisionGeometry& mesh, int triangle, const Vec3& barycentric) {
  const TriangleFeature feature = ClassifyFeature(barycentric);
  if (feature.type == TriangleFeature::Type::kFace) return FacePlace::kInterior;
  if (feature.type == TriangleFeature::Type::kEdge && IsFlatEdge(mesh, triangle, feature.index)) {
    return FacePlace::kFlatEdge;
  }
  return FacePlace::kElsewhere;
}

// Klamp't's ContactNormal: the normal from b into a at nearly coincident closest points p (on
// a's triangle) and q (on b's), all in a's frame.
Vec3 MeshMeshFeatureNormal(const MeshPair& m, int ta, int tb, const Vec3& p, const Vec3& q) {
  const CollisionGeometry& a = m.a;
  const CollisionGeometry& b = m.b;
  const Triangle3 tri_a = m.TriangleA(ta);
  const Triangle3 tri_b = m.TriangleB(tb);
  const TriangleFeature fa = ClassifyFeature(BarycentricCoordinates(p, tri_a));
  const TriangleFeature fb = ClassifyFeature(BarycentricCoordinates(q, tri_b));
  using Type = TriangleFeature::Type;
  if (fa.type == Type::kFace) return -a.triangle_normals()[ta];
  const Mat3 R = m.X_ab.linear();
  if (fb.type == Type::kFace) return R * b.triangle_normals()[tb];
  const Vec3 na = FeatureNormal(a, ta, fa);
  const Vec3 nb = R * FeatureNormal(b, tb, fb);
  // an edge inside a flat region is a face: its normal is the only one it has
  if (fb.type == Type::kEdge && IsFlatEdge(b, tb, fb.index)) return nb;
  if (fa.type == Type::kEdge && IsFlatEdge(a, ta, fa.index)) return -na;
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
  int face = 0;                ///< the other mesh's triangle it lies over
  double distance = 0.0;       ///< signed along the face normal, negative behind the face
  Vec3 normal = Vec3::Zero();  ///< from b into a, in a's frame
  Vec3 on_a = Vec3::Zero();
  Vec3 on_b = Vec3::Zero();
};

// Working memory of MeshMeshContacts, kept between calls so that a call does not allocate.
struct MeshMeshScratch {
  PlacedVertices b_vertices;
  std::vector<TrianglePairHit> hits;
  std::vector<PairCandidate> candidates;
  // SelectPairs: the candidates taking part, each triangle's closest one, the result
  std::vector<int> order;
  SparseArray<int> closest_partner;
  std::vector<int> owners;  // the triangles that have a closest partner
  std::vector<int> selected;
  std::vector<char> is_selected;  // per candidate
  // CollectVertexHits: the candidates chained by face (GroupByFace), the face each vertex was
  // last tested against, each vertex's nearest face, the vertices that have one, the result
  std::vector<int> faces;
  SparseArray<int> first_of_face;
  std::vector<int> next_of_face;
  SparseArray<int> tested_face;
  SparseArray<VertexHit> nearest_face;
  std::vector<int> vertices;
  std::vector<VertexHit> vertex_hits;
  // per side (0: a's vertices, 1: b's), the face each vertex contact holds its vertex on
  SparseArray<int> hit_face[2];
};

MeshMeshScratch& MeshMeshScratchSpace() {
  thread_local MeshMeshScratch scratch;
  return scratch;
}

// Crossing pairs have distance 0 and their closest points at the middle of the crossing. FCL
// reports other pairs at distance exactly 0 (touching) with arbitrary points: those are
// recomputed from the triangles' features.
void FindCrossings(const MeshPair& m, MeshMeshScratch* s) {
  s->candidates.clear();
  for (const TrianglePairHit& hit : s->hits) {
    PairCandidate candidate{hit, false};
    if (hit.distance < kFeatureNormalDistance) {
      const Triangle3 ta = m.TriangleA(hit.triangle_a);
      const Triangle3 tb = m.TriangleB(hit.triangle_b);
      Vec3 middle;
      if (TrianglesCross(ta, tb, &middle)) {
        candidate = {{hit.triangle_a, hit.triangle_b, 0.0, middle, middle}, true};
      } else if (hit.distance == 0.0) {
        const TrianglePairPoints points = ClosestPointsOfTriangles(ta, tb);
        candidate.hit.foot = TrianglePairHit::Foot::kGeneral;
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
// direction, as Klamp't does. A point on a flat edge counts as on the face.
Vec3 PairNormal(const MeshPair& m, const PairCandidate& c, double* signed_distance,
                bool* from_face) {
  *from_face = false;
  const Vec3& p = c.hit.point_a;
  const Vec3& q = c.hit.point_b;
  const double d = c.hit.distance;
  if (!c.crossing) {
    // a closest point that is a corner (TrianglePairHit::foot) lies on a vertex: kElsewhere
    using Foot = TrianglePairHit::Foot;
    const FacePlace q_place =
        c.hit.foot == Foot::kCornerOfBOverA
            ? FacePlace::kElsewhere
            : PlaceOnFace(m.b, c.hit.triangle_b,
                          BarycentricCoordinates(q, m.TriangleB(c.hit.triangle_b)));
    const FacePlace p_place =
        c.hit.foot == Foot::kCornerOfAOverB
            ? FacePlace::kElsewhere
            : PlaceOnFace(m.a, c.hit.triangle_a,
                          BarycentricCoordinates(p, m.TriangleA(c.hit.triangle_a)));
    // parallel faces: their closest points are an arbitrary spot of the overlap; the vertex
    // contacts (CollectVertexHits) hold such faces at their corners instead
    if (q_place == FacePlace::kInterior && p_place == FacePlace::kInterior) return Vec3::Zero();
    Vec3 face_normal = Vec3::Zero();
    if (q_place != FacePlace::kElsewhere && p_place != FacePlace::kInterior) {
      face_normal = m.X_ab.linear() * m.b.triangle_normals()[c.hit.triangle_b];
    } else if (p_place != FacePlace::kElsewhere) {
      face_normal = -m.a.triangle_normals()[c.hit.triangle_a];
    }
    if (!face_normal.isZero()) {
      *signed_distance = face_normal.dot(p - q);
      *from_face = true;
      return face_normal;
    }
  }
  *signed_distance = d;
  return d < kFeatureNormalDistance
             ? MeshMeshFeatureNormal(m, c.hit.triangle_a, c.hit.triangle_b, p, q)
             : Vec3((p - q) / d);
}

// Appends to `selected` the closest partner of every triangle of one side: `side` 0 groups by
// a's triangles, 1 by b's. Ties go to crossing pairs, then to the lower partner index.
void SelectClosestPartners(int side, int triangle_count, MeshMeshScratch* s) {
  const auto own = [side](const PairCandidate& c) {
    return side == 0 ? c.hit.triangle_a : c.hit.triangle_b;
  };
  const auto key = [side](const PairCandidate& c) {
    const int partner = side == 0 ? c.hit.triangle_b : c.hit.triangle_a;
    return std::make_tuple(c.hit.distance, !c.crossing, partner);
  };
  s->closest_partner.Clear(triangle_count);
  s->owners.clear();
  for (const int i : s->order) {
    const int triangle = own(s->candidates[i]);
    if (!s->closest_partner.Has(triangle)) {
      s->closest_partner.Set(triangle) = i;
      s->owners.push_back(triangle);
    } else if (key(s->candidates[i]) < key(s->candidates[s->closest_partner[triangle]])) {
      s->closest_partner.Set(triangle) = i;
    }
  }
  for (const int triangle : s->owners) s->selected.push_back(s->closest_partner[triangle]);
}

// Sorts s->selected and drops repeats. The candidates are in (triangle_a, triangle_b) order
// (NearTrianglePairs' order), so candidate index order is pair order: marks in one pass.
void KeepInOrder(MeshMeshScratch* s) {
  s->is_selected.assign(s->candidates.size(), 0);
  for (const int i : s->selected) s->is_selected[i] = 1;
  s->selected.clear();
  for (size_t i = 0; i < s->candidates.size(); ++i) {
    if (s->is_selected[i]) s->selected.push_back(static_cast<int>(i));
  }
}

// Crossing triangles (the meshes interpenetrate beyond the boundary layer) give no usable
// normal: a side face crossing a bottom face would push sideways. They only take part when no
// triangle pair of the two meshes is separated, so deep overlaps still produce contacts.
void SelectPairs(int triangles_a, int triangles_b, MeshMeshScratch* s) {
  s->order.clear();
  for (size_t i = 0; i < s->candidates.size(); ++i) {
    if (!s->candidates[i].crossing) s->order.push_back(static_cast<int>(i));
  }
  if (s->order.empty()) {
    for (size_t i = 0; i < s->candidates.size(); ++i) s->order.push_back(static_cast<int>(i));
  }
  s->selected.clear();
  SelectClosestPartners(0, triangles_a, s);
  SelectClosestPartners(1, triangles_b, s);
  KeepInOrder(s);
}

// Vertices this much farther than the tolerance from a face's plane are not tested exactly (m):
// far beyond the rounding that separates the plane distance from the exact one.
constexpr double kPlaneSlack = 1e-9;

// A face of the other mesh that CollectVertexHits holds vertices against, in a's frame. Its
// barycentric map is made on first use: most vertices are turned away by the face's plane or
// by the ball about its centroid that holds it.
struct FaceFrame {
  FaceFrame(const MeshPair& m, int face_index, bool face_of_b)
      : face(face_index),
        triangle(face_of_b ? m.TriangleB(face) : m.TriangleA(face)),
        outward(face_of_b ? Vec3(m.X_ab.linear() * m.b.triangle_normals()[face])
                          : m.a.triangle_normals()[face]),
        centroid((triangle[0] + triangle[1] + triangle[2]) / 3.0),
        radius(std::sqrt(std::max({(triangle[0] - centroid).squaredNorm(),
                                   (triangle[1] - centroid).squaredNorm(),
                                   (triangle[2] - centroid).squaredNorm()}))) {}

  const BarycentricMap& ToFace() const {
    if (!to_face) to_face.emplace(triangle);
    return *to_face;
  }

  int face;
  Triangle3 triangle;
  Vec3 outward;
  Vec3 centroid;
  double radius;  ///< of the ball about the centroid that holds the triangle

 private:
  mutable std::optional<BarycentricMap> to_face;
};

// Vertex `vertex` at v (a's frame) over the face within `tolerance`, if it is: the vertex must
// project onto the face or its boundary (aligned boxes put corners on the partner's edges).
std::optional<VertexHit> VertexOverFace(const FaceFrame& f, int vertex, const Vec3& v,
                                        double tolerance, bool from_a) {
  // a vertex over the face within the tolerance is within radius + tolerance of the centroid
  const double reach = f.radius + tolerance + kPlaneSlack;
  if (!(std::abs(f.outward.dot(v - f.triangle[0])) <= tolerance + kPlaneSlack) ||
      !((v - f.centroid).squaredNorm() <= reach * reach)) {
    return std::nullopt;  // also turns NaN away, as the exact test below would
  }
  const Vec3 barycentric = f.ToFace()(v);
  if ((barycentric.array() < -kOverFaceTolerance).any()) return std::nullopt;
  const Vec3 projected = barycentric[0] * f.triangle[0] + barycentric[1] * f.triangle[1] +
                         barycentric[2] * f.triangle[2];
  const double distance = f.outward.dot(v - projected);
  if (distance > tolerance || distance < -tolerance) return std::nullopt;
  // touching the face's boundary: the face normal is one of several; the triangle pairs'
  // feature normals decide there
  const bool on_boundary = (barycentric.array() <= kOverFaceTolerance).any();
  if (on_boundary && std::abs(distance) < kFeatureNormalDistance) return std::nullopt;
  VertexHit hit{vertex, f.face, distance, from_a ? f.outward : Vec3(-f.outward), v, projected};
  if (!from_a) std::swap(hit.on_a, hit.on_b);
  return hit;
}

// Chains the candidates by their face of the other mesh (b's triangle if `from_a`), so that
// each face is set up once: s->faces holds each face once, and each face's candidates run
// from s->first_of_face through s->next_of_face (-1 ends the chain).
void GroupByFace(bool from_a, int face_count, MeshMeshScratch* s) {
  s->first_of_face.Clear(face_count);
  s->faces.clear();
  s->next_of_face.resize(s->candidates.size());
  for (int i = static_cast<int>(s->candidates.size()) - 1; i >= 0; --i) {
    const PairCandidate& c = s->candidates[i];
    const int face = from_a ? c.hit.triangle_b : c.hit.triangle_a;
    s->next_of_face[i] = s->first_of_face.Has(face) ? s->first_of_face[face] : -1;
    if (!s->first_of_face.Has(face)) s->faces.push_back(face);
    s->first_of_face.Set(face) = i;
  }
}

// Keeps each vertex's nearest face (the lowest-numbered of equally near ones).
void KeepNearest(const VertexHit& hit, MeshMeshScratch* s) {
  if (!s->nearest_face.Has(hit.vertex)) {
    s->nearest_face.Set(hit.vertex) = hit;
    s->vertices.push_back(hit.vertex);
    return;
  }
  const VertexHit& kept = s->nearest_face[hit.vertex];
  if (std::make_pair(std::abs(hit.distance), hit.face) <
      std::make_pair(std::abs(kept.distance), kept.face)) {
    s->nearest_face.Set(hit.vertex) = hit;
  }
}

// True when no corner of b's candidate triangles lies within `reach` of a's bounds: none of them
// can then lie over a face of a within the tolerance. A terrain's far corners under a small
// mesh are turned away at once instead of face by face.
bool NoVertexOfBNearA(const MeshPair& m, double reach, const MeshMeshScratch& s) {
  const Eigen::AlignedBox3d& bounds = m.a.local_bounds();
  for (const PairCandidate& c : s.candidates) {
    for (const int vertex : m.b.mesh().triangles[c.hit.triangle_b]) {
      const Vec3& v = m.VertexB(vertex);
      // written so that a NaN coordinate counts as near (the exact tests decide then)
      if (!((v - bounds.max()).maxCoeff() > reach || (bounds.min() - v).maxCoeff() > reach)) {
        return false;
      }
    }
  }
  return true;
}

// The vertices of one mesh that lie over a face of the other within `tolerance` (or behind it by
// less than `tolerance`), each with its nearest face: a face resting on a face touches at its
// corners, which the closest points of triangle pairs alone do not find. `from_a` picks whose
// vertices; everything is in a's frame. The result is s->vertex_hits, in vertex order.
void CollectVertexHits(const MeshPair& m, double tolerance, bool from_a, MeshMeshScratch* s) {
  const CollisionGeometry& own = from_a ? m.a : m.b;
  const CollisionGeometry& other = from_a ? m.b : m.a;
  s->vertices.clear();
  s->vertex_hits.clear();
  if (!from_a && NoVertexOfBNearA(m, tolerance + kPlaneSlack, *s)) return;
  GroupByFace(from_a, other.mesh().triangle_count(), s);
  s->nearest_face.Clear(own.mesh().vertices.size());
  s->tested_face.Clear(own.mesh().vertices.size());
  for (const int face : s->faces) {
    const FaceFrame frame(m, face, from_a);
    // a face without area has no normal and nothing can be over it (its distance would read 0:
    // a contact the whole layer deep); its edges still meet the other mesh in the triangle pairs
    if (frame.outward.isZero(0.0)) continue;
    for (int i = s->first_of_face[face]; i >= 0; i = s->next_of_face[i]) {
      const PairCandidate& c = s->candidates[i];
      const Eigen::Vector3i& corners =
          own.mesh().triangles[from_a ? c.hit.triangle_a : c.hit.triangle_b];
      for (int k = 0; k < 3; ++k) {
        const int vertex = corners[k];
        if (s->tested_face.Has(vertex) && s->tested_face[vertex] == face) continue;
        s->tested_face.Set(vertex) = face;
        const Vec3& v = from_a ? own.mesh().vertices[vertex] : m.VertexB(vertex);
        const std::optional<VertexHit> hit = VertexOverFace(frame, vertex, v, tolerance, from_a);
        if (hit) KeepNearest(*hit, s);
      }
    }
  }
  std::sort(s->vertices.begin(), s->vertices.end());
  for (const int vertex : s->vertices) s->vertex_hits.push_back(s->nearest_face[vertex]);
}

// True when a pair's contact (normal n_a, from a face if `from_face`) would only repeat a vertex
// contact: its closest points are a corner and its foot on the other triangle's face, that
// corner's vertex holds a vertex contact on this very face, and the pair's normal is that face's
// (the same expression as the vertex contact's). Both contacts then have the same points, normal
// and depth, and the merge of coincident contacts would fold the pair's into the vertex's.
bool RepeatsVertexHit(const MeshPair& m, const TrianglePairHit& hit, const Vec3& n_a,
                      bool from_face, const MeshMeshScratch& s) {
  using Foot = TrianglePairHit::Foot;
  if (hit.foot == Foot::kGeneral || !from_face) return false;
  const bool corner_of_a = hit.foot == Foot::kCornerOfAOverB;
  const int own_triangle = corner_of_a ? hit.triangle_a : hit.triangle_b;
  const int face = corner_of_a ? hit.triangle_b : hit.triangle_a;
  const int vertex = (corner_of_a ? m.a : m.b).mesh().triangles[own_triangle][hit.corner];
  const SparseArray<int>& held = s.hit_face[corner_of_a ? 0 : 1];
  if (!held.Has(vertex) || held[vertex] != face) return false;
  const Vec3 face_normal = corner_of_a ? Vec3(m.X_ab.linear() * m.b.triangle_normals()[face])
                                       : Vec3(-m.a.triangle_normals()[face]);
  return n_a == face_normal;
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
                      const CollisionGeometry& b, const Pose& X_Wb, double pad_b, ContactList* out,
                      NearPairCache* cache) {
  const double tolerance = pad_a + pad_b;
  const Pose X_ab = X_Wa.inverse() * X_Wb;
  MeshMeshScratch& s = MeshMeshScratchSpace();
  s.hits.clear();
  mesh_detail::NearTrianglePairs(a.bvh(), b.bvh(), X_ab, tolerance, &s.hits,
                                 mesh_detail::PairSearch::kAuto, cache);
  if (s.hits.empty()) return;
  s.b_vertices.Reset(b.mesh(), X_ab);
  const MeshPair m{a, b, X_ab, &s.b_vertices};
  FindCrossings(m, &s);
  const bool crossing = std::any_of(s.candidates.begin(), s.candidates.end(),
                                    [](const PairCandidate& c) { return c.crossing; });
  SelectPairs(a.mesh().triangle_count(), b.mesh().triangle_count(), &s);
  // vertices over faces first: their face normals tell which way the pair separates
  Vec3 reference = Vec3::Zero();
  for (const bool from_a : {true, false}) {
    CollectVertexHits(m, tolerance, from_a, &s);
    SparseArray<int>& held = s.hit_face[from_a ? 0 : 1];
    held.Clear((from_a ? a : b).mesh().vertices.size());
    for (const VertexHit& hit : s.vertex_hits) {
      held.Set(hit.vertex) = hit.face;
      reference += hit.normal;
      AppendContact(X_Wa, pad_a, pad_b, hit.on_a, hit.on_b, hit.normal, tolerance - hit.distance,
                    crossing || hit.distance < 0.0, out);
    }
  }
  for (const int i : s.selected) {
    const PairCandidate& c = s.candidates[i];
    double signed_distance = c.hit.distance;
    bool from_face = false;
    Vec3 n_a = PairNormal(m, c, &signed_distance, &from_face);
    if (!(n_a.norm() >= kMinNormalLength)) continue;  // also rejects NaN
    if (RepeatsVertexHit(m, c.hit, n_a, from_face, s)) continue;
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
