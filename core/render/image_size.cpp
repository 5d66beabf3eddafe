// SPDX-License-Identifier: MIT
#include "core/render/image_size.h"

#include <stdexcept>

namespace lamina::core {

bool ParseImageSize(const std::string& text, int* width, int* height) {
  const size_t x = text.find('x');
  if (x == std::string::npos) return false;
  try {
    size_t used_w = 0, used_h = 0;
    const std::string w = text.substr(0, x), h = text.substr(x + 1);
    *width = std::stoi(w, &used_w);
    *height = std::stoi(h, &used_h);
    if (used_w != w.size() || used_h != h.size()) return false;
  } catch (const std::exception&) {
    return false;
  }
  return *width >= 1 && *height >= 1 && *width <= kMaxImageSide && *height <= kMaxImageSide;
}

}  // namespace lamina::core
