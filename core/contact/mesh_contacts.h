// SPDX-License-Identifier: MIT
// Contacts involving triangle meshes: mesh-mesh (every triangle pair within the padding sum,
// from a traversal of both FCL bounding-volume hierarchies) and mesh-primitive.
#pragma once

#include "core/contact/collision_geometry.h"

namespace lamina::core {

/// a and b are meshes. Normals are feature-based (vertex/edge/face) so they stay consistent
/// from step to step. Appends to `out`; sets `penetrating` where triangles intersect. `cache`:
/// the pair's candidate triangle pairs from earlier calls (near_pair_cache.h), or null.
void MeshMeshContacts(const CollisionGeometry& a, const Pose& X_Wa, double pad_a,
                      const CollisionGeometry& b, const Pose& X_Wb, double pad_b, ContactList* out,
                      NearPairCache* cache = nullptr);

/// a is a mesh, b a primitive (including the plane: every mesh vertex within the padding).
void MeshPrimitiveContacts(const CollisionGeometry& a, const Pose& X_Wa, double pad_a,
                           const CollisionGeometry& b, const Pose& X_Wb, double pad_b,
                           ContactList* out);

}  // namespace lamina::core
