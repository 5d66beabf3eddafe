// SPDX-License-Identifier: MIT
// GLSL sources of shaders/, compiled into the program by cmake/EmbedShaders.cmake.
#pragma once

namespace lamina::ui {

/// Source of shaders/<name> (e.g. "mesh.frag"), or nullptr when there is no such file.
const char* EmbeddedShader(const char* name);

}  // namespace lamina::ui
