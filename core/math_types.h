// SPDX-License-Identifier: MIT
// Math vocabulary of the core: Eigen aliases and the rotation conventions of Klamp't files.
// Units are SI and radians everywhere in core/.
#pragma once

#include <array>
#include <limits>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace lamina::core {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Mat4 = Eigen::Matrix4d;
using VecX = Eigen::VectorXd;
using MatX = Eigen::MatrixXd;
/// A rigid transform (rotation + translation).
using Pose = Eigen::Isometry3d;
/// A general affine map (rotation, scale, shear + translation).
using Affine = Eigen::Affine3d;

inline constexpr double kInf = std::numeric_limits<double>::infinity();
inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kTwoPi = 2.0 * kPi;

/// R = Rz(yaw) * Ry(pitch) * Rx(roll), the Klamp't `rotateRPY` convention.
Mat3 RotationFromRollPitchYaw(double roll, double pitch, double yaw);
/// Exponential map: rotation by |moment| radians about moment/|moment|.
Mat3 RotationFromMoment(const Vec3& moment);
/// Logarithm map, the inverse of RotationFromMoment (angle in [0, pi]).
Vec3 MomentFromRotation(const Mat3& rotation);
/// Roll, pitch, yaw such that RotationFromRollPitchYaw reproduces `rotation`.
Vec3 RollPitchYawFromRotation(const Mat3& rotation);
/// True when the three scale factors are exactly equal (a scale that keeps shapes).
inline bool IsUniformScale(const Vec3& scale) {
  return scale.x() == scale.y() && scale.y() == scale.z();
}
/// True when `m` is orthonormal with determinant +1 within `tolerance`.
bool IsRotation(const Mat3& m, double tolerance = 1e-6);

/// A Klamp't RigidTransform written as 12 numbers: rotation row-major, then translation.
Pose PoseFromKlamptNumbers(const double* twelve);
/// The 12 numbers of `pose` in the Klamp't order (rotation row-major, then translation).
std::array<double, 12> KlamptNumbersFromPose(const Pose& pose);

/// The affine matrix of a geometry: `transform * diag(scale)` (scale first, then transform).
Affine GeometryMatrix(const Affine& transform, const Vec3& scale);

}  // namespace lamina::core
