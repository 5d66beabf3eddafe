// SPDX-License-Identifier: MIT
#include "ui/platform/image_file.h"

#include <stb_image_write.h>

namespace lamina::ui {

bool WritePngBottomUp(const std::string& path, int width, int height,
                      const std::vector<std::uint8_t>& rgba) {
  if (width <= 0 || height <= 0 || rgba.size() < static_cast<size_t>(width) * height * 4) {
    return false;
  }
  const int stride = width * 4;
  // start at the last (top) row and walk backwards
  const std::uint8_t* top_row = rgba.data() + static_cast<size_t>(height - 1) * stride;
  return stbi_write_png(path.c_str(), width, height, 4, top_row, -stride) != 0;
}

}  // namespace lamina::ui
