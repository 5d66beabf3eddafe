// SPDX-License-Identifier: MIT
#include "core/io/load_context.h"

#include <utility>

#include "core/io/mesh_file.h"
#include "core/io/point_cloud_file.h"

namespace lamina::core {

std::shared_ptr<const TriangleMesh> MeshCache::Get(const std::string& path,
                                                   const SourceLocation& where,
                                                   Diagnostics& diagnostics) {
  const auto found = meshes_.find(path);
  if (found != meshes_.end()) return found->second;
  std::optional<TriangleMesh> mesh = ReadMeshFile(path, where, diagnostics);
  if (!mesh) return nullptr;  // failures are reported, not cached
  auto shared = std::make_shared<const TriangleMesh>(std::move(*mesh));
  meshes_.emplace(path, shared);
  return shared;
}

std::shared_ptr<const PointCloud> MeshCache::GetPointCloud(const std::string& path,
                                                           const SourceLocation& where,
                                                           Diagnostics& diagnostics) {
  const auto found = point_clouds_.find(path);
  if (found != point_clouds_.end()) return found->second;
  std::optional<PointCloud> cloud = ReadPointCloudFile(path, where, diagnostics);
  if (!cloud) return nullptr;
  auto shared = std::make_shared<const PointCloud>(std::move(*cloud));
  point_clouds_.emplace(path, shared);
  return shared;
}

}  // namespace lamina::core
