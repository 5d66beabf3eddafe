// SPDX-License-Identifier: MIT
// The simulation CSV log in Klamp't SimTest's `simtest_log.csv` layout: a `time` column, per robot
// its q, dq and actuator torques, then per sensor `<robot>_<sensor>[<measurement>]` columns and an
// empty column (images left out), then per object `_x,_y,_z,_rz,_ry,_rx,_dx,_dy,_dz,_wz,_wy,_wx`
// and an empty column.
#pragma once

#include <ostream>
#include <string>

#include "core/sim/simulator.h"

namespace lamina::core {

/// The header line (with a trailing newline).
std::string SimLogHeader(const Simulator& simulator);
/// One row for the simulator's current state: object frame position, ZYX Euler angles
/// (rz = yaw, ry = pitch, rx = roll), origin velocity and angular velocity (world).
std::string SimLogRow(const Simulator& simulator);

/// The log as a step observer (Simulator::AddStepObserver): a row at the start and whenever an
/// accepted step reaches the next multiple of `interval` of simulated time (Klamp't SimTest logs
/// every 0.01 s), so the rows do not depend on how the run is chunked. It measures the wall time it
/// spends writing, which a run's real-time factor leaves out.
class SimLogWriter {
 public:
  SimLogWriter(std::ostream* out, const Simulator& simulator, double interval);
  void operator()(const StepEvent& event);
  /// A last row when the run ended between two marks.
  void Finish(const Simulator& simulator);
  double seconds_spent() const { return seconds_; }

 private:
  void Write(const Simulator& simulator);
  std::ostream* out_;
  double interval_;
  double next_ = 0.0;      ///< simulated time of the next row (s)
  double last_row_ = 0.0;  ///< simulated time of the last row (s)
  double seconds_ = 0.0;   ///< wall time spent writing (s)
};

}  // namespace lamina::core
