// SPDX-License-Identifier: MIT
// Orbit camera math, framing and the text description.
#include "core/render/camera.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>
#include <vector>

#include "core/math_types.h"

namespace lamina::core {

namespace {

double Radians(double degrees) {
  return degrees * kPi / 180.0;
}

// extra room around a framed box
constexpr double kFramingMargin = 1.08;

std::string ExactNumber(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, result.ptr);
}

bool ParseNumber(const std::string& text, double* value) {
  const char* end = text.data() + text.size();
  const auto result = std::from_chars(text.data(), end, *value);
  return result.ec == std::errc() && result.ptr == end && std::isfinite(*value);
}

std::vector<std::string> Split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::istringstream in(text);
  std::string part;
  while (std::getline(in, part, separator)) parts.push_back(part);
  return parts;
}

std::string TrimText(const std::string& text) {
  const size_t first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

bool CheckRanges(const OrbitCamera& camera, std::string* error) {
  if (!(camera.pitch > -90.0 && camera.pitch < 90.0)) {
    *error = "pitch must be in (-90, 90) degrees, got " + ExactNumber(camera.pitch);
  } else if (!(camera.distance > 0.0)) {
    *error = "dist must be > 0, got " + ExactNumber(camera.distance);
  } else if (!(camera.fov_y > 0.0 && camera.fov_y < 180.0)) {
    *error = "fov must be in (0, 180) degrees, got " + ExactNumber(camera.fov_y);
  } else {
    return true;
  }
  return false;
}

bool ParseCompact(const std::string& text, OrbitCamera* camera, std::string* error) {
  std::istringstream in(text);
  std::vector<double> values;
  std::string word;
  while (in >> word) {
    double value = 0.0;
    if (!ParseNumber(word, &value)) {
      *error = "camera: '" + word + "' is not a number";
      return false;
    }
    values.push_back(value);
  }
  if (values.size() != 6 && values.size() != 7) {
    *error =
        "camera: expected 'target=x,y,z;yaw=..;pitch=..;dist=..;fov=..' or 6-7 numbers "
        "'x y z yaw pitch dist [fov]', got " +
        std::to_string(values.size()) + " numbers";
    return false;
  }
  OrbitCamera parsed = *camera;
  parsed.target = Eigen::Vector3d(values[0], values[1], values[2]);
  parsed.yaw = values[3];
  parsed.pitch = values[4];
  parsed.distance = values[5];
  if (values.size() == 7) parsed.fov_y = values[6];
  if (!CheckRanges(parsed, error)) {
    *error = "camera: " + *error;
    return false;
  }
  *camera = parsed;
  return true;
}

bool ParseKey(const std::string& key, const std::string& value, OrbitCamera* camera,
              std::string* error) {
  if (key == "target") {
    const std::vector<std::string> parts = Split(value, ',');
    Eigen::Vector3d target;
    if (parts.size() != 3 || !ParseNumber(TrimText(parts[0]), &target.x()) ||
        !ParseNumber(TrimText(parts[1]), &target.y()) ||
        !ParseNumber(TrimText(parts[2]), &target.z())) {
      *error = "camera: target expects three numbers 'x,y,z', got '" + value + "'";
      return false;
    }
    camera->target = target;
    return true;
  }
  double* field = key == "yaw"     ? &camera->yaw
                  : key == "pitch" ? &camera->pitch
                  : key == "dist"  ? &camera->distance
                  : key == "fov"   ? &camera->fov_y
                                   : nullptr;
  if (field == nullptr) {
    *error = "camera: unknown key '" + key + "' (expected target, yaw, pitch, dist, fov)";
    return false;
  }
  if (!ParseNumber(value, field)) {
    *error = "camera: " + key + " expects a number, got '" + value + "'";
    return false;
  }
  return true;
}

}  // namespace

Eigen::Vector3d OrbitCamera::Eye() const {
  const double y = Radians(yaw), p = Radians(pitch);
  const Eigen::Vector3d offset(std::cos(p) * std::cos(y), std::cos(p) * std::sin(y), std::sin(p));
  return target + distance * offset;
}

Eigen::Matrix4d LookAt(const Eigen::Vector3d& eye, const Eigen::Vector3d& target) {
  const Eigen::Vector3d forward = (target - eye).normalized();
  const Eigen::Vector3d helper =
      std::abs(forward.z()) < 0.99 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitX();
  const Eigen::Vector3d right = forward.cross(helper).normalized();
  const Eigen::Vector3d up = right.cross(forward);
  Eigen::Matrix4d view = Eigen::Matrix4d::Identity();
  view.block<1, 3>(0, 0) = right.transpose();
  view.block<1, 3>(1, 0) = up.transpose();
  view.block<1, 3>(2, 0) = -forward.transpose();
  view(0, 3) = -right.dot(eye);
  view(1, 3) = -up.dot(eye);
  view(2, 3) = forward.dot(eye);
  return view;
}

Eigen::Matrix4d OrbitCamera::ViewMatrix() const {
  return LookAt(Eye(), target);
}

void ClipDistances(const OrbitCamera& camera, double scene_radius, double* near_plane,
                   double* far_plane) {
  const double radius = std::max(scene_radius, 1e-3);
  *far_plane = camera.distance + 2.0 * radius;
  *near_plane = std::max(*far_plane * 1e-4, std::max(camera.distance - radius, 0.0) * 0.5);
  *near_plane = std::min(*near_plane, camera.distance * 0.5);
}

Eigen::Matrix4d OrbitCamera::ProjectionMatrix(double aspect, double scene_radius) const {
  double n = 0.0, f = 0.0;
  ClipDistances(*this, scene_radius, &n, &f);
  const double t = 1.0 / std::tan(0.5 * Radians(fov_y));
  Eigen::Matrix4d projection = Eigen::Matrix4d::Zero();
  projection(0, 0) = t / aspect;
  projection(1, 1) = t;
  projection(2, 2) = -(f + n) / (f - n);
  projection(2, 3) = -2.0 * f * n / (f - n);
  projection(3, 2) = -1.0;
  return projection;
}

Eigen::Matrix4d CameraFrameViewMatrix(const Pose& camera) {
  Eigen::Matrix4d flip = Eigen::Matrix4d::Identity();
  flip(1, 1) = flip(2, 2) = -1.0;  // y down, z forward -> y up, looking down -z
  return flip * camera.inverse().matrix();
}

Eigen::Matrix4d HorizontalFovProjection(double xfov, double aspect, double near_plane,
                                        double far_plane) {
  const double t = 1.0 / std::tan(0.5 * xfov);
  const double n = near_plane, f = far_plane;
  Eigen::Matrix4d projection = Eigen::Matrix4d::Zero();
  projection(0, 0) = t;
  projection(1, 1) = t * aspect;
  projection(2, 2) = -(f + n) / (f - n);
  projection(2, 3) = -2.0 * f * n / (f - n);
  projection(3, 2) = -1.0;
  return projection;
}

OrbitCamera FramingCamera(const Eigen::AlignedBox3d& box, double aspect) {
  OrbitCamera camera;
  if (box.isEmpty()) return camera;
  camera.target = box.center();
  camera.distance = 1.0;
  const Eigen::Matrix4d view = camera.ViewMatrix();
  const Eigen::Vector3d right = view.block<1, 3>(0, 0).transpose();
  const Eigen::Vector3d up = view.block<1, 3>(1, 0).transpose();
  const Eigen::Vector3d forward = -view.block<1, 3>(2, 0).transpose();
  const double tan_vertical = std::tan(0.5 * Radians(camera.fov_y));
  const double tan_horizontal = tan_vertical * aspect;
  // the eye sits at target - distance * forward: each corner must be inside both half-angles
  double distance = 1e-3;
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d p =
        box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(i)) - camera.target;
    const double depth_offset = p.dot(forward);
    distance = std::max(distance, std::abs(p.dot(right)) / tan_horizontal - depth_offset);
    distance = std::max(distance, std::abs(p.dot(up)) / tan_vertical - depth_offset);
  }
  camera.distance = kFramingMargin * distance;
  return camera;
}

std::string FormatCamera(const OrbitCamera& camera) {
  return "target=" + ExactNumber(camera.target.x()) + "," + ExactNumber(camera.target.y()) + "," +
         ExactNumber(camera.target.z()) + ";yaw=" + ExactNumber(camera.yaw) +
         ";pitch=" + ExactNumber(camera.pitch) + ";dist=" + ExactNumber(camera.distance) +
         ";fov=" + ExactNumber(camera.fov_y);
}

bool ParseCamera(const std::string& text, OrbitCamera* camera, std::string* error) {
  if (text.find('=') == std::string::npos) return ParseCompact(text, camera, error);
  OrbitCamera parsed = *camera;
  for (const std::string& raw : Split(text, ';')) {
    const std::string entry = TrimText(raw);
    if (entry.empty()) continue;
    const size_t equals = entry.find('=');
    if (equals == std::string::npos) {
      *error = "camera: '" + entry + "' is not key=value";
      return false;
    }
    if (!ParseKey(TrimText(entry.substr(0, equals)), TrimText(entry.substr(equals + 1)), &parsed,
                  error)) {
      return false;
    }
  }
  if (!CheckRanges(parsed, error)) {
    *error = "camera: " + *error;
    return false;
  }
  *camera = parsed;
  return true;
}

}  // namespace lamina::core
