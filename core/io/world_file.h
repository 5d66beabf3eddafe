// SPDX-License-Identifier: MIT
// Klamp't world XML: loading (`<world>` with `<robot>`, `<rigidObject>`, `<terrain>` and the
// `<simulation>` block) and saving so that load -> save -> load gives the same WorldDesc.
// Every tunable is read, checked and written as a row of the parameter table
// (core/model/params.h). Lamina's additions to Klamp't's format: the `<globals>` attributes of
// Lamina's settings rows (written only when they differ from SimSettings{}) and `<robot
// velocity="N ...">` (the initial joint rates, written only when not zero).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "core/io/load_context.h"
#include "core/model/world_desc.h"

namespace lamina::core {

/// Loads the world in `path`. A robot, object or terrain file given instead of a world loads
/// as a world holding just that element. Returns false when any error was reported; the
/// description then holds whatever could be read.
bool LoadWorldFile(const std::string& path, LoadContext& context, WorldDesc* out);

/// Parses world XML text; `path` names it in messages and anchors relative file names.
bool ParseWorldXml(const std::string& text, const std::string& path, LoadContext& context,
                   WorldDesc* out);

/// The XML of `world` for a file at `path`: file references relative to its directory, each
/// robot as a `.rob` in `<stem>_robots/` beside it, inline primitives as `.geom` files there.
struct WorldFileSet {
  std::string world_xml;
  std::vector<std::pair<std::string, std::string>> robot_files;  ///< absolute path -> text
  /// `.geom` files for robot primitives that had no file (from URDF): absolute path -> text.
  std::vector<std::pair<std::string, std::string>> geometry_files;
  std::vector<std::string> errors;  ///< what the files cannot express (nothing is saved then)
};
WorldFileSet WriteWorld(const WorldDesc& world, const std::string& path);

/// Saves `world` to `path` (and its robot files), each written atomically. False with an
/// error diagnostic on failure.
bool SaveWorldFile(const WorldDesc& world, const std::string& path, Diagnostics& diagnostics);

}  // namespace lamina::core
