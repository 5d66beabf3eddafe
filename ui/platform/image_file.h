// SPDX-License-Identifier: MIT
// Writing RGBA8 pixel buffers as PNG (stb_image_write).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace lamina::ui {

/// Writes `rgba` (width*height*4 bytes, rows bottom-up as OpenGL reads them) as a PNG with the
/// top row first. False when the file cannot be written.
bool WritePngBottomUp(const std::string& path, int width, int height,
                      const std::vector<std::uint8_t>& rgba);

}  // namespace lamina::ui
