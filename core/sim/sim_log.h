// SPDX-License-Identifier: MIT
// The simulation CSV log in Klamp't SimTest's `simtest_log.csv` layout (objects part): a `time`
// column, then per object `_x,_y,_z,_rz,_ry,_rx,_dx,_dy,_dz,_wz,_wy,_wx` and an empty column.
#pragma once

#include <string>

#include "core/sim/simulator.h"

namespace lamina::core {

/// The header line (with a trailing newline).
std::string SimLogHeader(const Simulator& simulator);
/// One row for the simulator's current state: object frame position, ZYX Euler angles
/// (rz = yaw, ry = pitch, rx = roll), origin velocity and angular velocity (world).
std::string SimLogRow(const Simulator& simulator);

}  // namespace lamina::core
