// SPDX-License-Identifier: MIT
// Keys shapes by mesh identity or primitive parameters and builds their RenderMeshes once.
#include "core/render/render_mesh_cache.h"

#include <cstdio>

#include "core/geometry/tessellate.h"

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

std::string MeshKey(const TriangleMesh* mesh) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "mesh %p", static_cast<const void*>(mesh));
  return buffer;
}

std::string ShapeKey(const GeometryDesc& geometry) {
  if (geometry.kind == GeometryKind::kPrimitive) return PrimitiveKey(geometry.primitive);
  return MeshKey(geometry.mesh.get());
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
  if (geometry.empty() || (geometry.kind == GeometryKind::kMesh && !geometry.mesh)) return nullptr;
  const std::string key = ShapeKey(geometry);
  const auto found = meshes_.find(key);
  if (found != meshes_.end()) return found->second.mesh;
  meshes_[key].source = geometry.mesh;
  if (geometry.kind == GeometryKind::kPrimitive) {
    return Store(key, PrimitiveMesh(geometry.primitive));
  }
  return Store(key, *geometry.mesh);
}

std::shared_ptr<const RenderMesh> RenderMeshCache::PaddedShape(const GeometryDesc& geometry,
                                                               double padding) {
  if (geometry.empty() || (geometry.kind == GeometryKind::kMesh && !geometry.mesh)) return nullptr;
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
  meshes_[key].source = geometry.mesh;
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
