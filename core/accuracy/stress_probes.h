// SPDX-License-Identifier: MIT
// Probes of the stress suite (stress_case.h) for the worlds the accuracy scenes do not cover: how
// close the rigid objects' cores came to a floor, and how well a robot's joints held together.
#pragma once

#include <memory>

#include "core/accuracy/accuracy_scene.h"

namespace lamina::core {

/// The lowest point of any rigid object's core (its geometry, padding not counted) above the
/// plane z = `floor` (m): the error is the smallest value over the run (negative: a core went
/// below the floor's surface), metric "final lowest core m" the value at the end, and "padding m"
/// the smallest object padding (a body resting in its layer ends between 0 and the padding).
std::unique_ptr<AccuracyProbe> MakeFloorGapProbe(const WorldDesc& world, double floor);

/// Robot 0's joints: a link's frame origin should stay where its parent's frame and its
/// parent_transform put it (on the joint axis). The error is the largest such gap over the run
/// (m); metrics "final joint gap m", "largest link displacement m" (a link origin from its start,
/// at the end) and "largest joint speed rad/s" (at the end).
std::unique_ptr<AccuracyProbe> MakeJointGapProbe(const WorldDesc& world);

}  // namespace lamina::core
