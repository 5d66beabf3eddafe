// SPDX-License-Identifier: MIT
// What `lamina-headless info` prints: every terrain, object and robot with its counts, mass
// and the simulation parameters in force, as text or as JSON. The tunables are the parameter
// table's rows (core/model/params.h), keyed by the row key: the settings, each body's padding
// and surface, objects' mass properties and initial conditions, links' mass properties and
// joint limits, drivers' gains, limits and friction.
#pragma once

#include <string>

#include "core/model/element.h"
#include "core/model/world_desc.h"

namespace lamina::core {

/// Human-readable summary, one block per element.
std::string WorldSummaryText(const WorldDesc& world);
/// The same facts as a JSON document (infinite values as the strings "inf" / "-inf").
std::string WorldSummaryJson(const WorldDesc& world);

/// Every table row of `element` as a JSON object keyed by row key (the form `info --json` uses;
/// `run --json` reports the settings with it).
std::string ParamsJson(const WorldDesc& world, const ElementIndex& element);

/// Triangles of all of a robot's link geometry.
int RobotTriangleCount(const RobotDesc& robot);
/// Points of every point-cloud geometry of the robot's links.
int RobotPointCount(const RobotDesc& robot);

}  // namespace lamina::core
