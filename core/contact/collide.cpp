// SPDX-License-Identifier: MIT
// The contact dispatcher: picks the routine for a pair of geometry kinds, adds the geometries'
// own margins to the paddings, and swaps roles so that normals always point from b into a.
// A point cloud on either side goes to PointCloudContacts (the cloud as its first body).
#include "core/contact/collision_geometry.h"
#include "core/contact/mesh_contacts.h"
#include "core/contact/point_cloud_contacts.h"
#include "core/contact/primitive_contacts.h"

namespace lamina::core {

namespace {

// runs `collide(b, a)` and turns its contacts around so they read as (a, b)
template <typename Function>
void CollideSwapped(Function collide, ContactList* out) {
  const size_t first = out->size();
  collide();
  for (size_t i = first; i < out->size(); ++i) (*out)[i].normal = -(*out)[i].normal;
}

}  // namespace

void Collide(const CollisionGeometry& a, const Pose& X_Wa, double pad_a, const CollisionGeometry& b,
             const Pose& X_Wb, double pad_b, ContactList* out, NearPairCache* cache) {
  // the layer-edge slack split evenly: the contacts' midpoints do not move
  const double padding_a = pad_a + a.margin() + 0.5 * kLayerEdgeSlack;
  const double padding_b = pad_b + b.margin() + 0.5 * kLayerEdgeSlack;
  using Kind = CollisionGeometry::Kind;
  if (a.kind() == Kind::kPointCloud) {
    PointCloudContacts(a, X_Wa, padding_a, b, X_Wb, padding_b, out);
  } else if (b.kind() == Kind::kPointCloud) {
    CollideSwapped([&] { PointCloudContacts(b, X_Wb, padding_b, a, X_Wa, padding_a, out); }, out);
  } else if (a.kind() == Kind::kPrimitive && b.kind() == Kind::kPrimitive) {
    PrimitiveContacts(a.primitive(), X_Wa, padding_a, b.primitive(), X_Wb, padding_b, out);
  } else if (a.kind() == Kind::kMesh && b.kind() == Kind::kMesh) {
    MeshMeshContacts(a, X_Wa, padding_a, b, X_Wb, padding_b, out, cache);
  } else if (a.kind() == Kind::kMesh) {
    MeshPrimitiveContacts(a, X_Wa, padding_a, b, X_Wb, padding_b, out);
  } else {
    CollideSwapped([&] { MeshPrimitiveContacts(b, X_Wb, padding_b, a, X_Wa, padding_a, out); },
                   out);
  }
}

}  // namespace lamina::core
