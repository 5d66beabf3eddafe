// SPDX-License-Identifier: MIT
// A motion as a list of milestones: what the motion files hold (core/io/trajectory_file.h reads
// and writes them) and what the controller's trajectories and SendMotion are built from.
#pragma once

#include <vector>

#include "core/math_types.h"

namespace lamina::core {

/// A timed or untimed sequence of milestones. `times` is empty when untimed; `velocities` is
/// empty when the file gave none.
struct MilestoneSequence {
  std::vector<double> times;     ///< s, nondecreasing
  std::vector<VecX> configs;     ///< all the same length
  std::vector<VecX> velocities;  ///< same count and length as configs, or empty
};

}  // namespace lamina::core
