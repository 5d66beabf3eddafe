// SPDX-License-Identifier: MIT
// Keys shapes by mesh identity or primitive parameters and builds their RenderMeshes once.
#include "core/render/render_mesh_cache.h"

#include <cstdio>

#include "core/geometry/tessellate.h"
#include "core/render/point_markers.h"

namespace lamina::core {

namespace {

// a text key that identifies a primitive exactly
std::string PrimitiveKey(const Primitive& p) {
  std::string key = p.TypeName();
  char buffer[64];
  auto append = [&](double value) {
    std::snprintf(buffer, sizeof(buffer), " %.17g", value);
    key += buffer;
  };
  append(p.radius);
  append(p.length);
  for (int i = 0; i < 3; ++i) append(p.size[i]);
  for (int i = 0; i < 16; ++i) append(p.pose.matrix()(i));
  return key;
}

// "mesh 0x…" or "cloud 0x…": a shared shape by its address
std::string AddressKey(const char* what, const void* address) {
  char buffer[48];
  std::snprintf(buffer, sizeof(buffer), "%s %p", what, address);
  return buffer;
}

std::string ShapeKey(const GeometryDesc& geometry) {
  if (geometry.kind == GeometryKind::kPrimitive) return PrimitiveKey(geometry.primitive);
  if (geometry.kind == GeometryKind::kPointCloud) {
    return AddressKey("cloud", geometry.point_cloud.get());
  }
  return AddressKey("mesh", geometry.mesh.get());
}

// what the shape's key refers to, kept alive with the entry
std::shared_ptr<const void> ShapeSource(const GeometryDesc& geometry) {
  if (geometry.kind == GeometryKind::kPointCloud) return geometry.point_cloud;
  return geometry.mesh;
}

// nothing to draw: no kind, or a mesh or cloud that is missing
bool Undrawable(const GeometryDesc& geometry) {
  return geometry.empty() || (geometry.kind == GeometryKind::kMesh && !geometry.mesh) ||
         (geometry.kind == GeometryKind::kPointCloud && !geometry.point_cloud);
}

// the octahedra of a cloud's points, file coordinates
TriangleMesh CloudMarkers(const PointCloud& cloud) {
  return PointMarkers(cloud.points, PointMarkerRadius(cloud));
}

// a square of +-kPlaneDisplayHalfSize in the plane's z = 0, facing +z
TriangleMesh PlaneQuad(const Pose& pose) {
  const double h = kPlaneDisplayHalfSize;
  TriangleMesh quad;
  for (const auto& [x, y] : {std::pair{-h, -h}, {h, -h}, {h, h}, {-h, h}}) {
    quad.vertices.push_back(pose * Vec3(x, y, 0.0));
  }
  quad.triangles = {{0, 1, 2}, {0, 2, 3}};
  return quad;
}

TriangleMesh PrimitiveMesh(const Primitive& primitive) {
  if (primitive.type == PrimitiveType::kPlane) return PlaneQuad(primitive.pose);
  return Tessellate(primitive, 48);
}

TriangleMesh Transformed(TriangleMesh mesh, const Affine& matrix) {
  for (Vec3& v : mesh.vertices) v = matrix * v;
  // a mirroring matrix turns the winding inside out; keep it outward
  if (matrix.linear().determinant() < 0.0) {
    for (Eigen::Vector3i& t : mesh.triangles) std::swap(t[1], t[2]);
  }
  return mesh;
}

bool UniformScale(const Vec3& scale) {
  return scale.x() > 0.0 && scale.x() == scale.y() && scale.y() == scale.z();
}

}  // namespace

Primitive InflatePrimitive(const Primitive& primitive, double padding) {
  Primitive grown = primitive;
  switch (primitive.type) {
    case PrimitiveType::kSphere:
    case PrimitiveType::kCapsule:
      grown.radius += padding;
      break;
    case PrimitiveType::kBox:
      grown.size += Vec3::Constant(2.0 * padding);
      break;
    case PrimitiveType::kCylinder:
      grown.radius += padding;
      grown.length += 2.0 * padding;
      break;
    case PrimitiveType::kPlane:
      grown.pose.translation() += grown.pose.linear().col(2) * padding;
      break;
  }
  return grown;
}

std::shared_ptr<const RenderMesh> RenderMeshCache::Store(const std::string& key,
                                                         const TriangleMesh& mesh) {
  auto built = std::make_shared<const RenderMesh>(BuildRenderMesh(mesh));
  if (built->empty()) built = nullptr;
  meshes_[key].mesh = built;
  return built;
}

std::shared_ptr<const RenderMesh> RenderMeshCache::Shape(const GeometryDesc& geometry) {
  if (Undrawable(geometry)) return nullptr;
  const std::string key = ShapeKey(geometry);
  const auto found = meshes_.find(key);
  if (found != meshes_.end()) return found->second.mesh;
  meshes_[key].source = ShapeSource(geometry);
  if (geometry.kind == GeometryKind::kPrimitive) {
    return Store(key, PrimitiveMesh(geometry.primitive));
  }
  if (geometry.kind == GeometryKind::kPointCloud)
    return Store(key, CloudMarkers(*geometry.point_cloud));
  return Store(key, *geometry.mesh);
}

const std::vector<ColoredShape>& RenderMeshCache::ColoredShapes(const GeometryDesc& geometry) {
  static const std::vector<ColoredShape> kNone;
  if (geometry.kind != GeometryKind::kPointCloud || !geometry.point_cloud) return kNone;
  const PointCloud& cloud = *geometry.point_cloud;
  const auto found = colored_.find(&cloud);
  if (found != colored_.end()) return found->second.shapes;
  ColoredEntry& entry = colored_[&cloud];
  entry.source = geometry.point_cloud;
  const double radius = PointMarkerRadius(cloud);
  Eigen::AlignedBox3f whole;
  std::vector<RenderMesh> meshes;
  for (const PointColorGroup& group : GroupPointsByColor(cloud)) {
    meshes.push_back(BuildRenderMesh(PointMarkers(group.points, radius)));
    entry.shapes.push_back({nullptr, group.color});
    whole.extend(meshes.back().bounds);
  }
  for (std::size_t g = 0; g < meshes.size(); ++g) {
    meshes[g].bounds = whole;
    entry.shapes[g].mesh = std::make_shared<const RenderMesh>(std::move(meshes[g]));
  }
  return entry.shapes;
}

std::shared_ptr<const RenderMesh> RenderMeshCache::PaddedShape(const GeometryDesc& geometry,
                                                               double padding) {
  if (Undrawable(geometry)) return nullptr;
  char suffix[64];
  std::snprintf(suffix, sizeof(suffix), " padded %.17g", padding);
  std::string key = ShapeKey(geometry) + suffix;
  const Affine matrix = geometry.Matrix();
  for (int i = 0; i < 16; ++i) {
    std::snprintf(suffix, sizeof(suffix), " %.17g", matrix.matrix()(i));
    key += suffix;
  }
  const auto found = meshes_.find(key);
  if (found != meshes_.end()) return found->second.mesh;
  meshes_[key].source = ShapeSource(geometry);
  if (geometry.kind == GeometryKind::kPointCloud) {
    return Store(key, PointMarkers(BakedPoints(geometry), padding));
  }
  if (geometry.kind == GeometryKind::kPrimitive && UniformScale(geometry.scale)) {
    const Primitive grown = InflatePrimitive(geometry.primitive, padding / geometry.scale.x());
    return Store(key, Transformed(PrimitiveMesh(grown), matrix));
  }
  const TriangleMesh baked = geometry.kind == GeometryKind::kPrimitive
                                 ? Transformed(PrimitiveMesh(geometry.primitive), matrix)
                                 : Transformed(*geometry.mesh, matrix);
  return Store(key, OffsetMesh(baked, padding));
}

}  // namespace lamina::core
