// SPDX-License-Identifier: MIT
#include "core/render/point_markers.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

namespace lamina::core {

namespace {

// the six vertex directions of an octahedron and its eight faces, counter-clockwise outside
constexpr std::array<std::array<int, 3>, 6> kDirections = {
    {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}};
constexpr std::array<std::array<int, 3>, 8> kFaces = {
    {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}}};

Rgba ColorOf(std::uint32_t rgb) {
  return Rgba(((rgb >> 16) & 0xFF) / 255.0f, ((rgb >> 8) & 0xFF) / 255.0f, (rgb & 0xFF) / 255.0f,
              1.0f);
}

// 0xRRGGBB binned to 8 levels a channel (the top 3 bits of each)
std::uint32_t Binned(std::uint32_t rgb) {
  return rgb & 0xE0E0E0u;
}

int DistinctColors(const std::vector<std::uint32_t>& colors) {
  std::vector<std::uint32_t> sorted = colors;
  std::sort(sorted.begin(), sorted.end());
  return static_cast<int>(std::unique(sorted.begin(), sorted.end()) - sorted.begin());
}

}  // namespace

double PointMarkerRadius(const PointCloud& cloud) {
  const double diagonal = cloud.points.empty() ? 0.0 : cloud.Bounds().diagonal().norm();
  if (!(diagonal > 0.0)) return 0.005;
  const double spacing = diagonal / std::sqrt(static_cast<double>(cloud.points.size()));
  return std::clamp(0.5 * spacing, 0.002 * diagonal, 0.02 * diagonal);
}

TriangleMesh PointMarkers(const std::vector<Vec3>& points, double radius) {
  TriangleMesh mesh;
  mesh.vertices.reserve(6 * points.size());
  mesh.triangles.reserve(8 * points.size());
  for (const Vec3& p : points) {
    const int first = mesh.vertex_count();
    for (const auto& d : kDirections) mesh.vertices.push_back(p + radius * Vec3(d[0], d[1], d[2]));
    for (const auto& f : kFaces)
      mesh.triangles.emplace_back(first + f[0], first + f[1], first + f[2]);
  }
  return mesh;
}

std::vector<PointColorGroup> GroupPointsByColor(const PointCloud& cloud) {
  if (!cloud.has_colors()) return {};
  const bool exact = DistinctColors(cloud.colors) <= kMaxColorGroups;
  std::vector<PointColorGroup> groups;
  std::vector<Eigen::Vector3d> sums;  // of the members' colours, for binned groups
  std::map<std::uint32_t, int> index;
  for (std::size_t i = 0; i < cloud.points.size(); ++i) {
    const std::uint32_t rgb = cloud.colors[i];
    const auto [found, added] = index.emplace(exact ? rgb : Binned(rgb), int(groups.size()));
    if (added) {
      groups.push_back({ColorOf(rgb), {}});
      sums.push_back(Eigen::Vector3d::Zero());
    }
    groups[found->second].points.push_back(cloud.points[i]);
    sums[found->second] += ColorOf(rgb).head<3>().cast<double>();
  }
  for (std::size_t g = 0; g < groups.size() && !exact; ++g) {
    const Eigen::Vector3d mean = sums[g] / static_cast<double>(groups[g].points.size());
    groups[g].color.head<3>() = mean.cast<float>();
  }
  return groups;
}

}  // namespace lamina::core
