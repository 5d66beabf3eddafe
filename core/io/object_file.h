// SPDX-License-Identifier: MIT
// Klamp't rigid-object `.obj` files (key-value text, not Wavefront: told apart by content) and
// `.env` terrain files.
#pragma once

#include <string>

#include "core/io/load_context.h"
#include "core/model/world_desc.h"

namespace lamina::core {

/// True when `text` reads as a Klamp't object file rather than a Wavefront OBJ mesh.
bool LooksLikeKlamptObject(const std::string& text);

/// Loads a rigid object from `path`: a Klamp't `.obj`, or any mesh file (then mass 1 with
/// automass, friction 0.5, restitution 0.5, rigid). Sets pose, geometry, mass properties,
/// surface and initial velocity; the name is the file stem.
bool LoadRigidObjectFile(const std::string& path, const SourceLocation& where, LoadContext& context,
                         RigidObjectDesc* out);

/// Loads a terrain from `path`: a `.env` file or any mesh file (friction 0.5).
bool LoadTerrainFile(const std::string& path, const SourceLocation& where, LoadContext& context,
                     TerrainDesc* out);

}  // namespace lamina::core
