// SPDX-License-Identifier: MIT
// Field-by-field comparison of two world descriptions: what a round trip through a file must
// preserve, and what the editor uses to tell whether a world has unsaved changes. The tunables
// are compared row by row of the parameter table (core/model/params.h) and named by their
// access paths ("settings.gravity", "objects[1].kFriction", "robots[0].drivers[2].servoP");
// what is not a row (names, geometry, link structure, ...) field by field as before.
#pragma once

#include <string>
#include <vector>

#include "core/model/world_desc.h"

namespace lamina::core {

/// Every difference between `a` and `b`, one line each ("objects[1].mass: 1 vs 2", a row's
/// value in FormatParamValue); empty when they describe the same world. Numbers are equal when
/// |x - y| <= tolerance (or both the same infinity). Geometry compares file path, kind, margin,
/// Matrix() and, for primitives, the shape. Source paths and the world name are not compared.
std::vector<std::string> CompareWorlds(const WorldDesc& a, const WorldDesc& b,
                                       double tolerance = 0.0);
/// The same for two robots, with `prefix` before each field name ("robot.links[2].mass").
std::vector<std::string> CompareRobots(const RobotDesc& a, const RobotDesc& b, double tolerance,
                                       const std::string& prefix = "robot");

}  // namespace lamina::core
