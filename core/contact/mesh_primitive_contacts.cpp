// SPDX-License-Identifier: MIT
// Mesh-primitive contacts (MeshPrimitiveContacts, declared in mesh_contacts.h). A plane gives
// one contact per mesh vertex within the padding. Other primitives are tested triangle by
// triangle near their bounds: each of a few feature points of the primitive (a sphere's centre,
// a capsule's end centres, a box's corners, points on a cylinder's rims) against the triangle,
// as Klamp't does for spheres, plus the exact closest pair of the triangle and the primitive's
// core (GJK) for edge and ridge contacts; then Klamp't's back-face drop and local
// non-maximum suppression among adjacent triangles. Boxes and cylinders also take one contact
// per nearby mesh vertex, so that a mesh resting on their flat faces stands on its corners.
#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>

#include "core/contact/mesh_contacts.h"
#include "core/contact/mesh_query.h"
#include "core/contact/triangle_queries.h"

namespace lamina::core {

namespace {

using mesh_detail::ClassifyFeature;
using mesh_detail::ClosestPointOnTriangle;
using mesh_detail::ClosestSurfacePoint;
using mesh_detail::FeatureNormal;
using mesh_detail::kFeatureNormalDistance;
using mesh_detail::kMinNormalLength;
using mesh_detail::SupportShape;
using mesh_detail::SurfacePoint;
using mesh_detail::Topology;
using mesh_detail::Triangle3;
using mesh_detail::TrianglePoint;
using mesh_detail::TrianglesBelowPlane;
using mesh_detail::TriangleShapeDistance;
using mesh_detail::TriangleShapeDistanceResult;
using mesh_detail::TrianglesNearBox;

// feature id of the exact closest pair of a triangle and the primitive's core
constexpr int kCoreFeature = 100;
// feature ids of a cylinder's rim points deepest toward a triangle
constexpr int kRimSupportFeature = 8;
// redundant contacts: distances equal within this
constexpr double kSameDistance = 1e-9;

// A contact on one triangle (or at one mesh vertex, then `triangle` is the vertex), mesh
// frame: `normal` points from the primitive into the mesh, `distance` is the signed distance
// between the unpadded surfaces along it.
struct Candidate {
  int triangle = 0;
  int feature = 0;
  double distance = 0.0;
  Vec3 on_mesh = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();
};

// The primitive as the mesh sees it (mesh frame): feature points that are spheres of
// `point_radius`, the core shape whose distance minus `core_radius` is the surface distance,
// and the half extents of the box (frame `pose`) that holds it.
struct PrimitiveModel {
  Pose pose = Pose::Identity();
  std::array<Vec3, 8> points;
  int point_count = 0;
  double point_radius = 0.0;
  bool has_core = false;
  SupportShape core;
  double core_radius = 0.0;
  bool vertex_contacts = false;
  Vec3 half_extents = Vec3::Zero();

  /// The least height along the unit `n` over the primitive.
  double Lowest(const Vec3& n) const {
    return has_core ? n.dot(core.Support(-n)) - core_radius : n.dot(points[0]) - point_radius;
  }
};

struct MeshPrimitiveScratch {
  std::vector<int> triangles;
  std::vector<Candidate> candidates;
  std::vector<Candidate> vertex_candidates;
  std::vector<char> keep;
  std::vector<int> vertices;
};

MeshPrimitiveScratch& MeshPrimitiveScratchSpace() {
  thread_local MeshPrimitiveScratch scratch;
  return scratch;
}

void SetCore(SupportShape::Type type, double core_radius, PrimitiveModel* m) {
  m->has_core = true;
  m->core.type = type;
  m->core.pose = m->pose;
  m->core_radius = core_radius;
}

PrimitiveModel MakeModel(const Primitive& p, const Pose& X_mesh_primitive) {
  PrimitiveModel m;
  m.pose = X_mesh_primitive;
  const double half_length = 0.5 * p.length;
  switch (p.type) {
    case PrimitiveType::kSphere:
      m.points[m.point_count++] = m.pose.translation();
      m.point_radius = p.radius;
      m.half_extents = Vec3::Constant(p.radius);
      break;
    case PrimitiveType::kCapsule:
      m.points[m.point_count++] = m.pose * Vec3(0, 0, half_length);
      m.points[m.point_count++] = m.pose * Vec3(0, 0, -half_length);
      m.point_radius = p.radius;
      SetCore(SupportShape::Type::kSegment, p.radius, &m);
      m.core.half_length = half_length;
      m.half_extents = Vec3(p.radius, p.radius, half_length + p.radius);
      break;
    case PrimitiveType::kBox:
      m.half_extents = 0.5 * p.size;
      for (int i = 0; i < 8; ++i) {
        const Vec3 corner((i & 1) ? 1 : -1, (i & 2) ? 1 : -1, (i & 4) ? 1 : -1);
        m.points[m.point_count++] = m.pose * corner.cwiseProduct(m.half_extents);
      }
      SetCore(SupportShape::Type::kBox, 0.0, &m);
      m.core.half_extents = m.half_extents;
      m.vertex_contacts = true;
      break;
    case PrimitiveType::kCylinder:
      // four points on each rim keep a cylinder standing on its cap
      for (int i = 0; i < 8; ++i) {
        const double angle = 0.5 * kPi * (i % 4);
        const double z = i < 4 ? half_length : -half_length;
        m.points[m.point_count++] =
            m.pose * Vec3(p.radius * std::cos(angle), p.radius * std::sin(angle), z);
      }
      SetCore(SupportShape::Type::kCylinder, 0.0, &m);
      m.core.radius = p.radius;
      m.core.half_length = half_length;
      m.vertex_contacts = true;
      m.half_extents = Vec3(p.radius, p.radius, half_length);
      break;
    case PrimitiveType::kPlane:
      break;
  }
  return m;
}

// Everything one triangle contributes, appended to the scratch candidates.
class TriangleTester {
 public:
  TriangleTester(const CollisionGeometry& mesh, const PrimitiveModel& model, double tolerance,
                 std::vector<Candidate>* out)
      : mesh_(mesh), model_(model), tolerance_(tolerance), out_(out) {}

  void Test(int t) {
    const Vec3& n = mesh_.triangle_normals()[t];
    if (n.isZero()) return;  // no area, no contact
    const Eigen::Vector3i& index = mesh_.mesh().triangles[t];
    const std::vector<Vec3>& v = mesh_.mesh().vertices;
    const Triangle3 triangle = {v[index[0]], v[index[1]], v[index[2]]};
    // the whole primitive farther in front of the triangle's plane than the tolerance
    if (model_.Lowest(n) - n.dot(triangle[0]) > tolerance_) return;
    for (int i = 0; i < model_.point_count; ++i) {
      TestPoint(triangle, t, i, model_.points[i], model_.point_radius);
    }
    if (model_.core.type == SupportShape::Type::kCylinder && model_.has_core) {
      TestRimSupport(triangle, t, n);
    }
    if (model_.has_core) TestCore(triangle, t, n);
  }

 private:
  // Klamp't's sphere rule: unsigned distance, feature normal when touching or penetrating.
  void TestPoint(const Triangle3& triangle, int t, int feature, const Vec3& center, double radius) {
    const TrianglePoint closest = ClosestPointOnTriangle(center, triangle);
    const Vec3 v = center - closest.point;
    const double length = v.norm();
    const double distance = length - radius;
    if (distance > tolerance_) return;
    const Vec3 normal = distance < kFeatureNormalDistance
                            ? Vec3(-FeatureNormal(mesh_, t, ClassifyFeature(closest.barycentric)))
                            : Vec3(-v / length);
    Add(t, feature, distance, closest.point, normal);
  }

  // the two rim points of a cylinder deepest toward the triangle's plane
  void TestRimSupport(const Triangle3& triangle, int t, const Vec3& n) {
    const Vec3 d = model_.pose.linear().transpose() * -n;
    const double across = std::hypot(d.x(), d.y());
    if (across < 1e-9) return;  // the cap faces the triangle: the fixed rim points cover it
    const Vec3 rim(model_.core.radius * d.x() / across, model_.core.radius * d.y() / across, 0);
    for (int side = 0; side < 2; ++side) {
      const Vec3 p =
          rim + Vec3(0, 0, side == 0 ? model_.core.half_length : -model_.core.half_length);
      TestPoint(triangle, t, kRimSupportFeature + side, model_.pose * p, 0.0);
    }
  }

  // The exact closest pair; when the core crosses the triangle, the depth below its plane.
  void TestCore(const Triangle3& triangle, int t, const Vec3& n) {
    const TriangleShapeDistanceResult r = TriangleShapeDistance(triangle, model_.core);
    if (r.intersecting) {
      const Vec3 deepest = model_.core.Support(-n);
      const double below = n.dot(triangle[0] - deepest);
      Add(t, kCoreFeature, -(below + model_.core_radius), deepest + below * n, -n);
      return;
    }
    const double distance = r.distance - model_.core_radius;
    if (distance > tolerance_) return;
    const Vec3 normal =
        distance < kFeatureNormalDistance
            ? Vec3(-FeatureNormal(mesh_, t, ClassifyFeature(r.on_triangle.barycentric)))
            : Vec3((r.on_triangle.point - r.on_shape) / r.distance);
    Add(t, kCoreFeature, distance, r.on_triangle.point, normal);
  }

  void Add(int t, int feature, double distance, const Vec3& on_mesh, const Vec3& normal) {
    if (!(normal.norm() >= kMinNormalLength)) return;
    out_->push_back({t, feature, distance, on_mesh, normal});
  }

  const CollisionGeometry& mesh_;
  const PrimitiveModel& model_;
  const double tolerance_;
  std::vector<Candidate>* out_;
};

bool Before(const Candidate& x, const Candidate& y) {
  return std::tie(x.triangle, x.feature) < std::tie(y.triangle, y.feature);
}

// The least distance among the vertex contacts of triangle t's corners (sorted by vertex).
double NearestCorner(const CollisionGeometry& mesh, int t, const std::vector<Candidate>& vertices) {
  double nearest = kInf;
  for (int k = 0; k < 3; ++k) {
    Candidate probe;
    probe.triangle = Topology(mesh.bvh()).welded[mesh.mesh().triangles[t][k]];
    const auto found = std::lower_bound(
        vertices.begin(), vertices.end(), probe,
        [](const Candidate& x, const Candidate& y) { return x.triangle < y.triangle; });
    if (found != vertices.end() && found->triangle == probe.triangle) {
      nearest = std::min(nearest, found->distance);
    }
  }
  return nearest;
}

// Back-facing contacts (normal along the triangle's outward normal) go first. Then a rim
// support point that a fixed feature point of the same triangle already matches, and a core
// contact that any feature point or corner vertex of the triangle matches. The list is sorted
// by triangle, then feature.
void DropBackFacingAndRedundant(const CollisionGeometry& mesh,
                                const std::vector<Candidate>& vertices,
                                std::vector<Candidate>* list) {
  std::erase_if(*list, [&mesh](const Candidate& c) {
    return c.normal.dot(mesh.triangle_normals()[c.triangle]) > 0.0;
  });
  size_t kept = 0;
  double nearest_fixed = kInf, nearest_point = kInf;  // over the current triangle
  for (size_t i = 0; i < list->size(); ++i) {
    const Candidate c = (*list)[i];
    if (i > 0 && c.triangle != (*list)[i - 1].triangle) nearest_fixed = nearest_point = kInf;
    const bool core = c.feature == kCoreFeature;
    const bool fixed = c.feature < kRimSupportFeature;
    const double nearest = core ? std::min(nearest_point, NearestCorner(mesh, c.triangle, vertices))
                                : (fixed ? kInf : nearest_fixed);
    if (fixed) nearest_fixed = std::min(nearest_fixed, c.distance);
    if (!core) nearest_point = std::min(nearest_point, c.distance);
    if (nearest > c.distance + kSameDistance) (*list)[kept++] = c;
  }
  list->resize(kept);
}

// Local non-maximum suppression: a contact goes if the same feature has a deeper contact (or
// an equally deep one on a lower-numbered triangle) on an edge-adjacent triangle.
void SuppressNonMaxima(const CollisionGeometry& mesh, const std::vector<Candidate>& list,
                       std::vector<char>* keep) {
  const std::vector<Eigen::Vector3i>& neighbors = Topology(mesh.bvh()).neighbors;
  keep->assign(list.size(), 1);
  for (size_t i = 0; i < list.size(); ++i) {
    const Candidate& c = list[i];
    for (int k = 0; k < 3; ++k) {
      Candidate probe;
      probe.triangle = neighbors[c.triangle][k];
      probe.feature = c.feature;
      if (probe.triangle < 0) continue;
      const auto found = std::lower_bound(list.begin(), list.end(), probe, Before);
      if (found == list.end() || found->triangle != probe.triangle ||
          found->feature != probe.feature) {
        continue;
      }
      const double difference = found->distance - c.distance;
      if (difference < -1e-12 || (difference <= 1e-12 && probe.triangle < c.triangle)) {
        (*keep)[i] = 0;
      }
    }
  }
}

// The distinct (welded) vertices of the scratch triangles, sorted, into the scratch vertices.
void CollectVertices(const CollisionGeometry& mesh, MeshPrimitiveScratch* s) {
  s->vertices.clear();
  const std::vector<int>& welded = Topology(mesh.bvh()).welded;
  for (const int t : s->triangles) {
    for (int k = 0; k < 3; ++k) s->vertices.push_back(welded[mesh.mesh().triangles[t][k]]);
  }
  std::sort(s->vertices.begin(), s->vertices.end());
  s->vertices.erase(std::unique(s->vertices.begin(), s->vertices.end()), s->vertices.end());
}

// One contact per mesh vertex near the core's surface that faces it (the vertex normal
// opposes the contact normal).
void VertexContacts(const CollisionGeometry& mesh, const PrimitiveModel& model, double tolerance,
                    MeshPrimitiveScratch* s) {
  CollectVertices(mesh, s);
  s->vertex_candidates.clear();
  for (const int v : s->vertices) {
    const Vec3& p = mesh.mesh().vertices[v];
    const SurfacePoint surface = ClosestSurfacePoint(model.core, p);
    if (surface.distance > tolerance) continue;
    if (surface.normal.dot(Topology(mesh.bvh()).vertex_normals[v]) > 0.0) continue;
    s->vertex_candidates.push_back({v, 0, surface.distance, p, surface.normal});
  }
}

// Appends the contact of candidate c: `on_mesh - distance * normal` is on the primitive, and
// the contact sits midway between the padded surfaces.
void Emit(const Candidate& c, const Pose& X_Wa, double pad_a, double pad_b, ContactList* out) {
  Contact contact;
  contact.normal = X_Wa.linear() * c.normal;
  contact.position = X_Wa * c.on_mesh + 0.5 * (pad_b - pad_a - c.distance) * contact.normal;
  contact.depth = pad_a + pad_b - c.distance;
  contact.penetrating = c.distance < 0.0;
  out->push_back(contact);
}

void PlaneContacts(const CollisionGeometry& a, const Pose& X_Wa, double pad_a, const Pose& X_ap,
                   double pad_b, ContactList* out) {
  const double tolerance = pad_a + pad_b;
  const Vec3 n = X_ap.linear().col(2);  // from the plane into the mesh
  const double plane_height = n.dot(X_ap.translation());
  MeshPrimitiveScratch& s = MeshPrimitiveScratchSpace();
  s.triangles.clear();
  TrianglesBelowPlane(a.bvh(), n, plane_height + tolerance, &s.triangles);
  CollectVertices(a, &s);
  for (const int v : s.vertices) {
    const double height = n.dot(a.mesh().vertices[v]) - plane_height;
    if (height < tolerance) Emit({v, 0, height, a.mesh().vertices[v], n}, X_Wa, pad_a, pad_b, out);
  }
}

}  // namespace

void MeshPrimitiveContacts(const CollisionGeometry& a, const Pose& X_Wa, double pad_a,
                           const CollisionGeometry& b, const Pose& X_Wb, double pad_b,
                           ContactList* out) {
  const Pose X_ap = X_Wa.inverse() * X_Wb * b.primitive().pose;
  if (b.primitive().type == PrimitiveType::kPlane) {
    PlaneContacts(a, X_Wa, pad_a, X_ap, pad_b, out);
    return;
  }
  const double tolerance = pad_a + pad_b;
  const PrimitiveModel model = MakeModel(b.primitive(), X_ap);
  MeshPrimitiveScratch& s = MeshPrimitiveScratchSpace();
  s.triangles.clear();
  TrianglesNearBox(a.bvh(), X_ap, model.half_extents + Vec3::Constant(tolerance), &s.triangles);
  std::sort(s.triangles.begin(), s.triangles.end());
  s.candidates.clear();
  s.vertex_candidates.clear();
  if (model.vertex_contacts) VertexContacts(a, model, tolerance, &s);
  TriangleTester tester(a, model, tolerance, &s.candidates);
  for (const int t : s.triangles) tester.Test(t);
  DropBackFacingAndRedundant(a, s.vertex_candidates, &s.candidates);
  SuppressNonMaxima(a, s.candidates, &s.keep);
  for (size_t i = 0; i < s.candidates.size(); ++i) {
    if (s.keep[i]) Emit(s.candidates[i], X_Wa, pad_a, pad_b, out);
  }
  for (const Candidate& c : s.vertex_candidates) Emit(c, X_Wa, pad_a, pad_b, out);
}

}  // namespace lamina::core
