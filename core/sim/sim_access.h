// SPDX-License-Identifier: MIT
// Access paths (core/model/access_path.h) on a running simulation: the table's rows through
// Simulator::GetParam and Simulator::SetParam (the one live-edit path; a refused set changes
// nothing), and the current state under the names Klamp't's simulator access uses.
//
// State items (values in the rows' layouts; world frame; SI units):
//   time                                   s, read-only
//   objects[i].transform                   current object frame: rotation column-major, then
//                                          translation (m); setting it teleports the object
//   objects[i].velocity                    angular (rad/s), then linear velocity of the object
//                                          frame's origin (m/s); settable
//   robots[r].config / actualConfig        joint values (rad or m), one per link; settable
//                                          (teleport; the controller is not told)
//   robots[r].velocity / actualVelocity    joint rates, one per link; settable
//   robots[r].torques / actualTorques      clamped driver efforts (N·m or N), one per driver
//   robots[r].links[j].transform, velocity the link frame and its twist, read-only
//   controllers[r].commandedConfig, commandedVelocity, sensedConfig, sensedVelocity
//                                          one per link, read-only
// Objects' transform and velocity and robots' config and velocity therefore mean the current
// state here and the initial conditions on a WorldDesc (Klamp't's simulator access does the
// same); the initial conditions of a running simulation are not reachable by path.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/model/access_path.h"
#include "core/sim/simulator.h"

namespace lamina::core {

/// ResolveAccessPath on the simulated world in AccessContext::kSimulation.
std::optional<AccessTarget> ResolveSimulationPath(const Simulator& simulator, std::string_view path,
                                                  std::string* error);

/// The current value of a resolved simulation target (a row, a state item, or one component);
/// nullopt with `error` naming the path (a commanded config while a driver is not in PID mode).
std::optional<ParamValue> GetPath(const Simulator& simulator, const AccessTarget& target,
                                  std::string* error);
std::optional<ParamValue> GetPath(const Simulator& simulator, std::string_view path,
                                  std::string* error);
/// Checks with the table (rows and the settable state items' layouts) and applies; false with
/// `error` naming the path ("controllers[0].commandedConfig: read-only") and nothing changed.
bool SetPath(Simulator* simulator, const AccessTarget& target, const ParamValue& value,
             std::string* error);
bool SetPath(Simulator* simulator, std::string_view path, const ParamValue& value,
             std::string* error);
/// SetPath with the value as text (ParseAccessValue).
bool SetPathText(Simulator* simulator, std::string_view path, std::string_view value_text,
                 std::string* error);

/// A path as it was given and its value.
struct PathValue {
  std::string path;
  ParamValue value;
};
/// `json` (a JSON object, e.g. RunReportJson's) with a `"get"` member: each path as given ->
/// its value, a number for one component and an array otherwise, infinities as "inf"/"-inf".
std::string AddGetJson(const std::string& json, const std::vector<PathValue>& values);

}  // namespace lamina::core
