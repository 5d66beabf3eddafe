// SPDX-License-Identifier: MIT
#include "core/render/sensor_overlay.h"

#include "core/robot/kinematics.h"

namespace lamina::core {

namespace {

const Rgba kHitColor(0.25f, 0.9f, 0.35f, 1.0f);
const Rgba kMissColor(0.6f, 0.6f, 0.6f, 0.5f);
const Rgba kOutlineColor(0.2f, 0.85f, 0.95f, 1.0f);
const Rgba kHotColor(0.95f, 0.2f, 0.15f, 1.0f);
const Rgba kSensedForceColor(1.0f, 0.55f, 0.1f, 1.0f);
const Rgba kTorqueColor(0.6f, 0.3f, 0.9f, 1.0f);
const Rgba kAccelerationColor(0.95f, 0.3f, 0.8f, 1.0f);

Rgba SegmentColor(SensorDrawing::Kind kind) {
  switch (kind) {
    case SensorDrawing::Kind::kRayHit:
      return kHitColor;
    case SensorDrawing::Kind::kRayMiss:
      return kMissColor;
    case SensorDrawing::Kind::kOutline:
      return kOutlineColor;
    case SensorDrawing::Kind::kOutlineHot:
      return kHotColor;
  }
  return kOutlineColor;
}

void AddArrow(const SensorDrawing::Arrow& arrow, const OverlayOptions& options,
              RenderScene* scene) {
  double scale = kAccelerationArrowScale;
  Rgba color = kAccelerationColor;
  if (arrow.quantity == SensorDrawing::Quantity::kForce) {
    scale = options.force_scale;
    color = kSensedForceColor;
  } else if (arrow.quantity == SensorDrawing::Quantity::kTorque) {
    scale = kTorqueArrowScale;
    color = kTorqueColor;
  }
  const Vec3 vector = arrow.value * scale;
  if (!vector.allFinite() || vector.norm() < 1e-3) return;
  scene->arrows.push_back(
      {arrow.from.cast<float>(), (arrow.from + vector).cast<float>(), 0.004f, color});
}

}  // namespace

void AddSensorOverlay(const SensorDrawing& drawing, const OverlayOptions& options,
                      RenderScene* scene) {
  for (const SensorDrawing::Segment& s : drawing.segments) {
    scene->lines.push_back({s.from.cast<float>(), s.to.cast<float>(), SegmentColor(s.kind)});
  }
  for (const Vec3& hit : drawing.hits)
    scene->points.push_back({hit.cast<float>(), 0.01f, kHitColor});
  for (const SensorDrawing::Arrow& a : drawing.arrows) AddArrow(a, options, scene);
}

void AddSensorOverlays(const Simulator& simulator, const OverlayOptions& options,
                       RenderScene* scene) {
  if (!options.sensors) return;
  for (int r = 0; r < simulator.robot_count(); ++r) {
    const std::vector<Pose> frames =
        LinkTransforms(simulator.world().robots[r], simulator.GetRobotConfig(r));
    AddSensorOverlay(simulator.sensors(r).Drawing(frames), options, scene);
  }
}

}  // namespace lamina::core
