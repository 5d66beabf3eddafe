// SPDX-License-Identifier: MIT
// Robot sensors drawn in 3-D (the `sensors` overlay): laser rays (green to a hit, with a point
// there; grey when they miss), camera frusta and contact patches (cyan outlines; a patch in
// contact red), and the measured forces (orange, the contact overlay's force_scale m per N),
// torques (purple, 0.1 m per N·m) and accelerometer readings (magenta, 0.02 m per m/s²) as arrows.
#pragma once

#include <vector>

#include "core/render/overlay_options.h"
#include "core/render/render_scene.h"
#include "core/sensors/sensor.h"
#include "core/sim/simulator.h"

namespace lamina::core {

/// Metres of arrow per N·m of torque and per m/s² of acceleration.
inline constexpr double kTorqueArrowScale = 0.1;
inline constexpr double kAccelerationArrowScale = 0.02;

/// Appends `drawing`'s lines, points and arrows to `scene` (arrows shorter than 1 mm left out).
void AddSensorOverlay(const SensorDrawing& drawing, const OverlayOptions& options,
                      RenderScene* scene);
/// Every robot's sensors of `simulator` as they are now, when options.sensors is on (for views
/// on the simulation's own thread: `shot`, `record`, Python's vis.run).
void AddSensorOverlays(const Simulator& simulator, const OverlayOptions& options,
                       RenderScene* scene);

}  // namespace lamina::core
