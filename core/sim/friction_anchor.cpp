// SPDX-License-Identifier: MIT
#include "core/sim/friction_anchor.h"

#include <algorithm>
#include <tuple>

#include <Eigen/Geometry>

namespace lamina::core {

namespace {

bool AnchorLess(const FrictionAnchor& x, const FrictionAnchor& y) {
  return std::tie(x.a, x.b) < std::tie(y.a, y.b);
}

}  // namespace

FrictionAnchor MakeAnchor(int a, int b, const BodyFrame& frame_a, const BodyFrame& frame_b) {
  FrictionAnchor anchor;
  anchor.a = a;
  anchor.b = b;
  anchor.rotation = frame_b.rotation.transpose() * frame_a.rotation;
  anchor.position = frame_b.rotation.transpose() * (frame_a.position - frame_b.position);
  return anchor;
}

double AnchorRotation(const FrictionAnchor& anchor, const BodyFrame& frame_a,
                      const BodyFrame& frame_b) {
  const Mat3 now = frame_b.rotation.transpose() * frame_a.rotation;
  return Eigen::AngleAxisd(now * anchor.rotation.transpose()).angle();
}

Vec3 AnchorDrift(const FrictionAnchor& anchor, const BodyFrame& frame_a, const BodyFrame& frame_b,
                 const Vec3& point, const Vec3& normal) {
  // the point in a's frame, then where it is in b's frame now and where it was when anchored
  const Vec3 in_a = frame_a.rotation.transpose() * (point - frame_a.position);
  const Vec3 now_in_b = frame_b.rotation.transpose() * (point - frame_b.position);
  const Vec3 then_in_b = anchor.rotation * in_a + anchor.position;
  const Vec3 drift = frame_b.rotation * (now_in_b - then_in_b);
  return drift - drift.dot(normal) * normal;
}

Vec3 AnchorCorrectionVelocity(const Vec3& drift, double step, double gain) {
  const double distance = drift.norm();
  if (distance < kAnchorMinDrift) return Vec3::Zero();
  const double speed = std::min(gain * distance / step, kAnchorMaxCorrectionSpeed);
  return -speed / distance * drift;
}

const FrictionAnchor* FindAnchor(const std::vector<FrictionAnchor>& anchors, int a, int b) {
  FrictionAnchor key;
  key.a = a;
  key.b = b;
  const auto it = std::lower_bound(anchors.begin(), anchors.end(), key, AnchorLess);
  return it != anchors.end() && it->a == a && it->b == b ? &*it : nullptr;
}

void SortAnchors(std::vector<FrictionAnchor>* anchors) {
  std::sort(anchors->begin(), anchors->end(), AnchorLess);
}

void ForgetAnchors(std::vector<FrictionAnchor>* anchors, int id) {
  std::erase_if(*anchors,
                [id](const FrictionAnchor& anchor) { return anchor.a == id || anchor.b == id; });
}

}  // namespace lamina::core
