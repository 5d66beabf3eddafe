// SPDX-License-Identifier: MIT
// A point cloud in the coordinates of the file it came from (PCL's `.pcd`): points with no size
// and no surface, optionally one display colour each.
//
// Conventions and differences from Klamp't:
//  - Units are the file's (metres for Klamp't's data); the frame is the file's, so a body places
//    it with GeometryDesc::Matrix() like a mesh. The file's VIEWPOINT (the sensor pose) is not
//    applied to the points, as in PCL and Klamp't.
//  - Points are finite: the reader drops PCL's "no return" points (NaN coordinates), which
//    Klamp't keeps.
//  - Colours are 0xRRGGBB (alpha dropped). Klamp't keeps every PCD field as a property; Lamina
//    keeps x, y, z and the colour only.
//  - In contact, each point is a ball of its body's padding radius (docs/contact-model.md).
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Geometry>

#include "core/math_types.h"

namespace lamina::core {

struct PointCloud {
  std::vector<Vec3> points;           ///< file coordinates, finite
  std::vector<std::uint32_t> colors;  ///< empty, or one 0xRRGGBB per point

  int point_count() const { return static_cast<int>(points.size()); }
  bool has_colors() const { return !colors.empty() && colors.size() == points.size(); }
  /// Axis-aligned bounds; empty (min > max) when there are no points.
  Eigen::AlignedBox3d Bounds() const;
};

/// The points mapped through `matrix` (file -> body coordinates), in order.
std::vector<Vec3> TransformedPoints(const PointCloud& cloud, const Affine& matrix);

}  // namespace lamina::core
