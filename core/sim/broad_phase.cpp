// SPDX-License-Identifier: MIT
#include "core/sim/broad_phase.h"

namespace lamina::core {

Eigen::AlignedBox3d WorldBounds(const CollisionGeometry& geometry, const Pose& pose,
                                double padding) {
  const Eigen::AlignedBox3d& local = geometry.local_bounds();
  Eigen::AlignedBox3d world;
  if (local.isEmpty()) return world;
  if (!local.min().allFinite() || !local.max().allFinite()) {
    return Eigen::AlignedBox3d(Vec3::Constant(-kInf), Vec3::Constant(kInf));
  }
  for (int corner = 0; corner < 8; ++corner) {
    world.extend(pose * local.corner(static_cast<Eigen::AlignedBox3d::CornerType>(corner)));
  }
  // as Collide pads: a pair at the layer's edge is still a candidate
  const double grow = padding + geometry.margin() + 0.5 * kLayerEdgeSlack;
  world.min().array() -= grow;
  world.max().array() += grow;
  return world;
}

}  // namespace lamina::core
