// SPDX-License-Identifier: MIT
// GPU copies of RenderMeshes (one vertex array per mesh), uploaded on first draw and dropped when
// a mesh has not been drawn for a while.
#pragma once

#include <cstdint>
#include <unordered_map>

#include "core/render/render_mesh.h"

namespace lamina::ui {

struct GpuMesh {
  unsigned vertex_array = 0;
  unsigned buffer = 0;
  int corner_count = 0;
  std::uint64_t last_frame = 0;
};

class GpuMeshCache {
 public:
  GpuMeshCache() = default;
  GpuMeshCache(const GpuMeshCache&) = delete;
  GpuMeshCache& operator=(const GpuMeshCache&) = delete;
  ~GpuMeshCache();

  /// The GPU copy of `mesh`, uploading it the first time (attribute 0 position, 1 normal).
  const GpuMesh& Get(const core::RenderMesh& mesh);
  /// Marks a new frame and frees meshes unused for `max_idle_frames` frames.
  void EndFrame(std::uint64_t max_idle_frames = 120);
  int size() const { return static_cast<int>(meshes_.size()); }

 private:
  std::unordered_map<std::uint64_t, GpuMesh> meshes_;
  std::uint64_t frame_ = 0;
};

/// Draws a GpuMesh's triangles with whatever program is bound.
void DrawGpuMesh(const GpuMesh& mesh);

}  // namespace lamina::ui
