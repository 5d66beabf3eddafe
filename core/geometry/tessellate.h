// SPDX-License-Identifier: MIT
// Triangle meshes of primitives, closed and outward-facing, for display and mass checks.
#pragma once

#include "core/geometry/primitive.h"
#include "core/geometry/triangle_mesh.h"

namespace lamina::core {

/// A closed mesh of `primitive` in its geometry frame (primitive.pose applied). `segments` is
/// the number of divisions around a circle. A plane gives an empty mesh.
TriangleMesh Tessellate(const Primitive& primitive, int segments = 32);

}  // namespace lamina::core
