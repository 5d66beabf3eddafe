// SPDX-License-Identifier: MIT
// Point clouds made drawable as ordinary meshes: one small octahedron per point (8 triangles,
// vertices along ±x, ±y, ±z of the mesh frame), so every renderer of RenderMeshes draws them
// with no special path. A renderer colours a whole mesh, so a cloud with per-point colours
// becomes one mesh per colour group.
#pragma once

#include <cstdint>
#include <vector>

#include "core/geometry/point_cloud.h"
#include "core/geometry/triangle_mesh.h"
#include "core/render/display_color.h"

namespace lamina::core {

/// The octahedron "radius" (centre to vertex) drawn for each point of `cloud`, in its file
/// units: half the typical spacing of points sampled over a surface, 0.5·D/√n for the bounds'
/// diagonal D and n points, kept within [0.002 D, 0.02 D]; 0.005 for a single point.
double PointMarkerRadius(const PointCloud& cloud);

/// One octahedron of `radius` around each point, outward-facing, in the points' frame.
TriangleMesh PointMarkers(const std::vector<Vec3>& points, double radius);

/// Points sharing one display colour.
struct PointColorGroup {
  Rgba color;
  std::vector<Vec3> points;
};

/// The points of a coloured cloud grouped by colour, in order of each group's first point. Up
/// to kMaxColorGroups distinct colours are kept exactly; with more, colours are binned to 8
/// levels a channel (at most 512 groups) and each group takes its members' mean colour. Empty
/// when the cloud has no colours. Alpha is 1.
std::vector<PointColorGroup> GroupPointsByColor(const PointCloud& cloud);
inline constexpr int kMaxColorGroups = 256;

}  // namespace lamina::core
