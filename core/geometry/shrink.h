// SPDX-License-Identifier: MIT
// Preshrinking (Klamp't's "preshrink"): a body gets a boundary layer of thickness p and its
// geometry is shrunk by p, so that the padded surface lies where the original surface was.
#pragma once

#include "core/diagnostics.h"
#include "core/geometry/geometry_desc.h"
#include "core/geometry/triangle_mesh.h"

namespace lamina::core {

/// A mesh shrunk by ApproximateShrink.
struct ShrunkMesh {
  TriangleMesh mesh;
  /// Triangles whose normal turned around: the shrink amount is large for the mesh's features.
  int flipped_triangles = 0;
};

/// Klamp't's Meshing::ApproximateShrink: moves every vertex inward so that each triangle
/// touching it moves `amount` along its normal (a local, approximate erosion). Vertices closer
/// than 1e-6 (mesh units, L-inf) share one set of incident triangles and move together, so
/// seams of duplicated vertices stay closed. Vertex and triangle lists keep their order and
/// size. The mesh must be oriented counter-clockwise seen from outside.
/// Per vertex, with the distinct normals n_i of its faces: one normal, x = amount n; two, the
/// minimum-norm x with n_i.x = amount; three, the solution of n_i.x = amount; more, the triple
/// solution whose shallowest face moves most. x longer than 3 amount (a thin wedge) falls back
/// to amount times the average normal. Differences from Klamp't: above 48 normals (C(48, 3)
/// triples) the vertex moves along the average normal d by amount / min_i(n_i.d), which moves
/// every face at least `amount` (exact for a cone tip); when no triple moves every face
/// inward, the average normal is used (Klamp't leaves the vertex where it was).
ShrunkMesh ApproximateShrink(const TriangleMesh& mesh, double amount);

/// The geometry shrunk by `amount` (m, body units: after scale and transform), in place of
/// `geometry` for a body with padding `amount`. The input, and the mesh it shares, are not
/// modified; a shrunk mesh is a new mesh.
///  - sphere, capsule: radius - amount; box: each full size - 2 amount; cylinder: radius -
///    amount and length - 2 amount; plane: moved down (into its half-space) by amount. Under a
///    scale or non-rigid transform the amounts are converted to the primitive's own units
///    exactly: boxes and planes always (an affine image of a box is a parallelepiped whose
///    faces move independently), spheres and capsules under a uniform scale, cylinders under
///    a uniform scale across their axis. Other scaled primitives (an ellipsoid, ...) are not
///    the same kind of shape once offset: they are tessellated as the simulator would collide
///    them, and the mesh is shrunk instead (with a warning).
///  - meshes: ApproximateShrink in the frame where distances are body distances (scale baked
///    in, scale 1 and the transform kept; or everything baked in, when the transform is not
///    rigid). Warns when triangles flip.
///  - point clouds: unchanged, with a warning (their points have no surface; Klamp't likewise).
/// A dimension that would reach 0 is clamped to 1/1000 of its original value, with a warning.
/// amount 0 returns a copy; a negative or non-finite amount returns a copy with a warning.
/// Diagnostics are reported at `where`, or at the geometry's file when `where.file` is empty;
/// `diagnostics` may be nullptr.
GeometryDesc ShrinkGeometry(const GeometryDesc& geometry, double amount, Diagnostics* diagnostics,
                            const SourceLocation& where = {});

}  // namespace lamina::core
