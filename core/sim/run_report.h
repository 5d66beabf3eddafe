// SPDX-License-Identifier: MIT
// The report of `lamina-headless run`: final body states, worst status, counters, timing.
#pragma once

#include <string>

#include "core/sim/simulator.h"

namespace lamina::core {

struct RunTiming {
  double wall_time = 0.0;  ///< s spent in Simulate
};

/// One JSON object: time, wall_time, steps, status, rollbacks, instability_corrections,
/// unreliable_steps, max_penetration, max_contacts, real_time_factor, `settings` (every settings
/// row of the parameter table in force, keyed by row key) and `objects` (name, position,
/// quaternion [w,x,y,z], velocity, angular_velocity of every rigid object's frame).
std::string RunReportJson(const Simulator& simulator, const RunTiming& timing);
/// The same as readable text.
std::string RunReportText(const Simulator& simulator, const RunTiming& timing);

}  // namespace lamina::core
