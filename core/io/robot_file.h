// SPDX-License-Identifier: MIT
// Loading robots: Klamp't `.rob` files and URDF (through urdfdom), and writing `.rob`.
#pragma once

#include <string>
#include <vector>

#include "core/io/load_context.h"
#include "core/model/world_desc.h"

namespace lamina::core {

/// Loads a `.rob` or `.urdf` robot from `path` (absolute), by extension. `where` is the place
/// that referenced it (for a missing file). Mass properties are final (automass applied),
/// `config`/`velocity` are set from the file. The name is the file stem unless set later.
bool LoadRobotFile(const std::string& path, const SourceLocation& where, LoadContext& context,
                   RobotDesc* out);

/// Parses `.rob` text; `path` is used for messages and to resolve relative file names.
bool ParseRob(const std::string& text, const std::string& path, LoadContext& context,
              RobotDesc* out);

/// Parses URDF text; `path` is used for messages and to resolve mesh file names
/// (relative to the file, or package://NAME/... searched upward from the file's directory).
bool ParseUrdf(const std::string& text, const std::string& path, LoadContext& context,
               RobotDesc* out);

/// `.rob` text that ParseRob turns back into an identical RobotDesc (name, config and velocity
/// aside). Mesh paths are written relative to directory `rob_dir`.
/// The limits of a normal, translation or rotation driver are written as its link's velmin,
/// velmax and torquemax (from which the reader copies them).
std::string WriteRob(const RobotDesc& robot, const std::string& rob_dir);
/// The same, adding to `errors` what the file cannot hold ("drivers[2].torqueLimits -3,5 cannot
/// be saved: ..."; a `.rob` gives such a driver symmetric torque limits).
std::string WriteRob(const RobotDesc& robot, const std::string& rob_dir,
                     std::vector<std::string>* errors);

}  // namespace lamina::core
