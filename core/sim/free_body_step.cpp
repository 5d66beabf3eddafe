// SPDX-License-Identifier: MIT
#include "core/sim/free_body_step.h"

#include <cmath>

#include <Eigen/Cholesky>
#include <Eigen/LU>

namespace lamina::core {

Vec3 FreeAngularVelocity(const Mat3& inertia, const Vec3& omega, const Vec3& torque, double step,
                         bool gyroscopic) {
  // (no solve for the usual zero torque)
  const Vec3 pushed = torque.isZero(0.0) ? Vec3::Zero() : Vec3(step * inertia.ldlt().solve(torque));
  if (!gyroscopic) return omega + pushed;
  const Vec3 momentum = inertia * omega;
  Mat3 cross;  // [L]×
  cross << 0.0, -momentum.z(), momentum.y(), momentum.z(), 0.0, -momentum.x(), -momentum.y(),
      momentum.x(), 0.0;
  // the closed-form inverse, as ODE's dInvertMatrix3 (never singular: its symmetric part is I)
  return (inertia - step * cross).inverse() * momentum + pushed;
}

namespace {

// ODE's sinc (ode/src/util.cpp): the two-term series below 1e-4, exact to the last bit there
double OdeSinc(double x) {
  return std::abs(x) < 1.0e-4 ? 1.0 - x * x * 0.166666666666666666667 : std::sin(x) / x;
}

// dQMultiply0: a b
OdeQuaternion Multiply(const OdeQuaternion& a, const OdeQuaternion& b) {
  return {a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
          a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
          a[0] * b[2] + a[2] * b[0] + a[3] * b[1] - a[1] * b[3],
          a[0] * b[3] + a[3] * b[0] + a[1] * b[2] - a[2] * b[1]};
}

Vec3 CapAngularSpeed(const Vec3& omega, double max_angular_speed) {
  if (std::isinf(max_angular_speed)) return omega;
  const double speed2 = omega.x() * omega.x() + omega.y() * omega.y() + omega.z() * omega.z();
  if (!(speed2 > max_angular_speed * max_angular_speed)) return omega;
  const double scale = max_angular_speed / std::sqrt(speed2);
  return {omega.x() * scale, omega.y() * scale, omega.z() * scale};
}

}  // namespace

FreeBodyPose StepFreeBody(const Vec3& position, const OdeQuaternion& rotation, const Vec3& velocity,
                          const Vec3& omega, double max_angular_speed, double step) {
  FreeBodyPose pose;
  pose.omega = CapAngularSpeed(omega, max_angular_speed);
  for (int j = 0; j < 3; ++j) pose.position[j] = position[j] + step * velocity[j];
  const Vec3& w = pose.omega;
  const double length = std::sqrt(w.x() * w.x() + w.y() * w.y() + w.z() * w.z());
  const double half = 0.5 * step;
  const double theta = length * half;
  const double s = OdeSinc(theta) * half;
  pose.rotation = Multiply({std::cos(theta), w.x() * s, w.y() * s, w.z() * s}, rotation);
  return pose;
}

}  // namespace lamina::core
