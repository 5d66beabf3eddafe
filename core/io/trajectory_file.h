// SPDX-License-Identifier: MIT
// Klamp't configuration and motion files: `.config`, `.path` (timed milestones),
// `.milestones` (configuration + velocity records) and MultiPath `.xml`.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/control/milestone_sequence.h"
#include "core/control/trajectory.h"
#include "core/diagnostics.h"
#include "core/math_types.h"

namespace lamina::core {

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

/// A Trajectory from any motion file ReadMotionFile reads. Untimed milestones (.milestones,
/// untimed MultiPath sections, .config) are timed with `limits`; when `limits` is empty (dof 0)
/// unit limits are used (1 per s, 1 per s^2, unbounded positions) and a note says so. Errors go
/// to `diagnostics`.
std::optional<Trajectory> LoadTrajectory(const std::string& path, Diagnostics& diagnostics,
                                         const JointLimits& limits = {});

}  // namespace lamina::core
