// SPDX-License-Identifier: MIT
// Klamp't configuration and motion files: `.config`, `.path` (timed milestones),
// `.milestones` (configuration + velocity records) and MultiPath `.xml`.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/diagnostics.h"
#include "core/math_types.h"

namespace lamina::core {

/// A timed or untimed sequence of milestones. `times` is empty when untimed; `velocities` is
/// empty when the file gave none.
struct MilestoneSequence {
  std::vector<double> times;     ///< s, nondecreasing
  std::vector<VecX> configs;     ///< all the same length
  std::vector<VecX> velocities;  ///< same count and length as configs, or empty
};

/// A `.config` file: one "N q1 ... qN" vector.
std::optional<VecX> ReadConfigFile(const std::string& path, Diagnostics& diagnostics);
std::optional<VecX> ParseConfig(const std::string& text, const std::string& file,
                                Diagnostics& diagnostics);
/// A `.path` file: lines "t  N q1 ... qN".
std::optional<MilestoneSequence> ParseLinearPath(const std::string& text, const std::string& file,
                                                 Diagnostics& diagnostics);
/// A `.milestones` file: records "N q...  N dq...".
std::optional<MilestoneSequence> ParseMilestones(const std::string& text, const std::string& file,
                                                 Diagnostics& diagnostics);
/// A MultiPath `.xml` file: the milestones of all sections in order (ikgoals are ignored with
/// a note).
std::optional<MilestoneSequence> ParseMultiPath(const std::string& text, const std::string& file,
                                                Diagnostics& diagnostics);
/// Any of the above by extension (.config gives one untimed milestone).
std::optional<MilestoneSequence> ReadMotionFile(const std::string& path, Diagnostics& diagnostics);

/// Text writers that the parsers read back exactly.
std::string WriteConfig(const VecX& config);
std::string WriteLinearPath(const MilestoneSequence& path);
std::string WriteMilestones(const MilestoneSequence& milestones);

}  // namespace lamina::core
