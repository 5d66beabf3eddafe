// SPDX-License-Identifier: MIT
// Contacts of point clouds (Klamp't's CollisionPointCloud contacts with the boundary layer).
//
// Model: a point has no size; with its body's padding (plus the geometry's margin) it is a ball
// of that radius, so a point p of cloud a touches body b where the distance from p to b's
// unpadded geometry is below pad_a + pad_b, exactly as a sphere primitive of radius 0 padded by
// pad_a would. Each point gives at most one contact, built like every other pair's
// (core/contact/contact.h): the normal points from b into a, the depth is pad_a + pad_b - d, the
// position lies midway between the padded surfaces, and `penetrating` is set when the point is
// inside b's geometry (d < 0). Clustering to maxContacts and the contact law then apply
// unchanged.
//  - vs a primitive: d is the signed distance from p to the primitive (negative inside), the
//    normal the primitive's outward normal at its closest point (the sphere rule of
//    primitive_contacts.h with radius 0).
//  - vs a mesh: the nearest triangle (the lower index on a tie) gives the closest point c. When c
//    is inside that face, the normal is the face's outward normal and d = n.(p - c) is signed,
//    so a point that sank behind the face is pushed back out; on an edge or vertex the normal is
//    (p - c)/|p - c| turned to agree with the feature's outward normal (d negative when turned),
//    and the feature normal itself closer than 1e-5 m (Klamp't's rule). Klamp't takes p - c
//    unsigned, so a point behind a face is pulled through it.
//  - vs a point cloud: for each point of a, the nearest point q of b (the lower index on a tie),
//    d = |p - q|, normal (p - q)/d; coincident points (no direction) give none.
// Speed: the points are grouped into leaves of at most 16 nearby points with their bounds; a
// leaf is tested against the other body's bounds (primitive), its triangles near the leaf (the
// mesh's bounding-volume hierarchy: one query per leaf, not per point, so a 10k-point cloud on a
// terrain costs ~600 hierarchy queries) or the other cloud's leaves before any single point.
#pragma once

#include <vector>

#include "core/contact/collision_geometry.h"

namespace lamina::core {

/// a is a point cloud; b a primitive, a mesh or a point cloud. Appends to `out`.
void PointCloudContacts(const CollisionGeometry& a, const Pose& X_Wa, double pad_a,
                        const CollisionGeometry& b, const Pose& X_Wb, double pad_b,
                        ContactList* out);

namespace point_cloud_detail {

/// Reorders `points` into leaves of at most `per_leaf` points (halving the longest side of their
/// bounds at the median point, recursively) and returns the leaves in order. Deterministic.
std::vector<CollisionGeometry::PointLeaf> PartitionPoints(int per_leaf, std::vector<Vec3>* points);

}  // namespace point_cloud_detail

}  // namespace lamina::core
