// SPDX-License-Identifier: MIT
// RenderMeshCache: one RenderMesh per distinct shape, built on first use and shared by every body
// and every frame that draws it, so extraction never re-tessellates.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/geometry/geometry_desc.h"
#include "core/render/display_color.h"
#include "core/render/render_mesh.h"

namespace lamina::core {

/// Half the edge of the square drawn for an (infinite) plane primitive, m.
inline constexpr double kPlaneDisplayHalfSize = 50.0;

/// One colour group of a point cloud as a mesh (see ColoredShapes).
struct ColoredShape {
  std::shared_ptr<const RenderMesh> mesh;
  Rgba color;
};

class RenderMeshCache {
 public:
  /// The shape of `geometry` before its matrix (file coordinates; draw it with
  /// body pose * geometry.Matrix()). nullptr for empty geometry or a mesh without triangles.
  /// A point cloud is an octahedron per point, sized by PointMarkerRadius (point_markers.h).
  std::shared_ptr<const RenderMesh> Shape(const GeometryDesc& geometry);

  /// A point cloud with per-point colours as one mesh per colour group (GroupPointsByColor),
  /// in file coordinates like Shape. Each mesh's `bounds` are those of the whole cloud, so that
  /// boxes and framing see the body, not the group. Empty for any other geometry.
  const std::vector<ColoredShape>& ColoredShapes(const GeometryDesc& geometry);

  /// The shape grown by `padding` (m) in body coordinates (draw it with the body pose):
  /// primitives grow analytically, meshes by OffsetMesh, a point cloud's points become
  /// octahedra of radius `padding` (the balls they collide as). nullptr as for Shape.
  std::shared_ptr<const RenderMesh> PaddedShape(const GeometryDesc& geometry, double padding);

  int size() const { return static_cast<int>(meshes_.size()); }
  void Clear() {
    meshes_.clear();
    colored_.clear();
  }

 private:
  std::shared_ptr<const RenderMesh> Store(const std::string& key, const TriangleMesh& mesh);

  struct Entry {
    std::shared_ptr<const void> source;  ///< keeps the keyed mesh or cloud address alive
    std::shared_ptr<const RenderMesh> mesh;
  };
  struct ColoredEntry {
    std::shared_ptr<const PointCloud> source;
    std::vector<ColoredShape> shapes;
  };
  std::map<std::string, Entry> meshes_;
  std::map<const PointCloud*, ColoredEntry> colored_;
};

/// A primitive grown by `padding` on every side (a box stays a box: its corners are not rounded).
Primitive InflatePrimitive(const Primitive& primitive, double padding);

}  // namespace lamina::core
