// SPDX-License-Identifier: MIT
// OffscreenContext over OSMesa: an OpenGL 3.3 core context (Mesa's llvmpipe) rendering into a
// buffer in memory — no display, no window. Only programs that do not link libGL/libOpenGL may
// use it (see docs/rendering.md). Kept small so that an EGL-surfaceless context can replace it
// when Mesa drops OSMesa.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace lamina::ui {

class OsmesaContext {
 public:
  OsmesaContext() = default;
  OsmesaContext(const OsmesaContext&) = delete;
  OsmesaContext& operator=(const OsmesaContext&) = delete;
  ~OsmesaContext();

  /// Creates a core-profile 3.3 context with a `width` x `height` RGBA buffer and makes it
  /// current. False with `error` set when OSMesa refuses.
  bool Create(int width, int height, std::string* error);
  /// Makes the context current on this thread with a buffer of the new size.
  bool Resize(int width, int height);
  bool MakeCurrent();
  /// Waits until every GL command has finished (there is nothing to swap).
  void SwapOrFinish();
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  void* context_ = nullptr;  ///< OSMesaContext
  std::vector<std::uint8_t> buffer_;
  int width_ = 0, height_ = 0;
};

}  // namespace lamina::ui
