// SPDX-License-Identifier: MIT
// Picking: the ray is taken into each item's mesh coordinates (an affine map keeps the ray
// parameter), culled by the mesh bounds, then tested against every triangle.
#include "core/render/picking.h"

#include <cmath>
#include <limits>

#include <Eigen/LU>

namespace lamina::core {

namespace {

// the ray parameter range [t_enter, t_exit] inside `box`; false when the ray misses it
bool RayHitsBox(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                const Eigen::AlignedBox3d& box, double max_distance) {
  double t_enter = 0.0, t_exit = max_distance;
  for (int axis = 0; axis < 3; ++axis) {
    const double inverse = 1.0 / direction[axis];  // +-inf for a zero component
    double t0 = (box.min()[axis] - origin[axis]) * inverse;
    double t1 = (box.max()[axis] - origin[axis]) * inverse;
    if (std::isnan(t0) || std::isnan(t1)) {
      // parallel to the slab: inside it or not
      if (origin[axis] < box.min()[axis] || origin[axis] > box.max()[axis]) return false;
      continue;
    }
    if (t0 > t1) std::swap(t0, t1);
    t_enter = std::max(t_enter, t0);
    t_exit = std::min(t_exit, t1);
    if (t_enter > t_exit) return false;
  }
  return true;
}

bool Pickable(const DrawItem& item, const PickFilter& filter) {
  if (item.world_id < 0 || !item.mesh || item.mesh->empty()) return false;
  if (item.has(kDrawUnlit)) return false;
  if (item.has(kDrawTranslucent) && !filter.translucent) return false;
  if (item.has(kDrawTerrain) && !filter.terrains) return false;
  return true;
}

// nearest hit of `ray` on `item`, as a world distance; infinity when missed
double ItemHitDistance(const DrawItem& item, const Ray& ray, double nearest) {
  const Eigen::Matrix4d transform = item.transform.cast<double>();
  const Eigen::Matrix3d linear = transform.topLeftCorner<3, 3>();
  if (std::abs(linear.determinant()) < 1e-300) return std::numeric_limits<double>::infinity();
  const Eigen::Matrix3d inverse = linear.inverse();
  // the mesh-space ray: origin mapped, direction mapped without normalising, so that the ray
  // parameter is the world distance
  const Eigen::Vector3d origin = inverse * (ray.origin - transform.block<3, 1>(0, 3));
  const Eigen::Vector3d direction = inverse * ray.direction;
  const RenderMesh& mesh = *item.mesh;
  const Eigen::AlignedBox3d bounds = mesh.bounds.cast<double>();
  if (!RayHitsBox(origin, direction, bounds, nearest)) {
    return std::numeric_limits<double>::infinity();
  }
  double best = nearest;
  for (int corner = 0; corner + 2 < mesh.corner_count(); corner += 3) {
    const double t = RayTriangleDistance(origin, direction, mesh.positions[corner].cast<double>(),
                                         mesh.positions[corner + 1].cast<double>(),
                                         mesh.positions[corner + 2].cast<double>());
    if (t >= 0.0 && t < best) best = t;
  }
  return best;
}

}  // namespace

Ray PixelRay(const OrbitCamera& camera, int width, int height, double x, double y) {
  const Eigen::Matrix4d view = camera.ViewMatrix();
  const Eigen::Vector3d right = view.block<1, 3>(0, 0).transpose();
  const Eigen::Vector3d up = view.block<1, 3>(1, 0).transpose();
  const Eigen::Vector3d forward = -view.block<1, 3>(2, 0).transpose();
  const double aspect = static_cast<double>(width) / std::max(height, 1);
  const double half_height = std::tan(camera.fov_y * kPi / 360.0);
  const double ndc_x = 2.0 * x / std::max(width, 1) - 1.0;
  const double ndc_y = 1.0 - 2.0 * y / std::max(height, 1);
  Ray ray;
  ray.origin = camera.Eye();
  ray.direction =
      (forward + right * (ndc_x * half_height * aspect) + up * (ndc_y * half_height)).normalized();
  return ray;
}

double RayTriangleDistance(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                           const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                           const Eigen::Vector3d& c) {
  const Eigen::Vector3d edge1 = b - a, edge2 = c - a;
  const Eigen::Vector3d p = direction.cross(edge2);
  const double determinant = edge1.dot(p);
  if (std::abs(determinant) < 1e-15) return -1.0;  // parallel to the triangle
  const double inverse = 1.0 / determinant;
  const Eigen::Vector3d s = origin - a;
  const double u = s.dot(p) * inverse;
  if (u < 0.0 || u > 1.0) return -1.0;
  const Eigen::Vector3d q = s.cross(edge1);
  const double v = direction.dot(q) * inverse;
  if (v < 0.0 || u + v > 1.0) return -1.0;
  return edge2.dot(q) * inverse;
}

PickHit PickBody(const RenderScene& scene, const Ray& ray, const PickFilter& filter) {
  PickHit result;
  double nearest = std::numeric_limits<double>::infinity();
  for (const DrawItem& item : scene.items) {
    if (!Pickable(item, filter)) continue;
    const double distance = ItemHitDistance(item, ray, nearest);
    if (distance < nearest) {
      nearest = distance;
      result.world_id = item.world_id;
    }
  }
  if (result.hit()) {
    result.distance = nearest;
    result.point = ray.origin + nearest * ray.direction;
  }
  return result;
}

}  // namespace lamina::core
