// SPDX-License-Identifier: MIT
// Upload and lifetime of GPU meshes.
#include "ui/render/gpu_mesh_cache.h"

#include <vector>

#include "ui/render/gl_api.h"

namespace lamina::ui {

namespace {

GpuMesh Upload(const core::RenderMesh& mesh) {
  std::vector<float> interleaved;
  interleaved.reserve(mesh.positions.size() * 6);
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    interleaved.insert(interleaved.end(), mesh.positions[i].data(), mesh.positions[i].data() + 3);
    interleaved.insert(interleaved.end(), mesh.normals[i].data(), mesh.normals[i].data() + 3);
  }
  GpuMesh gpu;
  gpu.corner_count = mesh.corner_count();
  glGenVertexArrays(1, &gpu.vertex_array);
  glGenBuffers(1, &gpu.buffer);
  glBindVertexArray(gpu.vertex_array);
  glBindBuffer(GL_ARRAY_BUFFER, gpu.buffer);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(interleaved.size() * sizeof(float)),
               interleaved.data(), GL_STATIC_DRAW);
  const GLsizei stride = 6 * sizeof(float);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, nullptr);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride,
                        reinterpret_cast<const void*>(3 * sizeof(float)));
  glBindVertexArray(0);
  return gpu;
}

void Free(GpuMesh* mesh) {
  glDeleteBuffers(1, &mesh->buffer);
  glDeleteVertexArrays(1, &mesh->vertex_array);
}

}  // namespace

GpuMeshCache::~GpuMeshCache() {
  for (auto& [serial, mesh] : meshes_) Free(&mesh);
}

const GpuMesh& GpuMeshCache::Get(const core::RenderMesh& mesh) {
  auto found = meshes_.find(mesh.serial);
  if (found == meshes_.end()) found = meshes_.emplace(mesh.serial, Upload(mesh)).first;
  found->second.last_frame = frame_;
  return found->second;
}

void GpuMeshCache::EndFrame(std::uint64_t max_idle_frames) {
  for (auto it = meshes_.begin(); it != meshes_.end();) {
    if (frame_ - it->second.last_frame > max_idle_frames) {
      Free(&it->second);
      it = meshes_.erase(it);
    } else {
      ++it;
    }
  }
  ++frame_;
}

void DrawGpuMesh(const GpuMesh& mesh) {
  glBindVertexArray(mesh.vertex_array);
  glDrawArrays(GL_TRIANGLES, 0, mesh.corner_count);
}

}  // namespace lamina::ui
