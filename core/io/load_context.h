// SPDX-License-Identifier: MIT
// What every loader shares: the diagnostics sink and the cache that makes each mesh and point
// cloud file load once however many bodies use it.
#pragma once

#include <map>
#include <memory>
#include <string>

#include "core/diagnostics.h"
#include "core/geometry/point_cloud.h"
#include "core/geometry/triangle_mesh.h"

namespace lamina::core {

class MeshCache {
 public:
  /// The mesh in file `path` (absolute), loaded on first use. On failure reports at `where`
  /// (the place that referenced the file) and returns nullptr; failures are not cached.
  std::shared_ptr<const TriangleMesh> Get(const std::string& path, const SourceLocation& where,
                                          Diagnostics& diagnostics);
  /// The point cloud in `.pcd` file `path` (absolute), likewise.
  std::shared_ptr<const PointCloud> GetPointCloud(const std::string& path,
                                                  const SourceLocation& where,
                                                  Diagnostics& diagnostics);
  /// Meshes loaded (point clouds not counted).
  int size() const { return static_cast<int>(meshes_.size()); }
  int point_cloud_count() const { return static_cast<int>(point_clouds_.size()); }

 private:
  std::map<std::string, std::shared_ptr<const TriangleMesh>> meshes_;
  std::map<std::string, std::shared_ptr<const PointCloud>> point_clouds_;
};

struct LoadContext {
  Diagnostics& diagnostics;
  MeshCache& meshes;
};

}  // namespace lamina::core
