// SPDX-License-Identifier: MIT
// Reading triangle meshes: OFF with a strict line-accurate reader of our own, every other
// format (Wavefront OBJ, STL, DAE, PLY, ...) through assimp.
#pragma once

#include <optional>
#include <string>

#include "core/diagnostics.h"
#include "core/geometry/triangle_mesh.h"

namespace lamina::core {

/// Loads the mesh in `path`. Polygons are triangulated. Errors name `path` (and the line for
/// OFF); a missing file is reported at `where`, the place that referenced it.
std::optional<TriangleMesh> ReadMeshFile(const std::string& path, const SourceLocation& where,
                                         Diagnostics& diagnostics);
/// Parses OFF text; `file` names it in diagnostics.
std::optional<TriangleMesh> ParseOff(const std::string& text, const std::string& file,
                                     Diagnostics& diagnostics);
/// True for extensions assimp or the OFF reader can load ("off", "obj", "stl", "dae", ...).
bool IsMeshExtension(const std::string& lower_extension);

}  // namespace lamina::core
