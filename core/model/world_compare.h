// SPDX-License-Identifier: MIT
// Field-by-field comparison of two world descriptions: what a round trip through a file must
// preserve, and what the editor uses to tell whether a world has unsaved changes.
#pragma once

#include <string>
#include <vector>

#include "core/model/world_desc.h"

namespace lamina::core {

/// Every difference between `a` and `b`, one line each ("objects[1].mass: 1 vs 2"); empty when
/// they describe the same world. Numbers are equal when |x - y| <= tolerance (or both the
/// same infinity). Geometry compares file path, kind, margin, Matrix() and, for primitives,
/// the shape. Source paths and the world name are not compared.
std::vector<std::string> CompareWorlds(const WorldDesc& a, const WorldDesc& b,
                                       double tolerance = 0.0);
/// The same for two robots, with `prefix` before each field name.
std::vector<std::string> CompareRobots(const RobotDesc& a, const RobotDesc& b, double tolerance,
                                       const std::string& prefix = "robot");

}  // namespace lamina::core
