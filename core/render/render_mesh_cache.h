// SPDX-License-Identifier: MIT
// RenderMeshCache: one RenderMesh per distinct shape, built on first use and shared by every body
// and every frame that draws it, so extraction never re-tessellates.
#pragma once

#include <map>
#include <memory>
#include <string>

#include "core/geometry/geometry_desc.h"
#include "core/render/render_mesh.h"

namespace lamina::core {

/// Half the edge of the square drawn for an (infinite) plane primitive, m.
inline constexpr double kPlaneDisplayHalfSize = 50.0;

class RenderMeshCache {
 public:
  /// The shape of `geometry` before its matrix (file coordinates; draw it with
  /// body pose * geometry.Matrix()). nullptr for empty geometry or a mesh without triangles.
  std::shared_ptr<const RenderMesh> Shape(const GeometryDesc& geometry);

  /// The shape grown by `padding` (m) in body coordinates (draw it with the body pose):
  /// primitives grow analytically, meshes by OffsetMesh. nullptr as for Shape.
  std::shared_ptr<const RenderMesh> PaddedShape(const GeometryDesc& geometry, double padding);

  int size() const { return static_cast<int>(meshes_.size()); }
  void Clear() { meshes_.clear(); }

 private:
  std::shared_ptr<const RenderMesh> Store(const std::string& key, const TriangleMesh& mesh);

  struct Entry {
    std::shared_ptr<const TriangleMesh> source;  ///< keeps the keyed mesh address alive
    std::shared_ptr<const RenderMesh> mesh;
  };
  std::map<std::string, Entry> meshes_;
};

/// A primitive grown by `padding` on every side (a box stays a box: its corners are not rounded).
Primitive InflatePrimitive(const Primitive& primitive, double padding);

}  // namespace lamina::core
