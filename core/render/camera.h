// SPDX-License-Identifier: MIT
// The orbit camera: a target point, a distance, yaw and pitch about the world z axis, and a
// vertical field of view. View and projection matrices (OpenGL conventions), a default view that
// frames a box, and a one-line text description that can be written and read back.
#pragma once

#include <string>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/math_types.h"

namespace lamina::core {

/// A right-handed view matrix looking from `eye` at `target`, with world z up (x when looking
/// straight up or down).
Eigen::Matrix4d LookAt(const Eigen::Vector3d& eye, const Eigen::Vector3d& target);

struct OrbitCamera {
  Eigen::Vector3d target = Eigen::Vector3d::Zero();  ///< the point orbited, world m
  double yaw = 45.0;      ///< degrees about +z; 0 looks from +x towards the target
  double pitch = 25.0;    ///< degrees above the horizontal plane the eye sits, (-90, 90)
  double distance = 5.0;  ///< eye to target, m (> 0)
  double fov_y = 45.0;    ///< vertical field of view, degrees in (0, 180)

  bool operator==(const OrbitCamera&) const = default;

  /// Eye position in the world.
  Eigen::Vector3d Eye() const;
  /// World -> camera (right-handed, looking down -z, z of the world up on screen).
  Eigen::Matrix4d ViewMatrix() const;
  /// Camera -> clip for `aspect` = width / height, depth range chosen around `scene_radius`
  /// (the radius of a sphere about the target holding everything drawn).
  Eigen::Matrix4d ProjectionMatrix(double aspect, double scene_radius) const;
};

/// World -> OpenGL eye space for a camera whose frame `camera` (in the world) looks along its
/// z with x right and y down (Klamp't's and OpenCV's convention).
Eigen::Matrix4d CameraFrameViewMatrix(const Pose& camera);
/// Perspective projection for a horizontal field of view `xfov` (rad), `aspect` = width /
/// height and clip planes near < far (m).
Eigen::Matrix4d HorizontalFovProjection(double xfov, double aspect, double near_plane,
                                        double far_plane);

/// Near and far plane distances used by ProjectionMatrix.
void ClipDistances(const OrbitCamera& camera, double scene_radius, double* near_plane,
                   double* far_plane);

/// The default view of `box` for a viewport of `aspect`: from the front-left and above
/// (yaw 45°, pitch 25°), target at the box centre, far enough that the whole box is in view.
OrbitCamera FramingCamera(const Eigen::AlignedBox3d& box, double aspect);

/// "target=x,y,z;yaw=Y;pitch=P;dist=D;fov=F" (angles in degrees), shortest exact numbers.
std::string FormatCamera(const OrbitCamera& camera);

/// Parses FormatCamera's form; keys may come in any order and missing ones keep the value
/// already in `camera`. The compact form "x y z yaw pitch dist [fov]" is accepted too.
/// False with `error` saying what is wrong (which key, which value, what was expected).
bool ParseCamera(const std::string& text, OrbitCamera* camera, std::string* error);

}  // namespace lamina::core
