// SPDX-License-Identifier: MIT
// Corner normals with a crease angle, and vertex offsets for the padding layer.
#include "core/render/render_mesh.h"

#include <atomic>
#include <cmath>

namespace lamina::core {

namespace {

// area-weighted (unnormalized) normal of each triangle
std::vector<Vec3> FaceNormals(const TriangleMesh& mesh) {
  std::vector<Vec3> normals;
  normals.reserve(mesh.triangles.size());
  for (const Eigen::Vector3i& t : mesh.triangles) {
    const Vec3& a = mesh.vertices[t[0]];
    normals.push_back((mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a));
  }
  return normals;
}

// for each vertex the triangles that use it, as a compressed list (offsets + entries)
struct VertexFaces {
  std::vector<int> offsets;
  std::vector<int> faces;
};

VertexFaces BuildVertexFaces(const TriangleMesh& mesh) {
  VertexFaces result;
  result.offsets.assign(mesh.vertices.size() + 1, 0);
  for (const Eigen::Vector3i& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) ++result.offsets[t[k] + 1];
  }
  for (size_t v = 1; v < result.offsets.size(); ++v) result.offsets[v] += result.offsets[v - 1];
  result.faces.resize(result.offsets.back());
  std::vector<int> fill(result.offsets.begin(), result.offsets.end() - 1);
  for (int f = 0; f < mesh.triangle_count(); ++f) {
    for (int k = 0; k < 3; ++k) result.faces[fill[mesh.triangles[f][k]]++] = f;
  }
  return result;
}

bool ValidTriangle(const Eigen::Vector3i& t, int vertex_count) {
  for (int k = 0; k < 3; ++k) {
    if (t[k] < 0 || t[k] >= vertex_count) return false;
  }
  return true;
}

}  // namespace

std::uint64_t NextRenderMeshSerial() {
  static std::atomic<std::uint64_t> next{1};
  return next++;
}

RenderMesh BuildRenderMesh(const TriangleMesh& mesh, double crease_angle) {
  RenderMesh out;
  out.serial = NextRenderMeshSerial();
  for (const Eigen::Vector3i& t : mesh.triangles) {
    if (!ValidTriangle(t, mesh.vertex_count())) return out;
  }
  const std::vector<Vec3> face_normals = FaceNormals(mesh);
  const VertexFaces vertex_faces = BuildVertexFaces(mesh);
  const double cos_crease = std::cos(crease_angle);
  out.positions.reserve(mesh.triangles.size() * 3);
  out.normals.reserve(mesh.triangles.size() * 3);
  for (int f = 0; f < mesh.triangle_count(); ++f) {
    const Vec3 own = face_normals[f].normalized();
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.triangles[f][k];
      Vec3 sum = Vec3::Zero();
      for (int i = vertex_faces.offsets[v]; i < vertex_faces.offsets[v + 1]; ++i) {
        const Vec3& other = face_normals[vertex_faces.faces[i]];
        if (other.normalized().dot(own) >= cos_crease) sum += other;
      }
      const Vec3 normal = sum.squaredNorm() > 0.0 ? sum.normalized() : own;
      out.positions.push_back(mesh.vertices[v].cast<float>());
      out.normals.push_back(normal.allFinite() ? Eigen::Vector3f(normal.cast<float>())
                                               : Eigen::Vector3f::UnitZ());
      out.bounds.extend(out.positions.back());
    }
  }
  return out;
}

TriangleMesh OffsetMesh(const TriangleMesh& mesh, double distance) {
  std::vector<Vec3> vertex_normals(mesh.vertices.size(), Vec3::Zero());
  const std::vector<Vec3> face_normals = FaceNormals(mesh);
  for (int f = 0; f < mesh.triangle_count(); ++f) {
    if (!ValidTriangle(mesh.triangles[f], mesh.vertex_count())) continue;
    for (int k = 0; k < 3; ++k) vertex_normals[mesh.triangles[f][k]] += face_normals[f];
  }
  TriangleMesh out = mesh;
  for (size_t v = 0; v < out.vertices.size(); ++v) {
    if (vertex_normals[v].squaredNorm() > 0.0) {
      out.vertices[v] += distance * vertex_normals[v].normalized();
    }
  }
  return out;
}

}  // namespace lamina::core
