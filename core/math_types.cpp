// SPDX-License-Identifier: MIT
#include "core/math_types.h"

#include <algorithm>
#include <cmath>

namespace lamina::core {

Mat3 RotationFromRollPitchYaw(double roll, double pitch, double yaw) {
  return (Eigen::AngleAxisd(yaw, Vec3::UnitZ()) * Eigen::AngleAxisd(pitch, Vec3::UnitY()) *
          Eigen::AngleAxisd(roll, Vec3::UnitX()))
      .toRotationMatrix();
}

Mat3 RotationFromMoment(const Vec3& moment) {
  const double angle = moment.norm();
  if (angle == 0.0) return Mat3::Identity();
  return Eigen::AngleAxisd(angle, moment / angle).toRotationMatrix();
}

Vec3 MomentFromRotation(const Mat3& rotation) {
  const Eigen::AngleAxisd angle_axis(rotation);
  return angle_axis.axis() * angle_axis.angle();
}

Vec3 RollPitchYawFromRotation(const Mat3& rotation) {
  // R = Rz(y) Ry(p) Rx(r): R(2,0) = -sin(p), R(2,1) = cos(p) sin(r), R(1,0) = cos(p) sin(y)
  const double pitch = std::asin(std::clamp(-rotation(2, 0), -1.0, 1.0));
  if (std::abs(std::cos(pitch)) < 1e-12) {
    // gimbal lock: put all of the remaining rotation into yaw
    const double yaw = std::atan2(-rotation(0, 1), rotation(1, 1));
    return {0.0, pitch, yaw};
  }
  const double roll = std::atan2(rotation(2, 1), rotation(2, 2));
  const double yaw = std::atan2(rotation(1, 0), rotation(0, 0));
  return {roll, pitch, yaw};
}

bool IsRotation(const Mat3& m, double tolerance) {
  if (!m.allFinite()) return false;
  const double orthogonality = (m * m.transpose() - Mat3::Identity()).cwiseAbs().maxCoeff();
  return orthogonality <= tolerance && std::abs(m.determinant() - 1.0) <= tolerance;
}

Pose PoseFromKlamptNumbers(const double* twelve) {
  Pose pose = Pose::Identity();
  Mat3 rotation;
  rotation << twelve[0], twelve[1], twelve[2], twelve[3], twelve[4], twelve[5], twelve[6],
      twelve[7], twelve[8];
  pose.linear() = rotation;
  pose.translation() = Vec3(twelve[9], twelve[10], twelve[11]);
  return pose;
}

std::array<double, 12> KlamptNumbersFromPose(const Pose& pose) {
  const Mat3& r = pose.linear();
  const Vec3& t = pose.translation();
  return {r(0, 0), r(0, 1), r(0, 2), r(1, 0), r(1, 1), r(1, 2),
          r(2, 0), r(2, 1), r(2, 2), t.x(),   t.y(),   t.z()};
}

Affine GeometryMatrix(const Affine& transform, const Vec3& scale) {
  return transform * Eigen::Scaling(scale);
}

}  // namespace lamina::core
